// SurfaceDisks.h: whether the part of a surface around a point is a topological disk.
#ifndef quadcover_SurfaceDisks_h
#define quadcover_SurfaceDisks_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/**
 * Whether the triangles around the points within a radius of a point (along edge paths) form a
 * topological disk: one piece, across edges, of Euler characteristic 1. A change of the frame
 * field's matchings along a path inside such a disk turns the field only along loops around the
 * path's ends, as on a surface without handles; a path that a handle's loop must cross also
 * turns the field along that loop. A ball of more than half its component's triangles counts as
 * no disk (the search stops there, so one test costs at most that half). Reusable for many
 * points: the work arrays are sized once.
 */
class DiskTest
{
public:
  /// edgeLength: #F x 3, the length of edge k of face f (from corner k to k + 1).
  DiskTest(const Eigen::MatrixX3i& F, const MeshTopology& topo, const Eigen::MatrixX3d& edgeLength);

  /// Whether the triangles within `radius` of point a form a disk.
  bool ballIsDisk(int a, double radius) { return ball(a, radius, false) == Ball::Disk; }

  /// What the triangles within `radius` of point a are: a disk; no disk (a handle or a neck, or
  /// with the boundary a hole, within reach); or beyond the test (more than half the component,
  /// a point of no triangle, or with boundaryBeyond any point of the boundary reached).
  enum class Ball
  {
    Disk,
    NotDisk,
    Beyond
  };
  Ball ball(int a, double radius, bool boundaryBeyond);

private:
  bool reached(int v) const;
  bool grow(int a, double radius, int limit);
  bool connected(const std::vector<int>& inside);
  long long eulerCharacteristic(const std::vector<int>& inside);

  const Eigen::MatrixX3i& F_;
  const MeshTopology& topo_;
  const Eigen::MatrixX3d& edgeLength_;
  std::vector<double> dist_;
  std::vector<char> faceSeen_, edgeSeen_;
  std::vector<int> points_, faces_;
};

}

#endif
