// QuadsOntoSource.h: the quads made on a simplified surface put onto the surface it was
// simplified from, without turning any over.
#ifndef quadcover_QuadsOntoSource_h
#define quadcover_QuadsOntoSource_h

#include "QuadMeshing.h"

#include <Eigen/Core>

namespace quadcover
{

/**
 * Each vertex of r.mesh, made on the working surface (workV, workF), moved to its closest point on
 * the surface (V, F) that one was simplified from. The corners of a quad that this turns over (its
 * normal against the one it had: across a crease or a thin rim the closest points can lie on
 * different sides), turns a corner of inside out, or turns to face against the triangle of
 * (V, F) closest to its centre where it faced the one closest before go back where they were,
 * until none does. The quads that then face against (V, F) or are inside out (a thin part whose
 * working surface lies farther from its other side than the quads bulge: a quad facing the
 * working surface can face the far side of the part) go to removeTurnedQuads when removeTurned
 * is set (QuadMeshOptions::repairInvertedQuads), measured against
 * (V, F) (the facing's cosine and the scaled Jacobian, the smaller), counted in r.collapse; the
 * quality figures are then measured again. (V, F)'s triangles are measured by their normals
 * turned as the working surface faces beside them: a raw input may have triangles the repair
 * turned over. The points the collapses move or merge get the triangles of (V, F) they lie in; the
 * others keep their triangles of the working surface.
 */
void putQuadsOnto(QuadMeshResult& r, const Eigen::MatrixX3d& workV, const Eigen::MatrixX3i& workF,
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, bool removeTurned = true);
}

#endif
