// vtkFrameSmoother and vtkMatchingBuilder through VTK: properties, errors, the array contract,
// the branch-point output, and the whole chain on every generated and shared surface.
#include "TestSurfaceFiles.h"

#include "vtkCellData.h"
#include "vtkCurvatureFrames.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFrameSmoother.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include "CutGraph.h"
#include "FrameField.h"
#include "MeshTopology.h"
#include "Surfaces.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace names = vtkQuadCoverArrayNames;

namespace
{
struct Chain
{
  vtkNew<vtkCurvatureFrames> curvature;
  vtkNew<vtkFrameSmoother> smoother;
  vtkNew<vtkMatchingBuilder> matching;
  vtkNew<vtkQuadCoverErrorObserver> errors;

  explicit Chain(vtkPolyData* surface)
  {
    // The default chain: no array selection anywhere.
    curvature->SetInputData(surface);
    smoother->SetInputConnection(curvature->GetOutputPort());
    matching->SetInputConnection(smoother->GetOutputPort());
    errors->Attach(curvature);
    errors->Attach(smoother);
    errors->Attach(matching);
  }
  vtkPolyData* Run()
  {
    matching->Update();
    return matching->GetOutput();
  }
};

double IndexSum(vtkPolyData* out)
{
  vtkDataArray* index = out->GetPointData()->GetArray(names::SingularityIndex);
  double sum = 0.0;
  for (vtkIdType p = 0; p < index->GetNumberOfTuples(); ++p)
  {
    sum += index->GetTuple1(p);
  }
  return sum;
}

double Field(vtkPolyData* out, const char* name, int i = 0)
{
  vtkDataArray* a = out->GetFieldData()->GetArray(name);
  return a ? a->GetComponent(0, i) : std::nan("");
}
}

TEST(vtkFrameSmoother, DefaultsClampsAndPrintSelf)
{
  vtkNew<vtkFrameSmoother> f;
  EXPECT_EQ(f->GetSmoothingWeight(), 0.95);
  EXPECT_EQ(f->GetMaximumNumberOfIterations(), 200);
  EXPECT_EQ(f->GetFeatureAngle(), 60.0);
  EXPECT_EQ(f->GetMinimumFeatureLength(), 3);
  EXPECT_TRUE(f->GetAlignToFeatures());
  EXPECT_TRUE(f->GetAlignToBoundary());
  EXPECT_TRUE(f->GetGlobalStart());
  EXPECT_EQ(f->GetCoherenceRadius(), 0.1);
  f->SetCoherenceRadius(-1.0);
  EXPECT_EQ(f->GetCoherenceRadius(), 0.0);
  f->SetCoherenceRadius(20.0);
  EXPECT_EQ(f->GetCoherenceRadius(), 10.0);
  f->SetSmoothingWeight(2.0);
  EXPECT_EQ(f->GetSmoothingWeight(), 1.0);
  f->SetFeatureAngle(-5.0);
  EXPECT_EQ(f->GetFeatureAngle(), 0.0);
  EXPECT_EQ(f->GetNumberOfThreads(), 0);
  f->SetNumberOfThreads(2000);
  EXPECT_EQ(f->GetNumberOfThreads(), 1024);
  std::ostringstream os;
  f->Print(os);
  for (const char* p : { "SmoothingWeight: 1", "FeatureAngle: 0", "AlignToBoundary: On",
         "CoherenceRadius: 10", "NumberOfThreads: 1024" })
  {
    EXPECT_NE(os.str().find(p), std::string::npos) << p;
  }
}

TEST(vtkMatchingBuilder, DefaultsClampsAndPrintSelf)
{
  vtkNew<vtkMatchingBuilder> m;
  EXPECT_FALSE(m->GetOptimizeBranchPoints());
  EXPECT_EQ(m->GetBranchPointWeight(), 4.0);
  EXPECT_EQ(m->GetNumberOfOutputPorts(), 2);
  m->SetBranchPointWeight(-1.0);
  EXPECT_EQ(m->GetBranchPointWeight(), 0.0);
  std::ostringstream os;
  m->Print(os);
  EXPECT_NE(os.str().find("OptimizeBranchPoints: Off"), std::string::npos);
}

