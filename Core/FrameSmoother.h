// FrameSmoother.h: smoothing and curvature alignment of a frame field (stage 2, Sect. 4.3).
#ifndef quadcover_FrameSmoother_h
#define quadcover_FrameSmoother_h

#include "Matchings.h"
#include "MeshTopology.h"
#include "Progress.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

struct SmootherOptions
{
  /// lambda in [0, 1]: E = lambda E_smooth + (1 - lambda) E_align.
  double smoothingWeight = 0.95;
  int maximumNumberOfIterations = 200;
  /// Stop when an iteration lowers the energy by less than this fraction.
  double convergenceTolerance = 1e-7;
  /// Hold the frames of triangles along sharp edges (dihedral angle above featureAngle degrees,
  /// the angle between the two normals as vtkFeatureEdges measures it) aligned to that edge.
  /// 60 rather than vtkFeatureEdges' 30: coarse or noisy scans have many 30-60 degree edges
  /// that are not features, while CAD creases are sharper.
  bool alignToFeatures = true;
  double featureAngle = 60.0;
  /// Sharp edges count only in chains of at least this many edges joined end to end, so
  /// isolated sharp edges (noise) do not pin frames, and only where at least half of a chain's
  /// edges have smooth sides (sharpEdges, SmoothSideFraction), so that the sharp edges of a
  /// coarsely sampled smooth surface pin nothing either.
  int minimumFeatureLength = 3;
  /// Hold the frames of triangles along the boundary aligned to it.
  bool alignToBoundary = true;
  /// Besides the input, start from the globally optimal four-fold fields (Knoeppel et al. 2013):
  /// the smoothest field blended with the alignment term, and (when no frame is held and the
  /// alignment term is weak, below 2% of the smoothing term's weight) the smoothest field
  /// itself; keep the run that ends with the lowest energy.
  bool globalStart = true;
  /// The curvature directions count where they are nearly parallel over this radius (a fraction
  /// of the square root of the surface's area), where following them costs little smoothness:
  /// each triangle's alignment weight is multiplied by its coherence to the 8th power, |c| for
  /// the four-fold field of the input frames diffused over the radius with the surface's
  /// transport (1 where they are parallel, as on a cylinder; towards 0 where they scatter, as on
  /// a noisy scan or over bumps smaller than the radius; about 0.5-0.65 where they turn, as on a
  /// torus). Elsewhere the field is the smoothest one. 0 (or smoothingWeight 1): the weights as
  /// given.
  double coherenceRadius = 0.1;
  /// Worker threads (0: defaultThreadCount()); the result does not depend on it.
  int numberOfThreads = 0;
};

struct SmootherResult
{
  Eigen::MatrixX3d frameU;       ///< #F x 3 smoothed frames
  Eigen::MatrixX3d frameV;       ///< #F x 3 (rotated with frameU)
  Eigen::VectorXd rotation;      ///< #F angle each frame turned (about its normal)
  std::vector<char> constrained; ///< #F 1 where the frame is held along an edge
  int numConstrained = 0;
  int featureEdges = 0; ///< sharp inner edges found
  int boundaryEdges = 0;
  double energyBefore = 0.0; ///< E of the input frames
  double energyAfter = 0.0;
  std::vector<double> energyHistory; ///< E at the start and after every iteration (chosen run)
  int iterations = 0;
  /// Steps that raised the energy by more than rounding (always 0 if the bound holds: the
  /// descent would stop at such a step, so only this count can show it).
  int rejectedSteps = 0;
  /// #F how far each curvature frame agrees with those around it, in [0, 1]
  /// (SmootherOptions::coherenceRadius; 1 everywhere when that is 0)
  Eigen::VectorXd coherence;
  bool fromGlobalStart = false; ///< the chosen run started from a global field
};

/**
 * Rotates each frame by an angle alpha_i about its triangle's normal to minimize
 *   E = lambda * sum_{inner edges ij} (A_i + A_j)/3 (1 - cos 4(theta_ij + alpha_i - alpha_j))
 *     + (1 - lambda) * sum_i A_i w_i alpha_i^2
 * where theta_ij is the angle between the frames after transporting one into the other's plane
 * and w is the curvature weight (FrameWeight, times the coherence to the 8th power with
 * options.coherenceRadius). Each iteration minimizes a quadratic upper bound
 * of E (1 - cos is bounded by its second-order expansion with curvature 1), so E never
 * increases; the bound's matrix does not change, so it is factored once.
 * Frames held along features and boundaries: the triangle's longest such edge wins (at corners,
 * where two meet at about a right angle, the cross fits both).
 * @param[in] frameU, frameV #F x 3 input frames (tangent), @param[in] weight #F
 * @throws std::invalid_argument on sizes that do not match or non-finite frames
 */
SmootherResult smoothFrames(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3d& frameV, const Eigen::VectorXd& weight,
  const SmootherOptions& options = SmootherOptions(), const Progress& progress = Progress());

}

#endif
