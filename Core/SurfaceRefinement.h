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

}

#endif
