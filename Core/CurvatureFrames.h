// CurvatureFrames.h: per-triangle curvature tensors and the guidance frame field (stage 1).
#ifndef quadcover_CurvatureFrames_h
#define quadcover_CurvatureFrames_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

struct CurvatureOptions
{
  /// Radius of the averaging neighbourhood in multiples of the median edge length (the median,
  /// not the mean, so that a few huge or tiny triangles do not change the scale). 0 uses each
  /// triangle's own three edges only.
  double neighborhoodRadius = 2.0;
  /// At most this many triangles are summed per neighbourhood (a guard against pathological
  /// geometry, e.g. thousands of triangles crowded into one point); 0 means no limit.
  int maximumNeighborhood = 8192;
  /// Worker threads (0: defaultThreadCount()). Results do not depend on it.
  int numberOfThreads = 0;
};

/// Per-triangle curvature and frames. Curvatures are positive where the surface bends away from
/// its normal (a sphere with outward normals has +1/R).
struct CurvatureField
{
  Eigen::MatrixX3d normals;    ///< #F x 3 unit triangle normals (zero where none can be had)
  Eigen::MatrixX2d curvatures; ///< #F x 2 (kappa1, kappa2), kappa1 >= kappa2
  Eigen::MatrixX3d direction1; ///< #F x 3 unit, in the triangle's plane, for kappa1
  Eigen::MatrixX3d direction2; ///< #F x 3 unit, normal x direction1, for kappa2
  Eigen::MatrixX3d frameU;     ///< #F x 3 guidance vector (direction2)
  Eigen::MatrixX3d frameV;     ///< #F x 3 normal x frameU
  Eigen::VectorXd weight;      ///< #F omega = |k1-k2| / sqrt(k1^2+k2^2), 0 where both vanish
  double medianEdgeLength = 0.0;
  double curvatureRadius = 0.0;   ///< the neighbourhood radius used, world units
  int degenerateFaces = 0;        ///< zero-area triangles (they take the neighbourhood's normal)
  int zeroFrames = 0;             ///< triangles left with zero frames: no normal could be found
  int truncatedNeighborhoods = 0; ///< neighbourhoods cut at maximumNeighborhood triangles
};

/// Unit normals of the triangles. A triangle is degenerate when twice its area is at most 1e-12
/// times its longest edge squared (collinear or coincident corners); it gets the normalized sum
/// of its non-degenerate neighbours' area-weighted normals, or zero if there are none.
/// @param[in] V #V x 3, @param[in] F #F x 3, @param[in] topo buildTopology(F, #V)
/// @param[out] degenerate if given, #F flags (1 for a degenerate triangle)
Eigen::MatrixX3d computeFaceNormals(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, std::vector<char>* degenerate = nullptr);

/// Median length of the mesh's edges (0 for no edges).
double medianEdgeLength(const Eigen::MatrixX3d& V, const MeshTopology& topo);

/**
 * Principal curvatures and directions per triangle from the normal-cycle curvature measure
 * (Cohen-Steiner and Morvan 2003): every interior edge e contributes beta(e) |e| e e^T, beta its
 * signed dihedral angle; a triangle's tensor is the sum over the triangles reachable from it
 * across edges whose centroids lie closer than the radius to its own, divided by their area
 * (each edge counted half from each side). The tensor is projected into the triangle's plane; its
 * eigenvector of the larger eigenvalue is the direction of the smaller curvature.
 * Edges with more than two triangles, and edges of degenerate triangles, contribute nothing.
 * @param[in] V    #V x 3 finite positions
 * @param[in] F    #F x 3 triangles, consistently oriented
 * @param[in] topo buildTopology(F, #V)
 * @throws std::invalid_argument on non-finite positions or sizes that do not match
 */
CurvatureField computeCurvatureField(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const CurvatureOptions& options = CurvatureOptions());

/**
 * Replaces the frames of a curvature field by a user frame field: each vector is projected into
 * its triangle's plane and normalized, and frameV = normal x frameU. Where the projection
 * vanishes (the vector was normal to the triangle, zero, or not finite), the curvature frame is
 * kept. Curvatures, directions and weights are unchanged.
 * @param[in] frameU #F x 3 user vectors
 * @return the number of triangles where the curvature frame was kept
 */
int applyInputFrames(CurvatureField& field, const Eigen::MatrixX3d& frameU);

}

#endif
