#include "vtkQuadCoverInput.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolygon.h"
#include "vtkTriangleStrip.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
/// Three distinct point ids: a triangle that can carry surface.
bool ProperTriangle(vtkIdList* cell)
{
  return cell->GetNumberOfIds() == 3 && cell->GetId(0) != cell->GetId(1) &&
    cell->GetId(1) != cell->GetId(2) && cell->GetId(2) != cell->GetId(0);
}

/// "" when every point id of every cell lies in [0, #points) and #points fits an int.
std::string CheckPointIds(vtkPolyData* in)
{
  const vtkIdType n = in->GetNumberOfPoints();
  if (n > static_cast<vtkIdType>(std::numeric_limits<int>::max()))
  {
    return "more than 2^31 points are not supported";
  }
  vtkCellArray* arrays[4] = { in->GetVerts(), in->GetLines(), in->GetPolys(), in->GetStrips() };
  const char* kinds[4] = { "vertex", "line", "polygon", "strip" };
  for (int a = 0; a < 4; ++a)
  {
    vtkCellArray* cells = arrays[a];
    if (!cells)
    {
      continue;
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      cells->GetCellAtId(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        if (ids->GetId(k) < 0 || ids->GetId(k) >= n)
        {
          return std::string(kinds[a]) + " cell " + std::to_string(c) + " refers to point " +
            std::to_string(ids->GetId(k)) + ", but there are only " + std::to_string(n) + " points";
        }
      }
    }
  }
  return "";
}

/// "" when every point coordinate is finite.
std::string CheckFinitePoints(vtkPolyData* in)
{
  double p[3];
  for (vtkIdType i = 0; i < in->GetNumberOfPoints(); ++i)
  {
    in->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "point " + std::to_string(i) + " has a non-finite (NaN or infinite) coordinate";
    }
  }
  return "";
}
}

namespace vtkQuadCoverInput
{
std::string CheckPoints(vtkPolyData* in)
{
  if (!in || in->GetNumberOfPoints() == 0)
  {
    return "the input has no points";
  }
  const std::string ids = CheckPointIds(in);
  return ids.empty() ? CheckFinitePoints(in) : ids;
}

std::string Triangulate(vtkPolyData* in, vtkPolyData* out, std::string& warning)
{
  warning.clear();
  if (!in || in->GetNumberOfPoints() == 0)
  {
    return "the input has no points";
  }
  const vtkIdType numPolys = in->GetNumberOfPolys() + in->GetNumberOfStrips();
  if (numPolys == 0)
  {
    return "the input has no polygons (a surface of triangles is needed)";
  }
  const std::string problem = CheckPoints(in);
  if (!problem.empty())
  {
    return problem;
  }
  const vtkIdType droppedCells = in->GetNumberOfVerts() + in->GetNumberOfLines();
  bool onlyTriangles = in->GetNumberOfStrips() == 0 && droppedCells == 0;
  if (onlyTriangles)
  {
    vtkCellArray* polys = in->GetPolys();
    vtkNew<vtkIdList> cell;
    for (vtkIdType c = 0; c < polys->GetNumberOfCells() && onlyTriangles; ++c)
    {
      polys->GetCellAtId(c, cell);
      onlyTriangles = ProperTriangle(cell);
    }
  }
  if (onlyTriangles)
  {
    out->ShallowCopy(in);
    return "";
  }
  vtkNew<vtkPolyData> t;
  TriangulateCells(in, t);

  // Keep the triangles with three distinct points, with their cell data.
  vtkNew<vtkCellArray> kept;
  vtkNew<vtkIdList> keptIds;
  vtkNew<vtkIdList> cell;
  vtkCellArray* polys = t->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, cell);
    if (ProperTriangle(cell))
    {
      kept->InsertNextCell(cell);
      keptIds->InsertNextId(c);
    }
  }
  const vtkIdType droppedTriangles = polys->GetNumberOfCells() - keptIds->GetNumberOfIds();
  out->ShallowCopy(t);
  if (droppedTriangles > 0)
  {
    vtkNew<vtkCellData> cd;
    cd->CopyAllocate(t->GetCellData(), keptIds->GetNumberOfIds());
    for (vtkIdType i = 0; i < keptIds->GetNumberOfIds(); ++i)
    {
      cd->CopyData(t->GetCellData(), keptIds->GetId(i), i);
    }
    out->SetPolys(kept);
    out->GetCellData()->ShallowCopy(cd);
  }
  if (droppedCells > 0 || droppedTriangles > 0)
  {
    warning = std::to_string(droppedCells) + " vertex/line cells and " +
      std::to_string(droppedTriangles) + " triangles that repeat a point were dropped";
  }
  if (out->GetNumberOfPolys() == 0)
  {
    return "the input's polygons are all degenerate (no triangle left)";
  }
  return "";
}

