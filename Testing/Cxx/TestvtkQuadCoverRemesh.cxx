// vtkQuadCoverRemesh: the six stages in one filter give what the six filters chained give; its
// properties reach the stages; errors, warnings, progress and re-execution behave as a filter's.
#include "vtkAlgorithmOutput.h"
#include "vtkCommand.h"
#include "vtkCurvatureFrames.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFrameSmoother.h"
#include "vtkInformation.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverRemesh.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadCoverSurfaceRepair.h"
#include "vtkQuadExtractor.h"
#include "vtkSphereSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTrivialProducer.h"

#include "SurfaceLocator.h"
#include "Surfaces.h"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> Dumbbell()
{
  const quadcover::Surface s = quadcover::makeDumbbell(2.0, 0.6, 0.25, 48, 96);
  return vtkQuadCoverEigen::ToPolyData(s.V, s.F);
}

class ProgressLog : public vtkCommand
{
public:
  static ProgressLog* New() { return new ProgressLog; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    this->Values.push_back(*static_cast<double*>(callData));
  }
  std::vector<double> Values;
};

/// The six stages chained, the repair on `upstream`.
struct Stages
{
  vtkNew<vtkQuadCoverSurfaceRepair> repair;
  vtkNew<vtkCurvatureFrames> curvature;
  vtkNew<vtkFrameSmoother> smoother;
  vtkNew<vtkMatchingBuilder> matching;
  vtkNew<vtkQuadCoverSolver> solver;
  vtkNew<vtkQuadExtractor> extractor;

  explicit Stages(vtkAlgorithmOutput* upstream)
  {
    repair->SetInputConnection(upstream);
    curvature->SetInputConnection(repair->GetOutputPort());
    smoother->SetInputConnection(curvature->GetOutputPort());
    matching->SetInputConnection(smoother->GetOutputPort());
    solver->SetInputConnection(matching->GetOutputPort());
    extractor->SetInputConnection(solver->GetOutputPort());
  }
};
}

TEST(vtkQuadCoverRemesh, GivesTheChainsQuads)
{
  vtkSmartPointer<vtkPolyData> surface = Dumbbell();
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(surface);
  Stages chain(producer->GetOutputPort());
  chain.solver->SetTargetQuadCount(800);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(chain.extractor), "");

  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputData(surface);
  remesh->SetTargetQuadCount(800);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  vtkPolyData* six = chain.extractor->GetOutput();
  vtkPolyData* one = remesh->GetOutput();
  ASSERT_GT(one->GetNumberOfPolys(), 400);
  ASSERT_EQ(one->GetNumberOfPolys(), six->GetNumberOfPolys());
  ASSERT_EQ(one->GetNumberOfPoints(), six->GetNumberOfPoints());
  for (vtkIdType p = 0; p < one->GetNumberOfPoints(); ++p)
  {
    double a[3], b[3];
    one->GetPoint(p, a);
    six->GetPoint(p, b);
    ASSERT_EQ(a[0], b[0]);
    ASSERT_EQ(a[1], b[1]);
    ASSERT_EQ(a[2], b[2]);
  }
  // the quad mesh's arrays come along
  EXPECT_NE(one->GetPointData()->GetArray("Valence"), nullptr);
  EXPECT_NE(one->GetFieldData()->GetArray("EulerCharacteristic"), nullptr);
}

