// vtkQuadCoverSolver through VTK: properties, errors, the array contract, the SplitSeams
// output, and the whole chain on every generated and shared surface at about 3,000 quads:
// seamless, branch points on the grid, no flipped triangle.
#include "TestSurfaceFiles.h"

#include "vtkCellData.h"
#include "vtkCurvatureFrames.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFrameSmoother.h"
#include "vtkIntArray.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverSolver.h"
#include "vtkTriangle.h"

#include "GridMapChecks.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "Surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace names = vtkQuadCoverArrayNames;
using namespace quadcover;

namespace
{
struct Chain
{
  vtkNew<vtkCurvatureFrames> curvature;
  vtkNew<vtkFrameSmoother> smoother;
  vtkNew<vtkMatchingBuilder> matching;
  vtkNew<vtkQuadCoverSolver> solver;
  vtkNew<vtkQuadCoverErrorObserver> errors;

  explicit Chain(vtkPolyData* surface)
  {
    curvature->SetInputData(surface);
    smoother->SetInputConnection(curvature->GetOutputPort());
    matching->SetInputConnection(smoother->GetOutputPort());
    solver->SetInputConnection(matching->GetOutputPort());
    for (vtkAlgorithm* a :
      std::initializer_list<vtkAlgorithm*>{ curvature, smoother, matching, solver })
    {
      errors->Attach(a);
    }
  }
  vtkPolyData* Run()
  {
    solver->Update();
    return solver->GetOutput();
  }
};

double Field(vtkPolyData* out, const char* name, int i = 0)
{
  vtkDataArray* a = out->GetFieldData()->GetArray(name);
  return a && i < a->GetNumberOfTuples() ? a->GetComponent(i, 0) : std::nan("");
}

Eigen::MatrixXd CornerUV(vtkPolyData* out)
{
  vtkDataArray* a = out->GetCellData()->GetArray(names::CornerUV);
  Eigen::MatrixXd uv(a->GetNumberOfTuples(), 6);
  for (vtkIdType f = 0; f < a->GetNumberOfTuples(); ++f)
  {
    for (int c = 0; c < 6; ++c)
    {
      uv(f, c) = a->GetComponent(f, c);
    }
  }
  return uv;
}

}

