#include "vtkQuadCoverSolver.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "FrameField.h"
#include "Parameterization.h"
#include "SurfaceRefinement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

vtkStandardNewMacro(vtkQuadCoverSolver);

namespace
{
namespace names = vtkQuadCoverArrayNames;

quadcover::RoundingMode CoreRounding(int mode)
{
  return mode == vtkQuadCoverSolver::ROUNDING_NONE
    ? quadcover::RoundingMode::None
    : (mode == vtkQuadCoverSolver::ROUNDING_SIMPLE ? quadcover::RoundingMode::Simple
                                                   : quadcover::RoundingMode::Greedy);
}

int FilterRounding(quadcover::RoundingMode mode)
{
  return mode == quadcover::RoundingMode::None
    ? vtkQuadCoverSolver::ROUNDING_NONE
    : (mode == quadcover::RoundingMode::Simple ? vtkQuadCoverSolver::ROUNDING_SIMPLE
                                               : vtkQuadCoverSolver::ROUNDING_GREEDY);
}

/// The Matching array as integers (computeParameterization checks their values).
Eigen::MatrixX3i ReadMatching(vtkDataArray* m)
{
  const Eigen::MatrixXd values = vtkQuadCoverEigen::FromArray(m);
  if (!(values.array() == values.array().round()).all() || !(values.array().abs() < 1e9).all())
  {
    throw std::invalid_argument(std::string(names::Matching) + " holds values that are not whole");
  }
  return values.cast<int>();
}

/// The surface cut open along the seams: a point per sector (at the input's point), UV its
/// texture coordinates.
void WriteSplitSurface(
  vtkPolyData* output, const vtkQuadCoverSurface& in, const quadcover::Parameterization& map)
{
  const Eigen::MatrixXd V = in.InWorldUnits(in.V);
  const vtkIdType ns = static_cast<vtkIdType>(map.sectorPoint.size());
  const vtkIdType nf = in.NumberOfTriangles();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(ns);
  vtkPointData* inPD = in.polyData->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(inPD, ns);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName(names::SurfacePointId);
  ids->SetNumberOfTuples(ns);
  for (vtkIdType s = 0; s < ns; ++s)
  {
    const int p = map.sectorPoint[s];
    points->SetPoint(s, V(p, 0), V(p, 1), V(p, 2));
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
  output->GetCellData()->ShallowCopy(in.polyData->GetCellData());
  output->GetFieldData()->ShallowCopy(in.polyData->GetFieldData());
  outPD->AddArray(ids);
  outPD->SetTCoords(vtkQuadCoverEigen::ToArray(map.sectorUV, names::UV));
}

/// LayerShift and SingularityIndex as the map has them (those of the Matching it read, but for
/// the pairs it cancelled), in place of any the input has: per point of the output, a surface
/// point or a sector.
void WriteOwnSingularities(vtkPolyData* output, const quadcover::Parameterization& map, bool split)
{
  const vtkIdType n = output->GetNumberOfPoints();
  vtkNew<vtkIntArray> shift;
  shift->SetName(names::LayerShift);
  shift->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> index;
  index->SetName(names::SingularityIndex);
  index->SetNumberOfTuples(n);
  for (vtkIdType s = 0; s < n; ++s)
  {
    const int p = split ? map.sectorPoint[s] : static_cast<int>(s);
    shift->SetValue(s, map.layerShift[p]);
    index->SetValue(s, map.singularityIndex[p]);
  }
  output->GetPointData()->AddArray(shift);
  output->GetPointData()->AddArray(index);
}

/// The map's figures as field data (the edge length in the input's units).
void AddFigures(
  vtkFieldData* fd, const quadcover::Parameterization& map, const vtkQuadCoverSurface& in)
{
  using vtkQuadCoverEigen::AddField;
  AddField<vtkDoubleArray>(fd, names::EdgeLength, { in.InWorldUnits(map.edgeLength) });
  AddField<vtkIntArray>(fd, names::WindingErrors, { double(map.wrongWindings) });
  AddField<vtkDoubleArray>(fd, names::UntangleWorkSpent,
    { double(map.untangleEvaluations) / std::max<vtkIdType>(1, in.NumberOfTriangles()) });
  AddField<vtkIntArray>(fd, names::FlippedTriangles,
    { double(map.flippedContinuous), double(map.flippedRounded), double(map.flipped) });
  AddField<vtkDoubleArray>(fd, names::ParameterizationEnergy,
    { map.energyContinuous, map.energyRounded, map.energyFinal });
  AddField<vtkIntArray>(fd, names::SeamEdgeCount, { double(map.seamEdges) });
  AddField<vtkIntArray>(fd, names::AlignedBoundaryEdges, { double(map.alignedBoundaryEdges) });
  AddField<vtkIntArray>(fd, names::AlignedFeatureEdges, { double(map.alignedFeatureEdges) });
  AddField<vtkIntArray>(fd, names::CancelledSingularityPairs, { double(map.cancelledPairs) });
  AddField<vtkIntArray>(fd, names::MovedSingularities, { double(map.movedSingularities) });
  AddField<vtkIntArray>(fd, names::AddedConePairs, { double(map.addedConePairs) });
  AddField<vtkIntArray>(fd, names::DroppedConePairs, { double(map.droppedConePairs) });
  AddField<vtkIntArray>(fd, names::FinerGridRetries, { double(map.finerGridRetries) });
  AddField<vtkIntArray>(fd, names::FinerGridTriangles, { double(map.finerGridTriangles) });
  AddField<vtkIntArray>(
    fd, names::BranchPointsOnGrid, { double(map.branchPoints), double(map.branchPointsOnGrid) });
  AddField<vtkDoubleArray>(fd, names::SeamTranslationError, { map.maxSeamError });
}
}

//------------------------------------------------------------------------------
vtkQuadCoverSolver::vtkQuadCoverSolver()
  : vtkQuadCoverAlgorithm(MANIFOLD_SURFACE, "parameterize")
{
  const quadcover::ParameterizationOptions defaults;
  this->TargetEdgeLength = defaults.targetEdgeLength;
  this->TargetQuadCount = static_cast<int>(defaults.targetQuadCount);
  this->PureQuads = defaults.pureQuads;
  this->RoundingMode = FilterRounding(defaults.roundingMode);
  this->AlignToBoundary = defaults.alignToBoundary;
  this->BoundaryTolerance = defaults.boundaryTolerance;
  this->FeatureLines = defaults.featureLines;
  this->FeatureAngle = defaults.featureAngle;
  this->MinimumFeatureLength = defaults.minimumFeatureLength;
  this->MaximumUntangleRounds = defaults.maximumUntangleRounds;
  this->UntangleWork = defaults.untangleWork;
  this->MinimumComponentQuadCount = defaults.minimumComponentQuadCount;
  this->CurvatureEdgeLength = defaults.curvatureEdgeLength;
  this->MinimumQuadsPerSingularity = defaults.minimumQuadsPerSingularity;
  this->MaximumRegrids = defaults.maximumRegrids;
  this->MaximumRegridQuadCount = defaults.maximumRegridQuadCount;
  this->MinimumSingularitySeparation = defaults.minimumSingularitySeparation;
  this->MaximumTriangleEdge = defaults.maximumTriangleEdge;
  this->ConePairGain = defaults.conePairGain;
  this->MaximumThinStripRefinement = defaults.maximumThinStripRefinement;
  this->AdaptiveCurvature = defaults.adaptiveCurvature;
  this->DefectGridRefinement = defaults.defectGridRefinement;
  this->DefectAdaptiveCurvature = defaults.defectAdaptiveCurvature;
  this->MaximumFinerGridRetries = defaults.maximumFinerGridRetries;
  this->NumberOfThreads = defaults.numberOfThreads;
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::FrameU);
  this->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::Matching);
}