TEST(vtkQuadCoverRemesh, AFineSurfaceIsSimplifiedAndTheQuadsPutBackOntoIt)
{
  const quadcover::Surface s = quadcover::makeDumbbell(2.0, 0.6, 0.25, 48, 96);
  vtkSmartPointer<vtkPolyData> surface = vtkQuadCoverEigen::ToPolyData(s.V, s.F);
  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputData(surface);
  remesh->SetTargetQuadCount(300);
  EXPECT_EQ(remesh->GetMaximumTriangleCount(), -1);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  auto collapsed = [&]() {
    vtkDataArray* a =
      remesh->GetSurfaceRepair()->GetOutput()->GetFieldData()->GetArray("CollapsedEdges");
    return a ? a->GetTuple1(0) : -1.0;
  };
  EXPECT_EQ(collapsed(), 0.0) << "9,000 triangles are below the default's 100,000";
  EXPECT_EQ(remesh->GetQuadExtractor()->GetNumberOfInputConnections(1), 0);

  remesh->SetMaximumTriangleCount(2000);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  EXPECT_GT(collapsed(), 3000.0);
  EXPECT_LE(remesh->GetSurfaceRepair()->GetOutput()->GetNumberOfPolys(), 2000);
  EXPECT_EQ(remesh->GetQuadExtractor()->GetNumberOfInputConnections(1), 1);
  vtkPolyData* quads = remesh->GetOutput();
  ASSERT_GT(quads->GetNumberOfPolys(), 150);
  EXPECT_EQ(quads->GetFieldData()->GetArray("EulerCharacteristic")->GetTuple1(0), 2.0);
  EXPECT_EQ(quads->GetFieldData()->GetArray("TurnedQuads")->GetTuple1(1), 0.0);
  // every quad vertex on the surface as it was given, not on the simplified one
  const quadcover::SurfaceLocator onInput(s.V, s.F);
  for (vtkIdType p = 0; p < quads->GetNumberOfPoints(); ++p)
  {
    double x[3];
    quads->GetPoint(p, x);
    ASSERT_LT(onInput.closest(Eigen::Vector3d(x[0], x[1], x[2])).distance, 1e-9) << "vertex " << p;
  }
  // the Hausdorff distance is measured against the input too
  EXPECT_LT(quads->GetFieldData()->GetArray("HausdorffDistance")->GetTuple1(0), 2.0);

  remesh->SetMaximumTriangleCount(0);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  EXPECT_EQ(collapsed(), 0.0);
  EXPECT_EQ(remesh->GetQuadExtractor()->GetNumberOfInputConnections(1), 0);
  std::ostringstream printed;
  remesh->Print(printed);
  EXPECT_NE(printed.str().find("MaximumTriangleCount: 0"), std::string::npos);
}

TEST(vtkQuadCoverRemesh, ARoughSurfaceIsSmoothedAndKeepsItsQuads)
{
  // a sphere of 5,120 triangles with noise of 0.3 edge lengths: smoothed, its 600 quads have
  // about 10 irregular vertices (left rough, about 50)
  const quadcover::Surface s = quadcover::withNoise(quadcover::makeIcosphere(1.0, 4), 0.3, 5);
  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputData(vtkQuadCoverEigen::ToPolyData(s.V, s.F));
  remesh->SetTargetQuadCount(600);
  for (const vtkIdType maximum : { vtkIdType(-1), vtkIdType(3000) })
  {
    remesh->SetMaximumTriangleCount(maximum); // -1: not simplified; 3000: simplified too
    ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
    vtkPolyData* repaired = remesh->GetSurfaceRepair()->GetOutput();
    EXPECT_TRUE(vtkQuadCoverSurfaceRepair::Smoothed(repaired));
    EXPECT_EQ(vtkQuadCoverSurfaceRepair::Simplified(repaired), maximum > 0);
    // the quads stay on the smoothed surface: the input's noise is what it took out
    EXPECT_EQ(remesh->GetQuadExtractor()->GetNumberOfInputConnections(1), 0);
    vtkPolyData* quads = remesh->GetOutput();
    vtkFieldData* fd = quads->GetFieldData();
    ASSERT_GT(quads->GetNumberOfPolys(), 400);
    EXPECT_EQ(fd->GetArray("QuadShare")->GetTuple1(0), 1.0);
    EXPECT_EQ(fd->GetArray("EulerCharacteristic")->GetTuple1(0), 2.0);
    EXPECT_EQ(fd->GetArray("BoundaryLoops")->GetTuple1(0), 0.0);
    EXPECT_EQ(fd->GetArray("TurnedQuads")->GetTuple1(1), 0.0);
    EXPECT_LE(fd->GetArray("IrregularVertices")->GetTuple1(0), 24.0);
    const Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(repaired);
    const Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(repaired);
    const quadcover::SurfaceLocator onRepaired(V, F); // (keeps references)
    for (vtkIdType p = 0; p < quads->GetNumberOfPoints(); p += 7)
    {
      double x[3];
      quads->GetPoint(p, x);
      ASSERT_LT(onRepaired.closest(Eigen::Vector3d(x[0], x[1], x[2])).distance, 1e-9)
        << "vertex " << p;
    }
  }
  // left rough, and simplified: the quads go back onto the input
  remesh->SmoothRoughSurfacesOff();
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  EXPECT_FALSE(vtkQuadCoverSurfaceRepair::Smoothed(remesh->GetSurfaceRepair()->GetOutput()));
  EXPECT_EQ(remesh->GetQuadExtractor()->GetNumberOfInputConnections(1), 1);
  remesh->SmoothRoughSurfacesOn();
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  EXPECT_EQ(remesh->GetQuadExtractor()->GetNumberOfInputConnections(1), 0);
  std::ostringstream printed;
  remesh->Print(printed);
  EXPECT_NE(printed.str().find("SmoothRoughSurfaces: On"), std::string::npos);
}

