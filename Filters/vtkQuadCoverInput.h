// vtkQuadCoverInput.h (private): the input checks and repairs every QuadCover filter shares.
#ifndef vtkQuadCoverInput_h
#define vtkQuadCoverInput_h

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <string>

namespace vtkQuadCoverInput
{
/**
 * Makes `out` a triangle-only surface over `in`: a shallow copy when `in` holds only triangles,
 * else the result of vtkTriangleFilter (polygons and strips triangulated, cell data copied to the
 * new triangles, vertices and lines dropped: `warning` says so).
 * @return "" on success, else a one-line reason (no points, no polygons, non-finite points).
 */
inline std::string Triangulate(vtkPolyData* in, vtkPolyData* out, std::string& warning)
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
  const vtkIdType n = in->GetNumberOfPoints();
  double p[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    in->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "point " + std::to_string(i) + " has a non-finite (NaN or infinite) coordinate";
    }
  }
  const vtkIdType dropped = in->GetNumberOfVerts() + in->GetNumberOfLines();
  bool onlyTriangles = in->GetNumberOfStrips() == 0 && dropped == 0;
  if (onlyTriangles)
  {
    vtkCellArray* polys = in->GetPolys();
    for (vtkIdType c = 0; c < polys->GetNumberOfCells() && onlyTriangles; ++c)
    {
      onlyTriangles = polys->GetCellSize(c) == 3;
    }
  }
  if (onlyTriangles)
  {
    out->ShallowCopy(in);
    return "";
  }
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputData(in);
  tri->PassVertsOff();
  tri->PassLinesOff();
  tri->Update();
  out->ShallowCopy(tri->GetOutput());
  if (dropped > 0)
  {
    warning = std::to_string(dropped) + " vertex and line cells were dropped (surfaces only)";
  }
  if (out->GetNumberOfPolys() == 0)
  {
    return "the input's polygons are all degenerate (no triangle left)";
  }
  return "";
}
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverInput.h
