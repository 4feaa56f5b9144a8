/**
 * @class   vtkQuadCoverSurfaceRepair
 * @brief   makes a raw surface (scanned, exported, stitched) one the QuadCover stages accept
 *
 * Stage 0 of the QuadCover pipeline. In this order, and counted in field data (names in
 * vtkQuadCoverArrayNames.h):
 * - polygons with more than three sides and triangle strips are triangulated, vertex and line
 *   cells dropped (TriangulatedPolygons; the dropped cells go to RemovedCells); triangulating
 *   first keeps the repeated-point joins of strips from becoming triangles;
 * - coincident points (to round-off: within 1e-12 of the bounding box's diagonal) are merged into
 *   one, as the seams of VTK's parametric sources and OBJ files that repeat a point per texture
 *   coordinate need (MergedPoints), unused points dropped, and triangles left with a repeated
 *   point removed (RemovedCells); numbered and kept as vtkCleanPolyData with that tolerance
 *   would (quadcover::mergeCoincidentPoints);
 * - T-junctions are closed (ClosedTJunctions; quadcover::closeTJunctions): a point at the end of
 *   a boundary edge that lies on another boundary edge (within 1e-7 of the bounding box's
 *   diagonal, farther from its ends) is put into that edge, its triangle split there, each part
 *   with its cell data; faces meshed one by one, their seams cut at different points, then
 *   share their seams' points and edges and become one surface. So are the points of a crack
 *   along a boundary edge (a curved seam: a path of other boundary edges between the edge's
 *   ends through at most 8 points, within a twentieth of its length of it);
 * - edges shared by three or more triangles are cut apart into manifold sheets (CutEdges):
 *   around such an edge the two triangles of a surface that passes through it (joined elsewhere
 *   through manifold edges, agreeing in orientation) stay joined, and each other triangle to its
 *   nearest neighbour on its back side when the two agree in orientation, so that solids
 *   touching along an edge separate and a fin comes off the surface it stands on, one leaning
 *   into the solid too; two triangles left over stay joined; the rest get a boundary there
 *   (quadcover::makeManifold);
 * - a point where separate fans of triangles touch (a "bowtie", or the ends of a cut edge) gets
 *   one copy per fan, at the same position, its point data copied along (SplitVertices);
 * - triangles are turned over where they disagree with their neighbours; each connected
 *   component keeps the orientation of most of its area (ReorientedTriangles; a cell `Normals`
 *   array turns with its triangles);
 * - a flat triangle (height at most 1e-6 of its longest edge) whose corner lies on that edge (a
 *   cap, as the repair of a T-junction or a point put on an edge leaves it) is removed by
 *   flipping that edge: the neighbour across it is split at the corner, both parts with the
 *   neighbour's cell data (FlippedEdges; quadcover::flipDegenerateTriangles). The surface moves
 *   by at most the cap's height; its gradients, round-off, would leave the map unsolvable;
 * - a rough component, one whose curvature is mostly noise (two pairs of Taubin's steps take
 *   more than 60% of it away: a raw scan, an isosurface of noisy data), is smoothed by Taubin's
 *   steps, its boundary held (SmoothedPoints; SmoothRoughSurfaces,
 *   quadcover::smoothRoughComponents). The frame field would otherwise have a singularity at
 *   nearly every other point. The quads then lie on the smoothed surface;
 * - every triangle of a component with fewer than MinimumComponentTriangleCount triangles is
 *   split into four at its edges' midpoints, again until the component has that many
 *   (RefinedTriangles; point data interpolated, cell data copied to the parts): a coarse cone,
 *   fans of long needles around its tips, leaves a map no room (quadcover::refineCoarseComponents).
 *   The points stay and the new ones lie on the old edges: the surface does not change.
 * - a surface of more than MaximumTriangleCount triangles (when it is set; 0 by default) is
 *   brought down to about that many by edge collapses (CollapsedEdges; point data of the kept
 *   points and cell data of the kept triangles carried): a point moves onto a neighbour, the
 *   cheapest by the quadric error of its planes first, keeping the topology, boundaries, edges
 *   bent more than 40 degrees (points on them move along them only) and each component's share
 *   (quadcover::simplifySurface). vtkQuadCoverRemesh and the command line set it from the quads
 *   asked (16 triangles a quad, at least 100,000; quadcover::simplificationBudget), and put the
 *   quads back onto the input surface (vtkQuadExtractor's second input) unless it was smoothed.
 * The input's point, cell and field data are kept (cell data follow the triangles), but for the
 * normals of a smoothed surface: cell normals made again, point normals dropped.
 *
 * Errors (no output): no points, point ids out of range, NaN or infinite coordinates, no
 * polygons, no triangle with three distinct points, and a component that cannot be oriented (a
 * Moebius strip; the message numbers it).
 * @sa vtkCurvatureFrames vtkCleanPolyData vtkPolyDataNormals vtkTriangleFilter
 */
