// CreaseSnapping.h: the quad vertices beside the input's creases put on them, so that quad edges
// follow the creases the map's grid lines run beside.
#ifndef quadcover_CreaseSnapping_h
#define quadcover_CreaseSnapping_h

#include "MeshTopology.h"
#include "QuadMesh.h"
#include "SurfaceLocator.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/**
 * Where a quad edge crosses a crease of the input (an edge flagged in `sharp`, #E: its two ends
 * lie on the two sides of the sharp edge closest to its nearer end, within that end's longest
 * quad edge, at most three mean quad edges), its nearer end moves onto the crease, to the closest
 * point. A vertex on a crease already, on the quad mesh's or the surface's boundary, or whose
 * closest crease point is where a chain of sharp edges ends, stays. With the frames held along
 * the creases the map's grid lines run beside them, so that the ends moved along a crease form a
 * row of quad edges on it: the quads on one side of the row grow and those on the other shrink by
 * the grid line's distance from the crease (about half a quad at most). Where the grid line
 * crosses the crease, a quad across it is left folded along its diagonal (a step, which
 * straightenCreaseSteps then straightens). On a wall about a quad high between two creases (a
 * thin plate's rim), where one end of a quad edge moves onto one crease and the other end lies
 * across its own nearest crease, the other end moves onto that one too. Then, quad by quad, the
 * longest move of a quad left facing against the surface or with a corner's scaled Jacobian below
 * 0.05 (quadWorstOf below 0.05), and worse than it was, is undone. Updates mesh.V, vertexTriangle
 * and vertexPoint.
 * @return the vertices moved, in order
 */
std::vector<int> snapToCreases(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const std::vector<char>& sharp, const SurfaceLocator& surface,
  QuadMesh& mesh);

/**
 * The steps snapToCreases leaves where a grid line crosses a crease: a quad with two opposite
 * corners on the crease, which runs along the diagonal between them (its midpoint within a
 * tenth of the diagonal of the crease), and the other two corners on either side of it. The one
 * of those two nearer the crease moves 0.7 of the way to its closest crease point (to the
 * surface's point closest to that, kept only within a tenth of the rest of the way of it: on
 * its side of the crease), so that two of the quad's edges run along the crease instead of its
 * diagonal (the rest of the way left, so that its corner there stays below a straight angle:
 * fandisk at 6,500 quads keeps 97.6% of its crease points instead of 94.6%). A move that leaves
 * one of the vertex's quads below 0.05 (quadWorstOf) and worse than it was is undone; vertices
 * on a crease or on the quad mesh's or the surface's boundary stay. A relaxation that follows
 * should hold the vertices moved, which lie on no crease. Updates mesh.V, vertexTriangle and
 * vertexPoint.
 * @return the vertices moved, in order
 */
std::vector<int> straightenCreaseSteps(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const std::vector<char>& sharp, const SurfaceLocator& surface,
  QuadMesh& mesh);
}

#endif
