#include "vtkQuadExtractor.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverInput.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "vtkAlgorithmOutput.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "QuadMeshing.h"
#include "QuadQuality.h"
#include "QuadsOntoSource.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkQuadExtractor);

namespace
{
namespace names = vtkQuadCoverArrayNames;

/// The solver's SplitSeams output: its points joined back through SurfacePointId (when the
/// points of one id lie together, as the solver writes them). Returns a warning or "".
std::string JoinSplitSurface(vtkQuadCoverSurface& in)
{
  vtkDataArray* ids = in.polyData->GetPointData()->GetArray(names::SurfacePointId);
  const vtkIdType n = in.polyData->GetNumberOfPoints();
  if (!ids || ids->GetNumberOfComponents() != 1 || ids->GetNumberOfTuples() != n ||
    ids->GetRange()[0] < 0 || !(ids->GetRange()[1] < static_cast<double>(n)))
  {
    return "";
  }
  std::vector<int> pointId(n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    pointId[p] = static_cast<int>(ids->GetTuple1(p));
  }
  if (!quadcover::splitPointsCoincide(in.V, pointId))
  {
    return std::string("the input's ") + names::SurfacePointId +
      " joins points that lie apart, so it is not a surface cut open along its seams; it is "
      "ignored";
  }
  in.V = quadcover::joinSplitPoints(in.V, in.F, pointId);
  in.topo = quadcover::buildTopology(in.F, static_cast<int>(in.V.rows()));
  if (!in.topo.isManifold() || !in.topo.isOriented())
  {
    throw std::invalid_argument(std::string("the surface joined through ") + names::SurfacePointId +
      " has " + in.topo.describeDefects());
  }
  return "";
}

/// The quads as vtkQuad cells (points in the input's units) with point data Valence and cell
/// data ScaledJacobian.
void WriteQuads(
  vtkPolyData* output, const quadcover::QuadMeshResult& r, const vtkQuadCoverSurface& in)
{
  const quadcover::QuadMesh& quads = r.mesh;
  const Eigen::MatrixXd V = in.InWorldUnits(quads.V);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(quads.V.rows());
  for (Eigen::Index v = 0; v < quads.V.rows(); ++v)
  {
    points->SetPoint(v, V(v, 0), V(v, 1), V(v, 2));
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
  output->GetPointData()->AddArray(
    vtkQuadCoverEigen::ToArray<vtkIntArray>(r.quality.valence, names::Valence));
  output->GetCellData()->AddArray(
    vtkQuadCoverEigen::ToArray(r.quality.scaledJacobian, names::ScaledJacobian));
}

/// The quality figures as field data.
void AddFigures(vtkFieldData* fd, const quadcover::QuadMeshResult& r)
{
  using vtkQuadCoverEigen::AddField;
  const quadcover::QuadQuality& m = r.quality;
  const quadcover::QuadMesh& quads = r.mesh;
  AddField<vtkDoubleArray>(fd, names::QuadShare, { m.faces > 0 ? double(m.quads) / m.faces : 0.0 });
  AddField<vtkIntArray>(
    fd, names::IrregularVertices, { double(m.irregularInner), double(m.irregularBoundary) });
  AddField<vtkDoubleArray>(fd, names::EdgeLengthRSD, { m.edgeLengthRSD });
  AddField<vtkDoubleArray>(fd, names::AngleRSD, { m.angleRSD });
  AddField<vtkDoubleArray>(
    fd, names::ScaledJacobianStatistics, { m.minScaledJacobian, m.meanScaledJacobian });
  AddField<vtkIntArray>(fd, names::NonManifoldEdges, { double(m.nonManifoldEdges) });
  AddField<vtkIntArray>(fd, names::EulerCharacteristic, { double(m.eulerCharacteristic) });
  AddField<vtkIntArray>(fd, names::BoundaryLoops, { double(m.boundaryLoops) });
  AddField<vtkIntArray>(
    fd, names::InvertedQuads, { double(r.invertedExtracted), double(r.invertedFinal) });
  AddField<vtkIntArray>(fd, names::DroppedCells,
    { double(quads.cellsOffSurface), double(quads.cellsDegenerate),
      double(quads.cellsConflicting) });
  AddField<vtkIntArray>(fd, names::FilledHoles,
    { double(r.patch.holesFilled), double(r.patch.holesLeft), double(r.patch.quadsAdded) });
  AddField<vtkIntArray>(
    fd, names::TurnedQuads, { double(r.turnedExtracted), double(r.turnedQuads) });
  AddField<vtkIntArray>(fd, names::SplitQuadVertices, { double(r.splitVertices) });
  AddField<vtkIntArray>(fd, names::FragmentQuads, { double(r.fragmentQuads) });
  AddField<vtkIntArray>(
    fd, names::RemovedTurnedQuads, { double(r.collapse.ears), double(r.collapse.collapsed) });
  AddField<vtkIntArray>(fd, names::SnappedVertices, { double(r.snappedVertices) });
  AddField<vtkIntArray>(fd, names::LiftedVertices, { double(r.liftedVertices) });
  AddField<vtkIntArray>(fd, names::EmptyComponents, { double(r.emptyComponents) });
}

/// Field data HausdorffDistance: two-sided, surface to quads, quads to surface, in % of the
/// surface's bounding-box diagonal.
void AddHausdorffDistance(vtkFieldData* fd, const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const quadcover::QuadMesh& quads)
{
  const quadcover::HausdorffSamples s = quadcover::hausdorffSamples(V, F, quads.V, quads.Q);
  const double toQuads = quadcover::largestDistance(s.surfacePoints, quads.V, s.quadTriangles);
  const double toSurface = quadcover::largestDistance(s.quadPoints, V, F);
  if (!std::isfinite(toQuads) || !std::isfinite(toSurface))
  {
    return; // no quad (or surface triangle) of positive area to measure against
  }
  vtkQuadCoverEigen::AddField<vtkDoubleArray>(fd, names::HausdorffDistance,
    { 100.0 * std::max(toQuads, toSurface) / s.diagonal, 100.0 * toQuads / s.diagonal,
      100.0 * toSurface / s.diagonal });
}

/// The triangles of `source` (any polygons, triangulated), in core units as `in` says.
void SourceSurface(
  vtkPolyData* source, const vtkQuadCoverSurface& in, Eigen::MatrixX3d& V, Eigen::MatrixX3i& F)
{
  vtkNew<vtkPolyData> triangles;
  vtkPolyData* t = source;
  if (!source || source->GetNumberOfStrips() > 0 || source->GetPolys()->IsHomogeneous() != 3)
  {
    // polygons and strips triangulated (a surface of triangles is read as it is, not copied)
    vtkNew<vtkPolyData> none;
    vtkQuadCoverInput::TriangulateCells(source ? source : none.Get(), triangles);
    t = triangles;
  }
  if (!source || t->GetNumberOfPolys() == 0 || t->GetPolys()->IsHomogeneous() != 3)
  {
    throw std::invalid_argument("the source surface (input 1) has no triangles");
  }
  V = in.InCoreUnits(vtkQuadCoverEigen::Points(t));
  F = vtkQuadCoverEigen::Triangles(t);
  if (F.minCoeff() < 0 || F.maxCoeff() >= V.rows() || !V.allFinite())
  {
    throw std::invalid_argument(
      "the source surface (input 1) has point ids out of range or non-finite points");
  }
}
}

//------------------------------------------------------------------------------
void vtkQuadExtractor::SetSourceConnection(vtkAlgorithmOutput* source)
{
  this->SetInputConnection(1, source);
}

//------------------------------------------------------------------------------
void vtkQuadExtractor::SetSourceData(vtkPolyData* source)
{
  this->SetInputData(1, source);
}

//------------------------------------------------------------------------------
int vtkQuadExtractor::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkQuadExtractor::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const int done = this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  // the source is read as a whole, as the surface is
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* surface = inputVector[0]->GetInformationObject(0);
  vtkInformation* source = inputVector[1]->GetInformationObject(0);
  if (surface && source)
  {
    for (vtkInformationIntegerKey* key : { SDDP::UPDATE_PIECE_NUMBER(),
           SDDP::UPDATE_NUMBER_OF_PIECES(), SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS() })
    {
      if (surface->Has(key))
      {
        source->Set(key, surface->Get(key));
      }
    }
  }
  return done;
}

