// FrameField.h: the discrete tangent geometry frame fields live on: a basis per triangle, the
// Levi-Civita transport across edges, angle defects, and frames as angles.
#ifndef quadcover_FrameField_h
#define quadcover_FrameField_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace quadcover
{

/// Angle wrapped into (-pi, pi].
double wrapAngle(double a);
/// Angle reduced modulo pi/2 into (-pi/4, pi/4] (the rotation between two crosses).
double wrapQuarter(double a);

/**
 * An orthonormal tangent basis per triangle: b1 along the triangle's first edge (from corner 0 to
 * corner 1) projected into its plane, b2 = normal x b1. Angles of tangent vectors are measured
 * from b1 towards b2 (counterclockwise seen from the normal).
 */
struct FaceBases
{
  Eigen::MatrixX3d normal; ///< #F x 3 (computeFaceNormals)
  Eigen::MatrixX3d b1;     ///< #F x 3
  Eigen::MatrixX3d b2;     ///< #F x 3
};

/// @param[in] V #V x 3, @param[in] F #F x 3, @param[in] topo buildTopology(F, #V)
FaceBases computeFaceBases(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo);

/// Angle of each row of U in its triangle's basis (#F).
Eigen::VectorXd vectorAngles(const FaceBases& bases, const Eigen::MatrixX3d& U);

/**
 * Frames as the smoothing takes them: each row of U projected into its triangle's plane and
 * normalized (the triangle's b1 where nothing tangent is left: a zero, normal or non-finite
 * vector); V as given where its row is finite, else normal x U.
 * @param[in] U #F x 3 @param[in] V #F x 3, or empty for normal x U everywhere
 * @return (U, V), #F x 3 each
 * @throws std::invalid_argument on sizes that do not match
 */
std::pair<Eigen::MatrixX3d, Eigen::MatrixX3d> tangentFrames(
  const FaceBases& bases, const Eigen::MatrixX3d& U, const Eigen::MatrixX3d& V);

/// Unit tangent vectors at the given angles (#F x 3).
Eigen::MatrixX3d angleVectors(const FaceBases& bases, const Eigen::VectorXd& angles);

/**
 * Transport across edges: for face f and its edge k with neighbour g = faceNeighbors(f,k),
 * transport(f,k) is the angle to add to an angle measured in g's basis to express the same
 * (unfolded) direction in f's basis; 0 on edges without a neighbour. transport(g,k') =
 * -transport(f,k) up to 2 pi, and around an interior vertex the transports add up to minus its
 * angle defect (modulo 2 pi): parallel transport once around a vertex of positive curvature
 * turns a vector counterclockwise by the defect.
 */
Eigen::MatrixX3d computeTransport(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FaceBases& bases);

/// Corner angles (#F x 3, at corner k).
Eigen::MatrixX3d cornerAngles(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// Angle defect per vertex: 2 pi - (sum of corner angles) inside, pi - (sum) on the boundary
/// (the discrete Gaussian and geodesic curvature); Gauss-Bonnet: the sum is 2 pi chi.
Eigen::VectorXd angleDefects(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo);

/// Rotates each frame (U, V) by alpha(f) about its triangle's normal (both vectors together, so
/// a non-orthogonal frame keeps its shape).
void rotateFrames(
  const FaceBases& bases, const Eigen::VectorXd& alpha, Eigen::MatrixX3d& U, Eigen::MatrixX3d& V);

/// Area of triangle f.
inline double triangleArea(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, Eigen::Index f)
{
  const Eigen::Vector3d a = V.row(F(f, 1)) - V.row(F(f, 0));
  const Eigen::Vector3d b = V.row(F(f, 2)) - V.row(F(f, 0));
  return 0.5 * a.cross(b).norm();
}

/// Total area of the triangles.
double surfaceArea(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// Area of each component (topo.faceComponent), summed in face order as surfaceArea sums it: on a
/// surface of one component the same number.
std::vector<double> componentAreas(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo);

/// The networks of the flagged edges (#E, 1 where flagged): per edge, one edge of the flagged
/// edges joined to it through shared points, the same for all of them (an unflagged edge: itself).
std::vector<int> edgeNetworks(const MeshTopology& topo, const std::vector<char>& flagged);

/// A sharp edge has smooth sides where the surface beside it bends across it by at most this
/// share of the edge's own bend (the normals seen along the edge).
constexpr double SmoothSideFraction = 0.15;

/**
 * Sharp inner edges, the creases: the two triangles' normals more than featureAngle degrees apart,
 * in networks (sharp edges joined through shared points) of at least minimumLength edges of which
 * at least half have smooth sides (SmoothSideFraction). Isolated sharp edges are noise; so is a
 * network whose sides bend as much as it does, as where a smooth surface is sampled coarsely (a
 * decimated scan, an irregularly triangulated thin tube), while a crease of a CAD part, even a
 * faceted one, has flat or gently curved sides (so has a regularly triangulated tube of few
 * sides: a faceted prism, whose creases stay).
 * @return #E, 1 on a sharp edge
 */
std::vector<char> sharpEdges(const MeshTopology& topo, const FaceBases& bases, double featureAngle,
  int minimumLength, double smoothSideFraction = SmoothSideFraction);
}

#endif
