// ScaledJacobian.h: the scaled Jacobian of a quad, for measureQuads and repairInvertedQuads
// (internal to Core).
#ifndef quadcover_ScaledJacobian_h
#define quadcover_ScaledJacobian_h

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace quadcover
{
/// The smallest scaled Jacobian over a quad's corners, against the quad's own normal (its
/// diagonals' cross product); 0 at a corner with a zero-length edge.
inline double quadScaledJacobian(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q, int i)
{
  const Eigen::Vector3d n = (Eigen::Vector3d(V.row(Q(i, 2)) - V.row(Q(i, 0))))
                              .cross(Eigen::Vector3d(V.row(Q(i, 3)) - V.row(Q(i, 1))))
                              .normalized();
  double smallest = 1.0;
  for (int k = 0; k < 4; ++k)
  {
    const Eigen::Vector3d next = V.row(Q(i, (k + 1) % 4)) - V.row(Q(i, k));
    const Eigen::Vector3d prev = V.row(Q(i, (k + 3) % 4)) - V.row(Q(i, k));
    const double ln = next.norm(), lp = prev.norm();
    const double sj = ln > 0 && lp > 0 ? next.cross(prev).dot(n) / (ln * lp) : 0.0;
    smallest = std::min(smallest, std::isfinite(sj) ? sj : 0.0);
  }
  return smallest;
}
}

#endif