TEST(vtkQuadCoverSolver, DefaultsClampsAndPrintSelf)
{
  vtkNew<vtkQuadCoverSolver> s;
  EXPECT_EQ(s->GetTargetEdgeLength(), 0.0);
  EXPECT_EQ(s->GetTargetQuadCount(), 3000);
  EXPECT_TRUE(s->GetPureQuads());
  EXPECT_EQ(s->GetRoundingMode(), vtkQuadCoverSolver::ROUNDING_GREEDY);
  EXPECT_TRUE(s->GetAlignToBoundary());
  EXPECT_FALSE(s->GetSplitSeams());
  s->SetTargetQuadCount(0);
  EXPECT_EQ(s->GetTargetQuadCount(), 1);
  s->SetRoundingMode(7);
  EXPECT_EQ(s->GetRoundingMode(), vtkQuadCoverSolver::ROUNDING_GREEDY);
  s->SetRoundingModeToSimple();
  EXPECT_EQ(s->GetRoundingMode(), vtkQuadCoverSolver::ROUNDING_SIMPLE);
  s->SetBoundaryTolerance(90.0);
  EXPECT_EQ(s->GetBoundaryTolerance(), 45.0);
  EXPECT_EQ(s->GetMaximumThinStripRefinement(),
    8.0); // ParameterizationOptions::maximumThinStripRefinement
  s->SetMaximumThinStripRefinement(0.5);
  EXPECT_EQ(s->GetMaximumThinStripRefinement(), 1.0);
  s->SetMaximumThinStripRefinement(4.0);
  std::ostringstream os;
  s->Print(os);
  EXPECT_NE(os.str().find("MaximumThinStripRefinement: 4"), std::string::npos);
  EXPECT_EQ(s->GetAdaptiveCurvature(), 0.0); // ParameterizationOptions::adaptiveCurvature
  s->SetAdaptiveCurvature(-1.0);
  EXPECT_EQ(s->GetAdaptiveCurvature(), 0.0);
  s->SetAdaptiveCurvature(0.5);
  std::ostringstream adaptive;
  s->Print(adaptive);
  EXPECT_NE(adaptive.str().find("AdaptiveCurvature: 0.5"), std::string::npos);
  EXPECT_EQ(s->GetDefectGridRefinement(), 2.0); // ParameterizationOptions::defectGridRefinement
  s->SetDefectGridRefinement(20.0);
  EXPECT_EQ(s->GetDefectGridRefinement(), 8.0);
  std::ostringstream again;
  s->Print(again);
  EXPECT_NE(again.str().find("DefectGridRefinement: 8"), std::string::npos);
  // ParameterizationOptions::defectAdaptiveCurvature
  EXPECT_EQ(s->GetDefectAdaptiveCurvature(), 1.5);
  s->SetDefectAdaptiveCurvature(11.0);
  EXPECT_EQ(s->GetDefectAdaptiveCurvature(), 10.0);
  s->SetDefectAdaptiveCurvature(0.0);
  std::ostringstream curved;
  s->Print(curved);
  EXPECT_NE(curved.str().find("DefectAdaptiveCurvature: 0"), std::string::npos);
  // ParameterizationOptions::maximumFinerGridRetries
  EXPECT_EQ(s->GetMaximumFinerGridRetries(), 2);
  s->SetMaximumFinerGridRetries(9);
  EXPECT_EQ(s->GetMaximumFinerGridRetries(), 4);
  s->SetMaximumFinerGridRetries(0);
  std::ostringstream retries;
  s->Print(retries);
  EXPECT_NE(retries.str().find("MaximumFinerGridRetries: 0"), std::string::npos);
  // ParameterizationOptions::minimumQuadsPerSingularity
  EXPECT_EQ(s->GetMinimumQuadsPerSingularity(), 4.0);
  s->SetMinimumQuadsPerSingularity(-1.0);
  EXPECT_EQ(s->GetMinimumQuadsPerSingularity(), 0.0);
  std::ostringstream singular;
  s->Print(singular);
  EXPECT_NE(singular.str().find("MinimumQuadsPerSingularity: 0"), std::string::npos);
  EXPECT_NE(os.str().find("RoundingMode: Simple"), std::string::npos);
  EXPECT_NE(os.str().find("PureQuads: On"), std::string::npos);
}

TEST(vtkQuadCoverSolver, MissingOrBrokenArraysAreErrors)
{
  const Surface sphere = makeIcosphere(1.0, 2);
  vtkSmartPointer<vtkPolyData> bare = vtkQuadCoverEigen::ToPolyData(sphere.V, sphere.F);
  {
    vtkNew<vtkQuadCoverSolver> s;
    vtkNew<vtkQuadCoverErrorObserver> errors;
    errors->Attach(s);
    s->SetInputData(bare);
    s->Update();
    EXPECT_NE(errors->GetError().find("no 3-component cell array FrameU"), std::string::npos)
      << errors->GetError();
  }
  Chain chain(bare);
  chain.matching->Update();
  vtkNew<vtkPolyData> noMatching;
  noMatching->DeepCopy(chain.matching->GetOutput());
  noMatching->GetCellData()->RemoveArray(names::Matching);
  {
    vtkNew<vtkQuadCoverSolver> s;
    vtkNew<vtkQuadCoverErrorObserver> errors;
    errors->Attach(s);
    s->SetInputData(noMatching);
    s->Update();
    EXPECT_NE(errors->GetError().find("no 3-component cell array Matching"), std::string::npos)
      << errors->GetError();
  }
  for (int broken : { 5, 1 }) // out of range; a valid value that is not its twin's inverse
  {
    vtkNew<vtkPolyData> bad;
    bad->DeepCopy(chain.matching->GetOutput());
    vtkIntArray* m = vtkIntArray::SafeDownCast(bad->GetCellData()->GetArray(names::Matching));
    m->SetTypedComponent(0, 0, broken == 5 ? 5 : (m->GetTypedComponent(0, 0) + 1) % 4);
    vtkNew<vtkQuadCoverSolver> s;
    vtkNew<vtkQuadCoverErrorObserver> errors;
    errors->Attach(s);
    s->SetInputData(bad);
    s->Update();
    EXPECT_NE(errors->GetError().find("Cannot parameterize"), std::string::npos)
      << errors->GetError();
    EXPECT_NE(errors->GetError().find(broken == 5 ? "must be 0, 1, 2 or 3" : "not inverse"),
      std::string::npos)
      << errors->GetError();
  }
}