#ifndef vtkQuadCoverSurfaceRepair_h
#define vtkQuadCoverSurfaceRepair_h

#include "vtkQuadCoverAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

class vtkPolyData;

class VTKQUADCOVERFILTERS_EXPORT vtkQuadCoverSurfaceRepair : public vtkQuadCoverAlgorithm
{
public:
  static vtkQuadCoverSurfaceRepair* New();
  vtkTypeMacro(vtkQuadCoverSurfaceRepair, vtkQuadCoverAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Components with fewer triangles than this are refined until they have as many, in
   * [0, 100000] (default 256; 0 refines none). */
  vtkSetClampMacro(MinimumComponentTriangleCount, int, 0, 100000);
  vtkGetMacro(MinimumComponentTriangleCount, int);
  ///@}

  ///@{
  /** Smooth the rough components, noisy at the triangle scale (default on; the quads then lie
   * on the smoothed surface). */
  vtkSetMacro(SmoothRoughSurfaces, bool);
  vtkGetMacro(SmoothRoughSurfaces, bool);
  vtkBooleanMacro(SmoothRoughSurfaces, bool);
  ///@}

  ///@{
  /** A surface with more triangles is simplified to about this many (default 0: never; fewer
   * than 1000 read as 1000). vtkQuadCoverRemesh sets it from its quads
   * (MaximumTriangleCountFor). */
  vtkSetClampMacro(MaximumTriangleCount, vtkIdType, 0, 2000000000);
  vtkGetMacro(MaximumTriangleCount, vtkIdType);
  ///@}

  /** The MaximumTriangleCount for `surface` to be meshed into `targetQuadCount` quads, or into
   * quads of side `targetEdgeLength` where that is positive (its polygons' area over the length
   * squared): 16 triangles a quad, at least 100,000 (quadcover::simplificationBudget); 0 for no
   * quads. vtkQuadCoverRemesh and the command line use it. */
  static vtkIdType MaximumTriangleCountFor(
    vtkPolyData* surface, int targetQuadCount, double targetEdgeLength);

  /** The area of `surface`'s polygons (fans) and strips in squares of side `length` (> 0): each
   * coordinate divided by `length` first, so that the sum stays in double's range for a surface
   * of any size; cells with a point id out of range are left out. */
  static double AreaInSquares(vtkPolyData* surface, double length);

  /** Whether `repaired`, an output of this filter, was simplified (CollapsedEdges > 0). */
  static bool Simplified(vtkPolyData* repaired);

  /** Whether `repaired`, an output of this filter, had rough components smoothed
   * (SmoothedPoints > 0): its quads belong on it, not on the rough input. */
  static bool Smoothed(vtkPolyData* repaired);

protected:
  vtkQuadCoverSurfaceRepair();
  ~vtkQuadCoverSurfaceRepair() override = default;

  void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) override;

  // default: quadcover::RefinementOptions
  int MinimumComponentTriangleCount;
  vtkIdType MaximumTriangleCount = 0;
  bool SmoothRoughSurfaces; // default: quadcover::RoughSurfaceOptions

private:
  vtkQuadCoverSurfaceRepair(const vtkQuadCoverSurfaceRepair&) = delete;
  void operator=(const vtkQuadCoverSurfaceRepair&) = delete;
};

#endif
