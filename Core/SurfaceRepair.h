// SurfaceRepair.h: a triangle soup made a manifold, consistently oriented surface: non-manifold
// edges cut apart into sheets, non-manifold points split, components oriented (stage 0).
#ifndef quadcover_SurfaceRepair_h
#define quadcover_SurfaceRepair_h

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/// Points merged by mergeCoincidentPoints.
struct MergedPoints
{
  /// per input point its merged point, -1 where no triangle uses it
  std::vector<int> pointOf;
  /// per merged point the input point it was made from (its first in the triangles' order)
  std::vector<int> source;
};

/**
 * Merges the points the triangles use that lie within `tolerance` of each other: the triangles'
 * corners are taken in order, and a point not met before becomes a new merged point unless one
 * made before lies within `tolerance` (the first made among those). Points no triangle uses are
 * left out. The merged points are numbered in the order the triangles first use them, as
 * vtkCleanPolyData numbers them. tolerance 0 merges equal points only. Expected time linear in
 * the number of corners (a hash of cells 1024 tolerances wide; a point within two tolerances of
 * its cell's side also looks in the neighbour cell there).
 * @throws std::invalid_argument for a negative or non-finite tolerance or a point index out of
 *         range
 */
MergedPoints mergeCoincidentPoints(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, double tolerance);

/**
 * The triangles a repair removes before makeManifold: each repeat of a triangle (the same three
 * points, in either orientation, as an earlier one) and every triangle of a component (joined
 * through shared points) whose area is zero next to the surface's size (1e-24 of its bounding
 * box diagonal squared): such a component is no surface, and no map can be solved on it.
 * @return #F, 1 for a triangle to remove
 */
std::vector<char> redundantTriangles(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// What makeManifold changed.
struct ManifoldRepair
{
  /// for each added point (index #V_old + i), the point it copies
  std::vector<int> copies;
  /// edges that had more than two triangles, now cut apart into manifold sheets
  int cutEdges = 0;
  /// triangles whose corner order was reversed (their normal turned over)
  std::vector<int> reversed;
};

/**
 * Makes a triangle mesh manifold and consistently oriented. The mesh must have no triangle that
 * repeats a point and no repeated triangle (redundantTriangles; a repeat facing the same way would
 * read as a Moebius strip):
 * 1. each patch of triangles joined through edges with exactly two triangles is oriented so that
 *    most of its area keeps the input's orientation;
 * 2. the triangles around an edge with more than two are paired: the two of a patch that has
 *    only those two there and agree in orientation with each other (so a solid stays closed
 *    whatever stands on its edge, a fin leaning into it too), then each with its nearest
 *    neighbour around the edge on its back side when the two agree in orientation (so the faces
 *    of solids that touch along an edge stay with their solid), then two left over with each
 *    other; the rest are cut off there, that edge becoming their boundary;
 * 3. every point whose triangles fall into several fans (joined only through the point, or only
 *    through cut edges) gets one copy per fan;
 * 4. each component is oriented again as a whole, most of its area keeping the input's
 *    orientation.
 * A component that cannot be oriented (a Moebius strip) is refused.
 * @param[in,out] V #V x 3 positions, grown by the copies
 * @param[in,out] F #F x 3 triangles, renumbered to the copies and reversed where turned
 * @throws std::invalid_argument naming the first non-orientable component (numbered from 1 in
 *         order of its lowest triangle) and the number of components
 */
ManifoldRepair makeManifold(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F);

}

#endif
