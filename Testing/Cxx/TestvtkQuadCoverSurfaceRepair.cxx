// vtkQuadCoverSurfaceRepair: every repair it counts, on surfaces made to need it; what it keeps
// (the input's point and cell data); what it refuses, as one error.
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCurvatureFrames.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverSurfaceRepair.h"
#include "vtkSmartPointer.h"

#include "FrameField.h"
#include "MeshTopology.h"
#include "SurfaceSmoothing.h"
#include "Surfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <vector>

namespace names = vtkQuadCoverArrayNames;

namespace
{
/// A polydata from points and cells (each cell a list of point ids, put with `kind`).
vtkSmartPointer<vtkPolyData> Make(const std::vector<std::vector<double>>& points,
  const std::vector<std::vector<vtkIdType>>& cells, const char* kind = "polys")
{
  vtkNew<vtkPoints> p;
  for (const auto& x : points)
  {
    p->InsertNextPoint(x[0], x[1], x[2]);
  }
  vtkNew<vtkCellArray> c;
  for (const auto& ids : cells)
  {
    c->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(p);
  if (std::string(kind) == "strips")
    pd->SetStrips(c);
  else if (std::string(kind) == "lines")
    pd->SetLines(c);
  else
    pd->SetPolys(c);
  return pd;
}

/// A cell array "Tag" holding each cell's number.
void AddCellTags(vtkPolyData* pd)
{
  vtkNew<vtkDoubleArray> tag;
  tag->SetName("Tag");
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    tag->InsertNextValue(static_cast<double>(c));
  }
  pd->GetCellData()->AddArray(tag);
}

struct Repaired
{
  vtkSmartPointer<vtkPolyData> output;
  std::string error;
  double Count(const char* name) const
  {
    vtkDataArray* a = this->output->GetFieldData()->GetArray(name);
    return a ? a->GetTuple1(0) : std::nan("");
  }
};

/// The repair of `input`; the tests of the other repairs use surfaces of a few triangles, which
/// the refinement of coarse components (off unless `refine`) would split.
Repaired Repair(vtkPolyData* input, bool refine = false)
{
  vtkNew<vtkQuadCoverSurfaceRepair> repair;
  if (!refine)
  {
    repair->SetMinimumComponentTriangleCount(0);
  }
  vtkNew<vtkQuadCoverErrorObserver> errors;
  errors->Attach(repair);
  repair->SetInputData(input);
  repair->Update();
  return { repair->GetOutput(), errors->GetError() };
}

/// A closed strip of 12 quads with a half turn.
vtkSmartPointer<vtkPolyData> MoebiusStrip()
{
  std::vector<std::vector<double>> points;
  std::vector<std::vector<vtkIdType>> cells;
  const int n = 12;
  for (int i = 0; i < n; ++i)
  {
    const double t = 2 * 3.14159265358979323846 * i / n;
    for (const double w : { -0.3, 0.3 })
    {
      points.push_back({ (3 + w * std::cos(t / 2)) * std::cos(t),
        (3 + w * std::cos(t / 2)) * std::sin(t), w * std::sin(t / 2) });
    }
    const vtkIdType a = 2 * i, b = a + 1;
    const vtkIdType c = i + 1 < n ? a + 2 : 1, d = i + 1 < n ? b + 2 : 0;
    cells.push_back({ a, c, b });
    cells.push_back({ b, c, d });
  }
  return Make(points, cells);
}

/// A normals array of `tuples` zero vectors (the repair makes them again where it moves triangles).
vtkSmartPointer<vtkDoubleArray> ZeroNormals(vtkIdType tuples)
{
  auto normals = vtkSmartPointer<vtkDoubleArray>::New();
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(tuples);
  normals->Fill(0.0);
  return normals;
}

quadcover::MeshTopology Topology(vtkPolyData* pd)
{
  return quadcover::buildTopology(
    vtkQuadCoverEigen::Triangles(pd), static_cast<int>(pd->GetNumberOfPoints()));
}
}

