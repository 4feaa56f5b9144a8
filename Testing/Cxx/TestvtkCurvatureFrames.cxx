// vtkCurvatureFrames through VTK: properties, error paths, arrays, user frames, shared meshes.

#include "TestSurfaceFiles.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCurvatureFrames.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"

#include "MeshTopology.h"
#include "Surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace names = vtkQuadCoverArrayNames;

namespace
{
vtkSmartPointer<vtkPolyData> ToPolyData(const quadcover::Surface& s)
{
  return vtkQuadCoverEigen::ToPolyData(s.V, s.F);
}

/// Runs the filter; returns the first error ("" if none) and the warnings.
struct Result
{
  std::string error;
  std::vector<std::string> warnings;
  vtkSmartPointer<vtkPolyData> output;
};

Result RunFilter(vtkPolyData* input, vtkCurvatureFrames* filter = nullptr)
{
  vtkSmartPointer<vtkCurvatureFrames> f = filter;
  if (!f)
  {
    f = vtkSmartPointer<vtkCurvatureFrames>::New();
  }
  vtkNew<vtkQuadCoverErrorObserver> observer;
  observer->Attach(f);
  f->SetInputData(input);
  f->Update();
  Result r;
  r.error = observer->GetError();
  for (int i = 0; i < observer->GetNumberOfWarnings(); ++i)
  {
    r.warnings.push_back(observer->GetWarning(i));
  }
  r.output = f->GetOutput();
  return r;
}

vtkDataArray* CellArray(vtkPolyData* pd, const char* name)
{
  return pd->GetCellData()->GetArray(name);
}
}

TEST(vtkCurvatureFrames, DefaultsClampsAndPrintSelf)
{
  vtkNew<vtkCurvatureFrames> f;
  EXPECT_EQ(f->GetNeighborhoodRadius(), 2.0);
  EXPECT_TRUE(f->GetUseInputFrames());
  EXPECT_EQ(f->GetNumberOfThreads(), 0);
  f->SetNeighborhoodRadius(-3.0);
  EXPECT_EQ(f->GetNeighborhoodRadius(), 0.0);
  f->SetNeighborhoodRadius(1e6);
  EXPECT_EQ(f->GetNeighborhoodRadius(), 20.0);
  f->SetNumberOfThreads(-1);
  EXPECT_EQ(f->GetNumberOfThreads(), 0);
  std::ostringstream os;
  f->Print(os);
  for (const char* p : { "NeighborhoodRadius: 20", "UseInputFrames: On", "NumberOfThreads: 0" })
  {
    EXPECT_NE(os.str().find(p), std::string::npos) << p;
  }
}

TEST(vtkCurvatureFrames, WritesEveryArrayWithItsType)
{
  vtkSmartPointer<vtkPolyData> torus = ToPolyData(quadcover::makeTorus(1.0, 0.4, 64, 32));
  const Result r = RunFilter(torus);
  ASSERT_EQ(r.error, "");
  const vtkIdType n = torus->GetNumberOfCells();
  ASSERT_EQ(r.output->GetNumberOfCells(), n);
  EXPECT_EQ(r.output->GetPoints(), torus->GetPoints()); // shallow: points shared, not copied
  const struct
  {
    const char* name;
    int components;
  } expected[] = { { names::PrincipalCurvatures, 2 }, { names::PrincipalDirection1, 3 },
    { names::PrincipalDirection2, 3 }, { names::FrameU, 3 }, { names::FrameV, 3 },
    { names::FrameWeight, 1 } };
  for (const auto& e : expected)
  {
    vtkDataArray* a = CellArray(r.output, e.name);
    ASSERT_NE(a, nullptr) << e.name;
    EXPECT_TRUE(vtkDoubleArray::SafeDownCast(a)) << e.name;
    EXPECT_EQ(a->GetNumberOfComponents(), e.components) << e.name;
    EXPECT_EQ(a->GetNumberOfTuples(), n) << e.name;
  }
  vtkDataArray* radius = r.output->GetFieldData()->GetArray(names::CurvatureRadius);
  ASSERT_NE(radius, nullptr);
  EXPECT_GT(radius->GetTuple1(0), 0.0);
  // The input is left alone.
  EXPECT_EQ(torus->GetCellData()->GetNumberOfArrays(), 0);
  // kappa1 = 1/r on the torus.
  vtkDataArray* k = CellArray(r.output, names::PrincipalCurvatures);
  for (vtkIdType c = 0; c < n; ++c)
  {
    ASSERT_NEAR(k->GetComponent(c, 0), 2.5, 0.1);
  }
}