TEST(vtkQuadCoverSolver, SolveSecondsAreKeptOutOfTheOutput)
{
  const Surface sphere = makeIcosphere(1.0, 2);
  Chain chain(vtkQuadCoverEigen::ToPolyData(sphere.V, sphere.F));
  EXPECT_EQ(chain.solver->GetNumberOfSolves(), 0) << "before an update";
  vtkPolyData* out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  // greedy rounding: the continuous solve, then the solve with the integers fixed
  ASSERT_GE(chain.solver->GetNumberOfSolves(), 2);
  for (int i = 0; i < chain.solver->GetNumberOfSolves(); ++i)
  {
    EXPECT_GE(chain.solver->GetSolveSeconds(i), 0.0);
  }
  EXPECT_EQ(chain.solver->GetSolveSeconds(-1), 0.0);
  EXPECT_EQ(chain.solver->GetSolveSeconds(chain.solver->GetNumberOfSolves()), 0.0);
  // no array of the output holds a time
  vtkFieldData* fd = out->GetFieldData();
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
  {
    const std::string name = fd->GetArrayName(i) ? fd->GetArrayName(i) : "";
    EXPECT_EQ(name.find("Seconds"), std::string::npos) << name;
  }
  // a failed update leaves no solves behind
  vtkNew<vtkPolyData> noMatching;
  noMatching->DeepCopy(chain.matching->GetOutput());
  noMatching->GetCellData()->RemoveArray(names::Matching);
  chain.solver->SetInputData(noMatching);
  chain.solver->Update();
  EXPECT_NE(chain.errors->GetError(), "");
  EXPECT_EQ(chain.solver->GetNumberOfSolves(), 0);
}

TEST(vtkQuadCoverSolver, SplitSeamsCutsTheSurfaceOpenWithTextureCoordinates)
{
  const Surface knot = makeKnotTube(2, 3, 1.0, 0.4, 0.12, 240, 20, 0.3, 0.03, 7);
  Chain chain(vtkQuadCoverEigen::ToPolyData(knot.V, knot.F));
  vtkNew<vtkPolyData> whole;
  whole->DeepCopy(chain.Run());
  chain.solver->SplitSeamsOn();
  vtkPolyData* split = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_EQ(split->GetNumberOfPolys(), whole->GetNumberOfPolys());
  EXPECT_GT(split->GetNumberOfPoints(), whole->GetNumberOfPoints()) << "seams double points";
  vtkDataArray* tc = split->GetPointData()->GetTCoords();
  ASSERT_NE(tc, nullptr);
  EXPECT_STREQ(tc->GetName(), names::UV);
  vtkDataArray* ids = split->GetPointData()->GetArray(names::SurfacePointId);
  ASSERT_NE(ids, nullptr);
  // the map's singularities, per sector those of its point
  vtkDataArray* shiftSplit = split->GetPointData()->GetArray(names::LayerShift);
  vtkDataArray* shiftWhole = whole->GetPointData()->GetArray(names::LayerShift);
  ASSERT_NE(shiftSplit, nullptr);
  ASSERT_NE(shiftWhole, nullptr);
  const Eigen::MatrixXd uv = CornerUV(split);
  const Eigen::MatrixX3i Fs = vtkQuadCoverEigen::Triangles(split);
  const Eigen::MatrixX3i Fw = vtkQuadCoverEigen::Triangles(whole);
  for (int f = 0; f < Fs.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType p = Fs(f, k);
      ASSERT_EQ(ids->GetTuple1(p), Fw(f, k)) << "same triangle, same original point";
      ASSERT_EQ(shiftSplit->GetTuple1(p), shiftWhole->GetTuple1(Fw(f, k)));
      ASSERT_EQ(tc->GetComponent(p, 0), uv(f, 2 * k));
      ASSERT_EQ(tc->GetComponent(p, 1), uv(f, 2 * k + 1));
      double a[3], b[3];
      split->GetPoint(p, a);
      whole->GetPoint(Fw(f, k), b);
      ASSERT_EQ(a[0], b[0]);
      ASSERT_EQ(a[1], b[1]);
      ASSERT_EQ(a[2], b[2]);
    }
  }
  // the cut-open surface has no seam left: its own edges are smooth in (u, v)
  const MeshTopology topo = buildTopology(Fs, static_cast<int>(split->GetNumberOfPoints()));
  EXPECT_EQ(checks::seamViolations(Fs, topo, uv, 0.0), 0);
  EXPECT_EQ(topo.numComponents(), 1);
  EXPECT_EQ(topo.components[0].eulerCharacteristic, 1) << "a disk";
}

