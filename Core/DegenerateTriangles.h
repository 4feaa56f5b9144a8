// DegenerateTriangles.h: triangles of zero area to round-off, and their removal by edge flips
// where a corner lies on the opposite edge (stage 0).
#ifndef quadcover_DegenerateTriangles_h
#define quadcover_DegenerateTriangles_h

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

namespace quadcover
{

/// A triangle is degenerate when twice its area is at most this times its longest edge squared:
/// its corners are collinear or coincident to round-off (the sine of its largest angle's
/// supplement, or of its smallest angle, is below about 1e-12). Its normal and its gradients
/// are then round-off: the frames and the map leave it out.
constexpr double DegenerateAreaRatio = 1e-12;

/// A triangle is flat when its height over its longest edge is at most this times that edge:
/// as good as degenerate, and what collinear points written with 6 to 9 digits give (a file's
/// T-junctions, points put on an edge); flipDegenerateTriangles removes such caps.
constexpr double FlatTriangleRatio = 1e-6;

/// Whether twice the area of the triangle (a, b, c) is at most `ratio` times its longest edge
/// squared (DegenerateAreaRatio: degenerate); NaN corners count as degenerate.
inline bool isDegenerateTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
  const Eigen::Vector3d& c, double ratio = DegenerateAreaRatio)
{
  const double longest2 =
    std::max({ (b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm() });
  return !((b - a).cross(c - a).norm() > ratio * longest2);
}

/// What flipDegenerateTriangles changed.
struct DegenerateFlips
{
  /// edges flipped; each made a flat triangle and its neighbour two proper ones
  int flippedEdges = 0;
  /// per triangle (the number does not change) the input triangle whose cell data it takes: the
  /// proper neighbour a flip split, for both triangles of the flip
  std::vector<int> triangleSource;
};

/**
 * Removes the flat triangles (FlatTriangleRatio) whose corner lies on the opposite edge (the cap
 * that a T-junction's repair, or a point inserted on an edge, leaves: a corner of 180 degrees)
 * by flipping that longest edge: the cap (u, v, m) and its proper neighbour (v, u, d) across u-v
 * become (m, u, d) and (d, v, m), which split the neighbour at m. The points and the triangle
 * count stay; the surface moves by at most the cap's height. A flip is made only where the
 * neighbour is not flat, the edge m-d does not exist yet, and both new triangles are not flat
 * and face as the neighbour did; so every flip removes one flat triangle, and a row of caps
 * (collinear points fanned from one corner) goes one by one from its proper end. Caps on the
 * boundary, and needles (two corners close together), are left as they are. Expects a
 * manifold, consistently oriented mesh (makeManifold).
 * @param[in,out] F #F x 3 triangles, changed where flipped
 */
DegenerateFlips flipDegenerateTriangles(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F);

}

#endif
