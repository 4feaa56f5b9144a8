#include "vtkQuadCoverRemesh.h"

#include "vtkCurvatureFrames.h"
#include "vtkFrameSmoother.h"
#include "vtkMatchingBuilder.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverPieces.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadCoverSurfaceRepair.h"
#include "vtkQuadExtractor.h"

#include "vtkCallbackCommand.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>

vtkStandardNewMacro(vtkQuadCoverRemesh);

//------------------------------------------------------------------------------
vtkQuadCoverRemesh::vtkQuadCoverRemesh()
{
  this->Repair->SetInputData(this->Surface);
  this->Curvature->SetInputConnection(this->Repair->GetOutputPort());
  this->Smoother->SetInputConnection(this->Curvature->GetOutputPort());
  this->Matching->SetInputConnection(this->Smoother->GetOutputPort());
  this->Solver->SetInputConnection(this->Matching->GetOutputPort());
  this->Extractor->SetInputConnection(this->Solver->GetOutputPort());
  this->Progress->SetCallback(&vtkQuadCoverRemesh::OnProgress);
  this->Progress->SetClientData(this);
  for (int i = 0; i < StageCount; ++i)
  {
    this->Errors->Attach(this->Stage(i));
    this->Stage(i)->AddObserver(vtkCommand::ProgressEvent, this->Progress);
  }
}

//------------------------------------------------------------------------------
vtkAlgorithm* vtkQuadCoverRemesh::Stage(int i) const
{
  vtkAlgorithm* const stages[StageCount] = { this->Repair, this->Curvature, this->Smoother,
    this->Matching, this->Solver, this->Extractor };
  return stages[i];
}

//------------------------------------------------------------------------------
vtkQuadCoverRemesh::~vtkQuadCoverRemesh()
{
  // a stage someone still holds must not call back into this filter
  for (int i = 0; i < StageCount; ++i)
  {
    vtkAlgorithm* stage = this->Stage(i);
    stage->RemoveObserver(this->Progress);
    stage->RemoveObserver(this->Errors);
    stage->GetExecutive()->RemoveObserver(this->Errors);
  }
}

//------------------------------------------------------------------------------
void vtkQuadCoverRemesh::SetTargetQuadCount(int count)
{
  this->Solver->SetTargetQuadCount(count);
}
int vtkQuadCoverRemesh::GetTargetQuadCount()
{
  return this->Solver->GetTargetQuadCount();
}
void vtkQuadCoverRemesh::SetTargetEdgeLength(double length)
{
  this->Solver->SetTargetEdgeLength(length);
}
double vtkQuadCoverRemesh::GetTargetEdgeLength()
{
  return this->Solver->GetTargetEdgeLength();
}
void vtkQuadCoverRemesh::SetFeatureLines(bool on)
{
  this->Solver->SetFeatureLines(on);
}
bool vtkQuadCoverRemesh::GetFeatureLines()
{
  return this->Solver->GetFeatureLines();
}
void vtkQuadCoverRemesh::SetSmoothRoughSurfaces(bool on)
{
  this->Repair->SetSmoothRoughSurfaces(on);
}
bool vtkQuadCoverRemesh::GetSmoothRoughSurfaces()
{
  return this->Repair->GetSmoothRoughSurfaces();
}
void vtkQuadCoverRemesh::SetFeatureAngle(double degrees)
{
  this->Smoother->SetFeatureAngle(degrees);
  this->Solver->SetFeatureAngle(degrees);
  this->Extractor->SetFeatureAngle(degrees);
}
double vtkQuadCoverRemesh::GetFeatureAngle()
{
  return this->Smoother->GetFeatureAngle();
}
void vtkQuadCoverRemesh::SetNumberOfThreads(int count)
{
  this->Curvature->SetNumberOfThreads(count);
  this->Smoother->SetNumberOfThreads(count);
  this->Solver->SetNumberOfThreads(count);
}
int vtkQuadCoverRemesh::GetNumberOfThreads()
{
  return this->Curvature->GetNumberOfThreads();
}

