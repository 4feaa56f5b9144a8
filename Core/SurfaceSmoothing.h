// SurfaceSmoothing.h: noise at the triangle scale (a rough scan) smoothed out before the frame
// field and the map see it (stage 0).
#ifndef quadcover_SurfaceSmoothing_h
#define quadcover_SurfaceSmoothing_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

struct RoughSurfaceOptions
{
  /// Rough components are smoothed (smoothRoughComponents); false: none is.
  bool smoothRoughSurfaces = true;
};

/// An inner edge whose two triangles' normals lie more than this many degrees apart is folded.
constexpr double RoughFoldAngle = 120.0;
/// A component is rough when more than this share of its inner edges are folded ...
constexpr double RoughFoldedShare = 0.015;
/// ... and more than this share of its edges join two inner points whose angle defects both
/// exceed RoughDefect in size and have opposite signs.
constexpr double RoughSignChangeShare = 0.02;
constexpr double RoughDefect = 3.14159265358979323846 / 8.0;
/// ... and at least this many of each (a few folds of a small part are its shape: a coarse
/// component of a CAD soup).
constexpr int RoughMinimumEdges = 32;
/// Taubin's steps (Taubin 1995): this many pairs of a smoothing step and an inflating one.
constexpr int RoughSmoothingPasses = 10;

/// How rough one component is.
struct Roughness
{
  int innerEdges = 0;  ///< edges with two triangles
  int foldedEdges = 0; ///< inner edges bent more than RoughFoldAngle
  int edges = 0;       ///< all its edges
  int signChanges = 0; ///< edges between inner points of large angle defects of opposite signs
  /// More than RoughFoldedShare of the inner edges folded and more than RoughSignChangeShare of
  /// the edges changing the curvature's sign, and at least RoughMinimumEdges of each.
  bool rough() const;
};

/**
 * How rough each component (topo.components) is. Noise of a third of an edge folds a surface
 * over at the triangle scale and flips the sign of its curvature from point to point; the frame
 * field then has a singularity at nearly every other point (a noisy metaball surface of 61k
 * triangles: 11,914), and no map can follow it. A smooth surface folds only along creases, whose
 * sides are flat (the curvature keeps its sign there), and a coarse sample of a smooth shape
 * (a decimated scan of 1,000 triangles) changes the sign of its curvature as often but folds
 * along less than 1% of its edges.
 */
std::vector<Roughness> componentRoughness(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo);

/**
 * Smooths the rough components (componentRoughness) by RoughSmoothingPasses pairs of Taubin's
 * steps (lambda 0.5, mu -0.53: each point moves by that share of the mean of its neighbours
 * less itself), which take out the noise below a few edges without shrinking the shape; points
 * on the boundary stay. The triangles do not change.
 * @param[in,out] V #V x 3 positions
 * @param[in]     F #F x 3 triangles of a manifold, consistently oriented surface
 * @return the number of points moved
 */
int smoothRoughComponents(Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);
}

#endif