TEST(vtkQuadCoverRemesh, PropertiesSetTheStagesThatUseThem)
{
  vtkNew<vtkQuadCoverRemesh> remesh;
  const vtkNew<vtkQuadCoverSolver> solver;
  const vtkNew<vtkFrameSmoother> smoother;
  const vtkNew<vtkCurvatureFrames> curvature;
  // defaults are the stages'
  EXPECT_EQ(remesh->GetTargetQuadCount(), solver->GetTargetQuadCount());
  EXPECT_EQ(remesh->GetTargetEdgeLength(), solver->GetTargetEdgeLength());
  EXPECT_EQ(remesh->GetFeatureLines(), solver->GetFeatureLines());
  EXPECT_EQ(remesh->GetFeatureAngle(), smoother->GetFeatureAngle());
  EXPECT_EQ(remesh->GetNumberOfThreads(), curvature->GetNumberOfThreads());

  remesh->SetTargetQuadCount(1234);
  remesh->SetTargetEdgeLength(0.5);
  remesh->FeatureLinesOn();
  remesh->SetFeatureAngle(40.0);
  remesh->SetNumberOfThreads(1);
  EXPECT_EQ(remesh->GetSolver()->GetTargetQuadCount(), 1234);
  EXPECT_EQ(remesh->GetSolver()->GetTargetEdgeLength(), 0.5);
  EXPECT_TRUE(remesh->GetSolver()->GetFeatureLines());
  EXPECT_EQ(remesh->GetFrameSmoother()->GetFeatureAngle(), 40.0);
  EXPECT_EQ(remesh->GetSolver()->GetFeatureAngle(), 40.0);
  EXPECT_EQ(remesh->GetCurvatureFrames()->GetNumberOfThreads(), 1);
  EXPECT_EQ(remesh->GetFrameSmoother()->GetNumberOfThreads(), 1);
  EXPECT_EQ(remesh->GetSolver()->GetNumberOfThreads(), 1);
  // the stages' own clamps hold
  remesh->SetTargetQuadCount(0);
  EXPECT_EQ(remesh->GetTargetQuadCount(), 1);
  remesh->SetFeatureAngle(500.0);
  EXPECT_EQ(remesh->GetFeatureAngle(), 180.0);

  std::ostringstream printed;
  remesh->Print(printed);
  for (const char* name : { "TargetQuadCount: 1", "TargetEdgeLength: 0.5", "FeatureLines: On",
         "FeatureAngle: 180", "NumberOfThreads: 1" })
  {
    EXPECT_NE(printed.str().find(name), std::string::npos) << name;
  }
}

TEST(vtkQuadCoverRemesh, RunsAgainOnlyWhenItOrAStageChanged)
{
  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputData(Dumbbell());
  remesh->SetTargetQuadCount(300);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  const vtkMTimeType first = remesh->GetOutput()->GetMTime();
  remesh->Update();
  EXPECT_EQ(remesh->GetOutput()->GetMTime(), first) << "ran again with nothing changed";
  const vtkIdType quads = remesh->GetOutput()->GetNumberOfPolys();

  // a stage's own property: the chain runs again from there, not from the start
  const vtkMTimeType smoothed = remesh->GetFrameSmoother()->GetOutput()->GetMTime();
  remesh->GetSolver()->SetTargetQuadCount(1200);
  remesh->Update();
  EXPECT_GT(remesh->GetOutput()->GetMTime(), first);
  EXPECT_GT(remesh->GetOutput()->GetNumberOfPolys(), 2 * quads);
  EXPECT_EQ(remesh->GetFrameSmoother()->GetOutput()->GetMTime(), smoothed)
    << "the smoothing ran again for a change of the solver";

  // a changed input runs it all
  vtkPolyData::SafeDownCast(remesh->GetInputDataObject(0, 0))->Modified();
  remesh->Update();
  EXPECT_GT(remesh->GetFrameSmoother()->GetOutput()->GetMTime(), smoothed);
}

