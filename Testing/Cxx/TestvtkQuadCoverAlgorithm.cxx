// What every QuadCover stage shares (vtkQuadCoverAlgorithm): progress that rises to 1, a stop
// soon after AbortExecute is set (empty outputs, no error), and errors of one line.
#include "vtkCommand.h"
#include "vtkCurvatureFrames.h"
#include "vtkFrameSmoother.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadCoverSurfaceRepair.h"
#include "vtkQuadExtractor.h"

#include "Surfaces.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace
{
/// Records a filter's progress; with `abortAt` in (0, 1), sets AbortExecute once it is reached.
class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject* caller, unsigned long, void* callData) override
  {
    const double p = *static_cast<double*>(callData);
    this->Values.push_back(p);
    if (this->AbortAt > 0 && p >= this->AbortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      ++this->AbortRequests;
    }
  }
  std::vector<double> Values;
  double AbortAt = 0.0;
  int AbortRequests = 0;
};

struct Chain
{
  vtkNew<vtkQuadCoverSurfaceRepair> repair;
  vtkNew<vtkCurvatureFrames> curvature;
  vtkNew<vtkFrameSmoother> smoother;
  vtkNew<vtkMatchingBuilder> matching;
  vtkNew<vtkQuadCoverSolver> solver;
  vtkNew<vtkQuadExtractor> extractor;
  vtkNew<vtkQuadCoverErrorObserver> errors;

  Chain()
  {
    // A knot tube with random singularities to merge: every stage has real work.
    const quadcover::Surface s =
      quadcover::makeKnotTube(2, 3, 1.0, 0.4, 0.12, 240, 20, 0.3, 0.03, 7);
    repair->SetInputData(vtkQuadCoverEigen::ToPolyData(s.V, s.F));
    curvature->SetInputConnection(repair->GetOutputPort());
    smoother->SetInputConnection(curvature->GetOutputPort());
    smoother->SetSmoothingWeight(0.5); // more iterations than the default
    matching->SetInputConnection(smoother->GetOutputPort());
    matching->OptimizeBranchPointsOn(); // the merges: the matching stage's long work
    solver->SetInputConnection(matching->GetOutputPort());
    solver->SetTargetQuadCount(1500);
    extractor->SetInputConnection(solver->GetOutputPort());
    extractor->SetRelaxationIterations(5);
    for (vtkQuadCoverAlgorithm* a : this->Stages())
    {
      errors->Attach(a);
    }
  }
  std::vector<vtkQuadCoverAlgorithm*> Stages()
  {
    return { repair, curvature, smoother, matching, solver, extractor };
  }
};
}

TEST(vtkQuadCoverAlgorithm, ProgressRisesToOneInEveryStage)
{
  Chain chain;
  std::vector<vtkNew<ProgressRecorder>> recorders(chain.Stages().size());
  for (std::size_t i = 0; i < recorders.size(); ++i)
  {
    chain.Stages()[i]->AddObserver(vtkCommand::ProgressEvent, recorders[i]);
  }
  chain.extractor->Update();
  ASSERT_EQ(chain.errors->GetError(), "");
  for (std::size_t i = 0; i < recorders.size(); ++i)
  {
    const std::vector<double>& v = recorders[i]->Values;
    SCOPED_TRACE(chain.Stages()[i]->GetClassName());
    ASSERT_GE(v.size(), 3u);
    EXPECT_EQ(v.back(), 1.0);
    for (std::size_t k = 0; k < v.size(); ++k)
    {
      EXPECT_GE(v[k], 0.0);
      EXPECT_LE(v[k], 1.0);
      EXPECT_TRUE(k == 0 || v[k] >= v[k - 1]) << v[k - 1] << " then " << v[k];
    }
  }
  // the long computations report from inside Core, not only at the filter's steps
  EXPECT_GE(recorders[2]->Values.size(), 10u) << "smoother";
  EXPECT_GE(recorders[4]->Values.size(), 10u) << "solver";
}