/// A closed coin: a regular n-gon of radius 1 and height h, each cap a fan of slivers from its
/// first corner, the side split into n quads of two triangles each.
Surface fanCoin(int n, double h)
{
  Surface s;
  s.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * M_PI * i / n;
    s.V.row(i) << std::cos(a), std::sin(a), 0.0;
    s.V.row(n + i) << std::cos(a), std::sin(a), h;
  }
  std::vector<Eigen::RowVector3i> faces;
  for (int i = 1; i + 1 < n; ++i)
  {
    faces.emplace_back(0, i + 1, i);         // bottom, facing down
    faces.emplace_back(n, n + i, n + i + 1); // top, facing up
  }
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + 1) % n;
    faces.emplace_back(i, j, n + j);
    faces.emplace_back(i, n + j, n + i);
  }
  s.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    s.F.row(static_cast<Eigen::Index>(f)) = faces[f];
  }
  return s;
}

TEST(vtkQuadCoverSolver, LongEdgesAreSplitBeforeTheMapCarryingTheArrays)
{
  const Surface coin = fanCoin(48, 0.2);
  vtkSmartPointer<vtkPolyData> surface = vtkQuadCoverEigen::ToPolyData(coin.V, coin.F);
  vtkNew<vtkDoubleArray> height; // a linear function: interpolated exactly at midpoints
  height->SetName("Height");
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    height->InsertNextValue(coin.V(p, 2));
  }
  surface->GetPointData()->AddArray(height);
  Chain chain(surface);
  chain.solver->SetTargetQuadCount(2000);
  chain.solver->SetMaximumTriangleEdge(0.0);
  const vtkIdType cells = chain.Run()->GetNumberOfPolys();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_EQ(cells, coin.F.rows()) << "0: the surface as it came";
  EXPECT_EQ(Field(chain.solver->GetOutput(), names::GridRefinedTriangles), 0.0);

  chain.solver->SetMaximumTriangleEdge(3.0);
  vtkPolyData* out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_EQ(Field(out, names::GridRefinedTriangles), static_cast<double>(coin.F.rows()))
    << "every triangle has an edge longer than 3 grid edges";
  ASSERT_GT(out->GetNumberOfPolys(), coin.F.rows());
  const Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(out);
  const double h = std::sqrt(surfaceArea(coin.V, coin.F) / 2000.0);
  const Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(out);
  for (Eigen::Index c = 0; c < F.rows(); ++c)
  {
    const Eigen::RowVector3i t = F.row(c);
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_LE((V.row(t[k]) - V.row(t[(k + 1) % 3])).norm(), 3.0 * h) << "triangle " << c;
    }
  }
  EXPECT_EQ(V.topRows(coin.V.rows()), coin.V) << "the input's points first, as they were";
  vtkDataArray* carried = out->GetPointData()->GetArray("Height");
  ASSERT_NE(carried, nullptr);
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    ASSERT_NEAR(carried->GetTuple1(p), V(p, 2), 1e-12) << "point " << p;
  }
  const MeshTopology topo = buildTopology(F, static_cast<int>(V.rows()));
  EXPECT_TRUE(topo.isManifold());
  EXPECT_EQ(topo.eulerCharacteristic(), 2);
  vtkDataArray* m = out->GetCellData()->GetArray(names::Matching);
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->GetNumberOfTuples(), out->GetNumberOfPolys()) << "Matching rewritten";
  Eigen::MatrixX3i matching(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      matching(f, k) = static_cast<int>(m->GetComponent(f, k));
    }
  }
  EXPECT_EQ(checkMatching(topo, matching), "");
  ASSERT_EQ(out->GetCellData()->GetArray(names::FrameU)->GetNumberOfTuples(), F.rows());
  EXPECT_EQ(checks::seamViolations(F, topo, CornerUV(out), 1e-6), 0);
}