TEST(vtkQuadCoverSurfaceRepair, MergesTriangulatesAndOrientsKeepingTheData)
{
  // Two unit squares side by side whose shared edge repeats its points (as OBJ files repeat a
  // point per texture coordinate), and a triangle on top facing the other way.
  vtkSmartPointer<vtkPolyData> in =
    Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 2, 0, 0 },
           { 2, 1, 0 }, { 1, 1, 0 }, { 0, 2, 0 } },
      { { 0, 1, 2, 3 }, { 4, 5, 6, 7 }, { 2, 3, 8 } });
  vtkNew<vtkDoubleArray> label;
  label->SetName("Label");
  for (double v : { 10.0, 20.0, 30.0 })
  {
    label->InsertNextValue(v);
  }
  in->GetCellData()->AddArray(label);
  vtkNew<vtkDoubleArray> scan;
  scan->SetName("ScanDate");
  scan->InsertNextValue(20261201);
  in->GetFieldData()->AddArray(scan);
  const Repaired r = Repair(in);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.Count(names::MergedPoints), 2);
  EXPECT_EQ(r.Count(names::TriangulatedPolygons), 2);
  EXPECT_EQ(r.Count(names::ReorientedTriangles), 1);
  EXPECT_EQ(r.Count(names::SplitVertices), 0);
  EXPECT_EQ(r.Count(names::RemovedCells), 0);
  EXPECT_EQ(r.output->GetNumberOfPoints(), 7);
  ASSERT_EQ(r.output->GetNumberOfPolys(), 5);
  const quadcover::MeshTopology topo = Topology(r.output);
  EXPECT_TRUE(topo.isManifold());
  EXPECT_TRUE(topo.isOriented());
  EXPECT_EQ(topo.eulerCharacteristic(), 1); // a disk
  // the cell data followed the triangles: two of each square's label, one of the triangle's
  vtkDataArray* kept = r.output->GetCellData()->GetArray("Label");
  ASSERT_NE(kept, nullptr);
  double sum = 0.0;
  for (vtkIdType c = 0; c < kept->GetNumberOfTuples(); ++c)
  {
    sum += kept->GetTuple1(c);
  }
  EXPECT_EQ(sum, 2 * 10 + 2 * 20 + 30);
  EXPECT_EQ(r.output->GetCellData()->GetArray("Normals"), nullptr) << "no by-product";
  ASSERT_NE(r.output->GetFieldData()->GetArray("ScanDate"), nullptr) << "field data kept";
  EXPECT_EQ(r.output->GetFieldData()->GetArray("ScanDate")->GetTuple1(0), 20261201);
  // the five stages take it as it is
  vtkNew<vtkCurvatureFrames> curvature;
  vtkNew<vtkQuadCoverErrorObserver> errors;
  errors->Attach(curvature);
  curvature->SetInputData(r.output);
  curvature->Update();
  EXPECT_EQ(errors->GetError(), "");
}

TEST(vtkQuadCoverSurfaceRepair, SplitsBowtiesWithTheirPointData)
{
  vtkSmartPointer<vtkPolyData> in =
    Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 } },
      { { 0, 1, 2 }, { 0, 3, 4 } });
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (double v : { 7.0, 1.0, 2.0, 3.0, 4.0 })
  {
    height->InsertNextValue(v);
  }
  in->GetPointData()->AddArray(height);
  const Repaired r = Repair(in);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.Count(names::SplitVertices), 1);
  ASSERT_EQ(r.output->GetNumberOfPoints(), 6);
  EXPECT_TRUE(Topology(r.output).nonManifoldVertices.empty());
  vtkDataArray* h = r.output->GetPointData()->GetArray("Height");
  ASSERT_NE(h, nullptr);
  int copiesOfTheCentre = 0;
  for (vtkIdType p = 0; p < r.output->GetNumberOfPoints(); ++p)
  {
    double x[3];
    r.output->GetPoint(p, x);
    if (x[0] == 0 && x[1] == 0)
    {
      ++copiesOfTheCentre;
      EXPECT_EQ(h->GetTuple1(p), 7.0);
    }
  }
  EXPECT_EQ(copiesOfTheCentre, 2);
}

