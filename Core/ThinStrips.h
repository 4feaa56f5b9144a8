// ThinStrips.h: where a strip of the surface between two boundary lines, or a wall between two
// creases, is narrower than a grid edge, and the finer grid the map needs there to keep it (the
// spreading of grid sizes is shared with CurvatureSizing).
#ifndef quadcover_ThinStrips_h
#define quadcover_ThinStrips_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/**
 * The grid edge each triangle needs, over edgeLength, so that no strip of the surface between two
 * boundary lines that face each other is narrower than a grid edge (the bars of a grille, the
 * surface between two slots), nor any wall between two creases (the rim of a thin plate): a
 * uniform grid rounds both sides of such a strip onto one grid line and cuts it, which joins two
 * holes and changes the topology; across a wall its quads fold over the rim, turned against the
 * surface, and cut its corners. Two boundary edges face each other when their inward directions
 * (in their triangles' planes) are opposite within 60 degrees and each one's nearest point to the
 * other lies within 60 degrees of its inward direction; the strip between them is as wide as the
 * edges are apart. A crease edge is a side seen from each of its two triangles; two crease sides
 * face each other the same way, and bound a wall where the triangles across them face apart (more
 * than 90 degrees; a step between two creases that turn less is no wall); a wall lower than
 * edgeLength / maximumRefinement is left alone. Their four points ask for that width (never less
 * than edgeLength / maximumRefinement), and the size grows away from
 * them along the edges of the surface by `gradation` times the distance walked (around a wall
 * twice as fast), up to edgeLength.
 * @param[in] creases #E (topo's edges), 1 on a crease (sharpEdges); empty: boundary strips only
 * @return #F, the mean over each triangle's points, in [1 / maximumRefinement, 1]; empty when no
 * strip narrower than edgeLength (or maximumRefinement <= 1): the grid stays uniform
 */
Eigen::VectorXd thinStripGridScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, double edgeLength, double maximumRefinement,
  const std::vector<char>& creases = {}, double gradation = 0.25);

/**
 * The grid edge each triangle needs, over edgeLength, so that a handle or a neck of the surface
 * whose loop passes near one of `points` (the field's singular points, which the negative
 * curvature of a small tunnel or a narrow neck gathers) keeps about three grid edges around it:
 * where the triangles within 2 edgeLength of such a point (along edge paths, the boundary out of
 * reach) are no disk, the point asks for two thirds of the largest radius at which they are
 * (about a third of the loop; never less than edgeLength / maximumRefinement), and the size
 * grows away from it as around thin strips.
 * A uniform grid puts such a loop on one or two grid edges, and no map can keep it: its quads
 * close the tunnel or cut the neck (an isosurface's necks at 3,000 quads, five negative quarter
 * singularities within one grid cell of a tunnel, kept flipped triangles and three holes).
 * @param edgeLengths #F x 3, the length of edge k of face f (from corner k to k + 1)
 * @return #F in [1 / maximumRefinement, 1], as thinStripGridScale; empty when no point asks
 */
Eigen::VectorXd shortLoopGridScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixX3d& edgeLengths, const std::vector<int>& points,
  double edgeLength, double maximumRefinement, double gradation = 0.25);

/// size(v) = min over the points w of size(w) + gradation times the shortest edge path from w to v
/// (Dijkstra from the smallest sizes up).
void spreadGridSizes(
  const Eigen::MatrixX3d& V, const MeshTopology& topo, double gradation, std::vector<double>& size);

/// Per triangle, the mean of its points' grid sizes over edgeLength.
Eigen::VectorXd faceGridScale(
  const Eigen::MatrixX3i& F, const std::vector<double>& size, double edgeLength);
}

#endif
