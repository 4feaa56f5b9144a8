#include "vtkMatchingBuilder.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "Matchings.h"

#include <map>
#include <stdexcept>

vtkStandardNewMacro(vtkMatchingBuilder);

namespace
{
namespace names = vtkQuadCoverArrayNames;

/// `a` when it has `components` components and a tuple per cell of `surface`, else null.
vtkDataArray* CellArray(vtkDataArray* a, vtkPolyData* surface, int components)
{
  return a && a->GetNumberOfComponents() == components &&
      a->GetNumberOfTuples() == surface->GetNumberOfCells()
    ? a
    : nullptr;
}

/// Field data SingularityCount, SingularityHistogram, SingularityIndexSum and the costs.
void AddFigures(vtkFieldData* fd, const quadcover::MatchingResult& r, const vtkQuadCoverSurface& in)
{
  using vtkQuadCoverEigen::AddField;
  const quadcover::FrameTopology& t = r.topology;
  AddField<vtkIntArray>(fd, names::SingularityCount, { double(t.singularities) });
  std::map<double, int> histogram;
  for (Eigen::Index p = 0; p < t.index.size(); ++p)
  {
    if (!in.topo.boundaryVertex[p] && t.index[p] != 0.0)
    {
      histogram[t.index[p]] += 1;
    }
  }
  vtkNew<vtkDoubleArray> table;
  table->SetName(names::SingularityHistogram);
  table->SetNumberOfComponents(2);
  for (const auto& [value, count] : histogram)
  {
    table->InsertNextTuple2(value, count);
  }
  fd->AddArray(table);
  AddField<vtkDoubleArray>(fd, names::SingularityIndexSum, { t.index.sum() });
  AddField<vtkIntArray>(
    fd, names::BranchPointCount, { double(r.branchPointsBefore), double(t.branchPoints) });
  AddField<vtkDoubleArray>(fd, names::MatchingCost, { r.matchingCostBefore, t.matchingCost });
  AddField<vtkDoubleArray>(
    fd, names::BranchPointObjective, { r.objectiveBefore, r.objectiveAfter });
}

/// The branch points (non-zero layer shift) as vertices at the input's points, for glyphs.
void WriteBranchPoints(
  vtkPolyData* out, const quadcover::FrameTopology& t, const vtkQuadCoverSurface& in)
{
  const Eigen::MatrixXd V = in.InWorldUnits(in.V);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkDoubleArray> index;
  index->SetName(names::SingularityIndex);
  vtkNew<vtkIntArray> layer;
  layer->SetName(names::LayerShift);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName(names::SurfacePointId);
  for (vtkIdType p = 0; p < V.rows(); ++p)
  {
    if (t.layerShift[p] != 0)
    {
      const vtkIdType id = points->InsertNextPoint(V(p, 0), V(p, 1), V(p, 2));
      verts->InsertNextCell(1, &id);
      index->InsertNextValue(t.index[p]);
      layer->InsertNextValue(t.layerShift[p]);
      ids->InsertNextValue(p);
    }
  }
  out->SetPoints(points);
  out->SetVerts(verts);
  out->GetPointData()->AddArray(index);
  out->GetPointData()->AddArray(layer);
  out->GetPointData()->AddArray(ids);
}
}