TEST(vtkQuadCoverSurfaceRepair, StripJoinsVerticesAndLinesAreRemoved)
{
  // A strip of four points, a repeated point (two degenerate joins), then four more.
  vtkSmartPointer<vtkPolyData> in = Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 },
                                           { 3, 0, 0 }, { 4, 0, 0 }, { 3, 1, 0 }, { 4, 1, 0 } },
    { { 0, 1, 2, 3, 3, 4, 4, 5, 6, 7 } }, "strips");
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(2, line);
  in->SetLines(lines);
  vtkNew<vtkCellArray> verts;
  const vtkIdType vert = 5;
  verts->InsertNextCell(1, &vert);
  in->SetVerts(verts);
  const Repaired r = Repair(in);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.output->GetNumberOfPolys(), 4);
  EXPECT_EQ(r.output->GetNumberOfLines() + r.output->GetNumberOfVerts(), 0);
  EXPECT_EQ(r.Count(names::TriangulatedPolygons), 1);
  EXPECT_EQ(r.Count(names::RemovedCells), 2 + 4); // the line, the vertex, four strip joins
}

TEST(vtkQuadCoverSurfaceRepair, CutsANonManifoldEdgeApartWithThePointData)
{
  // three triangles on the edge 0-1, each with its own height at its third point: the two that
  // agree in orientation and face each other stay joined, the third is cut off
  vtkSmartPointer<vtkPolyData> in =
    Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, -1, -1 } },
      { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (double v : { 7.0, 8.0, 2.0, 3.0, 4.0 })
  {
    height->InsertNextValue(v);
  }
  in->GetPointData()->AddArray(height);
  const Repaired r = Repair(in);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.Count(names::CutEdges), 1);
  EXPECT_EQ(r.Count(names::SplitVertices), 2);
  ASSERT_EQ(r.output->GetNumberOfPoints(), 7);
  const quadcover::MeshTopology topo = Topology(r.output);
  EXPECT_TRUE(topo.isManifold());
  EXPECT_TRUE(topo.isOriented());
  EXPECT_EQ(topo.numComponents(), 2);
  vtkDataArray* h = r.output->GetPointData()->GetArray("Height");
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->GetTuple1(5) + h->GetTuple1(6), 7.0 + 8.0) << "the copies of 0 and 1 carry theirs";
}

TEST(vtkQuadCoverSurfaceRepair, RemovesARepeatedTriangleKeepingTheData)
{
  // an octahedron in double precision, one triangle listed twice, a point and a cell array
  const double x = 1.0 + 1e-12; // not a float
  vtkSmartPointer<vtkPolyData> in =
    Make({ { x, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } },
      { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 },
        { 0, 3, 5 }, { 0, 2, 4 } });
  vtkNew<vtkPoints> precise;
  precise->SetDataTypeToDouble();
  precise->DeepCopy(in->GetPoints());
  precise->SetPoint(0, x, 0, 0);
  in->SetPoints(precise);
  vtkNew<vtkDoubleArray> height, tag;
  height->SetName("Height");
  tag->SetName("Tag");
  for (int p = 0; p < 6; ++p)
  {
    height->InsertNextValue(10 + p);
  }
  for (int c = 0; c < 9; ++c)
  {
    tag->InsertNextValue(c);
  }
  in->GetPointData()->AddArray(height);
  in->GetCellData()->AddArray(tag);
  const Repaired r = Repair(in);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.Count(names::RemovedCells), 1);
  ASSERT_EQ(r.output->GetNumberOfPolys(), 8);
  ASSERT_NE(r.output->GetPointData()->GetArray("Height"), nullptr);
  ASSERT_NE(r.output->GetCellData()->GetArray("Tag"), nullptr);
  EXPECT_EQ(r.output->GetCellData()->GetArray("Tag")->GetTuple1(7), 7.0) << "the first eight";
  double p0[3];
  r.output->GetPoint(0, p0);
  EXPECT_EQ(p0[0], x) << "double precision kept";
  EXPECT_EQ(r.output->GetPointData()->GetArray("Height")->GetTuple1(0), 10.0);
  EXPECT_EQ(Topology(r.output).eulerCharacteristic(), 2);
}

