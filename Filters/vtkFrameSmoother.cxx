#include "vtkFrameSmoother.h"

#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"

#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "FrameSmoother.h"
#include "Matchings.h"

vtkStandardNewMacro(vtkFrameSmoother);

//------------------------------------------------------------------------------
vtkFrameSmoother::vtkFrameSmoother()
  : vtkQuadCoverAlgorithm(MANIFOLD_EDGES, "smooth frames")
{
  const quadcover::SmootherOptions defaults;
  this->SmoothingWeight = defaults.smoothingWeight;
  this->MaximumNumberOfIterations = defaults.maximumNumberOfIterations;
  this->ConvergenceTolerance = defaults.convergenceTolerance;
  this->AlignToFeatures = defaults.alignToFeatures;
  this->FeatureAngle = defaults.featureAngle;
  this->MinimumFeatureLength = defaults.minimumFeatureLength;
  this->AlignToBoundary = defaults.alignToBoundary;
  this->GlobalStart = defaults.globalStart;
  this->CoherenceRadius = defaults.coherenceRadius;
  this->NumberOfThreads = defaults.numberOfThreads;
  namespace names = vtkQuadCoverArrayNames;
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::FrameU);
  this->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::FrameV);
  this->SetInputArrayToProcess(2, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, names::FrameWeight);
}

//------------------------------------------------------------------------------
void vtkFrameSmoother::Execute(vtkQuadCoverSurface& in, vtkInformationVector* outputVector)
{
  namespace names = vtkQuadCoverArrayNames;
  const vtkIdType nf = in.NumberOfTriangles();
  vtkDataArray* u = this->RequireCellArray(0, in.polyData, 3, names::FrameU,
    "run vtkCurvatureFrames first, or name your own with SetInputArrayToProcess");
  vtkDataArray* v = this->GetInputArrayToProcess(1, in.polyData);
  vtkDataArray* w = this->GetInputArrayToProcess(2, in.polyData);
  this->UpdateProgress(0.1);
  const quadcover::FrameGeometry geometry = quadcover::computeFrameGeometry(in.V, in.F, in.topo);
  // Frames as tangent unit vectors; FrameV defaults to n x FrameU, the weight to 1.
  const bool haveV = v && v->GetNumberOfComponents() == 3 && v->GetNumberOfTuples() == nf;
  const auto [U, Vf] = quadcover::tangentFrames(geometry.bases, vtkQuadCoverEigen::FromArray3(u),
    haveV ? vtkQuadCoverEigen::FromArray3(v) : Eigen::MatrixX3d());
  const bool haveWeight = w && w->GetNumberOfComponents() == 1 && w->GetNumberOfTuples() == nf;
  const Eigen::VectorXd weight =
    haveWeight ? Eigen::VectorXd(vtkQuadCoverEigen::FromArray(w)) : Eigen::VectorXd::Ones(nf);
  this->UpdateProgress(0.2);

  vtkQuadCoverEigen::RequireNumbers({ { "SmoothingWeight", this->SmoothingWeight },
    { "ConvergenceTolerance", this->ConvergenceTolerance }, { "FeatureAngle", this->FeatureAngle },
    { "CoherenceRadius", this->CoherenceRadius } });
  quadcover::SmootherOptions options;
  options.smoothingWeight = this->SmoothingWeight;
  options.maximumNumberOfIterations = this->MaximumNumberOfIterations;
  options.convergenceTolerance = this->ConvergenceTolerance;
  options.alignToFeatures = this->AlignToFeatures;
  options.featureAngle = this->FeatureAngle;
  options.minimumFeatureLength = this->MinimumFeatureLength;
  options.alignToBoundary = this->AlignToBoundary;
  options.globalStart = this->GlobalStart;
  options.coherenceRadius = this->CoherenceRadius;
  options.numberOfThreads = this->NumberOfThreads;
  const quadcover::SmootherResult r = quadcover::smoothFrames(in.V, in.F, in.topo, geometry, U, Vf,
    weight, options, vtkQuadCoverEigen::CoreProgress(this, 0.2, 0.95));

  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->ShallowCopy(in.polyData);
  vtkCellData* cd = output->GetCellData();
  using vtkQuadCoverEigen::ToArray;
  cd->AddArray(ToArray(r.frameU, names::FrameU));
  cd->AddArray(ToArray(r.frameV, names::FrameV));
  cd->AddArray(ToArray(r.rotation, names::FrameRotation));
  cd->AddArray(ToArray(r.coherence, names::FrameCoherence));
  cd->AddArray(ToArray<vtkUnsignedCharArray>(
    Eigen::Map<const Eigen::Matrix<char, Eigen::Dynamic, 1>>(r.constrained.data(), nf),
    names::FrameConstrained));
  vtkFieldData* fd = output->GetFieldData();
  // area-weighted: an area of the scaled surface (vtkQuadCoverSurface), in the input's units
  vtkQuadCoverEigen::AddField<vtkDoubleArray>(fd, names::SmoothingEnergy,
    { in.InWorldUnits(r.energyBefore, 2), in.InWorldUnits(r.energyAfter, 2) });
  vtkQuadCoverEigen::AddField<vtkIntArray>(
    fd, names::SmoothingIterations, { double(r.iterations) });
  vtkQuadCoverEigen::AddField<vtkIntArray>(
    fd, names::ConstrainedFrameCount, { double(r.numConstrained) });
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
  os << indent << "CoherenceRadius: " << this->CoherenceRadius << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
