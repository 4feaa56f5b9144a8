// QuadPatching.h: the last line of defence of the quad stage: the holes inside the surface
// filled with quads, and the quads that face against the surface counted.
#ifndef quadcover_QuadPatching_h
#define quadcover_QuadPatching_h

#include "MeshTopology.h"
#include "QuadMesh.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/// What patchQuadMesh did.
struct QuadPatchResult
{
  int holesFilled = 0; ///< holes inside the surface filled with quads
  /// holes left open: odd or too long loops, or a component whose holes are no disks (loops
  /// inside the surface, less those standing for its own holes where the quads stop short of them)
  int holesLeft = 0;
  int quadsAdded = 0;
};

/**
 * Where the map could not be repaired, the quad mesh can have holes (grid cells that gave no
 * quad). This fills every hole whose boundary loop lies inside the surface (none of its points
 * on the surface's boundary) and has an even number of edges (a loop through a point twice is
 * split there), on components whose holes are all missing disks (their quads' Euler
 * characteristic plus one per hole is the component's) and is at most sqrt(#quads) + 64 edges
 * long (a fill costs the loop's length times the triangles near it; a longer loop is left open):
 * four edges with one quad, more with a fan of quads around a new point on the surface (of the
 * two fans, the one with the better corners), so that the mesh keeps all quads, its manifold
 * orientation and the surface's Euler characteristic. A fill that would face against the surface
 * first takes in another ring of quads, up to three times; when the grown hole cannot be filled
 * (it wraps around a handle, say), the ring goes back and the hole gets the fill it had. Quads
 * that face against the surface are left to repairFacing (cutting them out and filling their hole
 * measured worse: the fill of a region the map folded over is far from the surface).
 * @param[in]     V, F, topo the surface the quads lie on
 * @param[in,out] q          the quad mesh; unused vertices are removed
 */
QuadPatchResult patchQuadMesh(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo, QuadMesh& q);

}

#endif