TEST(vtkFrameStages, MissingFramesAndBadSurfacesAreErrors)
{
  vtkSmartPointer<vtkPolyData> bare = vtkQuadCoverEigen::ToPolyData(
    quadcover::makeIcosphere(1.0, 2).V, quadcover::makeIcosphere(1.0, 2).F);
  for (int which = 0; which < 2; ++which)
  {
    vtkSmartPointer<vtkPolyDataAlgorithm> f;
    if (which == 0)
      f = vtkSmartPointer<vtkFrameSmoother>::New();
    else
      f = vtkSmartPointer<vtkMatchingBuilder>::New();
    vtkNew<vtkQuadCoverErrorObserver> errors;
    errors->Attach(f);
    f->SetInputData(bare);
    f->Update();
    EXPECT_NE(errors->GetError().find("no 3-component cell array FrameU"), std::string::npos)
      << errors->GetError();
  }
  // A bowtie: fine for smoothing (a warning), refused by the matchings (no one-ring).
  Eigen::MatrixX3d V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0;
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 3, 4;
  Chain chain(vtkQuadCoverEigen::ToPolyData(V, F));
  chain.Run();
  EXPECT_NE(chain.errors->GetError().find("non-manifold vertices"), std::string::npos)
    << chain.errors->GetError();
}

TEST(vtkFrameStages, ArraysOfTheChain)
{
  const quadcover::Surface s = quadcover::makeRoundedCube(0.0, 6);
  Chain chain(vtkQuadCoverEigen::ToPolyData(s.V, s.F));
  vtkPolyData* out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  const vtkIdType nf = out->GetNumberOfCells(), nv = out->GetNumberOfPoints();
  // Smoother's arrays.
  vtkPolyData* smoothed = chain.smoother->GetOutput();
  EXPECT_TRUE(vtkDoubleArray::SafeDownCast(smoothed->GetCellData()->GetArray(names::FrameU)));
  EXPECT_TRUE(
    vtkDoubleArray::SafeDownCast(smoothed->GetCellData()->GetArray(names::FrameRotation)));
  EXPECT_TRUE(
    vtkUnsignedCharArray::SafeDownCast(smoothed->GetCellData()->GetArray(names::FrameConstrained)));
  vtkDoubleArray* coherence =
    vtkDoubleArray::SafeDownCast(smoothed->GetCellData()->GetArray(names::FrameCoherence));
  ASSERT_NE(coherence, nullptr);
  EXPECT_EQ(coherence->GetNumberOfTuples(), smoothed->GetNumberOfCells());
  double range[2];
  coherence->GetRange(range);
  EXPECT_GE(range[0], 0.0);
  EXPECT_LE(range[1], 1.0);
  EXPECT_EQ(smoothed->GetFieldData()->GetArray(names::SmoothingEnergy)->GetNumberOfTuples(), 2);
  EXPECT_LT(Field(smoothed, names::SmoothingEnergy, 1), Field(smoothed, names::SmoothingEnergy, 0));
  // The curvature stage's arrays pass through untouched except the frames.
  EXPECT_NE(out->GetCellData()->GetArray(names::PrincipalCurvatures), nullptr);
  // Matching builder's.
  vtkIntArray* matching = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray(names::Matching));
  ASSERT_NE(matching, nullptr);
  EXPECT_EQ(matching->GetNumberOfComponents(), 3);
  EXPECT_EQ(matching->GetNumberOfTuples(), nf);
  vtkIntArray* shift = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray(names::LayerShift));
  ASSERT_NE(shift, nullptr);
  EXPECT_EQ(shift->GetNumberOfTuples(), nv);
  EXPECT_TRUE(vtkDoubleArray::SafeDownCast(out->GetPointData()->GetArray(names::SingularityIndex)));
  // The paper's Fig. 4: eight corners of layer shift 1, index 1/4, and nothing else.
  EXPECT_EQ(Field(out, names::SingularityCount), 8);
  EXPECT_EQ(Field(out, names::BranchPointCount, 1), 8);
  vtkDataArray* histogram = out->GetFieldData()->GetArray(names::SingularityHistogram);
  ASSERT_EQ(histogram->GetNumberOfTuples(), 1);
  EXPECT_EQ(histogram->GetComponent(0, 0), 0.25);
  EXPECT_EQ(histogram->GetComponent(0, 1), 8);
  // The branch points as their own output, at the cube's corners.
  vtkPolyData* branches = chain.matching->GetBranchPointsOutput();
  ASSERT_EQ(branches->GetNumberOfPoints(), 8);
  EXPECT_EQ(branches->GetNumberOfVerts(), 8);
  vtkIdTypeArray* ids =
    vtkIdTypeArray::SafeDownCast(branches->GetPointData()->GetArray(names::SurfacePointId));
  ASSERT_NE(ids, nullptr);
  for (vtkIdType i = 0; i < 8; ++i)
  {
    double p[3];
    branches->GetPoint(i, p);
    EXPECT_NEAR(std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]), 3.0, 1e-12);
    EXPECT_EQ(shift->GetValue(ids->GetValue(i)), 1);
    EXPECT_EQ(branches->GetPointData()->GetArray(names::LayerShift)->GetTuple1(i), 1);
  }
  // Matchings seen from both sides are inverse; boundary-free so no -1.
  EXPECT_GE(matching->GetValueRange()[0], 0);
  const quadcover::MeshTopology topo =
    quadcover::buildTopology(vtkQuadCoverEigen::Triangles(out), static_cast<int>(nv));
  for (vtkIdType f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      for (int kk = 0; kk < 3; ++kk)
      {
        if (topo.faceNeighbors(g, kk) == f)
        {
          ASSERT_EQ(
            (matching->GetTypedComponent(f, k) + matching->GetTypedComponent(g, kk)) % 4, 0);
        }
      }
    }
  }
}