//------------------------------------------------------------------------------
double vtkQuadCoverSolver::MaximumQuadCount(vtkIdType triangles)
{
  return std::max(2e6, 50.0 * static_cast<double>(triangles));
}

namespace
{
/// The quads `o` ask of the whole surface (before each component's minimum).
double TargetShare(const vtkQuadCoverSurface& in, const quadcover::ParameterizationOptions& o)
{
  return o.targetEdgeLength > 0.0
    ? quadcover::surfaceArea(in.V, in.F) / (o.targetEdgeLength * o.targetEdgeLength)
    : static_cast<double>(o.targetQuadCount);
}

/// Throws when `options` ask more quads of the surface than MaximumQuadCount allows.
void CheckQuadCount(const vtkQuadCoverSurface& in, const quadcover::ParameterizationOptions& o,
  double worldEdgeLength)
{
  const double share = TargetShare(in, o);
  // each component's minimum comes on top of its share, at most; with a target edge length an
  // adaptive grid's finer cells too
  const double growth =
    o.adaptiveCurvature > 0 && o.targetEdgeLength > 0 ? quadcover::AdaptiveMaximumGrowth : 1.0;
  const double quads = growth * share + o.minimumComponentQuadCount * in.topo.numComponents();
  const double most = vtkQuadCoverSolver::MaximumQuadCount(in.F.rows());
  if (!(quads > most)) // NaN (a zero-area surface) is for the map to refuse
  {
    return;
  }
  char text[320];
  if (o.targetEdgeLength > 0.0)
    std::snprintf(text, sizeof text, "TargetEdgeLength %g gives", worldEdgeLength);
  else
    std::snprintf(text, sizeof text, "TargetQuadCount %.0f gives", o.targetQuadCount);
  const std::string asked = text;
  std::snprintf(text, sizeof text,
    " about %.3g quads, too many for this surface (about %.0f GB of memory); at most %.0f quads "
    "are taken (2000000, or 50 for each of its %lld triangles)",
    quads, std::ceil(quads * 0.6e3 / 1e9), most, static_cast<long long>(in.F.rows()));
  throw std::invalid_argument(asked + text);
}

/**
 * `in` with the edges longer than o.maximumTriangleEdge grid edges split (refineLongEdges; the
 * grid edge of o's target on the whole surface), at most F + 16 quads triangles (500,000): the
 * new points after the input's with their point data interpolated, the cell data copied from the
 * triangle split, `U` carried and the `matching` array (and the cell array it came from)
 * rewritten. Returns the input triangles split (0: all untouched).
 */
int RefineLongEdges(vtkQuadCoverSurface& in, const quadcover::ParameterizationOptions& o,
  vtkDataArray* matchingArray, Eigen::MatrixX3d& U, Eigen::MatrixX3i& matching)
{
  if (!(o.maximumTriangleEdge > 0.0))
  {
    return 0;
  }
  const double h = o.targetEdgeLength > 0.0
    ? o.targetEdgeLength
    : quadcover::edgeLengthForQuadCount(in.V, in.F, o.targetQuadCount);
  if (!(h > 0.0))
  {
    return 0;
  }
  const double most = std::min(5e5, static_cast<double>(in.F.rows()) + 16.0 * TargetShare(in, o));
  const quadcover::EdgeRefinement r = quadcover::refineLongEdges(
    in.V, in.F, o.maximumTriangleEdge * h, static_cast<int>(std::max(0.0, most)));
  if (r.refinedTriangles == 0)
  {
    return 0;
  }
  vtkSmartPointer<vtkPolyData> made = vtkQuadCoverEigen::ToPolyData(in.InWorldUnits(r.V), r.F);
  vtkQuadCoverEigen::CarryRefinedAttributes(in.polyData, r.midpoints, r.parent, made);
  made->GetFieldData()->ShallowCopy(in.polyData->GetFieldData());
  Eigen::MatrixX3d carried(r.F.rows(), 3);
  for (Eigen::Index t = 0; t < r.F.rows(); ++t)
  {
    carried.row(t) = U.row(r.parent[static_cast<std::size_t>(t)]);
  }
  U = carried;
  matching = quadcover::refinedMatching(r, matching);
  vtkSmartPointer<vtkDataArray> rewritten = vtk::TakeSmartPointer(matchingArray->NewInstance());
  rewritten->SetName(matchingArray->GetName());
  rewritten->SetNumberOfComponents(3);
  rewritten->SetNumberOfTuples(r.F.rows());
  for (Eigen::Index t = 0; t < r.F.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      rewritten->SetComponent(t, k, matching(t, k));
    }
  }
  if (matchingArray->GetName())
  {
    made->GetCellData()->AddArray(rewritten);
  }
  in.polyData = made;
  in.V = r.V;
  in.F = r.F;
  in.topo = quadcover::buildTopology(in.F, static_cast<int>(in.V.rows()));
  return r.refinedTriangles;
}
}

