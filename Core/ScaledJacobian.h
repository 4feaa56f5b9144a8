// ScaledJacobian.h: the scaled Jacobian of quad corners, for measureQuads and the fold guard of
// relaxQuads (internal to Core).
#ifndef quadcover_ScaledJacobian_h
#define quadcover_ScaledJacobian_h

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace quadcover
{
/// The unit normal of quad i of Q: its diagonals' cross product, normalized.
inline Eigen::Vector3d quadNormal(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q, int i)
{
  return (Eigen::Vector3d(V.row(Q(i, 2)) - V.row(Q(i, 0))))
    .cross(Eigen::Vector3d(V.row(Q(i, 3)) - V.row(Q(i, 1))))
    .normalized();
}

/// Twice the area vector of quad i of Q: the sum of its corners' cross products about its centre
/// (the normal a quad is judged to face the surface by, QuadFacing).
inline Eigen::Vector3d quadAreaVector(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q, int i)
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k)
  {
    centre += V.row(Q(i, k)).transpose() / 4.0;
  }
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k)
  {
    n += (V.row(Q(i, k)).transpose() - centre).cross(V.row(Q(i, (k + 1) % 4)).transpose() - centre);
  }
  return n;
}

/// The scaled Jacobian of a corner with edges `next` and `prev` against `normal`: the sine of
/// its angle, negative where the corner turns the other way; `degenerate` at a zero-length edge
/// and where the figure is not finite.
inline double cornerScaledJacobian(const Eigen::Vector3d& next, const Eigen::Vector3d& prev,
  const Eigen::Vector3d& normal, double degenerate)
{
  const double ln = next.norm(), lp = prev.norm();
  const double sj = ln > 0 && lp > 0 ? next.cross(prev).dot(normal) / (ln * lp) : degenerate;
  return std::isfinite(sj) ? sj : degenerate;
}

/// The smallest scaled Jacobian over a quad's corners, against the quad's own normal (its
/// diagonals' cross product); 0 at a corner with a zero-length edge.
inline double quadScaledJacobian(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q, int i)
{
  const Eigen::Vector3d n = quadNormal(V, Q, i);
  double smallest = 1.0;
  for (int k = 0; k < 4; ++k)
  {
    const Eigen::Vector3d next = V.row(Q(i, (k + 1) % 4)) - V.row(Q(i, k));
    const Eigen::Vector3d prev = V.row(Q(i, (k + 3) % 4)) - V.row(Q(i, k));
    smallest = std::min(smallest, cornerScaledJacobian(next, prev, n, 0.0));
  }
  return smallest;
}

/// The quads of Q with a corner turned inside out (quadScaledJacobian <= 0), in order.
std::vector<int> invertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q);
}

#endif
