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

/// A component is rough when two pairs of Taubin's steps leave less than this share of its total
/// absolute curvature (the sum of |angle defect| over its inner points): noise is the curvature a
/// low-pass takes away, shape the curvature it leaves ...
constexpr double RoughCurvatureLeft = 0.4;
/// ... and at least this many of its inner points have an angle defect larger than RoughDefect in
/// size (a nearly flat part's noise bends nothing the field would follow).
constexpr int RoughMinimumPoints = 32;
constexpr double RoughDefect = 3.14159265358979323846 / 8.0;
/// Taubin's steps (Taubin 1995): this many pairs of a smoothing step and an inflating one smooth
/// a rough component, RoughProbePasses pairs measure whether it is.
constexpr int RoughSmoothingPasses = 10;
constexpr int RoughProbePasses = 2;

/// How rough one component is.
struct Roughness
{
  double curvature = 0.0;     ///< sum of |angle defect| over its inner points
  double curvatureLeft = 0.0; ///< the same after RoughProbePasses pairs of Taubin's steps
  int curvedPoints = 0;       ///< inner points whose angle defect exceeds RoughDefect in size
  /// Less than RoughCurvatureLeft of its curvature left, and RoughMinimumPoints curved points.
  bool rough() const;
};

/**
 * How rough each component (topo.components) is. Noise of a fraction of an edge folds a surface
 * over at the triangle scale and flips the sign of its curvature from point to point; the frame
 * field then has a singularity at nearly every other point (a noisy metaball surface of 61k
 * triangles: 11,914), and no map can follow it. Two pairs of Taubin's steps (the boundary held)
 * take most of that curvature away (the noisy metaballs keep 0.18 of it; with a tenth of that
 * noise, 0.03), while the curvature of a shape stays: a decimated scan of 1,000 triangles keeps
 * 0.58, a jittered knot tube 0.48, smooth surfaces 0.7 and more, and creases gain (fandisk 1.34).
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
