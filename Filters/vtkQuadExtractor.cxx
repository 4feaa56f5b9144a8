#include "vtkQuadExtractor.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"

#include "QuadExtraction.h"

#include <algorithm>
#include <exception>

vtkStandardNewMacro(vtkQuadExtractor);

namespace
{
/// Largest distance from the points to the triangles (#T x 3 into V).
double LargestDistance(
  const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& T)
{
  vtkSmartPointer<vtkPolyData> surface = vtkQuadCoverEigen::ToPolyData(V, T);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double largest = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    double x[3] = { points(i, 0), points(i, 1), points(i, 2) };
    double closest[3];
    vtkIdType cellId = -1;
    int subId = 0;
    double d2 = 0.0;
    locator->FindClosestPoint(x, closest, cell, cellId, subId, d2);
    largest = std::max(largest, d2);
  }
  return std::sqrt(largest);
}
}

//------------------------------------------------------------------------------
vtkQuadExtractor::vtkQuadExtractor()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkQuadCoverArrayNames::CornerUV);
}

//------------------------------------------------------------------------------
int vtkQuadExtractor::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  namespace names = vtkQuadCoverArrayNames;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  vtkNew<vtkPolyData> surface;
  vtkQuadCoverEigen::Mesh mesh;
  std::string warning;
  std::string problem = vtkQuadCoverEigen::Load(
    input, surface, mesh, vtkQuadCoverEigen::Needs::ManifoldSurface, warning);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Cannot extract quads: " << problem << ".");
    return 0;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }
  const vtkIdType nf = mesh.F.rows();
  vtkDataArray* uvArray = this->GetInputArrayToProcess(0, surface);
  if (!uvArray || uvArray->GetNumberOfComponents() != 6 || uvArray->GetNumberOfTuples() != nf)
  {
    vtkErrorMacro(<< "Cannot extract quads: the input has no 6-component cell array "
                  << names::CornerUV << " (run vtkQuadCoverSolver first, or name your own with "
                  << "SetInputArrayToProcess).");
    return 0;
  }
  Eigen::MatrixXd uv(nf, 6);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    for (int c = 0; c < 6; ++c)
    {
      uv(f, c) = uvArray->GetComponent(f, c);
    }
  }
  // The solver's SplitSeams output: points back together through SurfacePointId.
  vtkDataArray* ids = surface->GetPointData()->GetArray(names::SurfacePointId);
  if (ids && ids->GetNumberOfComponents() == 1 &&
    ids->GetNumberOfTuples() == surface->GetNumberOfPoints())
  {
    const double top = ids->GetRange()[1];
    if (ids->GetRange()[0] >= 0 && top < static_cast<double>(surface->GetNumberOfPoints()))
    {
      Eigen::MatrixX3d V(static_cast<Eigen::Index>(top) + 1, 3);
      V.setZero();
      for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
      {
        V.row(static_cast<Eigen::Index>(ids->GetTuple1(p))) = mesh.V.row(p);
      }
      for (vtkIdType f = 0; f < nf; ++f)
      {
        for (int k = 0; k < 3; ++k)
        {
          mesh.F(f, k) = static_cast<int>(ids->GetTuple1(mesh.F(f, k)));
        }
      }
      mesh.V = V;
      mesh.topo = quadcover::buildTopology(mesh.F, static_cast<int>(mesh.V.rows()));
      if (!mesh.topo.isManifold() || !mesh.topo.isOriented())
      {
        vtkErrorMacro(<< "Cannot extract quads: the surface joined through "
                      << names::SurfacePointId << " has " << mesh.topo.describeDefects() << ".");
        return 0;
      }
    }
  }
  if (!uv.allFinite())
  {
    vtkErrorMacro(<< "Cannot extract quads: " << names::CornerUV << " has non-finite values.");
    return 0;
  }
  this->UpdateProgress(0.1);

  try
  {
    quadcover::QuadMesh quads = quadcover::extractQuads(mesh.V, mesh.F, mesh.topo, uv);
    int invertedExtracted = 0;
    if (this->RepairInvertedQuads)
    {
      invertedExtracted = quadcover::repairInvertedQuads(mesh.V, mesh.F, mesh.topo, quads).first;
    }
    else
    {
      invertedExtracted = quadcover::countInvertedQuads(quads.V, quads.Q);
    }
    if (this->RelaxationIterations > 0)
    {
      this->UpdateProgress(0.4);
      quadcover::QuadRelaxOptions relax;
      relax.relaxationIterations = this->RelaxationIterations;
      quadcover::relaxQuads(mesh.V, mesh.F, mesh.topo, quads, relax);
    }
    this->UpdateProgress(0.6);
    const quadcover::QuadQuality m = quadcover::measureQuads(quads.V, quads.Q);
    const int dropped = quads.cellsOffSurface + quads.cellsDegenerate + quads.cellsConflicting;
    if (dropped > 0 || quads.nonIntegerTransitions > 0)
    {
      vtkWarningMacro(<< dropped << " grid cells gave no quad (" << quads.cellsOffSurface
                      << " off the surface, " << quads.cellsDegenerate << " degenerate, "
                      << quads.cellsConflicting << " overlapping) and "
                      << quads.nonIntegerTransitions
                      << " edges have a non-integer translation: the map is not seamless or "
                      << "flip-free there.");
    }
    if (quads.Q.rows() == 0)
    {
      vtkErrorMacro(<< "Cannot extract quads: no grid cell of the map gave a quad (is the grid "
                    << "much coarser than the surface?).");
      return 0;
    }

    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(quads.V.rows());
    for (Eigen::Index v = 0; v < quads.V.rows(); ++v)
    {
      points->SetPoint(v, quads.V(v, 0), quads.V(v, 1), quads.V(v, 2));
    }
    vtkNew<vtkCellArray> polys;
    polys->AllocateExact(quads.Q.rows(), 4 * quads.Q.rows());
    for (Eigen::Index i = 0; i < quads.Q.rows(); ++i)
    {
      const vtkIdType cell[4] = { quads.Q(i, 0), quads.Q(i, 1), quads.Q(i, 2), quads.Q(i, 3) };
      polys->InsertNextCell(4, cell);
    }
    output->SetPoints(points);
    output->SetPolys(polys);
    vtkNew<vtkIntArray> valence;
    valence->SetName(names::Valence);
    valence->SetNumberOfTuples(quads.V.rows());
    for (Eigen::Index v = 0; v < quads.V.rows(); ++v)
    {
      valence->SetValue(v, m.valence[v]);
    }
    output->GetPointData()->AddArray(valence);
    output->GetCellData()->AddArray(
      vtkQuadCoverEigen::ToArray(m.scaledJacobian, names::ScaledJacobian));

    vtkFieldData* fd = output->GetFieldData();
    using vtkQuadCoverEigen::AddField;
    AddField<vtkDoubleArray>(
      fd, names::QuadShare, { m.faces > 0 ? double(m.quads) / m.faces : 0.0 });
    AddField<vtkIntArray>(
      fd, names::IrregularVertices, { double(m.irregularInner), double(m.irregularBoundary) });
    AddField<vtkDoubleArray>(fd, names::EdgeLengthRSD, { m.edgeLengthRSD });
    AddField<vtkDoubleArray>(fd, names::AngleRSD, { m.angleRSD });
    AddField<vtkDoubleArray>(
      fd, names::ScaledJacobianStatistics, { m.minScaledJacobian, m.meanScaledJacobian });
    AddField<vtkIntArray>(fd, names::NonManifoldEdges, { double(m.nonManifoldEdges) });
    AddField<vtkIntArray>(fd, names::EulerCharacteristic, { double(m.eulerCharacteristic) });
    AddField<vtkIntArray>(fd, names::BoundaryLoops, { double(m.boundaryLoops) });
    int invertedNow = 0; // in the output, after the repair and any relaxation
    for (Eigen::Index i = 0; i < m.scaledJacobian.size(); ++i)
    {
      invertedNow += !(m.scaledJacobian[i] > 0);
    }
    AddField<vtkIntArray>(
      fd, names::InvertedQuads, { double(invertedExtracted), double(invertedNow) });
    AddField<vtkIntArray>(fd, names::DroppedCells,
      { double(quads.cellsOffSurface), double(quads.cellsDegenerate),
        double(quads.cellsConflicting) });
    this->UpdateProgress(0.7);

    if (this->ComputeHausdorffDistance && !this->GetAbortExecute())
    {
      // Samples: the input's points against the quads (two triangles each); the quads' corners,
      // edge midpoints and centres against the input.
      Eigen::MatrixX3i T(2 * quads.Q.rows(), 3);
      Eigen::MatrixX3d samples(quads.V.rows() + 5 * quads.Q.rows(), 3);
      samples.topRows(quads.V.rows()) = quads.V;
      Eigen::Index s = quads.V.rows();
      for (Eigen::Index i = 0; i < quads.Q.rows(); ++i)
      {
        const auto q = quads.Q.row(i);
        T.row(2 * i) << q[0], q[1], q[2];
        T.row(2 * i + 1) << q[0], q[2], q[3];
        Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
        for (int k = 0; k < 4; ++k)
        {
          samples.row(s++) = 0.5 * (quads.V.row(q[k]) + quads.V.row(q[(k + 1) % 4]));
          centre += 0.25 * quads.V.row(q[k]);
        }
        samples.row(s++) = centre;
      }
      // the input's points that triangles use (a re-joined or messy input may have others)
      std::vector<char> used(mesh.V.rows(), 0);
      for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      {
        used[mesh.F(f, 0)] = used[mesh.F(f, 1)] = used[mesh.F(f, 2)] = 1;
      }
      Eigen::MatrixX3d inputPoints(std::count(used.begin(), used.end(), 1), 3);
      for (Eigen::Index v = 0, i = 0; v < mesh.V.rows(); ++v)
      {
        if (used[v])
        {
          inputPoints.row(i++) = mesh.V.row(v);
        }
      }
      const double diagonal =
        (inputPoints.colwise().maxCoeff() - inputPoints.colwise().minCoeff()).norm();
      const double toQuads = LargestDistance(inputPoints, quads.V, T);
      const double toInput = LargestDistance(samples, mesh.V, mesh.F);
      AddField<vtkDoubleArray>(fd, names::HausdorffDistance,
        { 100.0 * std::max(toQuads, toInput) / diagonal, 100.0 * toQuads / diagonal,
          100.0 * toInput / diagonal });
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "Cannot extract quads: " << e.what());
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkQuadExtractor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RelaxationIterations: " << this->RelaxationIterations << "\n";
  os << indent << "RepairInvertedQuads: " << (this->RepairInvertedQuads ? "On" : "Off") << "\n";
  os << indent << "ComputeHausdorffDistance: " << (this->ComputeHausdorffDistance ? "On" : "Off")
     << "\n";
}
