/**
 * @class   vtkCurvatureFrames
 * @brief   per-triangle principal curvatures and the curvature-aligned guidance frame field
 *
 * First stage of the QuadCover pipeline (Kaelberer, Nieser, Polthier 2007, Sect. 3). For every
 * triangle it estimates the curvature tensor with the normal-cycle measure of Cohen-Steiner and
 * Morvan: every interior edge contributes its signed dihedral angle times its length times the
 * outer product of its direction, summed over the triangles whose centroids lie closer than
 * NeighborhoodRadius median edge lengths (reached across edges; at most 8192 triangles) and
 * divided by their area. The median rather than the mean edge length sets the scale, so that a
 * few outsized triangles do not blow up the neighbourhoods.
 *
 * Output: the input's triangles (polygons and strips triangulated) and points, plus cell data
 * (names in vtkQuadCoverArrayNames.h):
 * - PrincipalCurvatures (2 x double, kappa1 >= kappa2; positive where the surface bends away
 *   from the triangle normal, so a sphere with outward normals has +1/R),
 * - PrincipalDirection1, PrincipalDirection2 (3 x double, unit, in the triangle's plane),
 * - FrameU (along PrincipalDirection2, the smaller curvature), FrameV = normal x FrameU,
 * - FrameWeight omega = |k1 - k2| / sqrt(k1^2 + k2^2) (0 where both vanish),
 * and field data CurvatureRadius (the radius used, world units).
 *
 * With UseInputFrames on (the default) and a 3-component cell array FrameU on the input, that
 * field is kept instead of the curvature frame: each vector is projected into its triangle's
 * plane and normalized, FrameV completes it. Where a vector has no tangent part the curvature
 * frame is used (the count goes to a warning).
 *
 * Errors (no output): no points, no triangles, point ids out of range, non-finite coordinates,
 * non-manifold edges (three or more triangles on one edge), inconsistently oriented neighbours,
 * and a surface whose triangles all have zero area. Triangles that repeat a point id (e.g. the
 * joins of triangle strips) carry no surface and are dropped with a warning. Run
 * vtkQuadCoverSurfaceRepair first on a raw surface (it merges duplicate points, orients the
 * triangles and splits non-manifold vertices). Vertices and lines are dropped with a warning.
 * Zero-area triangles are accepted: they take their neighbourhood's normal and their edges add no
 * bending (zero frames, with a warning, where no neighbour has a normal either). Non-manifold
 * vertices (fans touching at one vertex) only give a warning: they do not disturb a per-triangle
 * estimate.
 *
 * @warning The estimate is cell-centred; vtkCurvatures gives per-vertex Gaussian/mean values.
 * @sa vtkFrameSmoother vtkCurvatures
 */
#ifndef vtkCurvatureFrames_h
#define vtkCurvatureFrames_h

#include "vtkQuadCoverAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

class VTKQUADCOVERFILTERS_EXPORT vtkCurvatureFrames : public vtkQuadCoverAlgorithm
{
public:
  static vtkCurvatureFrames* New();
  vtkTypeMacro(vtkCurvatureFrames, vtkQuadCoverAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Radius of the averaging neighbourhood in multiples of the median edge length, in [0, 20]
   * (default 2). 0 uses each triangle's own edges; larger values give steadier directions on
   * noisy scans at the cost of detail.
   */
  vtkSetClampMacro(NeighborhoodRadius, double, 0.0, 20.0);
  vtkGetMacro(NeighborhoodRadius, double);
  ///@}

  ///@{
  /**
   * Number of threads for the per-triangle estimate, 0 for all cores (default 0). The result
   * does not depend on it.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Keep a FrameU cell array found on the input as the guidance field (default on).
   */
  vtkSetMacro(UseInputFrames, bool);
  vtkGetMacro(UseInputFrames, bool);
  vtkBooleanMacro(UseInputFrames, bool);
  ///@}

protected:
  vtkCurvatureFrames();
  ~vtkCurvatureFrames() override = default;

  void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) override;

  double NeighborhoodRadius; // defaults: quadcover::CurvatureOptions
  int NumberOfThreads;
  bool UseInputFrames = true;

private:
  vtkCurvatureFrames(const vtkCurvatureFrames&) = delete;
  void operator=(const vtkCurvatureFrames&) = delete;
};

#endif
