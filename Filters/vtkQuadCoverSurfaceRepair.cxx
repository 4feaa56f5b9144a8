#include "vtkQuadCoverSurfaceRepair.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkTriangleFilter.h"

#include "MeshTopology.h"

#include <algorithm>
#include <stdexcept>

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
  vtkIdType splitVertices = 0;
};

/// Updates a VTK filter on `input`; its first error is thrown.
void Run(vtkAlgorithm* filter, vtkPolyData* input)
{
  filter->SetInputDataObject(input);
  const std::string error = vtkQuadCoverErrorObserver::Run(filter);
  if (!error.empty())
  {
    throw std::runtime_error(error);
  }
}

/// Points the polygons use.
vtkIdType UsedPoints(vtkPolyData* pd)
{
  std::vector<char> referenced(pd->GetNumberOfPoints(), 0);
  vtkIdType used = 0;
  vtkNew<vtkIdList> ids;
  for (pd->GetPolys()->InitTraversal(); pd->GetPolys()->GetNextCell(ids);)
  {
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      used += referenced[ids->GetId(k)] ? 0 : 1;
      referenced[ids->GetId(k)] = 1;
    }
  }
  return used;
}

/// Triangles whose point list differs between a and b (vtkPolyDataNormals reverses a triangle it
/// turns over).
vtkIdType TurnedTriangles(vtkPolyData* a, vtkPolyData* b)
{
  vtkCellArray* ca = a->GetPolys();
  vtkCellArray* cb = b->GetPolys();
  vtkNew<vtkIdList> ia, ib;
  vtkIdType turned = 0;
  for (vtkIdType c = 0; c < ca->GetNumberOfCells() && c < cb->GetNumberOfCells(); ++c)
  {
    ca->GetCellAtId(c, ia);
    cb->GetCellAtId(c, ib);
    bool same = ia->GetNumberOfIds() == ib->GetNumberOfIds();
    for (vtkIdType k = 0; same && k < ia->GetNumberOfIds(); ++k)
    {
      same = ia->GetId(k) == ib->GetId(k);
    }
    turned += same ? 0 : 1;
  }
  return turned;
}

/// Gives every fan of triangles at a bowtie point its own copy of the point (point data
/// copied along); refuses non-manifold edges.
vtkIdType SplitBowties(vtkPolyData* surface)
{
  const vtkIdType nv = surface->GetNumberOfPoints();
  Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(surface);
  Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(surface);
  const quadcover::MeshTopology topo = quadcover::buildTopology(F, static_cast<int>(nv));
  if (!topo.nonManifoldEdges.empty())
  {
    throw std::invalid_argument("the surface has " + std::to_string(topo.nonManifoldEdges.size()) +
      " non-manifold edges (more than two triangles on one edge); QuadCover needs a manifold "
      "surface");
  }
  if (topo.nonManifoldVertices.empty())
  {
    return 0;
  }
  const std::vector<int> copies = quadcover::splitNonManifoldVertices(V, F);
  vtkSmartPointer<vtkPolyData> split = vtkQuadCoverEigen::ToPolyData(V, F);
  vtkNew<vtkPointData> pointData;
  pointData->CopyAllocate(surface->GetPointData(), V.rows());
  for (vtkIdType i = 0; i < V.rows(); ++i)
  {
    pointData->CopyData(surface->GetPointData(), i < nv ? i : copies[i - nv], i);
  }
  surface->SetPoints(split->GetPoints());
  surface->GetPointData()->ShallowCopy(pointData);
  surface->SetPolys(split->GetPolys());
  return static_cast<vtkIdType>(copies.size());
}
}

//------------------------------------------------------------------------------
vtkQuadCoverSurfaceRepair::vtkQuadCoverSurfaceRepair()
  : vtkQuadCoverAlgorithm(ANY_POLYDATA, "repair the surface")
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
  vtkNew<vtkTriangleFilter> triangles;
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  Run(triangles.Get(), input);
  vtkPolyData* tri = triangles->GetOutput();
  this->UpdateProgress(0.25);

  // Merge exactly coincident points; triangles left with a repeated point are removed.
  vtkNew<vtkCleanPolyData> clean;
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->ConvertStripsToPolysOff();
  Run(clean.Get(), tri);
  vtkPolyData* cleaned = clean->GetOutput();
  counts.mergedPoints = std::max<vtkIdType>(0, UsedPoints(tri) - cleaned->GetNumberOfPoints());
  counts.removedCells += tri->GetNumberOfPolys() - cleaned->GetNumberOfPolys();
  if (cleaned->GetNumberOfPolys() == 0)
  {
    throw std::invalid_argument("the input has no triangle with three distinct points");
  }
  this->UpdateProgress(0.5);

  // Orientation: neighbours made to agree.
  vtkNew<vtkPolyDataNormals> orient;
  orient->ConsistencyOn();
  orient->SplittingOff();
  orient->ComputePointNormalsOff();
  orient->ComputeCellNormalsOn(); // with neither kind of normal requested it reorients nothing
  orient->AutoOrientNormalsOff();
  orient->NonManifoldTraversalOff();
  Run(orient.Get(), cleaned);
  counts.reorientedTriangles = TurnedTriangles(cleaned, orient->GetOutput());
  this->UpdateProgress(0.75);

  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->ShallowCopy(orient->GetOutput());
  if (!cleaned->GetCellData()->GetArray("Normals"))
  {
    output->GetCellData()->RemoveArray("Normals"); // the by-product of the reorientation
  }
  counts.splitVertices = SplitBowties(output);

  namespace names = vtkQuadCoverArrayNames;
  vtkFieldData* fd = output->GetFieldData();
  using vtkQuadCoverEigen::AddField;
  AddField<vtkIntArray>(fd, names::MergedPoints, { double(counts.mergedPoints) });
  AddField<vtkIntArray>(fd, names::RemovedCells, { double(counts.removedCells) });
  AddField<vtkIntArray>(fd, names::TriangulatedPolygons, { double(counts.triangulatedPolygons) });
  AddField<vtkIntArray>(fd, names::ReorientedTriangles, { double(counts.reorientedTriangles) });
  AddField<vtkIntArray>(fd, names::SplitVertices, { double(counts.splitVertices) });
}

//------------------------------------------------------------------------------
void vtkQuadCoverSurfaceRepair::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