namespace
{
/// The chain's map keeps defects, on a uniform grid.
void ExpectDefects(Chain& chain)
{
  vtkPolyData* out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_GT(Field(out, names::FlippedTriangles, 2) + Field(out, names::WindingErrors), 0)
    << "the uniform grid's map should keep defects (else the test proves nothing)";
  EXPECT_EQ(Field(out, names::FinerGridTriangles), 0);
}

/// The chain's map keeps no defect, on a grid finer somewhere, and is seamless.
void ExpectRepairedOnAFinerGrid(Chain& chain)
{
  vtkPolyData* out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_EQ(Field(out, names::FlippedTriangles, 2), 0);
  EXPECT_EQ(Field(out, names::WindingErrors), 0);
  EXPECT_GT(Field(out, names::FinerGridTriangles), 0);
  const Eigen::MatrixXd uv = CornerUV(out);
  const Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(out);
  const MeshTopology topo = buildTopology(F, static_cast<int>(out->GetNumberOfPoints()));
  EXPECT_EQ(checks::flippedTriangles(uv), 0);
  EXPECT_EQ(checks::seamViolations(F, topo, uv), 0) << "the finer grid's map is still seamless";
}
}

TEST(vtkQuadCoverSolver, AFieldOfMoreSingularitiesThanTheQuadsAskedGetsAFinerGridAndAWarning)
{
  // decimated-knight at 100 quads: its field keeps about 90 branch points, which a grid of 100
  // cells cannot hold (its quads came apart into two pieces); with MinimumQuadsPerSingularity
  // the grid has at least 4 cells each, and the solver says so.
  std::string path;
  vtkSmartPointer<vtkPolyData> surface = LoadTestSurface("decimated-knight", path);
  if (!surface)
  {
    GTEST_SKIP() << "mesh not found: " << path;
  }
  auto run = [&](double perPoint, double& cells, int& warned) {
    Chain chain(surface);
    chain.solver->SetTargetQuadCount(100);
    chain.solver->SetMinimumQuadsPerSingularity(perPoint);
    vtkPolyData* out = chain.Run();
    ASSERT_EQ(chain.errors->GetError(), "");
    const double h = out->GetFieldData()->GetArray("EdgeLength")->GetTuple1(0);
    double area = 0.0;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      double p[3][3];
      for (int k = 0; k < 3; ++k)
      {
        out->GetPoint(out->GetCell(c)->GetPointId(k), p[k]);
      }
      area += vtkTriangle::TriangleArea(p[0], p[1], p[2]);
    }
    cells = area / (h * h);
    warned = 0;
    for (int i = 0; i < chain.errors->GetNumberOfWarnings(); ++i)
    {
      warned += chain.errors->GetWarning(i).find("singular points") != std::string::npos;
    }
  };
  double without = 0.0, with = 0.0;
  int warnedWithout = 0, warnedWith = 0;
  run(0.0, without, warnedWithout);
  run(4.0, with, warnedWith);
  std::printf("cells: %.0f without the limit, %.0f with it\n", without, with);
  EXPECT_LT(without, 200.0);
  EXPECT_GT(with, 300.0) << "4 cells for each of some 90 branch points";
  EXPECT_EQ(warnedWithout, 0);
  EXPECT_EQ(warnedWith, 1);
}

