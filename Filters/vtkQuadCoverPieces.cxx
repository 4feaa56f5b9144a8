#include "vtkQuadCoverPieces.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

bool vtkQuadCoverPieces::RequestWholeSurface(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  // the port that was asked (the matching builder's branch points are port 1)
  const int port = request && request->Has(vtkExecutive::FROM_OUTPUT_PORT())
    ? request->Get(vtkExecutive::FROM_OUTPUT_PORT())
    : 0;
  vtkInformation* out = outputVector->GetInformationObject(
    port >= 0 && port < outputVector->GetNumberOfInformationObjects() ? port : 0);
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  if (!in || !out || !out->Has(SDDP::UPDATE_NUMBER_OF_PIECES()) ||
    out->Get(SDDP::UPDATE_NUMBER_OF_PIECES()) <= 1 ||
    vtkCompositeDataSet::SafeDownCast(in->Get(vtkDataObject::DATA_OBJECT())))
  {
    return false;
  }
  if (out->Has(SDDP::UPDATE_PIECE_NUMBER()) && out->Get(SDDP::UPDATE_PIECE_NUMBER()) != 0)
  {
    return true;
  }
  in->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
  in->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
  in->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return false;
}
