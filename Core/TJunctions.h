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
/// Steps of the search for a crack along one edge (a bound on its cost whatever the boundary).
constexpr int MaximumCrackSteps = 64;
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
 * from the corner opposite the edge (then along its other two edges, in the parts that have
 * them).
 * The two sides of the seam then share their points and edges, so that a box whose faces were
 * meshed one by one becomes one closed surface (the repair's later steps pair the edges and
 * orient the whole). The points do not move. An edge without such points that has a crack
 * along it (MaximumCrackPoints: a curved seam, the other side cut at more points, both sides
 * sharing the ends) gets the crack's points the same way: its triangle bends by the crack's
 * width to meet the other side. A point goes into one edge of a triangle only, never into an
 * edge of its own triangle; a triangle is split only where every part is proper and faces as
 * it did (else it stays, and the junction open). Edges of degenerate triangles
 * (DegenerateAreaRatio) and of non-finite points are neither split nor give points.
 * Time: a sort of the triangles' sides; then, per boundary edge, the boundary points in the
 * cells (the boundary's median edge wide) along it (linear in the boundary's length over that
 * edge, unless many points crowd into few cells) and at most MaximumCrackSteps steps of the
 * crack search.
 * @param[in,out] F #F x 3 triangles (no repeated point), grown by the splits
 * @throws std::invalid_argument for a negative or non-finite tolerance, or a point index out of
 *         range
 */
TJunctionSplits closeTJunctions(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, double tolerance);

}

#endif
