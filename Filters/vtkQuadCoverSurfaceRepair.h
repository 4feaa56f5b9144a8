/**
 * @class   vtkQuadCoverSurfaceRepair
 * @brief   makes a raw surface (scanned, exported, stitched) one the QuadCover stages accept
 *
 * Stage 0 of the QuadCover pipeline. In this order, and counted in field data (names in
 * vtkQuadCoverArrayNames.h):
 * - polygons with more than three sides and triangle strips are triangulated, vertex and line
 *   cells dropped (TriangulatedPolygons; the dropped cells go to RemovedCells); triangulating
 *   first keeps the repeated-point joins of strips from becoming triangles;
 * - exactly coincident points are merged into one, as OBJ files that repeat a point per texture
 *   coordinate need (MergedPoints), unused points dropped, and triangles left with a repeated
 *   point removed (RemovedCells);
 * - triangles are turned over where they disagree with their neighbours, one orientation per
 *   connected component (ReorientedTriangles);
 * - a point where separate fans of triangles touch (a "bowtie") gets one copy per fan, at the
 *   same position, its point data copied along (SplitVertices).
 * The input's point, cell and field data are kept (cell data follow the triangles).
 *
 * Errors (no output): no points, point ids out of range, NaN or infinite coordinates, no
 * polygons, no triangle with three distinct points, and edges shared by three or more triangles
 * (non-manifold edges: cutting them apart would change the surface).
 * @sa vtkCurvatureFrames vtkCleanPolyData vtkPolyDataNormals vtkTriangleFilter
 */
#ifndef vtkQuadCoverSurfaceRepair_h
#define vtkQuadCoverSurfaceRepair_h

#include "vtkQuadCoverAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

class VTKQUADCOVERFILTERS_EXPORT vtkQuadCoverSurfaceRepair : public vtkQuadCoverAlgorithm
{
public:
  static vtkQuadCoverSurfaceRepair* New();
  vtkTypeMacro(vtkQuadCoverSurfaceRepair, vtkQuadCoverAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkQuadCoverSurfaceRepair();
  ~vtkQuadCoverSurfaceRepair() override = default;

  void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) override;

private:
  vtkQuadCoverSurfaceRepair(const vtkQuadCoverSurfaceRepair&) = delete;
  void operator=(const vtkQuadCoverSurfaceRepair&) = delete;
};

#endif