TEST(vtkCurvatureFrames, ErrorPaths)
{
  {
    vtkNew<vtkPolyData> empty;
    EXPECT_NE(RunFilter(empty).error.find("no points"), std::string::npos);
  }
  {
    vtkNew<vtkPolyData> cloud;
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0, 0, 0);
    cloud->SetPoints(pts);
    vtkNew<vtkCellArray> verts;
    const vtkIdType id = 0;
    verts->InsertNextCell(1, &id);
    cloud->SetVerts(verts);
    EXPECT_NE(RunFilter(cloud).error.find("no polygons"), std::string::npos);
  }
  {
    vtkSmartPointer<vtkPolyData> s = ToPolyData(quadcover::makeIcosphere(1.0, 2));
    s->GetPoints()->SetPoint(5, std::nan(""), 0.0, 0.0);
    EXPECT_NE(RunFilter(s).error.find("non-finite"), std::string::npos);
  }
  {
    quadcover::Surface s = quadcover::makeIcosphere(1.0, 2);
    std::swap(s.F(0, 1), s.F(0, 2)); // one triangle turned against its neighbours
    const Result r = RunFilter(ToPolyData(s));
    EXPECT_NE(r.error.find("inconsistently oriented"), std::string::npos) << r.error;
    EXPECT_EQ(r.output->GetNumberOfCells(), 0);
  }
  {
    quadcover::Surface s = quadcover::makeIcosphere(1.0, 1);
    Eigen::MatrixX3i F(s.F.rows() + 1, 3);
    F << s.F, s.F(0, 0), s.F(0, 1), 0; // a third triangle on edge 0 of triangle 0
    F(F.rows() - 1, 2) = s.F(1, 2) == s.F(0, 0) || s.F(1, 2) == s.F(0, 1) ? s.F(2, 2) : s.F(1, 2);
    s.F = F;
    EXPECT_NE(RunFilter(ToPolyData(s)).error.find("non-manifold"), std::string::npos);
  }
}

TEST(vtkCurvatureFrames, PointIdsOutOfRangeAreErrorsNotCrashes)
{
  // VTK's own filters read past the points on such ids; the filter must refuse first.
  for (const vtkIdType bad : { vtkIdType(7), vtkIdType(-5), vtkIdType(4294967298LL) })
  {
    for (const int sides : { 3, 4 }) // triangles take the shallow path, quads the triangulation
    {
      vtkNew<vtkPoints> pts;
      for (int i = 0; i < 4; ++i)
      {
        pts->InsertNextPoint(i & 1, i >> 1, 0);
      }
      vtkNew<vtkCellArray> polys;
      const vtkIdType ids[4] = { 0, 1, bad, 2 };
      polys->InsertNextCell(sides, ids);
      vtkNew<vtkPolyData> pd;
      pd->SetPoints(pts);
      pd->SetPolys(polys);
      const Result r = RunFilter(pd);
      EXPECT_NE(r.error.find("refers to point"), std::string::npos) << bad << " " << r.error;
    }
  }
}

TEST(vtkCurvatureFrames, StripJoinsAreDroppedNotBridged)
{
  // Two separate unit squares as one strip with the usual repeated-point join.
  vtkNew<vtkPoints> pts;
  const double xy[8][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1, 1 }, { 3, 0 }, { 4, 0 }, { 3, 1 },
    { 4, 1 } };
  for (const auto& p : xy)
  {
    pts->InsertNextPoint(p[0], p[1], 0.0);
  }
  vtkNew<vtkCellArray> strips;
  const vtkIdType strip[10] = { 0, 1, 2, 3, 3, 4, 4, 5, 6, 7 };
  strips->InsertNextCell(10, strip);
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  pd->SetStrips(strips);
  const Result r = RunFilter(pd);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.output->GetNumberOfPolys(), 4);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("repeat a point"), std::string::npos) << r.warnings[0];
}