//------------------------------------------------------------------------------
vtkMatchingBuilder::vtkMatchingBuilder()
  : vtkQuadCoverAlgorithm(MANIFOLD_SURFACE, "build matchings")
{
  const quadcover::MatchingOptions defaults;
  this->OptimizeBranchPoints = defaults.optimizeBranchPoints;
  this->BranchPointWeight = defaults.branchPoints.branchPointWeight;
  this->MaximumSearchSize = defaults.branchPoints.maximumSearchSize;
  this->LengthScaledCost = defaults.branchPoints.lengthScaledCost;
  this->BoundaryTolerance = defaults.branchPoints.boundaryTolerance;
  this->FitFramesToMatchings = defaults.fitFramesToMatchings;
  this->SetNumberOfOutputPorts(2);
  const int cells = vtkDataObject::FIELD_ASSOCIATION_CELLS;
  this->SetInputArrayToProcess(0, 0, 0, cells, names::FrameU);
  this->SetInputArrayToProcess(1, 0, 0, cells, names::FrameV);
  this->SetInputArrayToProcess(2, 0, 0, cells, names::FrameWeight);
  this->SetInputArrayToProcess(3, 0, 0, cells, names::FrameConstrained);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkMatchingBuilder::GetBranchPointsOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
void vtkMatchingBuilder::Execute(vtkQuadCoverSurface& in, vtkInformationVector* outputVector)
{
  const vtkIdType nf = in.NumberOfTriangles();
  vtkDataArray* u = this->RequireCellArray(0, in.polyData, 3, names::FrameU,
    "run vtkCurvatureFrames and vtkFrameSmoother first, or name your own with "
    "SetInputArrayToProcess");
  const Eigen::MatrixX3d U = vtkQuadCoverEigen::FromArray3(u);
  if (!U.allFinite())
  {
    throw std::invalid_argument(
      std::string(u->GetName() ? u->GetName() : names::FrameU) + " has non-finite values");
  }
  this->UpdateProgress(0.1);
  const quadcover::FrameGeometry geometry = quadcover::computeFrameGeometry(in.V, in.F, in.topo);
  vtkDataArray* v = CellArray(this->GetInputArrayToProcess(1, in.polyData), in.polyData, 3);
  vtkDataArray* w = CellArray(this->GetInputArrayToProcess(2, in.polyData), in.polyData, 1);
  vtkDataArray* h = CellArray(this->GetInputArrayToProcess(3, in.polyData), in.polyData, 1);
  std::vector<char> held(h ? nf : 0);
  for (vtkIdType f = 0; f < static_cast<vtkIdType>(held.size()); ++f)
  {
    held[f] = h->GetComponent(f, 0) != 0.0;
  }
  vtkQuadCoverEigen::RequireNumbers({ { "BranchPointWeight", this->BranchPointWeight },
    { "BoundaryTolerance", this->BoundaryTolerance } });
  quadcover::MatchingOptions options;
  options.optimizeBranchPoints = this->OptimizeBranchPoints;
  options.fitFramesToMatchings = this->FitFramesToMatchings;
  options.branchPoints.branchPointWeight = this->BranchPointWeight;
  options.branchPoints.maximumSearchSize = this->MaximumSearchSize;
  options.branchPoints.lengthScaledCost = this->LengthScaledCost;
  options.branchPoints.boundaryTolerance = this->BoundaryTolerance;
  const quadcover::MatchingResult r = quadcover::buildMatchings(in.V, in.F, in.topo, geometry, U,
    v ? vtkQuadCoverEigen::FromArray3(v) : Eigen::MatrixX3d(),
    w ? Eigen::VectorXd(vtkQuadCoverEigen::FromArray(w)) : Eigen::VectorXd(), held, options,
    vtkQuadCoverEigen::CoreProgress(this, 0.15, 0.9));

  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->ShallowCopy(in.polyData);
  using vtkQuadCoverEigen::ToArray;
  if (r.framesFitted)
  {
    // new arrays: the input's stay untouched
    output->GetCellData()->AddArray(ToArray(r.frameU, u->GetName()));
    output->GetCellData()->AddArray(
      ToArray(r.frameV, v && v->GetName() ? v->GetName() : names::FrameV));
  }
  output->GetCellData()->AddArray(ToArray<vtkIntArray>(r.topology.matching, names::Matching));
  output->GetPointData()->AddArray(ToArray<vtkIntArray>(r.topology.layerShift, names::LayerShift));
  output->GetPointData()->AddArray(ToArray(r.topology.index, names::SingularityIndex));
  AddFigures(output->GetFieldData(), r, in);
  WriteBranchPoints(vtkPolyData::GetData(outputVector, 1), r.topology, in);
}

//------------------------------------------------------------------------------
void vtkMatchingBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OptimizeBranchPoints: " << (this->OptimizeBranchPoints ? "On" : "Off") << "\n";
  os << indent << "BranchPointWeight: " << this->BranchPointWeight << "\n";
  os << indent << "MaximumSearchSize: " << this->MaximumSearchSize << "\n";
  os << indent << "LengthScaledCost: " << (this->LengthScaledCost ? "On" : "Off") << "\n";
  os << indent << "BoundaryTolerance: " << this->BoundaryTolerance << "\n";
  os << indent << "FitFramesToMatchings: " << (this->FitFramesToMatchings ? "On" : "Off") << "\n";
}
