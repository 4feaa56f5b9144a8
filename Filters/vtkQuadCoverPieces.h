// vtkQuadCoverPieces.h: the QuadCover filters need a whole surface, never a piece of one.
//
// A distributed pipeline (ParaView's pvbatch or pvserver over MPI) asks each rank for piece p of
// n. Remeshed piece by piece, a closed surface would come out as open patches with seams that do
// not match. So the rank of piece 0 asks its input for the whole surface (piece 0 of 1, no ghost
// levels) and computes it; the other ranks leave their piece empty and pass their request on
// unchanged, so that upstream they read only their piece and the QuadCover stages there compute
// nothing either. The result is the whole surface's, once.
//
// A composite input (a multiblock of surfaces) is left as the pipeline distributes it, and each
// rank remeshes the blocks it holds. That is right when each block is whole on its rank (a .vtm
// reader hands out whole blocks), wrong when the blocks are themselves split over the ranks
// (sources grouped on several ranks): their pieces are remeshed as they are. The blocks carry
// nothing that tells the two apart (GroupDatasets leaves each block "piece 0 of 1").
//
// Likewise "piece 0 of 1" is the whole surface only where the upstream honours piece requests
// (readers and sources do; a redistribution such as D3 does not).
#ifndef vtkQuadCoverPieces_h
#define vtkQuadCoverPieces_h

class vtkInformation;
class vtkInformationVector;

namespace vtkQuadCoverPieces
{
/**
 * For RequestUpdateExtent, after the default request was copied upstream: when the output port
 * the request came from (FROM_OUTPUT_PORT) is asked for piece p of n > 1 and the input is not
 * composite, asks the input for piece 0 of 1 without ghost levels if p is 0, and leaves the
 * request as it is otherwise.
 * @return true when this piece is to be left empty (p != 0)
 */
bool RequestWholeSurface(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector);
}

#endif
