#include "vtkCurvatureFrames.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverInput.h"

#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "CurvatureFrames.h"
#include "MeshTopology.h"

#include <exception>

vtkStandardNewMacro(vtkCurvatureFrames);

//------------------------------------------------------------------------------
vtkCurvatureFrames::vtkCurvatureFrames()
{
  // A user frame field is looked up under this name unless pointed elsewhere.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkQuadCoverArrayNames::FrameU);
}

//------------------------------------------------------------------------------
int vtkCurvatureFrames::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);

  vtkNew<vtkPolyData> surface;
  vtkQuadCoverEigen::Mesh mesh;
  std::string warning;
  const std::string problem =
    vtkQuadCoverEigen::Load(input, surface, mesh, vtkQuadCoverEigen::Needs::ManifoldEdges, warning);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Cannot estimate curvature: " << problem << ".");
    return 0;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }

  try
  {
    const Eigen::MatrixX3d& V = mesh.V;
    const Eigen::MatrixX3i& F = mesh.F;
    const quadcover::MeshTopology& topo = mesh.topo;
    this->UpdateProgress(0.2);
    if (this->GetAbortExecute())
    {
      return 1;
    }

    quadcover::CurvatureOptions options;
    options.neighborhoodRadius = this->NeighborhoodRadius;
    options.numberOfThreads = this->NumberOfThreads;
    quadcover::CurvatureField field = quadcover::computeCurvatureField(V, F, topo, options);
    this->UpdateProgress(0.8);
    if (field.zeroFrames == static_cast<int>(F.rows()))
    {
      vtkErrorMacro(<< "Cannot estimate curvature: every triangle is degenerate (zero area).");
      return 0;
    }
    if (field.zeroFrames > 0)
    {
      vtkWarningMacro(<< field.zeroFrames << " degenerate triangles with no usable neighbour "
                      << "have zero frames.");
    }
    if (field.truncatedNeighborhoods > 0)
    {
      vtkWarningMacro(<< field.truncatedNeighborhoods << " neighbourhoods were cut at "
                      << options.maximumNeighborhood << " triangles (very uneven triangle sizes?).");
    }

    vtkDataArray* user = this->UseInputFrames ? this->GetInputArrayToProcess(0, surface) : nullptr;
    if (user && user->GetNumberOfComponents() == 3 &&
      user->GetNumberOfTuples() == static_cast<vtkIdType>(F.rows()))
    {
      const int kept = quadcover::applyInputFrames(field, vtkQuadCoverEigen::FromArray3(user));
      if (kept > 0)
      {
        vtkWarningMacro(<< kept << " input frame vectors have no tangent part; the curvature "
                        << "frame is used there.");
      }
    }
    else if (user)
    {
      vtkWarningMacro(<< "Input frame array " << (user->GetName() ? user->GetName() : "(unnamed)")
                      << " is not a 3-component cell array; curvature frames are used.");
    }

    namespace names = vtkQuadCoverArrayNames;
    output->ShallowCopy(surface);
    vtkCellData* cd = output->GetCellData();
    cd->AddArray(vtkQuadCoverEigen::ToArray(field.curvatures, names::PrincipalCurvatures));
    cd->AddArray(vtkQuadCoverEigen::ToArray(field.direction1, names::PrincipalDirection1));
    cd->AddArray(vtkQuadCoverEigen::ToArray(field.direction2, names::PrincipalDirection2));
    cd->AddArray(vtkQuadCoverEigen::ToArray(field.frameU, names::FrameU));
    cd->AddArray(vtkQuadCoverEigen::ToArray(field.frameV, names::FrameV));
    cd->AddArray(vtkQuadCoverEigen::ToArray(field.weight, names::FrameWeight));
    vtkQuadCoverEigen::AddField<vtkDoubleArray>(
      output->GetFieldData(), names::CurvatureRadius, { field.curvatureRadius });
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "Cannot estimate curvature: " << e.what());
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCurvatureFrames::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NeighborhoodRadius: " << this->NeighborhoodRadius << "\n";
  os << indent << "UseInputFrames: " << (this->UseInputFrames ? "On" : "Off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
