#include "vtkQuadCoverSurfaceRepair.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverInput.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "DegenerateTriangles.h"
#include "MeshTopology.h"
#include "SurfaceRefinement.h"
#include "SurfaceRepair.h"
#include "SurfaceSimplification.h"
#include "SurfaceSmoothing.h"
#include "TJunctions.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkQuadCoverSurfaceRepair);

namespace
{
/// What the repair changed (the field data it writes).
struct Counts
{
  vtkIdType mergedPoints = 0;
  vtkIdType removedCells = 0;
  vtkIdType triangulatedPolygons = 0;
  vtkIdType reorientedTriangles = 0;
  vtkIdType cutEdges = 0;
  vtkIdType splitVertices = 0;
  vtkIdType flippedEdges = 0;
  vtkIdType closedTJunctions = 0;
  vtkIdType refinedTriangles = 0;
  vtkIdType collapsedEdges = 0;
  vtkIdType smoothedPoints = 0;
};

/// Removes the repeated triangles and the components of zero area (quadcover::
/// redundantTriangles, on the points scaled as `in` says), with their cell data; returns how
/// many.
vtkIdType RemoveRedundantTriangles(vtkPolyData* surface, const vtkQuadCoverSurface& in)
{
  const std::vector<char> remove = quadcover::redundantTriangles(
    in.InCoreUnits(vtkQuadCoverEigen::Points(surface)), vtkQuadCoverEigen::Triangles(surface));
  vtkNew<vtkIdList> kept;
  for (vtkIdType c = 0; c < static_cast<vtkIdType>(remove.size()); ++c)
  {
    if (!remove[c])
    {
      kept->InsertNextId(c);
    }
  }
  const vtkIdType removed = static_cast<vtkIdType>(remove.size()) - kept->GetNumberOfIds();
  if (kept->GetNumberOfIds() == 0)
  {
    throw std::invalid_argument("every triangle of the input is degenerate (zero area)");
  }
  if (removed > 0)
  {
    // the kept triangles with their cell data, then the points no triangle uses dropped (the
    // points keep their precision and their data)
    vtkNew<vtkCellArray> polys;
    polys->AllocateExact(kept->GetNumberOfIds(), 3 * kept->GetNumberOfIds());
    vtkNew<vtkCellData> cellData;
    cellData->CopyAllocate(surface->GetCellData(), kept->GetNumberOfIds());
    vtkNew<vtkIdList> ids;
    for (vtkIdType i = 0; i < kept->GetNumberOfIds(); ++i)
    {
      surface->GetPolys()->GetCellAtId(kept->GetId(i), ids);
      polys->InsertNextCell(ids);
      cellData->CopyData(surface->GetCellData(), kept->GetId(i), i);
    }
    vtkNew<vtkPolyData> fewer;
    fewer->ShallowCopy(surface);
    fewer->SetPolys(polys);
    fewer->GetCellData()->ShallowCopy(cellData);
    vtkQuadCoverInput::RemoveUnusedPoints(fewer, surface);
  }
  return removed;
}

/// `tri` (triangles only) with its points within 1e-12 of the used points' bounding box diagonal
/// merged (round-off: parametric seams; quadcover::mergeCoincidentPoints), the points no
/// triangle uses left out and the triangles left with a repeated point removed, as
/// vtkCleanPolyData with that tolerance numbers and keeps them: point data from each merged
/// point's first point, cell data from the triangles kept, field data passed. `mergedPoints`:
/// the points the triangles use less those kept.
vtkSmartPointer<vtkPolyData> MergeCoincidentPoints(vtkPolyData* tri, vtkIdType& mergedPoints)
{
  const Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(tri);
  const Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(tri);
  Eigen::RowVector3d low = Eigen::RowVector3d::Zero(), high = Eigen::RowVector3d::Zero();
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::RowVector3d x = V.row(F(f, k));
      low = f == 0 && k == 0 ? x : low.cwiseMin(x);
      high = f == 0 && k == 0 ? x : high.cwiseMax(x);
    }
  }
  const double diagonal = (high - low).norm();
  const quadcover::MergedPoints merged =
    quadcover::mergeCoincidentPoints(V, F, std::isfinite(diagonal) ? 1e-12 * diagonal : 0.0);
  const vtkIdType n = static_cast<vtkIdType>(merged.source.size());
  mergedPoints =
    std::count_if(merged.pointOf.begin(), merged.pointOf.end(), [](int p) { return p >= 0; }) - n;
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(tri->GetPoints() ? tri->GetPoints()->GetDataType() : VTK_DOUBLE);
  points->SetNumberOfPoints(n);
  out->GetPointData()->CopyAllocate(tri->GetPointData(), n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Eigen::RowVector3d x = V.row(merged.source[i]); // (a row of V is not contiguous)
    points->SetPoint(i, x.data());
    out->GetPointData()->CopyData(tri->GetPointData(), merged.source[i], i);
  }
  out->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(F.rows(), 3 * F.rows());
  out->GetCellData()->CopyAllocate(tri->GetCellData(), F.rows());
  vtkIdType kept = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    const vtkIdType ids[3] = { merged.pointOf[F(f, 0)], merged.pointOf[F(f, 1)],
      merged.pointOf[F(f, 2)] };
    if (ids[0] != ids[1] && ids[1] != ids[2] && ids[2] != ids[0])
    {
      polys->InsertNextCell(3, ids);
      out->GetCellData()->CopyData(tri->GetCellData(), f, kept++);
    }
  }
  out->SetPolys(polys);
  out->GetCellData()->Squeeze();
  out->GetFieldData()->PassData(tri->GetFieldData());
  return out;
}

