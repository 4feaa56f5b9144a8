// TJunctions.h: boundary points that lie on another boundary edge (T-junctions: faces meshed
// apart, their shared sides cut at different points), or on a crack along it (a curved seam),
// made points of that edge (stage 0).
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

/// A crack along a boundary edge a-b (closeTJunctions): a path of other boundary edges from a
/// to b through at most MaximumCrackPoints points, each farther along a-b than the last and at
/// most CrackWidth of its length off it, the whole path at most CrackLength times as long; as a
/// curved seam leaves it where one side has more points than the other (their chords' height:
/// a twentieth of the chord at 16 chords a circle).
constexpr int MaximumCrackPoints = 8;
constexpr double CrackWidth = 0.05;
constexpr double CrackLength = 1.02;

/// What closeTJunctions changed.
struct TJunctionSplits
{
  /// points put into boundary edges they lay on (each a T-junction closed)
  int closed = 0;
  /// of those, the points of cracks: paths along a boundary edge, off it (CrackWidth)
  int crackPoints = 0;
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
 * edge's own triangle's third corner (a degenerate triangle) is left. An edge without such
 * points that has a crack along it (MaximumCrackPoints: a curved seam, the other side cut at
 * more points, both sides sharing the ends) gets the crack's points the same way, where the
 * fan's triangles face as the edge's triangle did: its triangle bends by the crack's width to
 * meet the other side. Expected time linear in the
 * boundary's length over its median edge (boundary points hashed in cells that wide, each edge
 * looking along itself).
 * @param[in,out] F #F x 3 triangles (no repeated point), grown by the splits
 * @throws std::invalid_argument for a negative or non-finite tolerance
 */
TJunctionSplits closeTJunctions(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, double tolerance);

}

#endif
