// TestvtkQuadCoverInput.cxx: vtkQuadCoverInput's triangulation and removal of unused points make
// what the VTK filters they stand in for make (vtkTriangleFilter, vtkCleanPolyData).
#include "vtkQuadCoverInput.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
/// The cells of `cells` as lists of point ids.
std::vector<std::vector<vtkIdType>> CellsOf(vtkCellArray* cells)
{
  std::vector<std::vector<vtkIdType>> list;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    cells->GetCellAtId(c, ids);
    list.emplace_back(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
  }
  return list;
}

/// The values of the array `name` of `data`.
std::vector<double> ValuesOf(vtkFieldData* data, const char* name)
{
  vtkDataArray* array = vtkDataArray::SafeDownCast(data->GetAbstractArray(name));
  std::vector<double> values;
  for (vtkIdType i = 0; array && i < array->GetNumberOfTuples(); ++i)
  {
    values.push_back(array->GetTuple1(i));
  }
  return values;
}

/// Points on a wavy sheet, vertices, lines, polygons of 1 to 12 points (convex, concave, with a
/// repeated point, non-planar) and strips, each cell numbered in a cell array, each point in a
/// point array, and a field array.
vtkNew<vtkPolyData> MixedCells()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkIntArray> pointNumber;
  pointNumber->SetName("pointNumber");
  for (int i = 0; i < 12; ++i)
  {
    for (int j = 0; j < 12; ++j)
    {
      points->InsertNextPoint(i, j, 0.3 * std::sin(i + 2.0 * j));
      pointNumber->InsertNextValue(12 * i + j);
    }
  }
  auto id = [](int i, int j) { return static_cast<vtkIdType>(12 * i + j); };
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  const vtkIdType vert[] = { id(0, 0), id(1, 1) };
  verts->InsertNextCell(2, vert);
  const vtkIdType line[] = { id(0, 1), id(0, 2), id(0, 3) };
  lines->InsertNextCell(3, line);
  const vtkIdType triangle[] = { id(1, 1), id(2, 1), id(2, 2) };
  polys->InsertNextCell(3, triangle);
  const vtkIdType quad[] = { id(3, 3), id(4, 3), id(4, 4), id(3, 4) };
  polys->InsertNextCell(4, quad);
  const vtkIdType concave[] = { id(5, 0), id(9, 0), id(9, 4), id(7, 2), id(5, 4) };
  polys->InsertNextCell(5, concave);
  const vtkIdType repeated[] = { id(0, 6), id(1, 6), id(1, 6), id(1, 7), id(0, 7) };
  polys->InsertNextCell(5, repeated);
  const vtkIdType two[] = { id(2, 9), id(3, 9) };
  polys->InsertNextCell(2, two);
  std::vector<vtkIdType> ring; // twelve points around a non-planar loop
  for (int k = 0; k < 4; ++k)
  {
    ring.push_back(id(6 + k, 6));
  }
  for (int k = 0; k < 4; ++k)
  {
    ring.push_back(id(10, 6 + k));
  }
  for (int k = 0; k < 4; ++k)
  {
    ring.push_back(id(10 - k, 10));
  }
  polys->InsertNextCell(static_cast<vtkIdType>(ring.size()), ring.data());
  const vtkIdType strip[] = { id(0, 10), id(1, 10), id(0, 11), id(1, 11), id(1, 11), id(2, 10),
    id(2, 11) };
  strips->InsertNextCell(7, strip);
  const vtkIdType shortStrip[] = { id(3, 10), id(4, 10), id(3, 11) };
  strips->InsertNextCell(3, shortStrip);
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetVerts(verts);
  surface->SetLines(lines);
  surface->SetPolys(polys);
  surface->SetStrips(strips);
  surface->GetPointData()->AddArray(pointNumber);
  vtkNew<vtkIntArray> cellNumber;
  cellNumber->SetName("cellNumber");
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    cellNumber->InsertNextValue(static_cast<int>(c));
  }
  surface->GetCellData()->AddArray(cellNumber);
  vtkNew<vtkDoubleArray> field;
  field->SetName("field");
  field->InsertNextValue(7.0);
  surface->GetFieldData()->AddArray(field);
  return surface;
}
}