TEST(vtkQuadCoverSurfaceRepair, FlipsACapAwayGivingItsNeighboursData)
{
  // an octahedron whose edge 0-2 has a point 6 on its middle: the triangle on one side split
  // there, the other side's gap filled by the cap (0, 6, 2) of zero area (cell 9)
  vtkSmartPointer<vtkPolyData> in = Make({ { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
                                           { 0, 0, 1 }, { 0, 0, -1 }, { 0.5, 0.5, 0 } },
    { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 6, 0, 5 }, { 2, 6, 5 }, { 1, 2, 5 },
      { 3, 1, 5 }, { 0, 3, 5 }, { 0, 6, 2 } });
  AddCellTags(in);
  const Repaired r = Repair(in);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.Count(names::FlippedEdges), 1);
  ASSERT_EQ(r.output->GetNumberOfPolys(), 10);
  EXPECT_EQ(Topology(r.output).eulerCharacteristic(), 2);
  const Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(r.output);
  const Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(r.output);
  vtkDataArray* tags = r.output->GetCellData()->GetArray("Tag");
  ASSERT_NE(tags, nullptr);
  for (int f = 0; f < F.rows(); ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    EXPECT_GT((b - a).cross(c - a).norm(), 0.1) << "triangle " << f << " is proper";
  }
  // the cap's row and its neighbour's (cell 0) now hold the neighbour's two halves
  EXPECT_EQ(tags->GetTuple1(9), 0.0);
  EXPECT_EQ(tags->GetTuple1(0), 0.0);
  EXPECT_EQ(tags->GetTuple1(4), 4.0);
}

TEST(vtkQuadCoverSurfaceRepair, ClosesATJunctionGivingThePartsTheirTrianglesData)
{
  // two unit squares side by side; the right one has a point (1, 0.5) on the side they share,
  // which the left one's triangle (0, 1, 2) (cell 0) lacks: a seam of two edges against one
  vtkSmartPointer<vtkPolyData> in = Make(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1, 0.5, 0 } },
    { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 4, 6 }, { 6, 4, 5 }, { 6, 5, 2 } });
  AddCellTags(in);
  const Repaired r = Repair(in);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.Count(names::ClosedTJunctions), 1);
  ASSERT_EQ(r.output->GetNumberOfPolys(), 6);
  const quadcover::MeshTopology T = Topology(r.output);
  EXPECT_EQ(T.components.size(), 1u);
  EXPECT_EQ(T.eulerCharacteristic(), 1) << "one sheet with one boundary loop";
  EXPECT_TRUE(T.isManifold());
  vtkDataArray* tags = r.output->GetCellData()->GetArray("Tag");
  ASSERT_NE(tags, nullptr);
  std::vector<double> got;
  for (vtkIdType c = 0; c < tags->GetNumberOfTuples(); ++c)
  {
    got.push_back(tags->GetTuple1(c));
  }
  EXPECT_EQ(got, (std::vector<double>{ 0, 0, 1, 2, 3, 4 })) << "cell 0's two parts";
}

TEST(vtkQuadCoverSurfaceRepair, RefusesWhatItCannotRepair)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case
  {
    vtkSmartPointer<vtkPolyData> input;
    const char* reason;
  };
  const std::vector<Case> cases = {
    { vtkSmartPointer<vtkPolyData>::New(), "no points" },
    { Make({ { 0, 0, 0 }, { 1, 0, 0 } }, { { 0, 1 } }, "lines"), "no polygons" },
    { Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 7 } }), "refers to point 7" },
    { Make({ { 0, 0, 0 }, { 1, 0, 0 }, { nan, 1, 0 } }, { { 0, 1, 2 } }), "non-finite" },
    { Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 0 } }, { { 0, 1, 2 } }), "three distinct points" },
    { MoebiusStrip(), "component 1 of 1 is not orientable" },
  };
  for (const Case& c : cases)
  {
    const Repaired r = Repair(c.input);
    EXPECT_EQ(r.error.rfind("Cannot repair the surface: ", 0), 0u) << r.error;
    EXPECT_NE(r.error.find(c.reason), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
    EXPECT_EQ(r.output->GetNumberOfPoints(), 0) << c.reason;
  }
}

