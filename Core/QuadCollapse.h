// QuadCollapse.h: the quad stage's last repair of the quads that still face against the surface
// or have a corner turned inside out once their corners have been moved: a change of the
// connectivity that removes the quad and keeps the mesh all quads, manifold, of the same Euler
// characteristic and boundary loops.
#ifndef quadcover_QuadCollapse_h
#define quadcover_QuadCollapse_h

#include "QuadMesh.h"
#include "SurfaceLocator.h"

#include <functional>
#include <vector>

namespace quadcover
{

/// What removeTurnedQuads did.
struct QuadCollapseResult
{
  int ears = 0;      ///< quads removed that hung off the mesh by one edge
  int collapsed = 0; ///< quads collapsed along a diagonal
};

/**
 * Each of `quads` (in index order: those that face against the surface or have a corner turned
 * inside out) that quadWorstOf still measures at 0 or less:
 * - an ear, a quad whose other three edges lie on the mesh's boundary (its two corners there on
 *   no other quad: the tip of a tube narrower than the quads, say), is removed: two points,
 *   three edges and a face less, the same boundary loops;
 * - else the quad is collapsed along a diagonal: its two opposite corners become one point, its
 *   two pairs of edges beside them one edge each (a point, two edges and a face less). Only where
 *   the corners have no other quad and no neighbour but the quad's other two corners in common,
 *   at most one of them lies on the mesh's boundary, the other two corners keep two quads (three
 *   inside the mesh) and do not lose a boundary edge; the point goes where the boundary corner
 *   was, else where one of the two was or onto the surface between them, whichever leaves its
 *   quads' worst (quadWorstOf) best, and only when that is above 0.
 * A quad that neither mends is left. quadTriangle follows the quads; the points no quad uses are
 * removed (removeUnusedVertices).
 * @param surface the surface the quads lie on, its triangles labelled with their components as
 *                for quadFacing
 */
QuadCollapseResult removeTurnedQuads(
  const SurfaceLocator& surface, const std::vector<int>& quads, QuadMesh& mesh);

/// How removeTurnedQuads measures a quad and finds the surface.
struct QuadJudge
{
  /// quad i's worst: at most 0 when it faces against the surface or has a corner inside out
  std::function<double(const QuadMesh& mesh, int i)> worst;
  /// the surface's point closest to p, and its triangle
  std::function<SurfaceLocator::Hit(const Eigen::Vector3d& p)> closest;
};

/// removeTurnedQuads with the quads measured by judge.worst instead of quadWorstOf, and the
/// points put onto the surface by judge.closest.
QuadCollapseResult removeTurnedQuads(
  const QuadJudge& judge, const std::vector<int>& quads, QuadMesh& mesh);

}

#endif
