/**
 * @class   vtkQuadCoverRemesh
 * @brief   the whole QuadCover chain in one filter: a surface in, a quad mesh out
 *
 * Runs vtkQuadCoverSurfaceRepair, vtkCurvatureFrames, vtkFrameSmoother, vtkMatchingBuilder,
 * vtkQuadCoverSolver and vtkQuadExtractor on its input, as the `quadcover` command line does, and
 * gives vtkQuadExtractor's output: the quad mesh with its point, cell and field data.
 *
 * The properties are the command line's main options and set the stages that use them:
 * TargetQuadCount or TargetEdgeLength (the solver), FeatureLines (the solver), FeatureAngle (the
 * smoother, the solver and the quad extractor), NumberOfThreads (the curvature estimate, the
 * smoother and the solver), MaximumTriangleCount (the repair, and the extractor's source),
 * SmoothRoughSurfaces (the repair). Every
 * other option is reached through the stage itself, e.g. GetFrameSmoother()->SetSmoothingWeight(1);
 * a change there re-runs the chain (GetMTime includes the stages').
 *
 * Errors: the first stage's error, as that stage words it ("Cannot smooth frames: ..."), through
 * vtkErrorMacro; RequestData then returns 0. The stages' warnings become this filter's.
 * A composite input (vtkMultiBlockDataSet, vtkPartitionedDataSetCollection) gives a composite
 * output of the same structure and names, each surface remeshed on its own (VTK's composite
 * pipeline runs the filter block by block; so do the stages).
 * Progress runs over the six stages; AbortExecute stops the running stage and leaves the output
 * empty, without an error. In a distributed
 * pipeline (pvbatch over MPI) a surface is remeshed whole on the rank of piece 0, never piece by
 * piece; the blocks of a composite input are remeshed each on the rank that holds it, as whole
 * surfaces (vtkQuadCoverPieces.h: blocks split over the ranks are not gathered).
 *
 * Memory: the six stages keep their outputs (and this filter a shallow copy of its input), so
 * that a changed property re-runs only from its stage; about the command line's peak.
 * @sa vtkQuadCoverSurfaceRepair vtkQuadExtractor
 */
#ifndef vtkQuadCoverRemesh_h
#define vtkQuadCoverRemesh_h

#include "vtkNew.h" // for vtkNew
#include "vtkPolyDataAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

class vtkAlgorithm;
class vtkCallbackCommand;
class vtkCurvatureFrames;
class vtkFrameSmoother;
class vtkMatchingBuilder;
class vtkPolyData;
class vtkQuadCoverErrorObserver;
class vtkQuadCoverSolver;
class vtkQuadCoverSurfaceRepair;
class vtkQuadExtractor;

class VTKQUADCOVERFILTERS_EXPORT vtkQuadCoverRemesh : public vtkPolyDataAlgorithm
{
public:
  static vtkQuadCoverRemesh* New();
  vtkTypeMacro(vtkQuadCoverRemesh, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** About this many quads (vtkQuadCoverSolver's TargetQuadCount, default 3000). */
  void SetTargetQuadCount(int count);
  int GetTargetQuadCount();
  ///@}

  ///@{
  /** Quad edge length in world units; 0 for TargetQuadCount (the solver's, default 0). */
  void SetTargetEdgeLength(double length);
  double GetTargetEdgeLength();
  ///@}

  ///@{
  /** Quad edges along the sharp creases (vtkQuadCoverSolver's FeatureLines, default off). */
  void SetFeatureLines(bool on);
  bool GetFeatureLines();
  vtkBooleanMacro(FeatureLines, bool);
  ///@}

  ///@{
  /** Edges sharper than this (degrees) are features: the smoother's and solver's (default 60). */
  void SetFeatureAngle(double degrees);
  double GetFeatureAngle();
  ///@}

  ///@{
  /** Smooth the components rough with noise at the triangle scale first; their quads then lie on
   * the smoothed surface (vtkQuadCoverSurfaceRepair's SmoothRoughSurfaces, default on). */
  void SetSmoothRoughSurfaces(bool on);
  bool GetSmoothRoughSurfaces();
  vtkBooleanMacro(SmoothRoughSurfaces, bool);
  ///@}

  ///@{
  /**
   * Worker threads of the curvature estimate, the smoother and the solver, 0 for all cores
   * (default 0).
   */
  void SetNumberOfThreads(int count);
  int GetNumberOfThreads();
  ///@}

  ///@{
  /**
   * A surface of more triangles is simplified to about this many first (vtkQuadCoverSurfaceRepair's
   * MaximumTriangleCount) and the quads put back onto it (vtkQuadExtractor's source; not when
   * the repair smoothed a rough surface: its quads stay on the smoothed one) (default -1:
   * 16 triangles a quad asked, at least 100,000, vtkQuadCoverSurfaceRepair::
   * MaximumTriangleCountFor; 0: never).
   */
  vtkSetClampMacro(MaximumTriangleCount, vtkIdType, -1, 2000000000);
  vtkGetMacro(MaximumTriangleCount, vtkIdType);
  ///@}

  ///@{
  /** The stages, for their other properties. */
  vtkQuadCoverSurfaceRepair* GetSurfaceRepair();
  vtkCurvatureFrames* GetCurvatureFrames();
  vtkFrameSmoother* GetFrameSmoother();
  vtkMatchingBuilder* GetMatchingBuilder();
  vtkQuadCoverSolver* GetSolver();
  vtkQuadExtractor* GetQuadExtractor();
  ///@}

  /// The latest of this filter's and its stages' modification times.
  vtkMTimeType GetMTime() override;

protected:
  vtkQuadCoverRemesh();
  ~vtkQuadCoverRemesh() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The whole surface on every rank, remeshed on the rank of piece 0 (vtkQuadCoverPieces.h).
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkQuadCoverRemesh(const vtkQuadCoverRemesh&) = delete;
  void operator=(const vtkQuadCoverRemesh&) = delete;

  static constexpr int StageCount = 6;
  /// Stage i (0: the repair ... 5: the extractor).
  vtkAlgorithm* Stage(int i) const;
  /// Stage `stage` (0..5) reported `progress`: this filter's progress, and its abort passed on.
  void StageProgress(int stage, double progress);
  static void OnProgress(vtkObject* caller, unsigned long, void* clientData, void* callData);

  vtkNew<vtkPolyData> Surface;
  vtkNew<vtkQuadCoverSurfaceRepair> Repair;
  vtkNew<vtkCurvatureFrames> Curvature;
  vtkNew<vtkFrameSmoother> Smoother;
  vtkNew<vtkMatchingBuilder> Matching;
  vtkNew<vtkQuadCoverSolver> Solver;
  vtkNew<vtkQuadExtractor> Extractor;
  vtkNew<vtkQuadCoverErrorObserver> Errors;
  vtkNew<vtkCallbackCommand> Progress;
  bool EmptyPiece = false;
  vtkIdType MaximumTriangleCount = -1;
  /// The input Surface was last copied from (compared, never dereferenced) and its MTime then.
  const void* LastInput = nullptr;
  vtkMTimeType LastInputTime = 0;
};

#endif