TEST(QuadCoverInput, TriangulateCellsMakesWhatTheTriangleFilterMakes)
{
  vtkNew<vtkPolyData> surface = MixedCells();
  vtkNew<vtkTriangleFilter> filter;
  filter->SetInputData(surface);
  filter->PassVertsOff();
  filter->PassLinesOff();
  filter->Update();
  vtkPolyData* expected = filter->GetOutput();
  vtkNew<vtkPolyData> made;
  vtkQuadCoverInput::TriangulateCells(surface, made);
  EXPECT_EQ(CellsOf(made->GetPolys()), CellsOf(expected->GetPolys()));
  EXPECT_GT(made->GetNumberOfPolys(), 15); // the polygons and strips gave triangles
  EXPECT_EQ(made->GetNumberOfVerts() + made->GetNumberOfLines(), 0);
  EXPECT_EQ(
    ValuesOf(made->GetCellData(), "cellNumber"), ValuesOf(expected->GetCellData(), "cellNumber"));
  EXPECT_EQ(made->GetPoints(), surface->GetPoints());
  EXPECT_EQ(ValuesOf(made->GetPointData(), "pointNumber"),
    ValuesOf(surface->GetPointData(), "pointNumber"));
  EXPECT_EQ(ValuesOf(made->GetFieldData(), "field"), std::vector<double>{ 7.0 });
}

TEST(QuadCoverInput, RemoveUnusedPointsMakesWhatTheCleanFilterMakes)
{
  // the triangles of the mixed cells but those that repeat a point, over every other point
  vtkNew<vtkPolyData> triangles;
  vtkQuadCoverInput::TriangulateCells(MixedCells(), triangles);
  vtkNew<vtkCellArray> proper;
  vtkNew<vtkIntArray> cellNumber;
  cellNumber->SetName("cellNumber");
  const std::vector<std::vector<vtkIdType>> cells = CellsOf(triangles->GetPolys());
  for (std::size_t c = cells.size(); c-- > 0;) // backwards: the points come first used anew
  {
    const std::vector<vtkIdType>& t = cells[c];
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
    {
      proper->InsertNextCell(3, t.data());
      cellNumber->InsertNextValue(static_cast<int>(c));
    }
  }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(triangles->GetPoints());
  surface->GetPointData()->ShallowCopy(triangles->GetPointData());
  surface->SetPolys(proper);
  surface->GetCellData()->AddArray(cellNumber);
  surface->GetFieldData()->ShallowCopy(triangles->GetFieldData());

  vtkNew<vtkCleanPolyData> filter;
  filter->SetInputData(surface);
  filter->PointMergingOff();
  filter->ConvertPolysToLinesOff();
  filter->ConvertLinesToPointsOff();
  filter->ConvertStripsToPolysOff();
  filter->Update();
  vtkPolyData* expected = filter->GetOutput();
  vtkNew<vtkPolyData> made;
  vtkQuadCoverInput::RemoveUnusedPoints(surface, made);
  ASSERT_LT(made->GetNumberOfPoints(), surface->GetNumberOfPoints());
  ASSERT_EQ(made->GetNumberOfPoints(), expected->GetNumberOfPoints());
  for (vtkIdType p = 0; p < made->GetNumberOfPoints(); ++p)
  {
    double a[3], b[3];
    made->GetPoint(p, a);
    expected->GetPoint(p, b);
    EXPECT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << "point " << p;
  }
  EXPECT_EQ(made->GetPoints()->GetDataType(), expected->GetPoints()->GetDataType());
  EXPECT_EQ(CellsOf(made->GetPolys()), CellsOf(expected->GetPolys()));
  EXPECT_EQ(ValuesOf(made->GetPointData(), "pointNumber"),
    ValuesOf(expected->GetPointData(), "pointNumber"));
  EXPECT_EQ(
    ValuesOf(made->GetCellData(), "cellNumber"), ValuesOf(expected->GetCellData(), "cellNumber"));
  EXPECT_EQ(ValuesOf(made->GetFieldData(), "field"), std::vector<double>{ 7.0 });
}
