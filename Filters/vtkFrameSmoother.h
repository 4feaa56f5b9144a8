/**
 * @class   vtkFrameSmoother
 * @brief   smooth a surface's guidance frame field and align it with curvature and features
 *
 * Second stage of the QuadCover pipeline (Sect. 4.3). Turns each triangle's frame (FrameU and
 * FrameV together, so non-orthogonal frames keep their shape) about the triangle's normal by an
 * angle alpha_i that minimizes
 *   E = lambda * sum_{edges ij} (A_i + A_j)/3 (1 - cos 4(theta_ij + alpha_i - alpha_j))
 *     + (1 - lambda) * sum_i A_i w_i alpha_i^2,
 * theta_ij being the angle between neighbouring frames after transport across their edge and
 * w = FrameWeight x FrameCoherence^8 (CoherenceRadius); lambda = SmoothingWeight. So frames spread
 * from where curvature is pronounced into umbilic and flat regions, with as few singularities as
 * the surface allows.
 *
 * The minimization starts from the input and from the globally optimal four-fold fields
 * (Knoeppel et al. 2013: the smoothest field blended with the alignment term, and the smoothest
 * field itself when nothing is held and the alignment is weak), and keeps the run that ends
 * lowest; every run descends monotonically (each iteration minimizes a quadratic upper bound of
 * E, factored once, and tries longer steps along it).
 *
 * Features and boundaries (AlignToFeatures, AlignToBoundary, on by default): triangles along a
 * boundary edge or a sharp edge (normals more than FeatureAngle degrees apart, as in
 * vtkFeatureEdges) get their frame turned onto that edge and held there, so quads will follow
 * borders and creases. A triangle on two such edges follows the longer one (at the usual
 * right-angled corner the cross fits both). Sharp edges count only in chains of at least
 * MinimumFeatureLength edges, so that isolated sharp edges of a noisy scan pin nothing; the
 * default FeatureAngle is 60 rather than vtkFeatureEdges' 30 for the same reason. A chain counts
 * only where at least half of its edges have smooth sides (the surface beside them bending
 * across them by at most 0.15 of their own bend): a coarsely sampled smooth surface, such as a
 * decimated scan, bends as much beside its sharp edges as at them, while a CAD part's creases,
 * even a faceted cylinder's rims, have flat or gently curved sides.
 *
 * Input: a triangle surface with cell arrays FrameU (required), FrameV (if absent, n x FrameU)
 * and FrameWeight (if absent, 1 everywhere), by default the names vtkCurvatureFrames writes;
 * point the filter at others with SetInputArrayToProcess(0|1|2, 0, 0,
 * vtkDataObject::FIELD_ASSOCIATION_CELLS, name). Output: the surface with FrameU and FrameV
 * replaced by the smoothed frames, cell data FrameRotation, FrameConstrained and FrameCoherence
 * (how nearly parallel the input frames are around each triangle, CoherenceRadius), field data
 * SmoothingEnergy (before: the input with held frames already on their edges; after),
 * SmoothingIterations and ConstrainedFrameCount. Names: vtkQuadCoverArrayNames.h.
 *
 * Errors: no points, no polygons, point ids out of range, non-finite coordinates, non-manifold
 * edges, inconsistently oriented neighbours, and a missing FrameU.
 * @sa vtkCurvatureFrames vtkMatchingBuilder
 */
#ifndef vtkFrameSmoother_h
#define vtkFrameSmoother_h

#include "vtkQuadCoverAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

class VTKQUADCOVERFILTERS_EXPORT vtkFrameSmoother : public vtkQuadCoverAlgorithm
{
public:
  static vtkFrameSmoother* New();
  vtkTypeMacro(vtkFrameSmoother, vtkQuadCoverAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Weight lambda of smoothness against curvature alignment, in [0, 1] (default 0.95). */
  vtkSetClampMacro(SmoothingWeight, double, 0.0, 1.0);
  vtkGetMacro(SmoothingWeight, double);
  ///@}

  ///@{
  /** Iterations at most per run, in [0, 100000] (default 200). */
  vtkSetClampMacro(MaximumNumberOfIterations, int, 0, 100000);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  ///@{
  /** Stop when an iteration lowers the energy by less than this fraction (default 1e-7). */
  vtkSetClampMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceTolerance, double);
  ///@}

  ///@{
  /** Hold frames along sharp edges (default on). */
  vtkSetMacro(AlignToFeatures, bool);
  vtkGetMacro(AlignToFeatures, bool);
  vtkBooleanMacro(AlignToFeatures, bool);
  ///@}

  ///@{
  /** Angle between normals above which an edge is sharp, degrees in [0, 180] (default 60). */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /** Shortest chain of sharp edges that counts as a feature, in [1, 10000] (default 3). */
  vtkSetClampMacro(MinimumFeatureLength, int, 1, 10000);
  vtkGetMacro(MinimumFeatureLength, int);
  ///@}

  ///@{
  /** Hold frames along boundary edges (default on). */
  vtkSetMacro(AlignToBoundary, bool);
  vtkGetMacro(AlignToBoundary, bool);
  vtkBooleanMacro(AlignToBoundary, bool);
  ///@}

  ///@{
  /**
   * The curvature directions count where they are nearly parallel over this radius, a fraction
   * of the square root of the surface's area (default 0.1; 0: everywhere): each triangle's
   * FrameWeight is multiplied by its FrameCoherence to the 8th power, so the field follows
   * curvature where that costs little smoothness (a cylinder: coherence 1) and is the smoothest
   * field where the directions scatter or turn (scan noise, bumps, a torus: 0.5-0.65). Not
   * computed at SmoothingWeight 1 (FrameCoherence 1 there).
   */
  vtkSetClampMacro(CoherenceRadius, double, 0.0, 10.0);
  vtkGetMacro(CoherenceRadius, double);
  ///@}

  ///@{
  /** Also start from the globally optimal fields (default on; off: from the input only). */
  vtkSetMacro(GlobalStart, bool);
  vtkGetMacro(GlobalStart, bool);
  vtkBooleanMacro(GlobalStart, bool);
  ///@}

  ///@{
  /**
   * Number of threads, 0 for all cores (default 0): the global starts and the descent's
   * factorization run at once on two. The result does not depend on it.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkFrameSmoother();
  ~vtkFrameSmoother() override = default;

  void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) override;

  // defaults: quadcover::SmootherOptions
  double SmoothingWeight;
  int MaximumNumberOfIterations;
  double ConvergenceTolerance;
  bool AlignToFeatures;
  double FeatureAngle;
  int MinimumFeatureLength;
  bool AlignToBoundary;
  bool GlobalStart;
  double CoherenceRadius;
  int NumberOfThreads;

private:
  vtkFrameSmoother(const vtkFrameSmoother&) = delete;
  void operator=(const vtkFrameSmoother&) = delete;
};

#endif