TEST(vtkQuadCoverSurfaceRepair, RefinesACoarseConeInterpolatingItsData)
{
  // a closed cone of 2 x 32 triangles (a fan of needles around its tip, another around the
  // centre of its base), point data a linear function of position, cell data the cell's id
  std::vector<std::vector<double>> points{ { 0, 0, 2 }, { 0, 0, 0 } };
  std::vector<std::vector<vtkIdType>> cells;
  const int n = 32;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * 3.14159265358979323846 * i / n;
    points.push_back({ std::cos(a), std::sin(a), 0 });
    const vtkIdType p = 2 + i, q = 2 + (i + 1) % n;
    cells.push_back({ 0, p, q });
    cells.push_back({ 1, q, p });
  }
  vtkSmartPointer<vtkPolyData> in = Make(points, cells);
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (vtkIdType p = 0; p < in->GetNumberOfPoints(); ++p)
  {
    double x[3];
    in->GetPoint(p, x);
    height->InsertNextValue(3 * x[0] - x[1] + 2 * x[2]);
  }
  in->GetPointData()->AddArray(height);
  vtkNew<vtkIntArray> cellId;
  cellId->SetName("CellId");
  for (vtkIdType c = 0; c < in->GetNumberOfCells(); ++c)
  {
    cellId->InsertNextValue(static_cast<int>(c));
  }
  in->GetCellData()->AddArray(cellId);

  Repaired r = Repair(in, true);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.Count(names::RefinedTriangles), 2 * n);
  EXPECT_EQ(r.output->GetNumberOfPolys(), 2 * n * 4) << "64 -> 256 triangles";
  const quadcover::MeshTopology topo = Topology(r.output);
  EXPECT_TRUE(topo.isManifold() && topo.isOriented() && topo.isClosed());
  EXPECT_EQ(topo.eulerCharacteristic(), 2);
  vtkDataArray* h = r.output->GetPointData()->GetArray("Height");
  ASSERT_NE(h, nullptr);
  for (vtkIdType p = 0; p < r.output->GetNumberOfPoints(); ++p)
  {
    double x[3];
    r.output->GetPoint(p, x);
    EXPECT_NEAR(h->GetTuple1(p), 3 * x[0] - x[1] + 2 * x[2], 1e-12) << "point " << p;
  }
  // each part keeps its triangle's id, and lies in it (its centre within the parent's plane)
  vtkDataArray* id = r.output->GetCellData()->GetArray("CellId");
  ASSERT_NE(id, nullptr);
  for (vtkIdType c = 0; c < r.output->GetNumberOfCells(); ++c)
  {
    const vtkIdType parent = static_cast<vtkIdType>(id->GetTuple1(c));
    double centre[3] = { 0, 0, 0 }, a[3], b[3], d[3];
    for (int k = 0; k < 3; ++k)
    {
      double x[3];
      r.output->GetPoint(r.output->GetCell(c)->GetPointId(k), x);
      for (int j = 0; j < 3; ++j)
        centre[j] += x[j] / 3;
    }
    in->GetPoint(in->GetCell(parent)->GetPointId(0), a);
    in->GetPoint(in->GetCell(parent)->GetPointId(1), b);
    in->GetPoint(in->GetCell(parent)->GetPointId(2), d);
    const Eigen::Vector3d pa(a), pb(b), pd(d), pc(centre);
    const Eigen::Vector3d normal = (pb - pa).cross(pd - pa).normalized();
    EXPECT_NEAR((pc - pa).dot(normal), 0.0, 1e-12) << "cell " << c;
  }
  // without refinement the cone stays as it was
  vtkNew<vtkQuadCoverSurfaceRepair> off;
  off->SetMinimumComponentTriangleCount(0);
  off->SetInputData(in);
  off->Update();
  EXPECT_EQ(off->GetOutput()->GetNumberOfPolys(), 2 * n);
}