TEST(vtkMatchingBuilder, BoundaryToleranceReachesTheTwistCheck)
{
  // On the tube whose cheaper merge would leave its boundary circles on different frame
  // families (TestSurfaces.h), the twist check undoes that merge when the frames along the
  // circles count as following them (within BoundaryTolerance degrees), and the pair stays; at 0
  // degrees none does, and the cheaper merge stays. So for one of the two sides the matchings
  // differ.
  const quadcover::Surface tube = quadcover::twistTube();
  const quadcover::MeshTopology topo =
    quadcover::buildTopology(tube.F, static_cast<int>(tube.V.rows()));
  const Eigen::MatrixX3d normal = quadcover::computeFaceBases(tube.V, tube.F, topo).normal;
  int differ = 0;
  for (const double offset : { 0.3, -0.3 })
  {
    vtkSmartPointer<vtkPolyData> pd = vtkQuadCoverEigen::ToPolyData(tube.V, tube.F);
    pd->GetCellData()->AddArray(
      vtkQuadCoverEigen::ToArray(quadcover::twistTubeFrames(tube, normal, offset), names::FrameU));
    Eigen::MatrixXd matching[2];
    for (int run = 0; run < 2; ++run)
    {
      vtkNew<vtkMatchingBuilder> m;
      m->SetInputData(pd);
      m->OptimizeBranchPointsOn();
      m->SetBranchPointWeight(100.0); // merge if at all possible
      m->SetBoundaryTolerance(run == 0 ? 10.0 : 0.0);
      vtkNew<vtkQuadCoverErrorObserver> errors;
      errors->Attach(m);
      m->Update();
      ASSERT_EQ(errors->GetError(), "");
      if (run == 1)
      {
        EXPECT_EQ(Field(m->GetOutput(), names::SingularityCount), 0) << "nothing stops the merge";
      }
      matching[run] =
        vtkQuadCoverEigen::FromArray(m->GetOutput()->GetCellData()->GetArray(names::Matching));
    }
    differ += matching[0] != matching[1];
  }
  EXPECT_EQ(differ, 1);
}

// ---- Poincare-Hopf through the whole chain on every surface ----

class ChainOn : public ::testing::TestWithParam<const char*>
{};

