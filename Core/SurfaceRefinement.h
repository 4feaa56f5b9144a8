// SurfaceRefinement.h: components too coarse for a map refined, the surface itself unchanged
// (stage 0).
#ifndef quadcover_SurfaceRefinement_h
#define quadcover_SurfaceRefinement_h

#include <Eigen/Core>

#include <array>
#include <vector>

namespace quadcover
{

struct RefinementOptions
{
  /// Components with fewer triangles are refined (refineCoarseComponents); 0: none is.
  int minimumComponentTriangleCount = 256;
};

/// What refineCoarseComponents added.
struct Refinement
{
  /// for each added point (index #V_old + i), the two points whose midpoint it is (either may be
  /// an added point itself)
  std::vector<std::array<int, 2>> midpoints;
  /// for each triangle of the result, the input triangle it lies in
  std::vector<int> parent;
  /// input triangles that were split
  int refinedTriangles = 0;
};

/**
 * A component with few triangles leaves a map too little room: its singularities must sit on its
 * points, at least a few edges apart (a closed component of genus 0 has eight or more), and each
 * triangle's frame is one direction however large the triangle is. A coarse cone of 128
 * triangles, a fan of long needles around each tip, gets no quad at all. This splits every
 * triangle of each component (joined through edges) with fewer than `minimumTriangles`
 * triangles into four at its edges' midpoints, again until the component has at least that many.
 * The points stay where they are and the new ones lie on the old edges, so the surface (as a set
 * of points in space), its orientation and its topology do not change. Components with enough
 * triangles are left exactly as they are.
 * @param[in,out] V #V x 3 points, grown by the midpoints
 * @param[in,out] F #F x 3 triangles, replaced by the refined ones (components in their order)
 * @param[in] minimumTriangles 0 or less: nothing is refined
 */
Refinement refineCoarseComponents(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, int minimumTriangles);

/// What refineLongEdges made.
struct EdgeRefinement
{
  Eigen::MatrixX3d V; ///< the input's points, then the midpoints
  Eigen::MatrixX3i F; ///< the triangles: the input's, or their pieces (orientation kept)
  /// for each added point (index #V_input + i), the two points whose midpoint it is (either may
  /// be an added point itself)
  std::vector<std::array<int, 2>> midpoints;
  /// for each triangle of F, the input triangle it lies in
  std::vector<int> parent;
  /// for each triangle of F and its edge k (corner k to k + 1), the edge of its parent it lies
  /// along, -1 for an edge inside the parent
  Eigen::MatrixX3i parentEdge;
  /// input triangles that were split
  int refinedTriangles = 0;
};

/**
 * A piecewise linear map bends only at edges: a triangle much larger than a grid cell (a CAD
 * export's slivers across a flat face, a coarse scan) cannot follow the grid around a hole or a
 * cone inside it, and flips. This splits edges longer than `maximumEdgeLength` at their
 * midpoints, each split triangle bisected at its longest edge first (Rivara's refinement: the
 * pieces' angles stay bounded away from 0, slivers become better shaped), until no edge is longer
 * or the next round would pass `maximumTriangles` triangles. Midpoints are shared, so the result
 * is conforming; the surface (as a set of points), its orientation and its topology do not change.
 * Nothing changes when no edge is too long, or when maximumEdgeLength is not positive.
 */
EdgeRefinement refineLongEdges(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  double maximumEdgeLength, int maximumTriangles);

/// The matchings of refined triangles: an edge along its parent's edge keeps that edge's
/// matching (-1 on the boundary), an edge inside its parent gets 0 (its sides share a frame).
Eigen::MatrixX3i refinedMatching(const EdgeRefinement& r, const Eigen::MatrixX3i& matching);
}

#endif
