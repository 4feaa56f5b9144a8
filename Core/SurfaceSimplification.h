// SurfaceSimplification.h: a surface far finer than the quads asked of it brought down to a
// working resolution by edge collapses, its topology, boundaries and creases kept (stage 0).
#ifndef quadcover_SurfaceSimplification_h
#define quadcover_SurfaceSimplification_h

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

struct SimplificationOptions
{
  /// The working surface keeps this many triangles per quad asked (simplificationBudget).
  int trianglesPerQuad = 16;
  /// ... and never fewer than this many triangles in all: a surface with at most this many is
  /// never simplified.
  int minimumTriangleCount = 100000;
  /// Edges whose triangles' normals differ by more than this (degrees), and boundary edges, are
  /// kept as lines: their points move only along them, and a point where one ends or three meet
  /// stays.
  double featureAngle = 40.0;
  /// A collapse may turn no triangle's normal by more than this (degrees)...
  double maximumNormalTurn = 45.0;
  /// ... nor leave a triangle whose quality (4 sqrt(3) area over the sum of its squared edges,
  /// 1 for an equilateral one) is below this, unless it was lower before.
  double minimumQuality = 0.2;
};

/**
 * The number of triangles simplifySurface is given for a surface meshed into `quads` quads:
 * trianglesPerQuad x quads, at least minimumTriangleCount; 0 (nothing simplified) for a quad
 * count that is not positive.
 */
long long simplificationBudget(double quads, const SimplificationOptions& options = {});

/// What simplifySurface kept.
struct Simplification
{
  /// per point of the result, the input point it is (the points are not moved)
  std::vector<int> pointSource;
  /// per triangle of the result, the input triangle it was (one or two corners renamed)
  std::vector<int> triangleSource;
  /// edges collapsed (points removed)
  int collapsedEdges = 0;
};

/**
 * Brings a manifold, consistently oriented triangle mesh down to at most `maximumTriangles`
 * triangles, or as near as the constraints allow, by half-edge collapses (a point moved onto a
 * neighbour), cheapest first by the quadric error of the planes of the triangles it has taken in
 * (Garland and Heckbert 1997), ties by the points' place along a Morton curve. A collapse is made
 * only where it keeps the surface's topology (the link condition; no triangle repeated), moves a
 * point on a feature line (options.featureAngle, boundaries) only along it, turns no triangle by
 * more than options. maximumNormalTurn in one step nor against the input triangle it was, leaves
 * none worse than options.minimumQuality where it was better, and leaves each component (joined
 * through edges) at least its share of `maximumTriangles` by area, and at least 256 triangles (all
 * of its own if it has fewer): no component vanishes. The points keep their positions (a subset of
 * the input's), and the triangles their orientation. Deterministic: one thread, a fixed order. Time
 * O(n log n) for n triangles of bounded valence; each step is linear in the valences of the two
 * points it looks at (a pole of 8,000 triangles is no trap).
 * @param[in,out] V #V x 3 points; the kept ones, in their order
 * @param[in,out] F #F x 3 triangles; the kept ones in their order, renumbered to the kept points
 * @param[in] maximumTriangles 0 or at least #F: nothing is changed
 */
Simplification simplifySurface(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, long long maximumTriangles,
  const SimplificationOptions& options = {});

}

#endif
