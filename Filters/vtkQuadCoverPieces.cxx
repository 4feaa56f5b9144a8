#include "vtkQuadCoverPieces.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

bool vtkQuadCoverPieces::RequestWholeSurface(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* out = outputVector->GetInformationObject(0);
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