/// Makes `surface` manifold and consistently oriented (quadcover::makeManifold, on the points
/// scaled as `in` says): points copied with their point data, triangles reversed with their cell
/// normals. Counts go to `counts`.
void MakeManifold(vtkPolyData* surface, const vtkQuadCoverSurface& in, Counts& counts)
{
  const vtkIdType nv = surface->GetNumberOfPoints();
  Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(surface);
  Eigen::MatrixX3d scaled = in.InCoreUnits(V);
  Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(surface);
  const quadcover::ManifoldRepair repair = quadcover::makeManifold(scaled, F);
  // the output's points: the input's, then the copies (only these were added)
  V.conservativeResize(nv + static_cast<Eigen::Index>(repair.copies.size()), 3);
  for (std::size_t i = 0; i < repair.copies.size(); ++i)
  {
    V.row(nv + static_cast<Eigen::Index>(i)) = V.row(repair.copies[i]);
  }
  const quadcover::MeshTopology topo = quadcover::buildTopology(F, static_cast<int>(V.rows()));
  if (!topo.nonManifoldEdges.empty() || !topo.isOriented())
  {
    throw std::runtime_error(
      "the surface could not be cut into manifold sheets (" + topo.describeDefects() + " left)");
  }
  counts.cutEdges = repair.cutEdges;
  counts.splitVertices = static_cast<vtkIdType>(repair.copies.size());
  counts.reorientedTriangles = static_cast<vtkIdType>(repair.reversed.size());
  vtkSmartPointer<vtkPolyData> made = vtkQuadCoverEigen::ToPolyData(V, F);
  vtkNew<vtkPointData> pointData;
  pointData->CopyAllocate(surface->GetPointData(), V.rows());
  for (vtkIdType i = 0; i < V.rows(); ++i)
  {
    pointData->CopyData(surface->GetPointData(), i < nv ? i : repair.copies[i - nv], i);
  }
  if (vtkDataArray* normals = surface->GetCellData()->GetNormals())
  {
    vtkSmartPointer<vtkDataArray> turned = vtk::TakeSmartPointer(normals->NewInstance());
    turned->DeepCopy(normals);
    for (const int f : repair.reversed)
    {
      for (int c = 0; c < turned->GetNumberOfComponents(); ++c)
      {
        turned->SetComponent(f, c, -turned->GetComponent(f, c));
      }
    }
    surface->GetCellData()->SetNormals(turned);
  }
  surface->SetPoints(made->GetPoints());
  surface->GetPointData()->ShallowCopy(pointData);
  surface->SetPolys(made->GetPolys());
}

/// The triangles F as cells (`polys`), and `cellData` with each one's data copied from
/// `from`'s tuple `source[f]`.
void MakeTriangles(vtkCellData* from, const Eigen::MatrixX3i& F, const std::vector<int>& source,
  vtkCellArray* polys, vtkCellData* cellData)
{
  polys->AllocateExact(F.rows(), 3 * F.rows());
  cellData->CopyAllocate(from, F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    const vtkIdType ids[3] = { F(f, 0), F(f, 1), F(f, 2) };
    polys->InsertNextCell(3, ids);
    cellData->CopyData(from, source[f], f);
  }
}

/// Replaces the triangles of `surface` (its points stay) by F, each with the cell data of its
/// source triangle.
void ReplaceTriangles(
  vtkPolyData* surface, const Eigen::MatrixX3i& F, const std::vector<int>& source)
{
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkCellData> cellData;
  MakeTriangles(surface->GetCellData(), F, source, polys, cellData);
  surface->SetPolys(polys);
  surface->GetCellData()->ShallowCopy(cellData);
}

