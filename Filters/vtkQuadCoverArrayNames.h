/**
 * @file   vtkQuadCoverArrayNames.h
 * @brief  The names of every array passed down the QuadCover pipeline: the public contract.
 *
 * Each stage reads the arrays the previous stage wrote and adds its own. The table in
 * README.md ("Arrays") lists, for every name here, its association, components, type, the filter
 * that writes it and the filters that read it. Change a name here and there, never elsewhere.
 */
#ifndef vtkQuadCoverArrayNames_h
#define vtkQuadCoverArrayNames_h

namespace vtkQuadCoverArrayNames
{
// ---- vtkCurvatureFrames (cell data, one tuple per triangle) ----
/// 2 x double: kappa1 >= kappa2. Positive where the surface bends away from its normal
/// (a sphere with outward normals has +1/R).
constexpr const char* PrincipalCurvatures = "PrincipalCurvatures";
/// 3 x double: unit vector in the triangle's plane, direction of kappa1.
constexpr const char* PrincipalDirection1 = "PrincipalDirection1";
/// 3 x double: unit vector in the triangle's plane, direction of kappa2.
constexpr const char* PrincipalDirection2 = "PrincipalDirection2";
/// 3 x double: first guidance frame vector (along kappa2 for curvature frames).
constexpr const char* FrameU = "FrameU";
/// 3 x double: second guidance frame vector (n x FrameU for curvature frames).
constexpr const char* FrameV = "FrameV";
/// 1 x double: omega = |k1 - k2| / sqrt(k1^2 + k2^2) in [0, sqrt(2)], 0 where both vanish.
constexpr const char* FrameWeight = "FrameWeight";

// ---- field data written by vtkCurvatureFrames ----
/// 1 x double: the neighbourhood radius used, in world units.
constexpr const char* CurvatureRadius = "CurvatureRadius";

// ---- vtkFrameSmoother (rewrites FrameU and FrameV, adds these) ----
/// cell, 1 x double: the angle (radians) each frame was turned about its normal.
constexpr const char* FrameRotation = "FrameRotation";
/// cell, 1 x unsigned char: 1 where the frame is held along a boundary or sharp edge.
constexpr const char* FrameConstrained = "FrameConstrained";
/// field, 1 x double, 2 tuples: the energy at the start of the descent (held frames already on
/// their edges) and at its end.
constexpr const char* SmoothingEnergy = "SmoothingEnergy";
/// field, 1 x int: iterations of the chosen run.
constexpr const char* SmoothingIterations = "SmoothingIterations";

// ---- vtkMatchingBuilder ----
/// cell, 3 x int: for edge k = (point k, point k+1) of the triangle, the matching r in {0..3} to
/// the triangle across it, X_{neighbour,m} = X_{this,(m - r) mod 4} (QuadCover Def. 5), with
/// X_0 = FrameU, X_1 = n x FrameU, X_2 = -FrameU, X_3 = -n x FrameU; -1 on boundary edges.
constexpr const char* Matching = "Matching";
/// point, 1 x int: layer shift (Def. 4) in {0..3}; 0 on the boundary.
constexpr const char* LayerShift = "LayerShift";
/// point, 1 x double: the frame field's index at the point (a multiple of 1/4 inside).
constexpr const char* SingularityIndex = "SingularityIndex";
/// field, 1 x int: inner points with a non-zero index.
constexpr const char* SingularityCount = "SingularityCount";
/// field, 2 x double per tuple (index, number of inner points with it), one tuple per non-zero
/// index, ascending.
constexpr const char* SingularityHistogram = "SingularityHistogram";
/// field, 1 x int, 2 tuples: branch points (non-zero layer shift) before and after the
/// optimization.
constexpr const char* BranchPointCount = "BranchPointCount";
/// field, 1 x double, 2 tuples: sum over inner edges of the matched frames' angle (C_ij), before
/// and after the optimization.
constexpr const char* MatchingCost = "MatchingCost";
/// point data of the branch-point output: the point's id in the surface.
constexpr const char* SurfacePointId = "SurfacePointId";
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverArrayNames.h
