// BoundaryPaths.h: the boundary loops of a triangle surface as paths that a point on them may
// slide along, between the corners where the boundary turns.
#ifndef quadcover_BoundaryPaths_h
#define quadcover_BoundaryPaths_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/**
 * The boundary loops of a surface as paths: each boundary point's loop and place in it, the
 * triangle of each boundary edge, and the corners, the points where the boundary turns by more
 * than `cornerTurn` radians within the surface (|pi - the sum of the point's corner angles|, the
 * geodesic turn). A slide stops at a corner: the quads' boundary has its corners there, and the
 * sides between them each follow one grid line.
 */
class BoundaryPaths
{
public:
  /// Where a point lies on the boundary: on edge `edge` of loop `loop` (from loop[edge] to
  /// loop[edge + 1]); loop -1 when it is not on the boundary or is on a corner.
  struct Place
  {
    int loop = -1;
    int edge = -1;
  };

  /// A point of the boundary, with the triangle it lies in and the surface point it is (or -1).
  struct Stop
  {
    Eigen::Vector3d point;
    int triangle = -1;
    int surfacePoint = -1;
  };

  BoundaryPaths(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
    double cornerTurn);

  /// The place of a point p on the boundary: on surface point `point` if that is >= 0, else on a
  /// boundary edge of `triangle` (within 1e-7 of the edge's length).
  Place placeOf(const Eigen::Vector3d& p, int triangle, int point) const;

  /// The points at arc lengths `distances` from p (at `place`) along the boundary, each way, and
  /// the surface points passed on the way; neither way goes past a corner or around the whole
  /// loop.
  std::vector<Stop> slides(
    const Place& place, const Eigen::Vector3d& p, const std::vector<double>& distances) const;

private:
  void walk(const Place& place, const Eigen::Vector3d& p, const std::vector<double>& distances,
    bool forward, std::vector<Stop>& stops) const;

  const Eigen::MatrixX3d& V_;
  const Eigen::MatrixX3i& F_;
  const MeshTopology& topo_;
  std::vector<int> loopOf_;                ///< per surface point: its loop, or -1
  std::vector<int> placeInLoop_;           ///< per surface point: its index in the loop
  std::vector<std::vector<int>> edgeFace_; ///< per loop and edge: its triangle
  std::vector<char> corner_;               ///< per surface point
};

}

#endif