TEST_P(ChainOn, IndicesSumToTheEulerCharacteristic)
{
  const std::string name = GetParam();
  std::string path;
  vtkSmartPointer<vtkPolyData> surface = LoadTestSurface(name, path);
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << "mesh not found: " << path;
  }
  ASSERT_TRUE(surface) << path;
  const bool shared = path.rfind(QUADCOVER_SHARED_DATA, 0) == 0;
  const quadcover::MeshTopology topo = quadcover::buildTopology(
    vtkQuadCoverEigen::Triangles(surface), static_cast<int>(surface->GetNumberOfPoints()));

  Chain chain(surface);
  chain.matching->OptimizeBranchPointsOff();
  vtkPolyData* before = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_NEAR(IndexSum(before), topo.eulerCharacteristic(), 1e-9);
  const double branchesBefore = Field(before, names::BranchPointCount, 1);
  const double singularBefore = Field(before, names::SingularityCount);
  const double costBefore = Field(before, names::BranchPointObjective, 1);
  double largestBefore = 0.0;
  // Inner points of index k/4 >= 3/4 are split into k quarters even without the optimization (no
  // quad mesh has a vertex of valence 1 or 0); those of index 1/2 the optimization splits into
  // two (one more singular point, two more branch points): the merges start from there.
  double splitMore = 0.0, splitBranches = 0.0;
  {
    vtkDataArray* index = before->GetPointData()->GetArray(names::SingularityIndex);
    for (vtkIdType p = 0; p < index->GetNumberOfTuples(); ++p)
    {
      if (topo.boundaryVertex[p])
        continue;
      const double i = index->GetTuple1(p);
      largestBefore = std::max(largestBefore, std::abs(i));
      const long k = std::lround(4 * i);
      EXPECT_LT(k, 3) << "point " << p << " of index " << i << " was not split";
      if (k >= 2)
      {
        splitMore += static_cast<double>(k - 1);
        splitBranches += static_cast<double>(k) - (k % 4 != 0 ? 1.0 : 0.0);
      }
    }
  }

  chain.matching->OptimizeBranchPointsOn();
  vtkPolyData* after = chain.Run();
  EXPECT_NEAR(IndexSum(after), topo.eulerCharacteristic(), 1e-9);
  const double branchesAfter = Field(after, names::BranchPointCount, 1);
  const double singularAfter = Field(after, names::SingularityCount);
  const double costAfter = Field(after, names::BranchPointObjective, 1);
  // both runs start from the smallest-angle matchings (without the optimization, whole turns
  // are split all the same: costBefore is then that field's)
  const double smallestAngle = Field(before, names::BranchPointObjective, 0);
  EXPECT_NEAR(
    Field(after, names::BranchPointObjective, 0), smallestAngle, 1e-9 * (1 + smallestAngle));
  EXPECT_LE(branchesAfter, branchesBefore + splitBranches);
  EXPECT_LE(singularAfter, singularBefore + splitMore);
  if (shared)
  {
    // Every shared mesh has pairs to cancel (Documentation/Algorithms.md, the singularity table:
    // bunny-lowres 44 -> 24 with the merges).
    EXPECT_LT(singularAfter, singularBefore + splitMore);
  }
  if (splitMore == 0)
  {
    // the split itself costs; the merges only ever lower the objective
    EXPECT_LE(costAfter, costBefore + 1e-9);
  }
  std::printf("[ %s ] chi %d, branch points %g -> %g, singularities %g -> %g, smoothing %g -> %g\n",
    name.c_str(), topo.eulerCharacteristic(), branchesBefore, branchesAfter, singularBefore,
    singularAfter, Field(chain.smoother->GetOutput(), names::SmoothingEnergy, 0),
    Field(chain.smoother->GetOutput(), names::SmoothingEnergy, 1));
  // Inner indices are quarters and match the layer shifts; no merge made one larger than any
  // the field had.
  vtkDataArray* index = after->GetPointData()->GetArray(names::SingularityIndex);
  vtkDataArray* shift = after->GetPointData()->GetArray(names::LayerShift);
  for (vtkIdType p = 0; p < index->GetNumberOfTuples(); ++p)
  {
    if (topo.boundaryVertex[p])
      continue;
    ASSERT_LE(std::abs(index->GetTuple1(p)), largestBefore) << p;
    const double q = 4.0 * index->GetTuple1(p);
    ASSERT_EQ(q, std::round(q)) << p;
    ASSERT_EQ(static_cast<int>(shift->GetTuple1(p)), ((static_cast<int>(q) % 4) + 4) % 4) << p;
  }
  // The cut graph through the singular points makes every component a disk (genus-0 closed
  // components have at least two singular points by Poincare-Hopf with quarter indices).
  std::vector<char> terminal(topo.numVertices, 0);
  for (vtkIdType p = 0; p < index->GetNumberOfTuples(); ++p)
  {
    terminal[p] = !topo.boundaryVertex[p] && index->GetTuple1(p) != 0.0;
  }
  const quadcover::CutGraph cut = quadcover::computeCutGraph(topo, terminal);
  for (int c = 0; c < topo.numComponents(); ++c)
  {
    EXPECT_EQ(cut.cutEuler[c], 1) << name << " component " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(Surfaces, ChainOn,
  ::testing::Values("sphere", "torus", "knot", "cylinder", "roundedcube", "bunny-lowres", "spot",
    "fandisk", "rocker-arm", "cheburashka", "teapot"));
