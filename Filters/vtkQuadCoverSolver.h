/**
 * @class   vtkQuadCoverSolver
 * @brief   the seamless integer-grid map (u, v) of a frame field with matchings (QuadCover Sect.
 *          2.5, 4, 4.1)
 *
 * Fourth stage of the QuadCover pipeline. The surface is cut into disks along a cut graph
 * through every singular point; the frames are combed so that their matchings vanish off the
 * cut; then the map phi = (u, v) minimizing sum_f area_f |grad phi - K_f|^2 is computed, K the
 * frame (FrameU, n x FrameU) divided by the grid size, with the covering's transition
 * functions across the cut: z' = i^r z + t (z = u + i v, r the matching, t in Z^2).
 *
 * Integers: every seam translation is integer and, with PureQuads (default), every branch point
 * maps to a grid point (Theorem 2 allows the middle of a grid cell otherwise), so the grid's
 * lines close up into a quad mesh (vtkQuadExtractor). RoundingMode Greedy (default) fixes one
 * integer unknown at a time, the one closest to an integer, and updates the others exactly with
 * the same factorization; Simple rounds them all at once; None leaves the continuous minimizer.
 * Triangles whose image is flipped (by a field the grid cannot follow, or by rounding) are then
 * untangled: the map moves in their neighbourhood to minimize a foldover-free distortion energy
 * (Garanzha et al. 2021), the integers kept (MaximumUntangleRounds). With AlignToBoundary, boundary
 * edges along a frame direction lie on integer grid lines; with FeatureLines, sharp edges too.
 *
 * The edge length of the grid (the world length of one grid unit) is TargetEdgeLength when
 * positive. Otherwise it is chosen so that the continuous map covers TargetQuadCount unit cells
 * (its (u, v) area): sqrt(area / TargetQuadCount) to begin with, corrected by the continuous
 * map's area, which is smaller where the field is far from integrable. The field data
 * EdgeLength reports the length used.
 *
 * Input: a manifold, consistently oriented triangle surface with the cell arrays FrameU
 * (SetInputArrayToProcess(0, ...)) and Matching (SetInputArrayToProcess(1, ...)), as
 * vtkMatchingBuilder writes them.
 *
 * Output: the surface with cell data CornerUV (6 x double: u0 v0 u1 v1 u2 v2 at the triangle's
 * points) and Seam (3 x unsigned char: 1 where edge k, from point k to k+1, is on the cut), point
 * data LayerShift and SingularityIndex as its map has them (from Matching, 0 at the points of the
 * pairs it cancelled, the quarters it moved apart where they went), field data EdgeLength,
 * FlippedTriangles, WindingErrors, ParameterizationEnergy, SeamEdgeCount, AlignedBoundaryEdges,
 * AlignedFeatureEdges, CancelledSingularityPairs, MovedSingularities, BranchPointsOnGrid and
 * SeamTranslationError (see vtkQuadCoverArrayNames.h). With SplitSeams
 * the surface is cut open along the seams instead: one point per sector of a point between seam
 * edges, point data UV (the active texture coordinates) and SurfacePointId, so a checkerboard
 * texture shows the parameter lines at once.
 * @sa vtkMatchingBuilder vtkQuadExtractor
 */
#ifndef vtkQuadCoverSolver_h
#define vtkQuadCoverSolver_h

#include "vtkQuadCoverAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

#include <vector> // for std::vector

class VTKQUADCOVERFILTERS_EXPORT vtkQuadCoverSolver : public vtkQuadCoverAlgorithm
{
public:
  static vtkQuadCoverSolver* New();

