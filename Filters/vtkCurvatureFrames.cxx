#include "vtkCurvatureFrames.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"

#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "CurvatureFrames.h"

#include <stdexcept>

vtkStandardNewMacro(vtkCurvatureFrames);

//------------------------------------------------------------------------------
vtkCurvatureFrames::vtkCurvatureFrames()
  : vtkQuadCoverAlgorithm(MANIFOLD_EDGES, "estimate curvature")
{
  const quadcover::CurvatureOptions defaults;
  this->NeighborhoodRadius = defaults.neighborhoodRadius;
  this->NumberOfThreads = defaults.numberOfThreads;
  // A user frame field is looked up under this name unless pointed elsewhere.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkQuadCoverArrayNames::FrameU);
}

//------------------------------------------------------------------------------
void vtkCurvatureFrames::Execute(vtkQuadCoverSurface& in, vtkInformationVector* outputVector)
{
  namespace names = vtkQuadCoverArrayNames;
  vtkQuadCoverEigen::RequireNumbers({ { "NeighborhoodRadius", this->NeighborhoodRadius } });
  quadcover::CurvatureOptions options;
  options.neighborhoodRadius = this->NeighborhoodRadius;
  options.numberOfThreads = this->NumberOfThreads;
  this->UpdateProgress(0.1);
  quadcover::CurvatureField field = quadcover::computeCurvatureField(in.V, in.F, in.topo, options);
  this->UpdateProgress(0.8);
  if (field.zeroFrames == static_cast<int>(in.F.rows()))
  {
    throw std::invalid_argument("every triangle is degenerate (zero area)");
  }
  if (field.zeroFrames > 0)
  {
    this->Warn(std::to_string(field.zeroFrames) +
      " degenerate triangles with no usable neighbour have zero frames");
  }
  if (field.truncatedNeighborhoods > 0)
  {
    this->Warn(std::to_string(field.truncatedNeighborhoods) + " neighbourhoods were cut at " +
      std::to_string(options.maximumNeighborhood) + " triangles (very uneven triangle sizes?)");
  }
  vtkDataArray* user =
    this->UseInputFrames ? this->GetInputArrayToProcess(0, in.polyData) : nullptr;
  if (user && user->GetNumberOfComponents() == 3 && user->GetNumberOfTuples() == in.F.rows())
  {
    const int kept = quadcover::applyInputFrames(field, vtkQuadCoverEigen::FromArray3(user));
    if (kept > 0)
    {
      this->Warn(std::to_string(kept) +
        " input frame vectors have no tangent part; the curvature frame is used there");
    }
  }
  else if (user)
  {
    this->Warn(std::string("Input frame array ") +
      (user->GetName() ? user->GetName() : "(unnamed)") +
      " is not a 3-component cell array; curvature frames are used");
  }

  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->ShallowCopy(in.polyData);
  vtkCellData* cd = output->GetCellData();
  using vtkQuadCoverEigen::ToArray;
  // per unit length of the scaled surface (vtkQuadCoverSurface): back to the input's units
  cd->AddArray(ToArray(in.InWorldUnits(field.curvatures, -1), names::PrincipalCurvatures));
  cd->AddArray(ToArray(field.direction1, names::PrincipalDirection1));
  cd->AddArray(ToArray(field.direction2, names::PrincipalDirection2));
  cd->AddArray(ToArray(field.frameU, names::FrameU));
  cd->AddArray(ToArray(field.frameV, names::FrameV));
  cd->AddArray(ToArray(field.weight, names::FrameWeight));
  vtkQuadCoverEigen::AddField<vtkDoubleArray>(
    output->GetFieldData(), names::CurvatureRadius, { in.InWorldUnits(field.curvatureRadius) });
}

//------------------------------------------------------------------------------
void vtkCurvatureFrames::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NeighborhoodRadius: " << this->NeighborhoodRadius << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "UseInputFrames: " << (this->UseInputFrames ? "On" : "Off") << "\n";
}