/// Closes the T-junctions of `surface` (quadcover::closeTJunctions, within TJunctionTolerance
/// of its bounding box's diagonal, on the points scaled as `in` says): the points stay, each
/// part of a split triangle takes its cell data. Counts go to `counts`.
void CloseTJunctions(vtkPolyData* surface, const vtkQuadCoverSurface& in, Counts& counts)
{
  const Eigen::MatrixX3d V = in.InCoreUnits(vtkQuadCoverEigen::Points(surface));
  Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(surface);
  if (V.rows() == 0)
  {
    return;
  }
  const double diagonal = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
  const quadcover::TJunctionSplits splits = quadcover::closeTJunctions(
    V, F, std::isfinite(diagonal) ? quadcover::TJunctionTolerance * diagonal : 0.0);
  counts.closedTJunctions = splits.closed;
  if (splits.closed == 0)
  {
    return;
  }
  ReplaceTriangles(surface, F, splits.triangleSource);
}

/// Flips the edges of `surface` that leave a flat triangle with a corner on the opposite
/// edge (quadcover::flipDegenerateTriangles, on the points scaled as `in` says): the points stay,
/// each new triangle takes the cell data of the proper triangle it lies in. Counts go to
/// `counts`.
void FlipDegenerateTriangles(vtkPolyData* surface, const vtkQuadCoverSurface& in, Counts& counts)
{
  Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(surface);
  const quadcover::DegenerateFlips flips =
    quadcover::flipDegenerateTriangles(in.InCoreUnits(vtkQuadCoverEigen::Points(surface)), F);
  counts.flippedEdges = flips.flippedEdges;
  if (flips.flippedEdges == 0)
  {
    return;
  }
  ReplaceTriangles(surface, F, flips.triangleSource);
}

/// Each triangle's unit normal written into `normals` (a cell normals array in its own type, or
/// nullptr: nothing to do).
void RemakeCellNormals(vtkDataArray* normals, const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  if (!normals)
  {
    return;
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    for (int k = 0; k < 3 && k < normals->GetNumberOfComponents(); ++k)
    {
      normals->SetComponent(f, k, std::isfinite(n[k]) ? n[k] : 0.0);
    }
  }
}

/// Brings `surface` down to about `maximum` triangles (quadcover::simplifySurface, on the
/// points scaled as `in` says): the kept points with their point data, the kept triangles with
/// their cell data. Counts go to `counts`.
void Simplify(
  vtkPolyData* surface, const vtkQuadCoverSurface& in, vtkIdType maximum, Counts& counts)
{
  if (maximum <= 0 || surface->GetNumberOfPolys() <= maximum)
  {
    return;
  }
  Eigen::MatrixX3d V = in.InCoreUnits(vtkQuadCoverEigen::Points(surface));
  Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(surface);
  const quadcover::Simplification s =
    quadcover::simplifySurface(V, F, std::max<vtkIdType>(maximum, 1000));
  counts.collapsedEdges = s.collapsedEdges;
  if (s.collapsedEdges == 0)
  {
    return;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(surface->GetPoints()->GetDataType());
  points->SetNumberOfPoints(static_cast<vtkIdType>(s.pointSource.size()));
  vtkNew<vtkPointData> pointData;
  pointData->CopyAllocate(surface->GetPointData(), points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, surface->GetPoint(s.pointSource[i]));
    pointData->CopyData(surface->GetPointData(), s.pointSource[i], i);
  }
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkCellData> cellData;
  MakeTriangles(surface->GetCellData(), F, s.triangleSource, polys, cellData);
  // a kept triangle may have a corner moved: its normal made again
  RemakeCellNormals(cellData->GetNormals(), V, F);
  surface->SetPoints(points);
  surface->SetPolys(polys);
  surface->GetPointData()->ShallowCopy(pointData);
  surface->GetCellData()->ShallowCopy(cellData);
}