  /**
   * The most quads the solver takes on a surface of `triangles` triangles: 2,000,000, or 50 a
   * triangle on larger surfaces. The quad extraction takes about 0.6 KB a quad whatever the
   * surface (1.2 GB at 2,000,000), and quads finer than a fiftieth of a triangle only resample
   * flat triangles, so a larger request (TargetQuadCount, or the area over TargetEdgeLength
   * squared, plus MinimumComponentQuadCount for each component) is refused before anything is
   * computed, rather than allocating for minutes and ending out of memory.
   */
  static double MaximumQuadCount(vtkIdType triangles);
  vtkTypeMacro(vtkQuadCoverSolver, vtkQuadCoverAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RoundingModes
  {
    ROUNDING_NONE = 0,
    ROUNDING_SIMPLE = 1,
    ROUNDING_GREEDY = 2
  };

  ///@{
  /** Edge length of the quads in world units, 0 for TargetQuadCount (default 0). */
  vtkSetClampMacro(TargetEdgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TargetEdgeLength, double);
  ///@}

  ///@{
  /** About how many quads, in [1, 10^8] (default 3000); used when TargetEdgeLength is 0. More
   * than MaximumQuadCount (2,000,000, or 50 a triangle) is refused with an error. */
  vtkSetClampMacro(TargetQuadCount, int, 1, 100000000);
  vtkGetMacro(TargetQuadCount, int);
  ///@}

  ///@{
  /** Branch points on grid points so that the extraction gives only quads (default on). */
  vtkSetMacro(PureQuads, bool);
  vtkGetMacro(PureQuads, bool);
  vtkBooleanMacro(PureQuads, bool);
  ///@}

  ///@{
  /** How the integer unknowns are rounded (default ROUNDING_GREEDY). */
  vtkSetClampMacro(RoundingMode, int, ROUNDING_NONE, ROUNDING_GREEDY);
  vtkGetMacro(RoundingMode, int);
  void SetRoundingModeToNone() { this->SetRoundingMode(ROUNDING_NONE); }
  void SetRoundingModeToSimple() { this->SetRoundingMode(ROUNDING_SIMPLE); }
  void SetRoundingModeToGreedy() { this->SetRoundingMode(ROUNDING_GREEDY); }
  ///@}

  ///@{
  /** Put boundary edges along a frame direction on integer grid lines (default on). */
  vtkSetMacro(AlignToBoundary, bool);
  vtkGetMacro(AlignToBoundary, bool);
  vtkBooleanMacro(AlignToBoundary, bool);
  ///@}

  ///@{
  /** Degrees, in [0, 45] (default 10): how far a boundary edge (or, with FeatureLines, a sharp
   * edge) may turn from its frame and still count as along it. */
  vtkSetClampMacro(BoundaryTolerance, double, 0.0, 45.0);
  vtkGetMacro(BoundaryTolerance, double);
  ///@}

  ///@{
  /** Put sharp edges along a frame direction on integer grid lines, as boundary edges are, so that
   * quad edges run along the creases and quad vertices sit on them (default off: meant for CAD
   * parts; on scans it puts noisy sharp edges on lines at a cost in time and evenness). Sharp: the
   * normals more than FeatureAngle degrees apart, in chains of at least MinimumFeatureLength
   * edges, on crease networks at least four grid edges long; along: within BoundaryTolerance
   * degrees of the frame in both triangles.
   * AlignedFeatureEdges counts them. */
  vtkSetMacro(FeatureLines, bool);
  vtkGetMacro(FeatureLines, bool);
  vtkBooleanMacro(FeatureLines, bool);
  ///@}

  ///@{
  /** Degrees, in [0, 180] (default 60): edges whose normals are further apart are sharp, for
   * FeatureLines; the same as vtkFrameSmoother's FeatureAngle. */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /** Sharp edges count for FeatureLines only in chains of at least this many, in [1, 10000]
   * (default 3); the same as vtkFrameSmoother's MinimumFeatureLength. */
  vtkSetClampMacro(MinimumFeatureLength, int, 1, 10000);
  vtkGetMacro(MinimumFeatureLength, int);
  ///@}

  ///@{
  /** Rounds of local untangling per neighbourhood of flipped triangles, in [0, 1000] (default
   * 30; 0 leaves flips in place). */
  vtkSetClampMacro(MaximumUntangleRounds, int, 0, 1000);
  vtkGetMacro(MaximumUntangleRounds, int);
  ///@}

  ///@{
  /** The untangling's budget of one repair of a map, in energy evaluations per triangle (a
   * surface of more than 20,000 triangles counted as one of 20,000), in [1, 1000000] (default
   * 10000); all of a map's repairs together (its trials on other grids) spend at most twice
   * that. It stops there (with a warning), so the time of each component's map stays bounded
   * whatever its size; counted as work, not seconds, so every machine gives the same map. */
  vtkSetClampMacro(UntangleWork, int, 1, 1000000);
  vtkGetMacro(UntangleWork, int);
  ///@}

  ///@{
  /** Each connected component gets a map of its own with at least this many quads per hole and
   * handle (2 minus its Euler characteristic, at least 1), in [1, 100000] (default 24): its
   * share of TargetQuadCount by area, or TargetEdgeLength made shorter where that would give
   * fewer, so that small components keep a coarse quad mesh with all their holes. */
  vtkSetClampMacro(MinimumComponentQuadCount, int, 1, 100000);
  vtkGetMacro(MinimumComponentQuadCount, int);
  ///@}

  ///@{
  /** With TargetQuadCount, the edge length is at most this over the surface's mean curvature,
   * in [0, 100] (default 1.5), so that a thin tube gets at least 4 quads around it; 0: no
   * limit. */
  vtkSetClampMacro(CurvatureEdgeLength, double, 0.0, 100.0);
  vtkGetMacro(CurvatureEdgeLength, double);
  ///@}

  ///@{
  /** With TargetQuadCount, the grid has at least this many cells per branch point of the
   * field, in [0, 1000] (default 4): a surface whose field has more singularities than a grid
   * of the quads asked can hold gets more quads; 0: no limit. */
  vtkSetClampMacro(MinimumQuadsPerSingularity, double, 0.0, 1000.0);
  vtkGetMacro(MinimumQuadsPerSingularity, double);
  ///@}

  ///@{
  /** A map that keeps flipped triangles or points wound the wrong way after its repair, or
   * whose quads would lose the surface's topology, is rounded and repaired again on up to this
   * many other grids (2, 1/2, 4, 1/4, 8 and 16 times the quads, 8 and 16 only up to
   * MaximumRegridQuadCount; a map whose quads keep the topology
   * and, repaired, face the right way only 2 and 1/2), in [0, 6] (default
   * 6); the first with neither replaces it, else the first better than it (the topology first); 0:
   * none. */
  vtkSetClampMacro(MaximumRegrids, int, 0, 6);
  vtkGetMacro(MaximumRegrids, int);
  ///@}

  ///@{
  /** Only maps (components) of at most this many quads are tried on other grids, in
   * [0, 100000000] (default 1000): each trial repairs the whole map again. */
  vtkSetClampMacro(MaximumRegridQuadCount, double, 0.0, 1e8);
  vtkGetMacro(MaximumRegridQuadCount, double);
  ///@}

  ///@{
  /** Opposite quarter singularities (+1/4 and -1/4) closer than this many grid edges along the
   * surface cancel before the surface is cut, and a quarter closer than a third of it to one of
   * the same index, or closer than a grid edge to the boundary, moves apart to it (on components
   * with handles only within a disk of the surface), the frames around them turned to agree, in
   * [0, 100] (default 1.5); 0 keeps every one where it is. Both would have to lie on grid points
   * (the boundary on grid lines): so close, the map folds or the quads between them stretch.
   * Counted in CancelledSingularityPairs and MovedSingularities. */
  vtkSetClampMacro(MinimumSingularitySeparation, double, 0.0, 100.0);
  vtkGetMacro(MinimumSingularitySeparation, double);
  ///@}

  ///@{
  /** Before the map, triangles with an edge longer than this many grid edges are split, the
   * longest edge first, in [0, 1000] (default 3; 0: none are): a linear map cannot bend inside a
   * triangle larger than a few grid cells, and folds there (slivers of a CAD export, a coarse
   * scan). The output is then the refined surface (the input's points first, the midpoints
   * after, point data interpolated, cell data copied from the triangle split, Matching carried),
   * counted in GridRefinedTriangles. */
  vtkSetClampMacro(MaximumTriangleEdge, double, 0.0, 1000.0);
  vtkGetMacro(MaximumTriangleEdge, double);
  ///@}

  ///@{
  /** Pairs of opposite quarter cones (+1/4 and -1/4) are added where the field's singularities
   * leave the quads uneven in size, each where it lowers the variance of the log scale of the
   * flat metric with cones at the singularities (the quads' log size follows about half of
   * it), summed over the grid's cells, by at least this, in [0, 1e6] (default 6; 0: none); and
   * the field's own quarter singularities, but those near sharp edges, move (three to six grid
   * edges) where that lowers it by twice this. The frames then turn as little as agrees with
   * the new matchings, all but those held along the boundary and sharp edges. Meant for a field
   * with its own singularities (the default: vtkMatchingBuilder::OptimizeBranchPoints off).
   * Counted in AddedConePairs and MovedSingularities. */
  vtkSetClampMacro(ConePairGain, double, 0.0, 1e6);
  vtkGetMacro(ConePairGain, double);
  ///@}

  ///@{
  /** Where a strip of the surface between two boundary lines that face each other is narrower
   * than a grid edge (the bars of a grille, the surface between two slots), or a wall between
   * two creases (FeatureAngle) is lower than one (the rim of a thin plate), the map's grid is
   * made finer around it, down to the strip's width but at most this many times finer, in
   * [1, 64] (default 8; 1: a uniform grid): on a uniform grid both sides of such a strip round
   * onto one grid line, which cuts it and joins the holes, and the quads fold over a wall,
   * turned against the surface. The same holds around a handle or a neck whose loop, within two
   * grid edges of a singular point of the field, is shorter than about four: the grid there
   * gets about three edges around it (a uniform one closes the tunnel or cuts the neck). Counted
   * in FinerGridTriangles. */
  vtkSetClampMacro(MaximumThinStripRefinement, double, 1.0, 64.0);
  vtkGetMacro(MaximumThinStripRefinement, double);
  ///@}

  ///@{
  /** Adaptive density: where the surface curves sharply against the grid (thin ears, fingers,
   * horns, small bumps), the grid edge is about this many times the radius of curvature, seen
   * at the grid's scale (at most 8 times finer, growing back over a few grid edges), so that
   * thin parts keep their shape; 0.5 puts about 12 quads around a thin tube, 1.5 refines only
   * parts thinner than about a grid edge. Sharp edges (FeatureAngle, as the smoother finds them)
   * are no thin parts: the grid stays uniform along them. The surface keeps
   * about TargetQuadCount quads in all, larger elsewhere (with TargetEdgeLength the finer ones
   * come on top, at most 4 times the uniform grid's). In [0, 10] (default 0: a uniform grid).
   * Counted in FinerGridTriangles. */
  vtkSetClampMacro(AdaptiveCurvature, double, 0.0, 10.0);
  vtkGetMacro(AdaptiveCurvature, double);
  ///@}

  ///@{
  /** Where the repaired map keeps defects (flipped triangles, points wound the wrong way: a
   * thin ear or finger a grid cell around, say), the grid is made this many times finer around
   * them, growing back over a few grid edges, and the map is rounded and repaired again; the
   * second map is kept when it has fewer defects. The same between two boundary loops that the
   * quads would join (a strip between two holes less than a grid edge or two wide, cut): kept
   * when its quads keep the surface's topology. In [1, 8] (default 2; 1: no second map).
   * Counted in FinerGridTriangles. */
  vtkSetClampMacro(DefectGridRefinement, double, 1.0, 8.0);
  vtkGetMacro(DefectGridRefinement, double);
  ///@}

  ///@{
  /** Where the repaired map keeps defects (a thin finger or claw a grid cell around), first the
   * adaptive grid of AdaptiveCurvature with this value is tried: the map is made again on it
   * and kept when it has fewer defects (then DefectGridRefinement around those left), in
   * [0, 10] (default 1.5; 0: not tried; unused when AdaptiveCurvature is set). Counted in
   * FinerGridTriangles. */
  vtkSetClampMacro(DefectAdaptiveCurvature, double, 0.0, 10.0);
  vtkGetMacro(DefectAdaptiveCurvature, double);
  ///@}

  ///@{
  /** A component whose map keeps defects (flipped triangles, wrong windings) after all the local
   * repairs, and whose quads would not keep its Euler characteristic and boundary loops, is
   * mapped again on a uniformly finer grid, sqrt(2) times finer each time (with PureQuads), at
   * most this many times; the first whose quads keep them is kept (more quads there
   * than asked). In [0, 4] (default 2; 0: never). Counted in FinerGridRetries. */
  vtkSetClampMacro(MaximumFinerGridRetries, int, 0, 4);
  vtkGetMacro(MaximumFinerGridRetries, int);
  ///@}

  ///@{
  /** Number of threads for the untangling and for the maps of the components (each component
   * on its own), 0 for all cores (default 0). The result does not depend on it. */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /** Cut the output open along the seams, with point texture coordinates (default off). */
  vtkSetMacro(SplitSeams, bool);
  vtkGetMacro(SplitSeams, bool);
  vtkBooleanMacro(SplitSeams, bool);
  ///@}

  ///@{
  /**
   * Wall-clock seconds of each sparse factorization and solve of the last update (the
   * continuous solve, then one per rounding step that solves again), for timing. Kept out of the
   * output so that the same input gives the same bytes; 0 solves before an update and after one
   * that failed or was aborted. GetSolveSeconds(i) is 0 for i out of range.
   */
  int GetNumberOfSolves() const;
  double GetSolveSeconds(int i) const;
  ///@}

protected:
  vtkQuadCoverSolver();
  ~vtkQuadCoverSolver() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) override;

  // defaults: quadcover::ParameterizationOptions
  double TargetEdgeLength;
  int TargetQuadCount;
  bool PureQuads;
  int RoundingMode;
  bool AlignToBoundary;
  double BoundaryTolerance;
  bool FeatureLines;
  double FeatureAngle;
  int MinimumFeatureLength;
  int MaximumUntangleRounds;
  int UntangleWork;
  int MinimumComponentQuadCount;
  double CurvatureEdgeLength;
  double MinimumQuadsPerSingularity;
  int MaximumRegrids;
  double MaximumRegridQuadCount;
  double MinimumSingularitySeparation;
  double MaximumTriangleEdge;
  double ConePairGain;
  double MaximumThinStripRefinement;
  double AdaptiveCurvature;
  double DefectGridRefinement;
  double DefectAdaptiveCurvature;
  int MaximumFinerGridRetries;
  int NumberOfThreads;
  bool SplitSeams = false;

private:
  std::vector<double> SolveSeconds; // of the last update

  vtkQuadCoverSolver(const vtkQuadCoverSolver&) = delete;
  void operator=(const vtkQuadCoverSolver&) = delete;
};

#endif