//------------------------------------------------------------------------------
void vtkQuadCoverSolver::Execute(vtkQuadCoverSurface& in, vtkInformationVector* outputVector)
{
  vtkDataArray* u = this->RequireCellArray(0, in.polyData, 3, names::FrameU,
    "run the earlier stages first, or name your own with SetInputArrayToProcess(0, ...)");
  vtkDataArray* m = this->RequireCellArray(1, in.polyData, 3, names::Matching,
    "run vtkMatchingBuilder first, or name your own with SetInputArrayToProcess(1, ...)");
  Eigen::MatrixX3d U = vtkQuadCoverEigen::FromArray3(u);
  if (!U.allFinite())
  {
    throw std::invalid_argument(std::string(names::FrameU) + " has non-finite values");
  }
  Eigen::MatrixX3i matching = ReadMatching(m);
  this->UpdateProgress(0.1);

  vtkQuadCoverEigen::RequireNumbers({ { "TargetEdgeLength", this->TargetEdgeLength },
    { "BoundaryTolerance", this->BoundaryTolerance }, { "FeatureAngle", this->FeatureAngle },
    { "CurvatureEdgeLength", this->CurvatureEdgeLength },
    { "MinimumQuadsPerSingularity", this->MinimumQuadsPerSingularity },
    { "MaximumRegridQuadCount", this->MaximumRegridQuadCount },
    { "MinimumSingularitySeparation", this->MinimumSingularitySeparation },
    { "MaximumTriangleEdge", this->MaximumTriangleEdge }, { "ConePairGain", this->ConePairGain },
    { "MaximumThinStripRefinement", this->MaximumThinStripRefinement },
    { "AdaptiveCurvature", this->AdaptiveCurvature },
    { "DefectGridRefinement", this->DefectGridRefinement },
    { "DefectAdaptiveCurvature", this->DefectAdaptiveCurvature } });
  quadcover::ParameterizationOptions options;
  options.targetEdgeLength = in.InCoreUnits(this->TargetEdgeLength); // for the scaled surface
  options.targetQuadCount = this->TargetQuadCount;
  options.pureQuads = this->PureQuads;
  options.roundingMode = CoreRounding(this->RoundingMode);
  options.alignToBoundary = this->AlignToBoundary;
  options.boundaryTolerance = this->BoundaryTolerance;
  options.featureLines = this->FeatureLines;
  options.featureAngle = this->FeatureAngle;
  options.minimumFeatureLength = this->MinimumFeatureLength;
  options.maximumUntangleRounds = this->MaximumUntangleRounds;
  options.untangleWork = this->UntangleWork;
  options.minimumComponentQuadCount = this->MinimumComponentQuadCount;
  options.curvatureEdgeLength = this->CurvatureEdgeLength;
  options.minimumQuadsPerSingularity = this->MinimumQuadsPerSingularity;
  options.maximumRegrids = this->MaximumRegrids;
  options.maximumRegridQuadCount = this->MaximumRegridQuadCount;
  options.minimumSingularitySeparation = this->MinimumSingularitySeparation;
  options.maximumTriangleEdge = this->MaximumTriangleEdge;
  options.conePairGain = this->ConePairGain;
  options.maximumThinStripRefinement = this->MaximumThinStripRefinement;
  options.adaptiveCurvature = this->AdaptiveCurvature;
  options.defectGridRefinement = this->DefectGridRefinement;
  options.defectAdaptiveCurvature = this->DefectAdaptiveCurvature;
  options.maximumFinerGridRetries = this->MaximumFinerGridRetries;
  options.numberOfThreads = this->NumberOfThreads;
  CheckQuadCount(in, options, this->TargetEdgeLength);
  const int refined = RefineLongEdges(in, options, m, U, matching);
  const quadcover::FrameGeometry geometry = quadcover::computeFrameGeometry(in.V, in.F, in.topo);
  const quadcover::Parameterization map = quadcover::computeParameterization(in.V, in.F, in.topo,
    geometry, U, matching, options, vtkQuadCoverEigen::CoreProgress(this, 0.15, 0.95));
  if (map.finerForSingularities)
  {
    this->Warn("the frame field has " + std::to_string(map.branchPoints) +
      " singular points, more than the quads asked can hold (MinimumQuadsPerSingularity); the "
      "grid was made finer, and there are more quads than asked");
  }
  if (map.finerGridRetries > 0)
  {
    this->Warn("on a grid as fine as asked the quads would not keep the surface's topology; the "
               "map was made again on a finer grid (FinerGridRetries " +
      std::to_string(map.finerGridRetries) + "), and there are more quads than asked");
  }
  if (map.wrongWindings > 0)
  {
    this->Warn(std::to_string(map.wrongWindings) +
      " points keep a map that winds around them unlike the frame field; the quads there may be "
      "irregular");
  }
  if (map.flipped > 0)
  {
    this->Warn(std::to_string(map.flipped) +
      " triangles keep a flipped (u, v) image after untangling; the quads there may be "
      "irregular (a finer or coarser grid may help)" +
      std::string(
        map.untangleBudgetSpent ? "; the untangling stopped at its budget (UntangleWork)" : ""));
  }

  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (this->SplitSeams)
  {
    WriteSplitSurface(output, in, map);
  }
  else
  {
    output->ShallowCopy(in.polyData);
  }
  WriteOwnSingularities(output, map, this->SplitSeams);
  output->GetCellData()->AddArray(vtkQuadCoverEigen::ToArray(map.cornerUV, names::CornerUV));
  output->GetCellData()->AddArray(
    vtkQuadCoverEigen::ToArray<vtkUnsignedCharArray>(map.seam, names::Seam));
  AddFigures(output->GetFieldData(), map, in);
  vtkQuadCoverEigen::AddField<vtkIntArray>(
    output->GetFieldData(), names::GridRefinedTriangles, { double(refined) });
  this->SolveSeconds = map.solveSeconds;
}

