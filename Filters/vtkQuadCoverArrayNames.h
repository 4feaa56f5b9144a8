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
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverArrayNames.h
