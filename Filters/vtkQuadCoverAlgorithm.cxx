#include "vtkQuadCoverAlgorithm.h"

#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverInput.h"
#include "vtkQuadCoverPieces.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"

#include "Progress.h"

#include <exception>
#include <stdexcept>

namespace
{
/// The input as a stage needs it; throws std::invalid_argument with the reason.
vtkQuadCoverSurface LoadSurface(
  vtkPolyData* input, vtkQuadCoverAlgorithm::InputRequirement requirement, std::string& warning)
{
  vtkQuadCoverSurface s;
  s.polyData = vtkSmartPointer<vtkPolyData>::New();
  if (requirement == vtkQuadCoverAlgorithm::ANY_POLYDATA)
  {
    const std::string problem = vtkQuadCoverInput::CheckPoints(input);
    if (!problem.empty())
    {
      throw std::invalid_argument(problem);
    }
    s.polyData->ShallowCopy(input);
    s.ScaleExponent = vtkQuadCoverInput::UnitScaleExponent(s.polyData);
    return s;
  }
  const std::string problem = vtkQuadCoverInput::Triangulate(input, s.polyData, warning);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  s.ScaleExponent = vtkQuadCoverInput::UnitScaleExponent(s.polyData);
  s.V = s.InCoreUnits(vtkQuadCoverEigen::Points(s.polyData), 1);
  s.F = vtkQuadCoverEigen::Triangles(s.polyData);
  s.topo = quadcover::buildTopology(s.F, static_cast<int>(s.V.rows()));
  const quadcover::MeshTopology& T = s.topo;
  const bool vertices = requirement == vtkQuadCoverAlgorithm::MANIFOLD_SURFACE;
  if (!T.degenerateFaces.empty() || !T.nonManifoldEdges.empty() || !T.misorientedEdges.empty() ||
    (vertices && !T.nonManifoldVertices.empty()))
  {
    throw std::invalid_argument("the surface has " + T.describeDefects() +
      "; run vtkQuadCoverSurfaceRepair first (it merges duplicate points, splits non-manifold "
      "vertices and orients the triangles consistently)");
  }
  if (!T.nonManifoldVertices.empty())
  {
    warning += std::string(warning.empty() ? "" : "; ") +
      std::to_string(T.nonManifoldVertices.size()) +
      " non-manifold vertices (fans of triangles touching at one vertex); later stages need them "
      "split (vtkQuadCoverSurfaceRepair)";
  }
  return s;
}

/// `text` without a final period, for messages that add their own.
std::string WithoutPeriod(std::string text)
{
  while (!text.empty() && (text.back() == '.' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}
}

//------------------------------------------------------------------------------
vtkQuadCoverAlgorithm::vtkQuadCoverAlgorithm(InputRequirement requirement, const char* action)
  : Requirement(requirement)
  , Action(action)
{}

//------------------------------------------------------------------------------
int vtkQuadCoverAlgorithm::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  auto clearOutputs = [&]() {
    for (int i = 0; i < this->GetNumberOfOutputPorts(); ++i)
    {
      vtkPolyData::GetData(outputVector, i)->Initialize();
    }
  };
  if (this->EmptyPiece)
  {
    clearOutputs(); // the rank of piece 0 computes the whole surface
    return 1;
  }
  try
  {
    std::string warning;
    vtkQuadCoverSurface surface =
      LoadSurface(vtkPolyData::GetData(inputVector[0]), this->Requirement, warning);
    if (!warning.empty())
    {
      this->Warn(warning);
    }
    this->Execute(surface, outputVector);
  }
  catch (const quadcover::Cancelled&)
  {
    clearOutputs(); // AbortExecute: no error, no result
    return 1;
  }
  catch (const std::exception& e)
  {
    clearOutputs();
    vtkErrorMacro(<< "Cannot " << this->Action << ": " << WithoutPeriod(e.what()) << ".");
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkQuadCoverAlgorithm::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const int done = this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  this->EmptyPiece = vtkQuadCoverPieces::RequestWholeSurface(request, inputVector, outputVector);
  return done;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkQuadCoverAlgorithm::RequireCellArray(
  int index, vtkPolyData* surface, int components, const char* name, const char* hint)
{
  vtkDataArray* a = this->GetInputArrayToProcess(index, surface);
  if (a && a->GetNumberOfComponents() == components &&
    a->GetNumberOfTuples() == surface->GetNumberOfCells())
  {
    return a;
  }
  vtkInformation* info = this->GetInputArrayInformation(index);
  const char* chosen = info && info->Has(vtkDataObject::FIELD_NAME())
    ? info->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  throw std::invalid_argument("the input has no " + std::to_string(components) +
    "-component cell array " + (chosen ? chosen : name) + " (" + hint + ")");
}

//------------------------------------------------------------------------------
void vtkQuadCoverAlgorithm::Warn(const std::string& text)
{
  vtkWarningMacro(<< WithoutPeriod(text) << ".");
}

//------------------------------------------------------------------------------
void vtkQuadCoverAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