void TriangulateCells(vtkPolyData* input, vtkPolyData* output)
{
  vtkCellData* inCD = input->GetCellData();
  vtkNew<vtkCellData> outCD;
  outCD->CopyAllocate(inCD, input->GetNumberOfCells());
  vtkNew<vtkCellArray> triangles;
  vtkIdType source = input->GetNumberOfVerts() + input->GetNumberOfLines(); // the cell ids
  vtkIdType made = 0;
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> corners;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++source)
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCurrentCell(n, ids);
    if (n == 3)
    {
      triangles->InsertNextCell(3, ids);
      outCD->CopyData(inCD, source, made++);
      continue;
    }
    if (n == 0)
    {
      continue;
    }
    polygon->PointIds->SetNumberOfIds(n);
    polygon->Points->SetNumberOfPoints(n);
    for (vtkIdType k = 0; k < n; ++k)
    {
      polygon->PointIds->SetId(k, ids[k]);
      polygon->Points->SetPoint(k, input->GetPoint(ids[k]));
    }
    polygon->Triangulate(corners); // local ids, three a triangle
    for (vtkIdType t = 0; t + 2 < corners->GetNumberOfIds(); t += 3)
    {
      const vtkIdType triangle[3] = { polygon->PointIds->GetId(corners->GetId(t)),
        polygon->PointIds->GetId(corners->GetId(t + 1)),
        polygon->PointIds->GetId(corners->GetId(t + 2)) };
      triangles->InsertNextCell(3, triangle);
      outCD->CopyData(inCD, source, made++);
    }
  }
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++source)
  {
    vtkIdType n;
    const vtkIdType* ids;
    strips->GetCurrentCell(n, ids);
    vtkTriangleStrip::DecomposeStrip(static_cast<int>(n), ids, triangles);
    for (vtkIdType k = 0; k + 2 < n; ++k)
    {
      outCD->CopyData(inCD, source, made++);
    }
  }
  outCD->Squeeze();
  vtkNew<vtkPolyData> result;
  result->SetPoints(input->GetPoints());
  result->GetPointData()->PassData(input->GetPointData());
  result->SetPolys(triangles);
  result->GetCellData()->ShallowCopy(outCD);
  result->GetFieldData()->PassData(input->GetFieldData());
  output->ShallowCopy(result);
}

void RemoveUnusedPoints(vtkPolyData* input, vtkPolyData* output)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<vtkIdType> newId(static_cast<std::size_t>(n), -1);
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  vtkPointData* inPD = input->GetPointData();
  vtkNew<vtkPointData> outPD;
  outPD->CopyAllOn(vtkDataSetAttributes::COPYTUPLE);
  outPD->CopyAllocate(inPD);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(
    input->GetPolys()->GetNumberOfCells(), input->GetPolys()->GetNumberOfConnectivityIds());
  std::vector<vtkIdType> renamed;
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    renamed.assign(ids, ids + size);
    for (vtkIdType& id : renamed)
    {
      vtkIdType& to = newId[static_cast<std::size_t>(id)];
      if (to < 0)
      {
        to = points->InsertNextPoint(input->GetPoint(id));
        outPD->CopyData(inPD, id, to);
      }
      id = to;
    }
    polys->InsertNextCell(size, renamed.data());
  }
  vtkNew<vtkPolyData> result;
  result->SetPoints(points);
  result->GetPointData()->ShallowCopy(outPD);
  result->SetPolys(polys);
  result->GetCellData()->PassData(input->GetCellData());
  result->GetFieldData()->PassData(input->GetFieldData());
  output->ShallowCopy(result);
}

int UnitScaleExponent(vtkPolyData* in)
{
  if (!in || !in->GetPoints() || in->GetNumberOfPoints() == 0)
  {
    return 0;
  }
  double b[6];
  in->GetPoints()->GetBounds(b);
  // half the largest side: halving first, so that no difference overflows
  double half = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    half = std::max(half, 0.5 * b[2 * axis + 1] - 0.5 * b[2 * axis]);
  }
  // the largest side (2 half) in [2^-16, 2^16]: an ordinary size, computed as it is
  if ((half >= 0x1p-17 && half <= 0x1p15) || !(half > 0.0) || !std::isfinite(half))
  {
    return 0;
  }
  // half in [2^k, 2^(k+1)), the largest side in [2^(k+1), 2^(k+2)): times 2^-(k+1) in [1, 2)
  const int k = std::ilogb(half);
  return std::clamp(-(k + 1), -1022, 1022);
}
}
