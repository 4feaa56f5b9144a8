#include "vtkFrameSmoother.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"

#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "FrameSmoother.h"
#include "Matchings.h"

#include <exception>

vtkStandardNewMacro(vtkFrameSmoother);

//------------------------------------------------------------------------------
vtkFrameSmoother::vtkFrameSmoother()
{
  namespace names = vtkQuadCoverArrayNames;
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::FrameU);
  this->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::FrameV);
  this->SetInputArrayToProcess(2, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::FrameWeight);
}

//------------------------------------------------------------------------------
int vtkFrameSmoother::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  namespace names = vtkQuadCoverArrayNames;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);

  vtkNew<vtkPolyData> surface;
  vtkQuadCoverEigen::Mesh mesh;
  std::string warning;
  const std::string problem =
    vtkQuadCoverEigen::Load(input, surface, mesh, vtkQuadCoverEigen::Needs::ManifoldEdges, warning);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Cannot smooth frames: " << problem << ".");
    return 0;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }
  const vtkIdType nf = mesh.F.rows();
  vtkDataArray* u = this->GetInputArrayToProcess(0, surface);
  vtkDataArray* v = this->GetInputArrayToProcess(1, surface);
  vtkDataArray* w = this->GetInputArrayToProcess(2, surface);
  const std::string missing = vtkQuadCoverEigen::CheckCellArray3(u, nf, names::FrameU,
    "run vtkCurvatureFrames first, or name your own with SetInputArrayToProcess");
  if (!missing.empty())
  {
    vtkErrorMacro(<< "Cannot smooth frames: " << missing << ".");
    return 0;
  }
  this->UpdateProgress(0.1);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  try
  {
    const quadcover::FrameGeometry geometry =
      quadcover::computeFrameGeometry(mesh.V, mesh.F, mesh.topo);
    // Frames as tangent unit vectors; FrameV defaults to n x FrameU, the weight to 1.
    const bool haveV = v && v->GetNumberOfComponents() == 3 && v->GetNumberOfTuples() == nf;
    const auto [U, Vf] = quadcover::tangentFrames(geometry.bases, vtkQuadCoverEigen::FromArray3(u),
      haveV ? vtkQuadCoverEigen::FromArray3(v) : Eigen::MatrixX3d());
    Eigen::VectorXd weight = Eigen::VectorXd::Ones(nf);
    if (w && w->GetNumberOfComponents() == 1 && w->GetNumberOfTuples() == nf)
    {
      for (vtkIdType f = 0; f < nf; ++f)
      {
        weight[f] = w->GetComponent(f, 0);
      }
    }
    this->UpdateProgress(0.2);

    quadcover::SmootherOptions options;
    options.smoothingWeight = this->SmoothingWeight;
    options.maximumNumberOfIterations = this->MaximumNumberOfIterations;
    options.convergenceTolerance = this->ConvergenceTolerance;
    options.alignToFeatures = this->AlignToFeatures;
    options.featureAngle = this->FeatureAngle;
    options.minimumFeatureLength = this->MinimumFeatureLength;
    options.alignToBoundary = this->AlignToBoundary;
    options.globalStart = this->GlobalStart;
    const quadcover::SmootherResult r =
      quadcover::smoothFrames(mesh.V, mesh.F, mesh.topo, geometry, U, Vf, weight, options);
    this->UpdateProgress(0.9);

    output->ShallowCopy(surface);
    vtkCellData* cd = output->GetCellData();
    cd->AddArray(vtkQuadCoverEigen::ToArray(r.frameU, names::FrameU));
    cd->AddArray(vtkQuadCoverEigen::ToArray(r.frameV, names::FrameV));
    cd->AddArray(vtkQuadCoverEigen::ToArray(r.rotation, names::FrameRotation));
    vtkNew<vtkUnsignedCharArray> held;
    held->SetName(names::FrameConstrained);
    held->SetNumberOfTuples(nf);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      held->SetValue(f, r.constrained[f]);
    }
    cd->AddArray(held);
    vtkQuadCoverEigen::AddField<vtkDoubleArray>(
      output->GetFieldData(), names::SmoothingEnergy, { r.energyBefore, r.energyAfter });
    vtkQuadCoverEigen::AddField<vtkIntArray>(
      output->GetFieldData(), names::SmoothingIterations, { double(r.iterations) });
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "Cannot smooth frames: " << e.what());
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFrameSmoother::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SmoothingWeight: " << this->SmoothingWeight << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "AlignToFeatures: " << (this->AlignToFeatures ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "MinimumFeatureLength: " << this->MinimumFeatureLength << "\n";
  os << indent << "AlignToBoundary: " << (this->AlignToBoundary ? "On" : "Off") << "\n";
  os << indent << "GlobalStart: " << (this->GlobalStart ? "On" : "Off") << "\n";
}