/// Smooths the rough components of `surface` (quadcover::smoothRoughComponents, on the points
/// scaled as `in` says); counts go to `counts`.
void SmoothRoughComponents(vtkPolyData* surface, const vtkQuadCoverSurface& in, Counts& counts)
{
  Eigen::MatrixX3d V = in.InCoreUnits(vtkQuadCoverEigen::Points(surface));
  const Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(surface);
  counts.smoothedPoints = quadcover::smoothRoughComponents(V, F);
  if (counts.smoothedPoints == 0)
  {
    return;
  }
  const Eigen::MatrixX3d moved = in.InWorldUnits(V);
  vtkNew<vtkPoints> points;
  points->SetDataType(surface->GetPoints()->GetDataType());
  points->SetNumberOfPoints(moved.rows());
  for (Eigen::Index i = 0; i < moved.rows(); ++i)
  {
    const Eigen::RowVector3d x = moved.row(i); // (a row of V is not contiguous)
    points->SetPoint(i, x.data());
  }
  surface->SetPoints(points);
  // the moved triangles' normals made again (the cell data are the repair's own copy since the
  // points were merged); point normals no longer the surface's: dropped
  RemakeCellNormals(surface->GetCellData()->GetNormals(), V, F);
  surface->GetPointData()->SetNormals(nullptr);
}

/// Refines the components of `surface` with fewer than `minimum` triangles
/// (quadcover::refineCoarseComponents): point data interpolated at the midpoints, cell data
/// copied to the parts. Counts go to `counts`.
void RefineCoarseComponents(vtkPolyData* surface, int minimum, Counts& counts)
{
  Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(surface);
  Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(surface);
  const quadcover::Refinement r = quadcover::refineCoarseComponents(V, F, minimum);
  counts.refinedTriangles = r.refinedTriangles;
  if (r.refinedTriangles == 0)
  {
    return;
  }
  vtkSmartPointer<vtkPolyData> made = vtkQuadCoverEigen::ToPolyData(V, F);
  vtkQuadCoverEigen::CarryRefinedAttributes(surface, r.midpoints, r.parent, made);
  surface->SetPoints(made->GetPoints());
  surface->SetPolys(made->GetPolys());
  surface->GetPointData()->ShallowCopy(made->GetPointData());
  surface->GetCellData()->ShallowCopy(made->GetCellData());
}
}

//------------------------------------------------------------------------------
vtkQuadCoverSurfaceRepair::vtkQuadCoverSurfaceRepair()
  : vtkQuadCoverAlgorithm(ANY_POLYDATA, "repair the surface")
  , MinimumComponentTriangleCount(quadcover::RefinementOptions().minimumComponentTriangleCount)
  , SmoothRoughSurfaces(quadcover::RoughSurfaceOptions().smoothRoughSurfaces)
{}

//------------------------------------------------------------------------------
void vtkQuadCoverSurfaceRepair::Execute(vtkQuadCoverSurface& in, vtkInformationVector* outputVector)
{
  vtkPolyData* input = in.polyData;
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    throw std::invalid_argument("the input has no polygons (a surface of triangles is needed)");
  }
  Counts counts;
  vtkCellArray* cells = input->GetPolys();
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    counts.triangulatedPolygons += cells->GetCellSize(c) > 3 ? 1 : 0;
  }
  counts.triangulatedPolygons += input->GetNumberOfStrips();
  counts.removedCells += input->GetNumberOfVerts() + input->GetNumberOfLines();

  // Triangulate first (the degenerate joins of strips stay degenerate and are removed below);
  // cell data follows the triangles.
  vtkNew<vtkPolyData> tri;
  vtkQuadCoverInput::TriangulateCells(input, tri);
  this->UpdateProgress(0.25);

  // Merge coincident points (to round-off); triangles left with a repeated point are removed.
  vtkSmartPointer<vtkPolyData> cleaned = MergeCoincidentPoints(tri, counts.mergedPoints);
  counts.removedCells += tri->GetNumberOfPolys() - cleaned->GetNumberOfPolys();
  if (cleaned->GetNumberOfPolys() == 0)
  {
    throw std::invalid_argument("the input has no triangle with three distinct points");
  }
  this->UpdateProgress(0.5);
  tri->Initialize(); // the steps below replace the arrays: each copy lives only while needed

  // Repeated triangles and components of zero area removed (a repeat would hide its edges'
  // T-junctions); T-junctions closed; non-manifold edges cut apart, bowties split, each
  // component oriented, flat caps flipped away.
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->ShallowCopy(cleaned);
  cleaned = nullptr;
  counts.removedCells += RemoveRedundantTriangles(output, in);
  CloseTJunctions(output, in, counts);
  MakeManifold(output, in, counts);
  FlipDegenerateTriangles(output, in, counts);
  if (this->SmoothRoughSurfaces)
  {
    SmoothRoughComponents(output, in, counts);
    if (counts.smoothedPoints > 0)
    {
      this->Warn("the surface is rough at the triangle scale (noise): " +
        std::to_string(counts.smoothedPoints) +
        " points smoothed, the quads lie on the smoothed surface (SmoothRoughSurfaces off keeps "
        "it as it is)");
    }
  }
  Simplify(output, in, this->MaximumTriangleCount, counts);
  RefineCoarseComponents(output, this->MinimumComponentTriangleCount, counts);

  namespace names = vtkQuadCoverArrayNames;
  vtkFieldData* fd = output->GetFieldData();
  using vtkQuadCoverEigen::AddField;
  AddField<vtkIntArray>(fd, names::MergedPoints, { double(counts.mergedPoints) });
  AddField<vtkIntArray>(fd, names::RemovedCells, { double(counts.removedCells) });
  AddField<vtkIntArray>(fd, names::TriangulatedPolygons, { double(counts.triangulatedPolygons) });
  AddField<vtkIntArray>(fd, names::ReorientedTriangles, { double(counts.reorientedTriangles) });
  AddField<vtkIntArray>(fd, names::CutEdges, { double(counts.cutEdges) });
  AddField<vtkIntArray>(fd, names::SplitVertices, { double(counts.splitVertices) });
  AddField<vtkIntArray>(fd, names::FlippedEdges, { double(counts.flippedEdges) });
  AddField<vtkIntArray>(fd, names::ClosedTJunctions, { double(counts.closedTJunctions) });
  AddField<vtkIntArray>(fd, names::RefinedTriangles, { double(counts.refinedTriangles) });
  AddField<vtkIntArray>(fd, names::CollapsedEdges, { double(counts.collapsedEdges) });
  AddField<vtkIntArray>(fd, names::SmoothedPoints, { double(counts.smoothedPoints) });
}

