#include "vtkMatchingBuilder.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "Matchings.h"

#include <exception>
#include <map>

vtkStandardNewMacro(vtkMatchingBuilder);

//------------------------------------------------------------------------------
vtkMatchingBuilder::vtkMatchingBuilder()
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkQuadCoverArrayNames::FrameU);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkMatchingBuilder::GetBranchPointsOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkMatchingBuilder::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  namespace names = vtkQuadCoverArrayNames;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* branchOutput = vtkPolyData::GetData(outputVector, 1);

  vtkNew<vtkPolyData> surface;
  vtkQuadCoverEigen::Mesh mesh;
  std::string warning;
  const std::string problem = vtkQuadCoverEigen::Load(
    input, surface, mesh, vtkQuadCoverEigen::Needs::ManifoldSurface, warning);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Cannot build matchings: " << problem << ".");
    return 0;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }
  const vtkIdType nf = mesh.F.rows();
  vtkDataArray* u = this->GetInputArrayToProcess(0, surface);
  const std::string missing = vtkQuadCoverEigen::CheckCellArray3(u, nf, names::FrameU,
    "run vtkCurvatureFrames and vtkFrameSmoother first, or name your own with "
    "SetInputArrayToProcess");
  if (!missing.empty())
  {
    vtkErrorMacro(<< "Cannot build matchings: " << missing << ".");
    return 0;
  }
  this->UpdateProgress(0.1);

  try
  {
    const quadcover::FrameGeometry geometry =
      quadcover::computeFrameGeometry(mesh.V, mesh.F, mesh.topo);
    const Eigen::MatrixX3d U = vtkQuadCoverEigen::FromArray3(u);
    if (!U.allFinite())
    {
      vtkErrorMacro(<< "Cannot build matchings: " << names::FrameU << " has non-finite values.");
      return 0;
    }
    vtkCellData* inCD = surface->GetCellData();
    vtkDataArray* v = inCD->GetArray(names::FrameV);
    vtkDataArray* w = inCD->GetArray(names::FrameWeight);
    vtkDataArray* h = inCD->GetArray(names::FrameConstrained);
    Eigen::VectorXd weight;
    if (w && w->GetNumberOfComponents() == 1 && w->GetNumberOfTuples() == nf)
    {
      weight.resize(nf);
      for (vtkIdType f = 0; f < nf; ++f)
      {
        weight[f] = w->GetComponent(f, 0);
      }
    }
    std::vector<char> held;
    if (h && h->GetNumberOfComponents() == 1 && h->GetNumberOfTuples() == nf)
    {
      held.resize(nf);
      for (vtkIdType f = 0; f < nf; ++f)
      {
        held[f] = h->GetComponent(f, 0) != 0.0;
      }
    }
    quadcover::MatchingOptions options;
    options.optimizeBranchPoints = this->OptimizeBranchPoints;
    options.fitFramesToMatchings = this->FitFramesToMatchings;
    options.branchPoints.branchPointWeight = this->BranchPointWeight;
    options.branchPoints.maximumSearchSize = this->MaximumSearchSize;
    options.branchPoints.lengthScaledCost = this->LengthScaledCost;
    const quadcover::MatchingResult result = quadcover::buildMatchings(mesh.V, mesh.F, mesh.topo,
      geometry, U,
      v && v->GetNumberOfComponents() == 3 && v->GetNumberOfTuples() == nf
        ? vtkQuadCoverEigen::FromArray3(v)
        : Eigen::MatrixX3d(),
      weight, held, options);
    const quadcover::FrameTopology& t = result.topology;
    this->UpdateProgress(0.9);

    output->ShallowCopy(surface);
    if (result.framesFitted)
    {
      // new arrays: the input's stay untouched
      output->GetCellData()->AddArray(vtkQuadCoverEigen::ToArray(result.frameU, u->GetName()));
      output->GetCellData()->AddArray(vtkQuadCoverEigen::ToArray(result.frameV, names::FrameV));
    }
    vtkNew<vtkIntArray> matching;
    matching->SetName(names::Matching);
    matching->SetNumberOfComponents(3);
    matching->SetNumberOfTuples(nf);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        matching->SetTypedComponent(f, k, t.matching(f, k));
      }
    }
    output->GetCellData()->AddArray(matching);
    const vtkIdType nv = mesh.V.rows();
    vtkNew<vtkIntArray> shift;
    shift->SetName(names::LayerShift);
    shift->SetNumberOfTuples(nv);
    for (vtkIdType p = 0; p < nv; ++p)
    {
      shift->SetValue(p, t.layerShift[p]);
    }
    output->GetPointData()->AddArray(shift);
    output->GetPointData()->AddArray(vtkQuadCoverEigen::ToArray(t.index, names::SingularityIndex));
    vtkFieldData* fd = output->GetFieldData();
    vtkQuadCoverEigen::AddField<vtkIntArray>(
      fd, names::SingularityCount, { double(t.singularities) });
    std::map<double, int> histogram;
    for (vtkIdType p = 0; p < nv; ++p)
    {
      if (!mesh.topo.boundaryVertex[p] && t.index[p] != 0.0)
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
    vtkQuadCoverEigen::AddField<vtkIntArray>(
      fd, names::BranchPointCount, { double(result.branchPointsBefore), double(t.branchPoints) });
    vtkQuadCoverEigen::AddField<vtkDoubleArray>(
      fd, names::MatchingCost, { result.matchingCostBefore, t.matchingCost });
    vtkQuadCoverEigen::AddField<vtkDoubleArray>(
      fd, names::BranchPointObjective, { result.objectiveBefore, result.objectiveAfter });

    // The branch points, for glyphs.
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> verts;
    vtkNew<vtkDoubleArray> index;
    index->SetName(names::SingularityIndex);
    vtkNew<vtkIntArray> layer;
    layer->SetName(names::LayerShift);
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName(names::SurfacePointId);
    for (vtkIdType p = 0; p < nv; ++p)
    {
      if (t.layerShift[p] != 0)
      {
        const vtkIdType id = points->InsertNextPoint(mesh.V(p, 0), mesh.V(p, 1), mesh.V(p, 2));
        verts->InsertNextCell(1, &id);
        index->InsertNextValue(t.index[p]);
        layer->InsertNextValue(t.layerShift[p]);
        ids->InsertNextValue(p);
      }
    }
    branchOutput->SetPoints(points);
    branchOutput->SetVerts(verts);
    branchOutput->GetPointData()->AddArray(index);
    branchOutput->GetPointData()->AddArray(layer);
    branchOutput->GetPointData()->AddArray(ids);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "Cannot build matchings: " << e.what());
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkMatchingBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OptimizeBranchPoints: " << (this->OptimizeBranchPoints ? "On" : "Off") << "\n";
  os << indent << "BranchPointWeight: " << this->BranchPointWeight << "\n";
  os << indent << "MaximumSearchSize: " << this->MaximumSearchSize << "\n";
  os << indent << "LengthScaledCost: " << (this->LengthScaledCost ? "On" : "Off") << "\n";
  os << indent << "FitFramesToMatchings: " << (this->FitFramesToMatchings ? "On" : "Off") << "\n";
}
