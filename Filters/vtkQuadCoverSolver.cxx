#include "vtkQuadCoverSolver.h"

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
#include "vtkUnsignedCharArray.h"

#include "Parameterization.h"

#include <exception>

vtkStandardNewMacro(vtkQuadCoverSolver);

//------------------------------------------------------------------------------
vtkQuadCoverSolver::vtkQuadCoverSolver()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkQuadCoverArrayNames::FrameU);
  this->SetInputArrayToProcess(
    1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkQuadCoverArrayNames::Matching);
}

//------------------------------------------------------------------------------
int vtkQuadCoverSolver::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  namespace names = vtkQuadCoverArrayNames;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  vtkNew<vtkPolyData> surface;
  vtkQuadCoverEigen::Mesh mesh;
  std::string warning;
  const std::string problem = vtkQuadCoverEigen::Load(
    input, surface, mesh, vtkQuadCoverEigen::Needs::ManifoldSurface, warning);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Cannot parameterize: " << problem << ".");
    return 0;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }
  const vtkIdType nf = mesh.F.rows();
  vtkDataArray* u = this->GetInputArrayToProcess(0, surface);
  vtkDataArray* m = this->GetInputArrayToProcess(1, surface);
  std::string missing = vtkQuadCoverEigen::CheckCellArray3(u, nf, names::FrameU,
    "run the earlier stages first, or name your own with SetInputArrayToProcess(0, ...)");
  if (missing.empty())
  {
    missing = vtkQuadCoverEigen::CheckCellArray3(m, nf, names::Matching,
      "run vtkMatchingBuilder first, or name your own with SetInputArrayToProcess(1, ...)");
  }
  if (!missing.empty())
  {
    vtkErrorMacro(<< "Cannot parameterize: " << missing << ".");
    return 0;
  }
  const Eigen::MatrixX3d U = vtkQuadCoverEigen::FromArray3(u);
  if (!U.allFinite())
  {
    vtkErrorMacro(<< "Cannot parameterize: " << names::FrameU << " has non-finite values.");
    return 0;
  }
  Eigen::MatrixX3i matching(nf, 3);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double r = m->GetComponent(f, k);
      const bool boundary = mesh.topo.faceNeighbors(f, k) < 0;
      if (!(boundary ? r == -1.0 : (r == 0.0 || r == 1.0 || r == 2.0 || r == 3.0)))
      {
        vtkErrorMacro(<< "Cannot parameterize: " << names::Matching << " of triangle " << f
                      << ", edge " << k << " is " << r << "; it must be 0, 1, 2 or 3 (-1 on "
                      << "the boundary).");
        return 0;
      }
      matching(f, k) = static_cast<int>(r);
    }
  }
  this->UpdateProgress(0.1);

  try
  {
    const quadcover::FrameGeometry geometry =
      quadcover::computeFrameGeometry(mesh.V, mesh.F, mesh.topo);
    quadcover::ParameterizationOptions options;
    options.targetEdgeLength = this->TargetEdgeLength;
    options.targetQuadCount = this->TargetQuadCount;
    options.pureQuads = this->PureQuads;
    options.roundingMode = this->RoundingMode == ROUNDING_NONE
      ? quadcover::RoundingMode::None
      : (this->RoundingMode == ROUNDING_SIMPLE ? quadcover::RoundingMode::Simple
                                               : quadcover::RoundingMode::Greedy);
    options.alignToBoundary = this->AlignToBoundary;
    options.boundaryTolerance = this->BoundaryTolerance;
    options.maximumUntangleRounds = this->MaximumUntangleRounds;
    this->UpdateProgress(0.2);
    const quadcover::Parameterization map =
      quadcover::computeParameterization(mesh.V, mesh.F, mesh.topo, geometry, U, matching, options);
    this->UpdateProgress(0.9);
    if (map.wrongWindings > 0)
    {
      vtkWarningMacro(<< map.wrongWindings << " points keep a map that winds around them unlike "
                      << "the frame field; the quads there may be irregular.");
    }
    if (map.flipped > 0)
    {
      vtkWarningMacro(<< map.flipped << " triangles keep a flipped (u, v) image after "
                      << "untangling; the quads there may be irregular (a finer or coarser grid "
                      << "may help).");
    }

    vtkNew<vtkUnsignedCharArray> seam;
    seam->SetName(names::Seam);
    seam->SetNumberOfComponents(3);
    seam->SetNumberOfTuples(nf);
    for (vtkIdType f = 0; f < nf; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        seam->SetTypedComponent(f, k, static_cast<unsigned char>(map.seam(f, k)));
      }
    }
    if (this->SplitSeams)
    {
      const vtkIdType ns = static_cast<vtkIdType>(map.sectorPoint.size());
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(ns);
      vtkPointData* inPD = surface->GetPointData();
      vtkPointData* outPD = output->GetPointData();
      outPD->CopyAllocate(inPD, ns);
      vtkNew<vtkIdTypeArray> ids;
      ids->SetName(names::SurfacePointId);
      ids->SetNumberOfTuples(ns);
      for (vtkIdType s = 0; s < ns; ++s)
      {
        const int p = map.sectorPoint[s];
        points->SetPoint(s, mesh.V(p, 0), mesh.V(p, 1), mesh.V(p, 2));
        outPD->CopyData(inPD, p, s);
        ids->SetValue(s, p);
      }
      vtkNew<vtkCellArray> polys;
      polys->AllocateExact(nf, 3 * nf);
      for (vtkIdType f = 0; f < nf; ++f)
      {
        const vtkIdType cell[3] = { map.cornerSector[3 * f], map.cornerSector[3 * f + 1],
          map.cornerSector[3 * f + 2] };
        polys->InsertNextCell(3, cell);
      }
      output->SetPoints(points);
      output->SetPolys(polys);
      output->GetCellData()->ShallowCopy(surface->GetCellData());
      output->GetFieldData()->ShallowCopy(surface->GetFieldData());
      outPD->AddArray(ids);
      outPD->SetTCoords(vtkQuadCoverEigen::ToArray(map.sectorUV, names::UV));
    }
    else
    {
      output->ShallowCopy(surface);
    }
    output->GetCellData()->AddArray(vtkQuadCoverEigen::ToArray(map.cornerUV, names::CornerUV));
    output->GetCellData()->AddArray(seam);
    vtkFieldData* fd = output->GetFieldData();
    vtkQuadCoverEigen::AddField<vtkDoubleArray>(fd, names::GridScale, { map.edgeLength });
    vtkQuadCoverEigen::AddField<vtkIntArray>(
      fd, names::WindingErrors, { double(map.wrongWindings) });
    vtkQuadCoverEigen::AddField<vtkIntArray>(fd, names::FlippedTriangles,
      { double(map.flippedContinuous), double(map.flippedRounded), double(map.flipped) });
    vtkQuadCoverEigen::AddField<vtkDoubleArray>(fd, names::ParameterizationEnergy,
      { map.energyContinuous, map.energyRounded, map.energyFinal });
    vtkNew<vtkDoubleArray> seconds;
    seconds->SetName(names::SolveSeconds);
    for (const double s : map.solveSeconds)
    {
      seconds->InsertNextValue(s);
    }
    fd->AddArray(seconds);
    vtkQuadCoverEigen::AddField<vtkIntArray>(fd, names::SeamEdgeCount, { double(map.seamEdges) });
    vtkQuadCoverEigen::AddField<vtkIntArray>(
      fd, names::BranchPointsOnGrid, { double(map.branchPoints), double(map.branchPointsOnGrid) });
    vtkQuadCoverEigen::AddField<vtkDoubleArray>(
      fd, names::SeamTranslationError, { map.maxSeamError });
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "Cannot parameterize: " << e.what());
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkQuadCoverSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetEdgeLength: " << this->TargetEdgeLength << "\n";
  os << indent << "TargetQuadCount: " << this->TargetQuadCount << "\n";
  os << indent << "PureQuads: " << (this->PureQuads ? "On" : "Off") << "\n";
  os << indent << "RoundingMode: "
     << (this->RoundingMode == ROUNDING_NONE
            ? "None"
            : (this->RoundingMode == ROUNDING_SIMPLE ? "Simple" : "Greedy"))
     << "\n";
  os << indent << "AlignToBoundary: " << (this->AlignToBoundary ? "On" : "Off") << "\n";
  os << indent << "BoundaryTolerance: " << this->BoundaryTolerance << "\n";
  os << indent << "MaximumUntangleRounds: " << this->MaximumUntangleRounds << "\n";
  os << indent << "SplitSeams: " << (this->SplitSeams ? "On" : "Off") << "\n";
}