TEST(vtkQuadCoverSolver, AFinerGridAroundTheDefectsRepairsTheMap)
{
  // decimated-knight at 2,500 quads: its repaired map keeps 2 defects; on a grid twice as fine
  // around them the second map keeps none (spot at 3,000 quads was the case until the cone-pair
  // gain 6 and the fit's edge weights of 2026-12-05, decimated-knight before the pairs' moves).
  // The grid is kept uniform around thin strips and walls, to test the finer grid around the
  // defects alone (the knight has a wall a third of a grid edge high).
  std::string path;
  vtkSmartPointer<vtkPolyData> surface = LoadTestSurface("decimated-knight", path);
  if (!surface)
  {
    GTEST_SKIP() << "mesh not found: " << path;
  }
  Chain chain(surface);
  chain.solver->SetTargetQuadCount(2500);
  chain.solver->SetMaximumThinStripRefinement(1.0);
  chain.solver->SetDefectAdaptiveCurvature(0.0);
  chain.solver->SetDefectGridRefinement(1.0);
  ExpectDefects(chain);
  chain.solver->SetDefectGridRefinement(2.0);
  ExpectRepairedOnAFinerGrid(chain);
}

TEST(vtkQuadCoverSolver, AnAdaptiveGridRepairsAMapThatKeepsDefects)
{
  // spot at 1,000 quads: the repaired map keeps 2 defects at its ears and horns, and so does the
  // grid twice as fine around them; on the adaptive grid (DefectAdaptiveCurvature) the map
  // keeps none.
  std::string path;
  vtkSmartPointer<vtkPolyData> surface = LoadTestSurface("spot", path);
  if (!surface)
  {
    GTEST_SKIP() << "mesh not found: " << path;
  }
  Chain chain(surface);
  chain.solver->SetTargetQuadCount(1000);
  chain.solver->SetDefectAdaptiveCurvature(0.0);
  ExpectDefects(chain);
  chain.solver->SetDefectAdaptiveCurvature(1.5);
  ExpectRepairedOnAFinerGrid(chain);
}

TEST(vtkQuadCoverSolver, AdaptiveCurvatureMakesTheGridFinerWhereTheSurfaceCurves)
{
  // the dumbbell's neck (radius 0.12 against bulbs of 0.8) at 500 quads: finer with the option,
  // a uniform grid without
  const quadcover::Surface dumbbell = quadcover::makeDumbbell(1.5, 0.8, 0.12, 48, 60);
  Chain chain(vtkQuadCoverEigen::ToPolyData(dumbbell.V, dumbbell.F));
  chain.solver->SetTargetQuadCount(500);
  vtkPolyData* out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_EQ(Field(out, names::FinerGridTriangles), 0);
  chain.solver->SetAdaptiveCurvature(0.5);
  out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  EXPECT_GT(Field(out, names::FinerGridTriangles), 0);
  EXPECT_EQ(Field(out, names::FlippedTriangles, 2), 0);
}

// ---- the whole chain on every surface ----

class ParameterizeOn : public ::testing::TestWithParam<const char*>
{};