TEST(vtkQuadCoverAlgorithm, AbortStopsAStageWithAnEmptyOutputAndNoError)
{
  Chain chain;
  // stages 2..5: the smoother, the matchings, the solver, the extractor
  for (std::size_t stage = 2; stage < chain.Stages().size(); ++stage)
  {
    vtkQuadCoverAlgorithm* filter = chain.Stages()[stage];
    SCOPED_TRACE(filter->GetClassName());
    chain.Stages()[stage - 1]->Update(); // its input, computed in full
    vtkNew<ProgressRecorder> recorder;
    recorder->AbortAt = 0.3;
    const unsigned long tag = filter->AddObserver(vtkCommand::ProgressEvent, recorder);
    filter->Modified();
    filter->Update();
    EXPECT_EQ(chain.errors->GetError(), "");
    EXPECT_GE(recorder->AbortRequests, 1);
    // stopped where it was: no report of its own near the end (the executive of ParaView 5.11's
    // VTK reports 1 after every run, aborted or not; the stages' own last report is below 1)
    std::vector<double> own = recorder->Values;
    if (!own.empty() && own.back() == 1.0)
    {
      own.pop_back();
    }
    ASSERT_FALSE(own.empty());
    EXPECT_LT(own.back(), 0.99);
    EXPECT_EQ(vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0))->GetNumberOfPoints(), 0);
    // a new request runs in full
    filter->RemoveObserver(tag);
    filter->AbortExecuteOff();
    filter->Modified();
    filter->Update();
    EXPECT_GT(vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0))->GetNumberOfCells(), 0);
  }
}

TEST(vtkQuadCoverAlgorithm, APropertyThatIsNotANumberIsAnError)
{
  // vtkSetClampMacro lets NaN through; each stage refuses it before it computes anything
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::string, std::function<void(Chain&)>>> cases = {
    { "Cannot estimate curvature: NeighborhoodRadius is not a number.",
      [&](Chain& c) { c.curvature->SetNeighborhoodRadius(nan); } },
    { "Cannot smooth frames: SmoothingWeight is not a number.",
      [&](Chain& c) { c.smoother->SetSmoothingWeight(nan); } },
    { "Cannot build matchings: BranchPointWeight is not a number.",
      [&](Chain& c) { c.matching->SetBranchPointWeight(nan); } },
    { "Cannot parameterize: TargetEdgeLength is not a number.",
      [&](Chain& c) { c.solver->SetTargetEdgeLength(nan); } },
  };
  for (const auto& [error, spoil] : cases)
  {
    Chain chain;
    spoil(chain);
    chain.extractor->Update();
    EXPECT_EQ(chain.errors->GetError(), error);
  }
}

TEST(vtkQuadCoverAlgorithm, ErrorsAreOneLineNamingTheStage)
{
  vtkNew<vtkPolyData> empty;
  const std::vector<std::pair<vtkSmartPointer<vtkQuadCoverAlgorithm>, const char*>> stages = {
    { vtkSmartPointer<vtkQuadCoverSurfaceRepair>::New(), "Cannot repair the surface: " },
    { vtkSmartPointer<vtkCurvatureFrames>::New(), "Cannot estimate curvature: " },
    { vtkSmartPointer<vtkFrameSmoother>::New(), "Cannot smooth frames: " },
    { vtkSmartPointer<vtkMatchingBuilder>::New(), "Cannot build matchings: " },
    { vtkSmartPointer<vtkQuadCoverSolver>::New(), "Cannot parameterize: " },
    { vtkSmartPointer<vtkQuadExtractor>::New(), "Cannot extract quads: " },
  };
  for (const auto& [filter, prefix] : stages)
  {
    vtkNew<vtkQuadCoverErrorObserver> errors;
    errors->Attach(filter);
    filter->SetInputData(empty);
    filter->Update();
    const std::string e = errors->GetError();
    EXPECT_EQ(e, std::string(prefix) + "the input has no points.");
  }
}
