// TJunctions.h: boundary points that lie on another boundary edge (T-junctions: faces meshed
// apart, their shared sides cut at different points) made points of that edge (stage 0).
#ifndef quadcover_TJunctions_h
#define quadcover_TJunctions_h

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/// The repair's tolerance for closeTJunctions, in bounding-box diagonals: a point within a
/// ten-millionth of the surface's size of an edge lies on it (single-precision coordinates, or
/// 9 digits, keep a point on an edge to a few times 1e-8).
constexpr double TJunctionTolerance = 1e-7;

/// What closeTJunctions changed.
struct TJunctionSplits
{
  /// points put into boundary edges they lay on (each a T-junction closed)
  int closed = 0;
  /// per output triangle the input triangle it is part of (its cell data)
  std::vector<int> triangleSource;
};

/**
 * Closes the T-junctions of a triangle soup: a point at the end of a boundary edge (an edge of
 * one triangle) that lies within `tolerance` of the inside of another boundary edge, farther
 * than `tolerance` from its ends, is put into that edge: its triangle is split there, by a fan
 * from the corner opposite the edge (again for each other edge of its parts with such points).
 * The two sides of the seam then share their points and edges, so that a box whose faces were
 * meshed one by one becomes one closed surface (the repair's later steps pair the edges and
 * orient the whole). The points do not move and the surface does not change; a point on the
 * edge's own triangle's third corner (a degenerate triangle) is left. Expected time linear in the
 * boundary's length over its median edge (boundary points hashed in cells that wide, each edge
 * looking along itself).
 * @param[in,out] F #F x 3 triangles (no repeated point), grown by the splits
 * @throws std::invalid_argument for a negative or non-finite tolerance
 */
TJunctionSplits closeTJunctions(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, double tolerance);

}

#endif