TEST(vtkCurvatureFrames, AllDegenerateIsAnErrorAndFast)
{
  // 20000 triangles whose points all coincide: no surface, and no quadratic neighbourhood search.
  const int n = 20000;
  vtkNew<vtkPoints> pts;
  for (int i = 0; i < n + 2; ++i)
  {
    pts->InsertNextPoint(1.0, 2.0, 3.0);
  }
  vtkNew<vtkCellArray> polys;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType ids[3] = { 0, i + 1, i + 2 };
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  pd->SetPolys(polys);
  EXPECT_NE(RunFilter(pd).error.find("degenerate"), std::string::npos);
}

TEST(vtkCurvatureFrames, OneHugeTriangleDoesNotChangeTheScale)
{
  // A unit sphere plus one far, huge, separate triangle: the median edge length, the per-triangle
  // degeneracy test and the neighbourhood cap keep the sphere's estimate as it was.
  quadcover::Surface s = quadcover::makeIcosphere(1.0, 4);
  const Eigen::Index nv = s.V.rows(), nf = s.F.rows();
  s.V.conservativeResize(nv + 3, 3);
  s.V.row(nv) << 1e5, 0, 0;
  s.V.row(nv + 1) << 2e5, 0, 0;
  s.V.row(nv + 2) << 1e5, 1e5, 0;
  s.F.conservativeResize(nf + 1, 3);
  s.F.row(nf) << static_cast<int>(nv), static_cast<int>(nv + 1), static_cast<int>(nv + 2);
  const Result r = RunFilter(ToPolyData(s));
  ASSERT_EQ(r.error, "");
  vtkDataArray* k = CellArray(r.output, names::PrincipalCurvatures);
  for (vtkIdType c = 0; c < nf; ++c)
  {
    ASSERT_NEAR(k->GetComponent(c, 0), 1.0, 0.05) << c;
    ASSERT_NEAR(k->GetComponent(c, 1), 1.0, 0.05) << c;
  }
}

TEST(vtkCurvatureFrames, TriangulatesPolygonsAndDropsLines)
{
  // A unit cube of six quads plus a stray line.
  vtkNew<vtkPoints> pts;
  for (int i = 0; i < 8; ++i)
  {
    pts->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  const vtkIdType quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  vtkNew<vtkCellArray> polys;
  for (const auto& q : quads)
  {
    polys->InsertNextCell(4, q);
  }
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 7 };
  lines->InsertNextCell(2, line);
  vtkNew<vtkPolyData> cube;
  cube->SetPoints(pts);
  cube->SetPolys(polys);
  cube->SetLines(lines);
  const Result r = RunFilter(cube);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.output->GetNumberOfPolys(), 12);
  EXPECT_EQ(r.output->GetNumberOfLines(), 0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("1 vertex/line cells"), std::string::npos) << r.warnings[0];
  // Cube faces are flat: no bending inside a face, the edges carry it all.
  EXPECT_EQ(CellArray(r.output, names::FrameU)->GetNumberOfTuples(), 12);
}

