// vtkQuadCoverPieces.h: the QuadCover filters need a whole surface, never a piece of one.
//
// A distributed pipeline (ParaView's pvbatch or pvserver over MPI) asks each rank for piece p of
// n. Remeshed piece by piece, a closed surface would come out as open patches with seams that do
// not match. So the rank of piece 0 asks its input for the whole surface (piece 0 of 1, no ghost
// levels) and computes it; the other ranks leave their piece empty and pass their request on
// unchanged, so that upstream they read only their piece and the QuadCover stages there compute
// nothing either. The result is the whole surface's, once.
//
// A composite input (a multiblock of surfaces) is left as the pipeline distributes it: each
// block is a whole surface on the rank that holds it, and each rank remeshes its own blocks.
#ifndef vtkQuadCoverPieces_h
#define vtkQuadCoverPieces_h

class vtkInformationVector;

namespace vtkQuadCoverPieces
{
/**
 * For RequestUpdateExtent, after the default request was copied upstream: when the output is
 * asked for piece p of n > 1 and the input is not composite, asks the input for piece 0 of 1
 * without ghost levels if p is 0, and leaves the request as it is otherwise.
 * @return true when this piece is to be left empty (p != 0)
 */
bool RequestWholeSurface(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
}

#endif