//------------------------------------------------------------------------------
vtkQuadExtractor::vtkQuadExtractor()
  : vtkQuadCoverAlgorithm(MANIFOLD_SURFACE, "extract quads")
{
  this->SetNumberOfInputPorts(2);
  const quadcover::QuadMeshOptions defaults;
  this->ComputeHausdorffDistance = defaults.computeHausdorffDistance;
  this->RelaxationIterations = defaults.relaxationIterations;
  this->RepairInvertedQuads = defaults.repairInvertedQuads;
  this->FillHoles = defaults.fillHoles;
  this->SnapToCreases = defaults.snapToCreases;
  this->FeatureAngle = defaults.featureAngle;
  this->MinimumFeatureLength = defaults.minimumFeatureLength;
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::CornerUV);
}

//------------------------------------------------------------------------------
void vtkQuadExtractor::Execute(vtkQuadCoverSurface& in, vtkInformationVector* outputVector)
{
  vtkDataArray* uvArray = this->RequireCellArray(0, in.polyData, 6, names::CornerUV,
    "run vtkQuadCoverSolver first, or name your own with SetInputArrayToProcess");
  const Eigen::MatrixXd uv = vtkQuadCoverEigen::FromArray(uvArray);
  const std::string ignored = JoinSplitSurface(in);
  if (!ignored.empty())
  {
    this->Warn(ignored);
  }
  if (!uv.allFinite())
  {
    throw std::invalid_argument(std::string(names::CornerUV) + " has non-finite values");
  }
  this->UpdateProgress(0.1);

  quadcover::QuadMeshOptions options;
  options.repairInvertedQuads = this->RepairInvertedQuads;
  options.fillHoles = this->FillHoles;
  options.relaxationIterations = this->RelaxationIterations;
  options.snapToCreases = this->SnapToCreases;
  options.featureAngle = this->FeatureAngle;
  options.minimumFeatureLength = this->MinimumFeatureLength;
  quadcover::QuadMeshResult r = quadcover::buildQuadMesh(
    in.V, in.F, in.topo, uv, options, vtkQuadCoverEigen::CoreProgress(this, 0.1, 0.7));
  const quadcover::QuadMesh& quads = r.mesh;
  if (r.droppedCells() > 0 || quads.nonIntegerTransitions > 0)
  {
    this->Warn(std::to_string(r.droppedCells()) + " grid cells gave no quad (" +
      std::to_string(quads.cellsOffSurface) + " off the surface, " +
      std::to_string(quads.cellsDegenerate) + " degenerate, " +
      std::to_string(quads.cellsConflicting) + " overlapping) and " +
      std::to_string(quads.nonIntegerTransitions) +
      " edges have a non-integer translation: the map is not seamless or flip-free there");
  }
  if (r.patch.holesLeft > 0)
  {
    this->Warn(std::to_string(r.patch.holesLeft) +
      " holes inside the surface are left open (odd, pinched or very long loops, or a band around "
      "a handle)");
  }
  if (r.turnedQuads > 0 || r.invertedFinal > 0)
  {
    this->Warn(std::to_string(r.turnedQuads) + " quads face against the input and " +
      std::to_string(r.invertedFinal) +
      " have a corner turned inside out (TurnedQuads, InvertedQuads): the map is too distorted "
      "there (slivers, a part thinner than the quads)");
  }
  if (r.emptyComponents > 0 && quads.Q.rows() > 0)
  {
    this->Warn(std::to_string(r.emptyComponents) + " of the surface's " +
      std::to_string(in.topo.numComponents()) +
      " components gave no quad (EmptyComponents): no cell of the map on them became a quad");
  }
  if (quads.Q.rows() == 0)
  {
    throw std::invalid_argument("no grid cell of the map gave a quad (is the grid much coarser "
                                "than the surface?)");
  }
  // the surface measured against: the source where one is connected, the quads put onto it
  Eigen::MatrixX3d sourceV;
  Eigen::MatrixX3i sourceF;
  const bool hasSource = this->GetNumberOfInputConnections(1) > 0;
  if (hasSource)
  {
    SourceSurface(vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0)), in, sourceV, sourceF);
    quadcover::putQuadsOnto(r, in.V, in.F, sourceV, sourceF, options.repairInvertedQuads);
  }
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  WriteQuads(output, r, in);
  AddFigures(output->GetFieldData(), r);
  this->UpdateProgress(0.7);
  if (this->ComputeHausdorffDistance)
  {
    if (this->GetAbortExecute())
    {
      throw quadcover::Cancelled();
    }
    AddHausdorffDistance(
      output->GetFieldData(), hasSource ? sourceV : in.V, hasSource ? sourceF : in.F, quads);
  }
}

//------------------------------------------------------------------------------
void vtkQuadExtractor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RelaxationIterations: " << this->RelaxationIterations << "\n";
  os << indent << "RepairInvertedQuads: " << (this->RepairInvertedQuads ? "On" : "Off") << "\n";
  os << indent << "FillHoles: " << (this->FillHoles ? "On" : "Off") << "\n";
  os << indent << "SnapToCreases: " << (this->SnapToCreases ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "MinimumFeatureLength: " << this->MinimumFeatureLength << "\n";
  os << indent << "ComputeHausdorffDistance: " << (this->ComputeHausdorffDistance ? "On" : "Off")
     << "\n";
}