TEST(vtkCurvatureFrames, KeepsUserFramesUnlessToldNot)
{
  vtkSmartPointer<vtkPolyData> torus = ToPolyData(quadcover::makeTorus(1.0, 0.4, 64, 32));
  const vtkIdType n = torus->GetNumberOfCells();
  vtkNew<vtkDoubleArray> user;
  user->SetName("MyField");
  user->SetNumberOfComponents(3);
  user->SetNumberOfTuples(n);
  for (vtkIdType c = 0; c < n; ++c)
  {
    user->SetTuple3(c, 0.0, 0.0, 1.0);
  }
  torus->GetCellData()->AddArray(user);

  vtkNew<vtkCurvatureFrames> f;
  f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "MyField");
  Result r = RunFilter(torus, f);
  ASSERT_EQ(r.error, "");
  vtkDataArray* u = CellArray(r.output, names::FrameU);
  vtkDataArray* d2 = CellArray(r.output, names::PrincipalDirection2);
  int followsUser = 0;
  for (vtkIdType c = 0; c < n; ++c)
  {
    // The torus' z direction projected: the tube circle, i.e. along kappa1, not kappa2.
    double uu[3];
    u->GetTuple(c, uu);
    followsUser += std::abs(uu[2]) > 0.05 || std::abs(d2->GetComponent(c, 2)) < 1e-9 ? 1 : 0;
  }
  EXPECT_EQ(followsUser, n);
  // The user's array itself is untouched and passed on.
  EXPECT_EQ(CellArray(r.output, "MyField")->GetComponent(0, 2), 1.0);

  f->UseInputFramesOff();
  r = RunFilter(torus, f);
  u = CellArray(r.output, names::FrameU);
  d2 = CellArray(r.output, names::PrincipalDirection2);
  for (vtkIdType c = 0; c < n; ++c)
  {
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(u->GetComponent(c, k), d2->GetComponent(c, k));
    }
  }
}

// ---- The shared scanned and CAD meshes (skipped when ../shared/data is absent) ----

class SharedMesh : public ::testing::TestWithParam<const char*>
{};

TEST_P(SharedMesh, RepairsThenGivesUnitTangentFrames)
{
  const std::string path = std::string(QUADCOVER_SHARED_DATA) + "/" + GetParam() + ".obj";
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << "shared mesh not found: " << path;
  }
  std::string error;
  vtkSmartPointer<vtkPolyData> surface = ReadRepaired(path, error);
  ASSERT_TRUE(surface) << error;
  const Result r = RunFilter(surface);
  ASSERT_EQ(r.error, "");

  // Topology of the repaired surface.
  Eigen::MatrixX3i F(surface->GetNumberOfPolys(), 3);
  {
    vtkNew<vtkIdList> ids;
    vtkIdType f = 0;
    for (surface->GetPolys()->InitTraversal(); surface->GetPolys()->GetNextCell(ids); ++f)
    {
      F.row(f) << ids->GetId(0), ids->GetId(1), ids->GetId(2);
    }
  }
  const quadcover::MeshTopology topo =
    quadcover::buildTopology(F, static_cast<int>(surface->GetNumberOfPoints()));
  EXPECT_TRUE(topo.isManifold()) << topo.describeDefects();
  EXPECT_TRUE(topo.isOriented());
  std::printf("[ %s ] %lld points, %lld triangles, %d components, chi %d, genus %d, %zu boundary "
              "loops, %lld merged points\n",
    GetParam(), static_cast<long long>(surface->GetNumberOfPoints()),
    static_cast<long long>(surface->GetNumberOfPolys()), topo.numComponents(),
    topo.eulerCharacteristic(), topo.numComponents() ? topo.components[0].genus : -1,
    topo.boundaryLoops.size(),
    static_cast<long long>(
      surface->GetFieldData()->GetArray(vtkQuadCoverArrayNames::MergedPoints)->GetTuple1(0)));

  vtkDataArray* u = CellArray(r.output, names::FrameU);
  vtkDataArray* v = CellArray(r.output, names::FrameV);
  vtkDataArray* w = CellArray(r.output, names::FrameWeight);
  for (vtkIdType c = 0; c < r.output->GetNumberOfCells(); ++c)
  {
    double uu[3], vv[3];
    u->GetTuple(c, uu);
    v->GetTuple(c, vv);
    ASSERT_NEAR(uu[0] * uu[0] + uu[1] * uu[1] + uu[2] * uu[2], 1.0, 1e-9) << c;
    ASSERT_NEAR(uu[0] * vv[0] + uu[1] * vv[1] + uu[2] * vv[2], 0.0, 1e-9) << c;
    ASSERT_TRUE(std::isfinite(w->GetTuple1(c)));
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, SharedMesh,
  ::testing::Values("bunny-lowres", "spot", "fandisk", "rocker-arm", "cheburashka", "teapot"));