TEST(vtkQuadCoverRemesh, StagesErrorsAndWarningsAreItsOwn)
{
  // an input with no polygons: the repair's error, as the repair words it, once
  vtkNew<vtkPolyData> points;
  vtkNew<vtkPoints> p;
  p->InsertNextPoint(0, 0, 0);
  points->SetPoints(p);
  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputData(points);
  vtkNew<vtkQuadCoverErrorObserver> errors;
  errors->Attach(remesh);
  remesh->Update();
  EXPECT_EQ(errors->GetError().rfind("Cannot repair the surface: ", 0), 0u) << errors->GetError();
  EXPECT_EQ(remesh->GetOutput()->GetNumberOfCells(), 0);

  // a target too large for the surface is refused before anything is allocated, and the
  // output holds nothing of the run before
  errors->Clear();
  remesh->SetInputData(Dumbbell());
  remesh->SetTargetQuadCount(300);
  remesh->Update();
  ASSERT_EQ(errors->GetError(), "");
  ASSERT_GT(remesh->GetOutput()->GetNumberOfCells(), 0);
  remesh->SetTargetQuadCount(100000000);
  remesh->Update();
  EXPECT_EQ(remesh->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(errors->GetError().rfind("Cannot parameterize: TargetQuadCount 100000000 gives about "
                                     "1e+08 quads, too many for this surface (about 61 GB",
              0),
    0u)
    << errors->GetError();
  errors->Clear();
  remesh->SetTargetQuadCount(0);
  remesh->SetTargetEdgeLength(1e-6);
  remesh->Update();
  EXPECT_EQ(
    errors->GetError().rfind("Cannot parameterize: TargetEdgeLength 1e-06 gives about ", 0), 0u)
    << errors->GetError();
  remesh->SetTargetEdgeLength(0.0);

  // then a good input runs, with no error left over from the bad one
  errors->Clear();
  remesh->SetInputData(Dumbbell());
  remesh->SetTargetQuadCount(300);
  remesh->Update();
  EXPECT_EQ(errors->GetError(), "");
  EXPECT_GT(remesh->GetOutput()->GetNumberOfPolys(), 100);
}

TEST(vtkQuadCoverRemesh, ProgressRunsOverTheSixStagesToOne)
{
  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputData(Dumbbell());
  remesh->SetTargetQuadCount(300);
  vtkNew<ProgressLog> log;
  remesh->AddObserver(vtkCommand::ProgressEvent, log);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  ASSERT_GT(log->Values.size(), 12u);
  for (std::size_t i = 1; i < log->Values.size(); ++i)
  {
    // each stage starts at its sixth (the executive reports 0 when a stage starts)
    EXPECT_GE(log->Values[i], log->Values[i - 1] - 1e-12) << "at report " << i;
  }
  EXPECT_EQ(log->Values.back(), 1.0);
  // every sixth was passed
  for (int stage = 1; stage < 6; ++stage)
  {
    bool seen = false;
    for (double v : log->Values)
    {
      seen = seen || (v >= stage / 6.0 - 1e-12 && v < (stage + 1) / 6.0);
    }
    EXPECT_TRUE(seen) << "no progress in stage " << stage;
  }
}

TEST(vtkQuadCoverRemesh, ASurfaceInPiecesIsRemeshedWholeOnPieceZero)
{
  // a source that gives pieces: half a sphere for piece 0 of 2
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(40);
  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputConnection(sphere->GetOutputPort());
  remesh->SetTargetQuadCount(300);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(remesh), "");
  const vtkIdType whole = remesh->GetOutput()->GetNumberOfPolys();
  ASSERT_GT(whole, 150);

  remesh->UpdatePiece(0, 2, 1);
  EXPECT_EQ(remesh->GetOutput()->GetNumberOfPolys(), whole);
  remesh->UpdatePiece(1, 2, 1);
  EXPECT_EQ(remesh->GetOutput()->GetNumberOfCells(), 0);

  // the stages do the same: the chain's last stage asked for piece 0 of 2 gives the whole
  // surface's quads, for piece 1 nothing
  Stages stages(sphere->GetOutputPort());
  stages.solver->SetTargetQuadCount(300);
  vtkQuadExtractor* extractor = stages.extractor;
  extractor->UpdatePiece(0, 2, 1);
  EXPECT_EQ(extractor->GetOutput()->GetNumberOfPolys(), whole);
  extractor->UpdatePiece(1, 2, 1);
  EXPECT_EQ(extractor->GetOutput()->GetNumberOfCells(), 0);
  // upstream of an empty piece only the piece was read, and nothing computed from it
  EXPECT_EQ(stages.solver->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_LT(sphere->GetOutput()->GetNumberOfCells(), 40 * 38 * 2 / 2 + 100);
}

namespace
{
class AbortAt : public vtkCommand
{
public:
  static AbortAt* New() { return new AbortAt; }
  void Execute(vtkObject* caller, unsigned long, void* callData) override
  {
    if (*static_cast<double*>(callData) >= 0.4)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      ++this->Requests;
    }
  }
  int Requests = 0;
};
}

