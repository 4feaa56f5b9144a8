/**
 * @class   vtkMatchingBuilder
 * @brief   per-edge matchings, layer shifts, singularity indices and branch points of a frame field
 *
 * Third stage of the QuadCover pipeline (Sect. 2.1-2.3, 3, 4.2). For every inner edge it picks
 * the matching r in {0,1,2,3} that best aligns the two triangles' frames after transport across
 * the edge (the smallest angle), then derives what the matchings imply at the points: the layer
 * shift of the branched covering (Def. 4) and the frame field's true index.
 *
 * With OptimizeBranchPoints (default off) it then runs the greedy search of Sect. 4.2: paths
 * from singular points (index +-1/4 or +-1/2) to nearby singular points get their matchings
 * changed when that lowers BranchPointWeight * (number of singular points) + sum over edges of
 * the matched frames' angle (radians), each edge's angle counted in proportion to its length
 * over sqrt(area / 2000) with LengthScaledCost (default; about one per edge on a 4,000-triangle
 * mesh), so that a finer mesh of the same surface keeps about the same singularities. Only pairs
 * that cancel are merged: no singularity grows. Poincare-Hopf holds before and after. It first
 * splits every inner point of index 1/2 or more into quarters; without it, those of index 3/4 or
 * more are split all the same (no map can follow a whole turn), and those of 1/2 stay.
 *
 * Output 0: the surface with cell data Matching (3 x int: for edge k = (point k, point k+1),
 * X_{neighbour,m} = X_{this,(m - r) mod 4}, X_0 = FrameU, X_1 = n x FrameU, ...; -1 on boundary
 * edges), point data LayerShift (int, 0 on the boundary) and SingularityIndex (double), field
 * data SingularityCount, SingularityHistogram ((index, inner points) per non-zero index),
 * SingularityIndexSum (the sum of all points' indices: the Euler characteristic),
 * BranchPointCount (before, after), MatchingCost (before, after) and BranchPointObjective
 * (before, after: the cost the optimization lowers).
 * Output 1: the branch points (non-zero layer shift) as points with vertex cells and point data
 * SingularityIndex, LayerShift and SurfacePointId, ready for glyphs in ParaView.
 *
 * Indices: (angle defect + turning of the frame relative to parallel transport around the
 * point) / 2 pi, a multiple of 1/4 at inner points (with LayerShift = 4 index mod 4). At
 * boundary points, half the index of the surface doubled across its boundary (a multiple of 1/4
 * when frames follow the boundary, as vtkFrameSmoother makes them). In every case the indices of
 * all points add up to the Euler characteristic.
 *
 * Input: a manifold, consistently oriented triangle surface (every point's triangles one fan)
 * with the cell array FrameU (SetInputArrayToProcess(0, ...) for another name). Only FrameU's
 * direction is used for the matchings: the field is treated as four-fold symmetric. When the
 * frames are fitted to changed matchings, FrameV (1; if absent, n x FrameU) turns with them,
 * FrameWeight (2) weighs the curvature alignment and FrameConstrained (3) holds boundary frames;
 * the fitted frames are written under the names of arrays 0 and 1.
 * @sa vtkFrameSmoother vtkQuadCoverSolver
 */
#ifndef vtkMatchingBuilder_h
#define vtkMatchingBuilder_h

#include "vtkQuadCoverAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

class VTKQUADCOVERFILTERS_EXPORT vtkMatchingBuilder : public vtkQuadCoverAlgorithm
{
public:
  static vtkMatchingBuilder* New();
  vtkTypeMacro(vtkMatchingBuilder, vtkQuadCoverAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Run the branch-point optimization of Sect. 4.2 (default off: merges buy few singularities
   * with stretch; the field's own singularities give evener quads). Off, singularities of index
   * >= 3/4 are still split into quarter ones (no quad mesh has vertices of valence 1 or 0, and
   * the map cannot follow such a field); nothing is merged. */
  vtkSetMacro(OptimizeBranchPoints, bool);
  vtkGetMacro(OptimizeBranchPoints, bool);
  vtkBooleanMacro(OptimizeBranchPoints, bool);
  ///@}

  ///@{
  /**
   * lambda: the cost of one singular point in radians of matching angle, in [0, 100]
   * (default 4). Larger values remove more singularities at the price of less straight
   * parameter lines (larger angles between matched frames along the merge paths).
   */
  vtkSetClampMacro(BranchPointWeight, double, 0.0, 100.0);
  vtkGetMacro(BranchPointWeight, double);
  ///@}

  ///@{
  /**
   * Count each edge's matching angle in proportion to its length (default on), so that the
   * cost of merging two singularities grows with their distance on the surface rather than
   * with the number of edges between them; off, every edge counts once (the paper's cost). The
   * quarters of a split singularity then also go at least 4 times sqrt(area / 2000) along the
   * surface (not only 4 edges: a fan of slivers has many in a short distance).
   */
  vtkSetMacro(LengthScaledCost, bool);
  vtkGetMacro(LengthScaledCost, bool);
  vtkBooleanMacro(LengthScaledCost, bool);
  ///@}

  ///@{
  /**
   * Degrees, in [0, 45] (default 10): frames within this angle of a boundary edge follow it, as
   * vtkQuadCoverSolver's BoundaryTolerance puts such edges on grid lines. A merge is undone when
   * it would leave a tube between two boundary loops with its frames following the loops in
   * different directions (the map would have to twist). Give both filters the same value.
   */
  vtkSetClampMacro(BoundaryTolerance, double, 0.0, 45.0);
  vtkGetMacro(BoundaryTolerance, double);
  ///@}

  ///@{
  /** Points one search may visit from a branch point, in [1, 10^7] (default 20000). */
  vtkSetClampMacro(MaximumSearchSize, int, 1, 10000000);
  vtkGetMacro(MaximumSearchSize, int);
  ///@}

  ///@{
  /**
   * After the optimization changed matchings, turn the frames (FrameU, FrameV) so that they
   * agree with them (default on): the turning a changed matching leaves on its path spreads
   * smoothly over the surface (vtkFrameSmoother's energy to second order, weighted 0.97 towards
   * smoothness, FrameWeight as alignment weight when present), indices unchanged. Frames held
   * along the boundary (FrameConstrained, on a triangle with a boundary edge) do not turn, so the
   * boundary stays on grid lines. Without it the
   * parameterization has to absorb a quarter turn along every merge path, which folds it.
   */
  vtkSetMacro(FitFramesToMatchings, bool);
  vtkGetMacro(FitFramesToMatchings, bool);
  vtkBooleanMacro(FitFramesToMatchings, bool);
  ///@}

  /** The branch points (output port 1). */
  vtkPolyData* GetBranchPointsOutput();

protected:
  vtkMatchingBuilder();
  ~vtkMatchingBuilder() override = default;

  void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) override;

  // defaults: quadcover::MatchingOptions and BranchPointOptions
  bool OptimizeBranchPoints;
  double BranchPointWeight;
  int MaximumSearchSize;
  bool LengthScaledCost;
  double BoundaryTolerance;
  bool FitFramesToMatchings;

private:
  vtkMatchingBuilder(const vtkMatchingBuilder&) = delete;
  void operator=(const vtkMatchingBuilder&) = delete;
};

#endif