//------------------------------------------------------------------------------
int vtkQuadCoverSolver::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->SolveSeconds.clear();
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkQuadCoverSolver::GetNumberOfSolves() const
{
  return static_cast<int>(this->SolveSeconds.size());
}

//------------------------------------------------------------------------------
double vtkQuadCoverSolver::GetSolveSeconds(int i) const
{
  return i >= 0 && i < this->GetNumberOfSolves() ? this->SolveSeconds[i] : 0.0;
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
  os << indent << "FeatureLines: " << (this->FeatureLines ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "MinimumFeatureLength: " << this->MinimumFeatureLength << "\n";
  os << indent << "MaximumUntangleRounds: " << this->MaximumUntangleRounds << "\n";
  os << indent << "UntangleWork: " << this->UntangleWork << "\n";
  os << indent << "MinimumComponentQuadCount: " << this->MinimumComponentQuadCount << "\n";
  os << indent << "CurvatureEdgeLength: " << this->CurvatureEdgeLength << "\n";
  os << indent << "MinimumQuadsPerSingularity: " << this->MinimumQuadsPerSingularity << "\n";
  os << indent << "MaximumRegrids: " << this->MaximumRegrids << "\n";
  os << indent << "MaximumRegridQuadCount: " << this->MaximumRegridQuadCount << "\n";
  os << indent << "MaximumTriangleEdge: " << this->MaximumTriangleEdge << "\n";
  os << indent << "MinimumSingularitySeparation: " << this->MinimumSingularitySeparation
     << "\n";
  os << indent << "ConePairGain: " << this->ConePairGain << "\n";
  os << indent << "MaximumThinStripRefinement: " << this->MaximumThinStripRefinement << "\n";
  os << indent << "AdaptiveCurvature: " << this->AdaptiveCurvature << "\n";
  os << indent << "DefectGridRefinement: " << this->DefectGridRefinement << "\n";
  os << indent << "DefectAdaptiveCurvature: " << this->DefectAdaptiveCurvature << "\n";
  os << indent << "MaximumFinerGridRetries: " << this->MaximumFinerGridRetries << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "SplitSeams: " << (this->SplitSeams ? "On" : "Off") << "\n";
}