TEST(vtkQuadCoverRemesh, AbortLeavesNoResultNoErrorAndTheNextRunWhole)
{
  vtkNew<vtkQuadCoverRemesh> remesh;
  remesh->SetInputData(Dumbbell());
  remesh->SetTargetQuadCount(300);
  vtkNew<AbortAt> abort;
  const unsigned long tag = remesh->AddObserver(vtkCommand::ProgressEvent, abort);
  vtkNew<vtkQuadCoverErrorObserver> errors;
  errors->Attach(remesh);
  remesh->Update();
  EXPECT_GE(abort->Requests, 1);
  EXPECT_EQ(errors->GetError(), "");
  EXPECT_EQ(remesh->GetOutput()->GetNumberOfCells(), 0);

  // the next request runs in full, whatever the executive did with the stages' abort flags
  remesh->RemoveObserver(tag);
  remesh->AbortExecuteOff();
  remesh->Modified();
  remesh->Update();
  EXPECT_EQ(errors->GetError(), "");
  EXPECT_GT(remesh->GetOutput()->GetNumberOfPolys(), 150);
}

TEST(vtkQuadCoverRemesh, AStageOutlivesItsRemesh)
{
  vtkSmartPointer<vtkQuadCoverRemesh> remesh = vtkSmartPointer<vtkQuadCoverRemesh>::New();
  remesh->SetInputData(Dumbbell());
  remesh->SetTargetQuadCount(300);
  remesh->Update();
  vtkSmartPointer<vtkQuadCoverSolver> solver = remesh->GetSolver();
  remesh = nullptr; // the stage must no longer report to it
  solver->SetTargetQuadCount(400);
  solver->Update();
  EXPECT_GT(solver->GetOutput()->GetNumberOfCells(), 0);
}

TEST(vtkQuadCoverRemesh, TheBranchPointPortInPieces)
{
  // the matching builder asked for its port 1 in pieces decides by port 1's request
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(40);
  Stages stages(sphere->GetOutputPort());
  vtkMatchingBuilder* matching = stages.matching;
  vtkNew<vtkQuadCoverErrorObserver> errors;
  errors->Attach(matching);
  matching->Update(1);
  const vtkIdType whole =
    vtkPolyData::SafeDownCast(matching->GetOutputDataObject(1))->GetNumberOfPoints();
  ASSERT_EQ(whole, 8);            // a sphere: eight +1/4 points
  matching->UpdatePiece(1, 2, 0); // port 0's last request: piece 1, which must not decide port 1
  for (int piece : { 1, 0 })
  {
    SCOPED_TRACE(piece);
    vtkStreamingDemandDrivenPipeline* exec =
      vtkStreamingDemandDrivenPipeline::SafeDownCast(matching->GetExecutive());
    vtkInformation* port1 = exec->GetOutputInformation(1);
    port1->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), piece);
    port1->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 2);
    port1->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    exec->Update(1);
    EXPECT_EQ(errors->GetError(), "");
    EXPECT_EQ(vtkPolyData::SafeDownCast(matching->GetOutputDataObject(1))->GetNumberOfPoints(),
      piece == 0 ? whole : 0);
  }
}