//------------------------------------------------------------------------------
vtkIdType vtkQuadCoverSurfaceRepair::MaximumTriangleCountFor(
  vtkPolyData* surface, int targetQuadCount, double targetEdgeLength)
{
  const double quads = targetEdgeLength > 0.0 ? AreaInSquares(surface, targetEdgeLength)
                                              : static_cast<double>(targetQuadCount);
  return static_cast<vtkIdType>(
    std::min<long long>(quadcover::simplificationBudget(quads), 2000000000));
}

//------------------------------------------------------------------------------
double vtkQuadCoverSurfaceRepair::AreaInSquares(vtkPolyData* surface, double length)
{
  double area = 0.0;
  const vtkIdType n = surface->GetNumberOfPoints();
  vtkNew<vtkIdList> ids;
  for (int strips = 0; strips < 2; ++strips)
  {
    vtkCellArray* cells = strips ? surface->GetStrips() : surface->GetPolys();
    if (!cells)
    {
      continue;
    }
    for (cells->InitTraversal(); cells->GetNextCell(ids);)
    {
      // a polygon's triangles as a fan, a strip's as a strip
      for (vtkIdType k = 2; k < ids->GetNumberOfIds(); ++k)
      {
        const vtkIdType corners[3] = { ids->GetId(strips ? k - 2 : 0), ids->GetId(k - 1),
          ids->GetId(k) };
        if (std::any_of(corners, corners + 3, [n](vtkIdType p) { return p < 0 || p >= n; }))
        {
          continue; // refused by the repair
        }
        double x[3][3];
        for (int c = 0; c < 3; ++c)
        {
          surface->GetPoint(corners[c], x[c]);
        }
        Eigen::Vector3d u, v;
        for (int j = 0; j < 3; ++j)
        {
          u[j] = x[1][j] / length - x[0][j] / length;
          v[j] = x[2][j] / length - x[0][j] / length;
        }
        area += 0.5 * u.cross(v).norm();
      }
    }
  }
  return area;
}

//------------------------------------------------------------------------------
bool vtkQuadCoverSurfaceRepair::Simplified(vtkPolyData* repaired)
{
  vtkDataArray* a = repaired->GetFieldData()->GetArray(vtkQuadCoverArrayNames::CollapsedEdges);
  return a && a->GetNumberOfTuples() > 0 && a->GetTuple1(0) > 0;
}

//------------------------------------------------------------------------------
bool vtkQuadCoverSurfaceRepair::Smoothed(vtkPolyData* repaired)
{
  vtkDataArray* a = repaired->GetFieldData()->GetArray(vtkQuadCoverArrayNames::SmoothedPoints);
  return a && a->GetNumberOfTuples() > 0 && a->GetTuple1(0) > 0;
}

//------------------------------------------------------------------------------
void vtkQuadCoverSurfaceRepair::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumComponentTriangleCount: " << this->MinimumComponentTriangleCount << "\n";
  os << indent << "MaximumTriangleCount: " << this->MaximumTriangleCount << "\n";
  os << indent << "SmoothRoughSurfaces: " << (this->SmoothRoughSurfaces ? "On" : "Off") << "\n";
}