TEST(vtkQuadCoverSurfaceRepair, SimplifiesAboveMaximumTriangleCountKeepingTheData)
{
  // a sphere of 20,480 triangles with a point array and cell normals, brought to 2,000
  vtkSmartPointer<vtkPolyData> in;
  {
    const quadcover::Surface s = quadcover::makeIcosphere(1.0, 5);
    in = vtkQuadCoverEigen::ToPolyData(s.V, s.F);
  }
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (vtkIdType p = 0; p < in->GetNumberOfPoints(); ++p)
  {
    height->InsertNextValue(in->GetPoint(p)[2]);
  }
  in->GetPointData()->AddArray(height);
  in->GetCellData()->SetNormals(ZeroNormals(in->GetNumberOfCells()));

  vtkNew<vtkQuadCoverSurfaceRepair> repair;
  EXPECT_EQ(repair->GetMaximumTriangleCount(), 0);
  repair->SetMaximumTriangleCount(2000);
  repair->SetInputData(in);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(repair), "");
  vtkPolyData* out = repair->GetOutput();
  EXPECT_LE(out->GetNumberOfPolys(), 2000);
  EXPECT_EQ(out->GetFieldData()->GetArray(names::CollapsedEdges)->GetTuple1(0),
    static_cast<double>(in->GetNumberOfPoints() - out->GetNumberOfPoints()));
  const quadcover::MeshTopology topo = Topology(out);
  EXPECT_TRUE(topo.isManifold() && topo.isOriented() && topo.isClosed());
  EXPECT_EQ(topo.eulerCharacteristic(), 2);
  vtkDataArray* h = out->GetPointData()->GetArray("Height");
  ASSERT_NE(h, nullptr);
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    ASSERT_EQ(h->GetTuple1(p), out->GetPoint(p)[2]) << "point " << p << " kept its data";
  }
  // the cell normals are the kept triangles' own (outward on the sphere)
  vtkDataArray* n = out->GetCellData()->GetNormals();
  ASSERT_NE(n, nullptr);
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    double centre[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      const double* x = out->GetPoint(out->GetCell(c)->GetPointId(k));
      for (int j = 0; j < 3; ++j)
        centre[j] += x[j] / 3;
    }
    const Eigen::Vector3d normal(n->GetTuple3(c)), outward(centre);
    ASSERT_NEAR(normal.norm(), 1.0, 1e-9) << "cell " << c;
    ASSERT_GT(normal.dot(outward.normalized()), 0.9) << "cell " << c;
  }
}