//------------------------------------------------------------------------------
vtkQuadCoverSurfaceRepair* vtkQuadCoverRemesh::GetSurfaceRepair()
{
  return this->Repair;
}
vtkCurvatureFrames* vtkQuadCoverRemesh::GetCurvatureFrames()
{
  return this->Curvature;
}
vtkFrameSmoother* vtkQuadCoverRemesh::GetFrameSmoother()
{
  return this->Smoother;
}
vtkMatchingBuilder* vtkQuadCoverRemesh::GetMatchingBuilder()
{
  return this->Matching;
}
vtkQuadCoverSolver* vtkQuadCoverRemesh::GetSolver()
{
  return this->Solver;
}
vtkQuadExtractor* vtkQuadCoverRemesh::GetQuadExtractor()
{
  return this->Extractor;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkQuadCoverRemesh::GetMTime()
{
  vtkMTimeType latest = this->Superclass::GetMTime();
  for (int i = 0; i < StageCount; ++i)
  {
    latest = std::max(latest, this->Stage(i)->GetMTime());
  }
  return latest;
}

//------------------------------------------------------------------------------
void vtkQuadCoverRemesh::OnProgress(
  vtkObject* caller, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<vtkQuadCoverRemesh*>(clientData);
  int stage = 0;
  while (stage + 1 < StageCount && self->Stage(stage) != caller)
  {
    ++stage;
  }
  self->StageProgress(stage, *static_cast<double*>(callData));
}

void vtkQuadCoverRemesh::StageProgress(int stage, double progress)
{
  this->UpdateProgress((stage + std::min(std::max(progress, 0.0), 1.0)) / StageCount);
  if (this->GetAbortExecute())
  {
    this->Stage(stage)->SetAbortExecute(1);
  }
}

//------------------------------------------------------------------------------
int vtkQuadCoverRemesh::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const int done = this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  this->EmptyPiece = vtkQuadCoverPieces::RequestWholeSurface(request, inputVector, outputVector);
  return done;
}

//------------------------------------------------------------------------------
int vtkQuadCoverRemesh::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (this->EmptyPiece)
  {
    output->Initialize(); // the rank of piece 0 remeshes the whole surface
    return 1;
  }
  // The stages' input stays connected (connecting it would make this filter look modified); a
  // new or changed input reaches them as a change of its data, and only then, so that a changed
  // property re-runs only its stage onward.
  if (input != this->LastInput || input->GetMTime() != this->LastInputTime)
  {
    this->Surface->ShallowCopy(input);
    this->LastInput = input;
    this->LastInputTime = input->GetMTime();
  }
  this->Errors->Clear();
  // VTK 9.2's executive leaves AbortExecute set after an aborted run: a stage stopped by an
  // earlier abort of this filter runs again
  for (int i = 0; i < StageCount; ++i)
  {
    this->Stage(i)->SetAbortExecute(0);
  }
  // a surface far finer than the quads need is simplified, the quads put back onto it
  this->Repair->SetMaximumTriangleCount(this->MaximumTriangleCount >= 0
      ? this->MaximumTriangleCount
      : vtkQuadCoverSurfaceRepair::MaximumTriangleCountFor(
          this->Surface, this->GetTargetQuadCount(), this->GetTargetEdgeLength()));
  this->Repair->Update();
  // (a smoothed surface keeps its quads: the input's noise is what it took out)
  const bool simplified = vtkQuadCoverSurfaceRepair::Simplified(this->Repair->GetOutput()) &&
    !vtkQuadCoverSurfaceRepair::Smoothed(this->Repair->GetOutput()) &&
    !this->Repair->GetAbortExecute();
  if (simplified != (this->Extractor->GetNumberOfInputConnections(1) > 0))
  {
    this->Extractor->SetSourceData(simplified ? this->Surface.Get() : nullptr);
  }
  this->Extractor->Update();
  bool aborted = false;
  for (int i = 0; i < StageCount; ++i)
  {
    aborted = aborted || this->Stage(i)->GetAbortExecute();
  }
  if (aborted)
  {
    // stopped on request: no result and no error (the stages after the stopped one found an
    // empty input)
    output->Initialize();
    return 1;
  }
  for (int w = 0; w < this->Errors->GetNumberOfWarnings(); ++w)
  {
    vtkWarningMacro(<< this->Errors->GetWarning(w));
  }
  if (!this->Errors->GetError().empty())
  {
    output->Initialize(); // nothing of an earlier run
    vtkErrorMacro(<< this->Errors->GetError());
    return 0;
  }
  output->ShallowCopy(this->Extractor->GetOutput());
  return 1;
}

//------------------------------------------------------------------------------
void vtkQuadCoverRemesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetQuadCount: " << this->GetTargetQuadCount() << "\n";
  os << indent << "TargetEdgeLength: " << this->GetTargetEdgeLength() << "\n";
  os << indent << "FeatureLines: " << (this->GetFeatureLines() ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->GetFeatureAngle() << "\n";
  os << indent << "NumberOfThreads: " << this->GetNumberOfThreads() << "\n";
  os << indent << "MaximumTriangleCount: " << this->MaximumTriangleCount << "\n";
  os << indent << "SmoothRoughSurfaces: " << (this->GetSmoothRoughSurfaces() ? "On" : "Off")
     << "\n";
}
