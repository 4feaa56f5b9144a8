// Pipeline.h: the QuadCover filters chained from the repair to the quads, run stage by stage
// with their seconds, warnings and first error.
#ifndef quadcover_app_Pipeline_h
#define quadcover_app_Pipeline_h

#include "vtkCurvatureFrames.h"
#include "vtkFrameSmoother.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadCoverSurfaceRepair.h"
#include "vtkQuadExtractor.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace quadcover_app
{
/// Seconds one step took ("read", a stage's name, "write").
struct Timing
{
  std::string name;
  double seconds = 0.0;
};

class Pipeline
{
public:
  /// The stages in order, by the names --stage takes.
  static const std::vector<std::string>& StageNames();
  /// The stage called `name`, or -1.
  static int StageIndex(const std::string& name);

  Pipeline();

  vtkNew<vtkQuadCoverSurfaceRepair> Repair;
  vtkNew<vtkCurvatureFrames> Curvature;
  vtkNew<vtkFrameSmoother> Smoother;
  vtkNew<vtkMatchingBuilder> Matching;
  vtkNew<vtkQuadCoverSolver> Solver;
  vtkNew<vtkQuadExtractor> Extractor;

  /// The filter of stage i.
  vtkQuadCoverAlgorithm* Filter(int stage) const;

  /**
   * The most quads the param stage may be asked for on a surface of `triangles` triangles:
   * vtkQuadCoverSolver::MaximumQuadCount (2,000,000, or 50 a triangle on larger surfaces). The
   * solver refuses more itself; CheckQuadCount refuses them right after the repair, before the
   * longer stages run.
   */
  static double MaximumQuadCount(long long triangles);

  /**
   * "" or why the solver's target (TargetQuadCount, or the repaired surface's area over
   * TargetEdgeLength squared) is more quads than MaximumQuadCount allows; run after the repair.
   */
  std::string CheckQuadCount() const;

  /// Set the repair's MaximumTriangleCount from the quads asked of `surface`
  /// (quadcover::simplificationBudget) when a stage after the repair runs (0 for --stage
  /// repair); off when --maximum-triangle-count is given.
  bool AutomaticTriangleCount = true;

  /**
   * Runs the stages 0..last on `surface`: each stage's warnings go to stderr as
   * "quadcover: warning: ...", its seconds to `timings`; with `progress`, a percentage line on
   * stderr while a stage runs. CheckQuadCount runs after the repair when the param stage is to
   * run. A std::bad_alloc in a stage is reported as "Cannot ...: out of memory." Where the
   * repair simplified the surface, the quads are put onto `surface` itself (the extractor's
   * source).
   * @return "" or the first error
   */
  std::string Run(vtkPolyData* surface, int last, bool progress, std::vector<Timing>& timings);
};
}

#endif