TEST(vtkQuadCoverSurfaceRepair, SmoothsARoughSurfaceAndRemakesItsCellNormals)
{
  // a sphere of 5,120 triangles with noise of 0.3 edge lengths, as a raw scan, with cell and
  // point normals
  const quadcover::Surface s = quadcover::withNoise(quadcover::makeIcosphere(1.0, 4), 0.3, 5);
  vtkSmartPointer<vtkPolyData> in = vtkQuadCoverEigen::ToPolyData(s.V, s.F);
  in->GetCellData()->SetNormals(ZeroNormals(in->GetNumberOfCells()));
  in->GetPointData()->SetNormals(ZeroNormals(in->GetNumberOfPoints()));

  vtkNew<vtkQuadCoverSurfaceRepair> repair;
  EXPECT_TRUE(repair->GetSmoothRoughSurfaces());
  repair->SetInputData(in);
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(repair), "");
  vtkPolyData* out = repair->GetOutput();
  EXPECT_EQ(out->GetFieldData()->GetArray(names::SmoothedPoints)->GetTuple1(0),
    static_cast<double>(in->GetNumberOfPoints()));
  EXPECT_TRUE(vtkQuadCoverSurfaceRepair::Smoothed(out));
  ASSERT_EQ(out->GetNumberOfPoints(), in->GetNumberOfPoints());
  ASSERT_EQ(out->GetNumberOfPolys(), in->GetNumberOfPolys());
  const quadcover::MeshTopology topo = Topology(out);
  EXPECT_TRUE(topo.isManifold() && topo.isOriented() && topo.isClosed());
  // smoother: few points sharply curved (the noise bent more than a fifth of them)
  const Eigen::VectorXd before = quadcover::angleDefects(s.V, s.F, topo);
  const Eigen::VectorXd after = quadcover::angleDefects(
    vtkQuadCoverEigen::Points(out), vtkQuadCoverEigen::Triangles(out), topo);
  const auto sharp = [](const Eigen::VectorXd& k) {
    return (k.array().abs() > quadcover::RoughDefect).count();
  };
  EXPECT_GT(sharp(before), in->GetNumberOfPoints() / 5);
  EXPECT_LT(sharp(after), in->GetNumberOfPoints() / 100);
  // the cell normals the triangles' own, outward; the point normals gone
  vtkDataArray* n = out->GetCellData()->GetNormals();
  ASSERT_NE(n, nullptr);
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    const Eigen::Vector3d normal(n->GetTuple3(c));
    const Eigen::Vector3d centre(out->GetPoint(out->GetCell(c)->GetPointId(0)));
    ASSERT_NEAR(normal.norm(), 1.0, 1e-9) << "cell " << c;
    ASSERT_GT(normal.dot(centre.normalized()), 0.5) << "cell " << c;
  }
  EXPECT_EQ(out->GetPointData()->GetNormals(), nullptr);

  repair->SmoothRoughSurfacesOff();
  ASSERT_EQ(vtkQuadCoverErrorObserver::Run(repair), "");
  out = repair->GetOutput();
  EXPECT_EQ(out->GetFieldData()->GetArray(names::SmoothedPoints)->GetTuple1(0), 0.0);
  EXPECT_FALSE(vtkQuadCoverSurfaceRepair::Smoothed(out));
  // the input's points, in the repair's order
  const auto sorted = [](vtkPolyData* pd) {
    std::vector<std::array<double, 3>> points(pd->GetNumberOfPoints());
    for (vtkIdType p = 0; p < pd->GetNumberOfPoints(); ++p)
    {
      pd->GetPoint(p, points[p].data());
    }
    std::sort(points.begin(), points.end());
    return points;
  };
  EXPECT_EQ(sorted(out), sorted(in));
  std::ostringstream printed;
  repair->Print(printed);
  EXPECT_NE(printed.str().find("SmoothRoughSurfaces: Off"), std::string::npos);
}

TEST(vtkQuadCoverSurfaceRepair, MergesTheRoundOffSeamsOfAParametricSurface)
{
  // A torus as VTK's parametric sources make it: the grid's last row and column are computed at
  // 2 pi, which round-off puts about 1e-15 away from the first's, and the triangles join them.
  const int n = 24;
  std::vector<std::vector<double>> points;
  std::vector<std::vector<vtkIdType>> cells;
  const double twoPi = 2 * 3.14159265358979323846;
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      const double u = twoPi * i / n, v = twoPi * j / n;
      points.push_back({ (1 + 0.4 * std::cos(v)) * std::cos(u),
        (1 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v) });
    }
  }
  auto id = [&](int i, int j) { return static_cast<vtkIdType>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      cells.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      cells.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  Repaired r = Repair(Make(points, cells));
  ASSERT_EQ(r.error, "");
  const int seamPoints = 2 * (n + 1) - 1;
  int exact = 0; // seam points that are exactly equal (sin(0) and cos(0) computed alike)
  for (int k = 0; k <= n; ++k)
  {
    exact += points[id(0, k)] == points[id(n, k)];
    exact += k < n && points[id(k, 0)] == points[id(k, n)];
  }
  ASSERT_LT(exact, seamPoints) << "the test needs seams that round-off moved";
  EXPECT_EQ(r.Count(names::MergedPoints), seamPoints);
  const quadcover::MeshTopology topo = Topology(r.output);
  EXPECT_TRUE(topo.isClosed());
  EXPECT_EQ(topo.eulerCharacteristic(), 0);
  EXPECT_EQ(topo.numComponents(), 1);
}