TEST_P(ParameterizeOn, SeamlessGridMapWithBranchPointsOnTheGridAndNoFlips)
{
  std::string path;
  vtkSmartPointer<vtkPolyData> surface = LoadTestSurface(GetParam(), path);
  if (!surface)
  {
    GTEST_SKIP() << "mesh not found: " << path;
  }
  Chain chain(surface);
  vtkPolyData* out = chain.Run();
  ASSERT_EQ(chain.errors->GetError(), "");
  const Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(out);
  const MeshTopology topo = buildTopology(F, static_cast<int>(out->GetNumberOfPoints()));
  const Eigen::MatrixXd uv = CornerUV(out);
  vtkDataArray* shift = out->GetPointData()->GetArray(names::LayerShift);
  Eigen::VectorXi layerShift(shift->GetNumberOfTuples());
  for (vtkIdType p = 0; p < shift->GetNumberOfTuples(); ++p)
  {
    layerShift[p] = static_cast<int>(shift->GetTuple1(p));
  }
  vtkDataArray* indexArray = out->GetPointData()->GetArray(names::SingularityIndex);
  Eigen::VectorXd index(indexArray->GetNumberOfTuples());
  for (vtkIdType p = 0; p < index.size(); ++p)
  {
    index[p] = indexArray->GetTuple1(p);
  }
  EXPECT_EQ(checks::seamViolations(F, topo, uv), 0);
  EXPECT_EQ(checks::branchPointsOffGrid(F, topo, layerShift, uv), 0);
  // the solver's LayerShift is its map's: as many branch points as it reports
  int branchPoints = 0;
  for (vtkIdType p = 0; p < shift->GetNumberOfTuples(); ++p)
  {
    branchPoints += layerShift[p] != 0 && !topo.boundaryVertex[p];
  }
  EXPECT_EQ(branchPoints, Field(out, names::BranchPointsOnGrid, 0));
  // No flipped triangle and every point keeps its index (cheburashka kept 1 of each where the
  // map folds at an ear until its cone pairs could be six grid edges long; 3 and 7 before the
  // grid was made finer around them, DefectGridRefinement).
  EXPECT_EQ(checks::flippedTriangles(uv), 0);
  EXPECT_EQ(checks::windingErrors(F, topo, index, uv), 0);
  EXPECT_EQ(Field(out, names::WindingErrors), 0);
  EXPECT_EQ(Field(out, names::FlippedTriangles, 2), checks::flippedTriangles(uv));
  EXPECT_EQ(Field(out, names::BranchPointsOnGrid, 0), Field(out, names::BranchPointsOnGrid, 1));
  EXPECT_LT(Field(out, names::SeamTranslationError), 1e-6);
  // the grid size follows the quad count: (u, v) area ~ 3000 cells (the map shrinks where the
  // frames are far from integrable: bunny-lowres, 12 branch points on 3,674 triangles, has 68%)
  double cells = 0.0;
  for (int f = 0; f < uv.rows(); ++f)
  {
    cells += 0.5 *
      std::imag(std::conj(checks::cornerZ(uv, f, 1) - checks::cornerZ(uv, f, 0)) *
        (checks::cornerZ(uv, f, 2) - checks::cornerZ(uv, f, 0)));
  }
  EXPECT_NEAR(cells / 3000.0, 1.0, 0.35);
  // Seam flags agree from both sides
  vtkDataArray* seam = out->GetCellData()->GetArray(names::Seam);
  int seamEdges = 0;
  for (int f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g >= 0)
      {
        const int kg = (MeshTopology::cornerOf(F, g, F(f, (k + 1) % 3)));
        ASSERT_EQ(seam->GetComponent(f, k), seam->GetComponent(g, kg));
        seamEdges += seam->GetComponent(f, k) != 0;
      }
    }
  }
  EXPECT_EQ(seamEdges, 2 * Field(out, names::SeamEdgeCount));
  const double continuous = Field(out, names::ParameterizationEnergy, 0);
  const double rounded = Field(out, names::ParameterizationEnergy, 1);
  const double final = Field(out, names::ParameterizationEnergy, 2);
  std::printf("[ %s ] %g branch points, %g seam edges, energy %.4f -> %.4f rounded (+%.1f%%) -> "
              "%.4f, flips %g -> %g -> %g\n",
    GetParam(), Field(out, names::BranchPointsOnGrid), Field(out, names::SeamEdgeCount), continuous,
    rounded, continuous > 0 ? 100 * (rounded / continuous - 1) : 0.0, final,
    Field(out, names::FlippedTriangles, 0), Field(out, names::FlippedTriangles, 1),
    Field(out, names::FlippedTriangles, 2));
  // Rounding costs little: 15% of the energy, plus 1e-4 (absolute: the energy is normalized so
  // that the whole map counts 1 per unit of squared gradient error) for each branch point put
  // on a grid point, about a quarter cell squared over one of the 3,000 cells (spot's 64:
  // +42%).
  EXPECT_LT(rounded, 1.15 * continuous + 1e-4 * Field(out, names::BranchPointsOnGrid) + 1e-3)
    << "rounding costs little";
}

INSTANTIATE_TEST_SUITE_P(Surfaces, ParameterizeOn,
  ::testing::Values("sphere", "torus", "knot", "cylinder", "roundedcube", "bunny-lowres", "spot",
    "fandisk", "rocker-arm", "cheburashka", "teapot"));
