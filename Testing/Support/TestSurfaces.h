// The catalogue of generated test surfaces shared by the core tests.
#ifndef quadcover_TestSurfaces_h
#define quadcover_TestSurfaces_h

#include "Surfaces.h"

#include <Eigen/Geometry>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadcover
{
/// Moderate resolutions: every core test over the catalogue stays well under a second.
inline Surface testSurface(const std::string& name)
{
  if (name == "torus")
    return makeTorus(1.0, 0.4, 96, 48);
  if (name == "sphere")
    return makeIcosphere(1.0, 4);
  if (name == "cylinder")
    return makeCylinder(0.5, 2.0, 48, 40);
  if (name == "saddle")
    return makeSaddle(1.0, 0.5, 40);
  if (name == "knot")
    return makeKnotTube(2, 3, 1.0, 0.4, 0.12, 240, 20, 0.3, 0.03, 7);
  if (name == "roundedcube")
    return makeRoundedCube(0.3, 20);
  throw std::invalid_argument("unknown test surface " + name);
}

/// Puts `count` points on the edge a-b of the sphere's triangle f = (a, b, c) at equal steps, a
/// `lift` of the edge's length off it towards c: the neighbour (b, a, d) is split from d, f's
/// side fanned from a into a row of caps (a, m1, m2), ..., (a, mk, b) beside f itself, as a
/// T-junction's repair leaves it. Returns the caps' count.
inline int fanCapsOnEdge(Surface& s, int f, int count, double lift)
{
  const int a = s.F(f, 0), b = s.F(f, 1), c = s.F(f, 2);
  int other = -1, d = -1;
  for (int g = 0; g < s.F.rows(); ++g)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (s.F(g, k) == b && s.F(g, (k + 1) % 3) == a)
      {
        other = g;
        d = s.F(g, (k + 2) % 3);
      }
    }
  }
  if (other < 0)
  {
    throw std::invalid_argument("fanCapsOnEdge: the edge has no neighbour");
  }
  const Eigen::RowVector3d A = s.V.row(a), B = s.V.row(b);
  const Eigen::RowVector3d up = (s.V.row(c) - 0.5 * (A + B)).normalized() * lift * (B - A).norm();
  std::vector<int> chain{ a };
  for (int j = 1; j <= count; ++j)
  {
    chain.push_back(static_cast<int>(s.V.rows()));
    s.V.conservativeResize(s.V.rows() + 1, 3);
    s.V.bottomRows(1) = A + (B - A) * j / (count + 1.0) + up;
  }
  chain.push_back(b);
  std::vector<Eigen::RowVector3i> added;
  for (std::size_t j = 0; j + 1 < chain.size(); ++j)
  {
    added.emplace_back(chain[j + 1], chain[j], d); // the neighbour split from d
  }
  for (std::size_t j = 1; j + 1 < chain.size(); ++j)
  {
    added.emplace_back(a, chain[j], chain[j + 1]); // the caps
  }
  s.F.row(other) = added.front();
  const Eigen::Index rows = s.F.rows();
  s.F.conservativeResize(rows + static_cast<Eigen::Index>(added.size()) - 1, 3);
  for (std::size_t j = 1; j < added.size(); ++j)
  {
    s.F.row(rows + static_cast<Eigen::Index>(j) - 1) = added[j];
  }
  return count;
}

/// The tube the twist check is tested on: makeCylinder(1, 8, 96, 160) (r = 1, z from -4 to 4).
inline Surface twistTube()
{
  return makeCylinder(1.0, 8.0, 96, 160);
}

/**
 * Frames on twistTube() that follow both boundary circles, with a +1/4 and a -1/4 point on
 * opposite sides at mid-height (angles 0 and pi + offset): theta = (arg(zeta - zeta_a) -
 * arg(zeta - zeta_b)) / 4 in zeta = exp(i (s + i z)), the tube's conformal image, plus a slow
 * turn along the tube that brings both ends back onto the circles. Merging the pair along one
 * side leaves a field that follows the circles at both ends; along the other side, one that
 * turns a quarter between them, and then no grid has both circles on grid lines.
 * @param[in] normal #F x 3 unit triangle normals
 * @return #F x 3 unit tangent frames
 */
inline Eigen::MatrixX3d twistTubeFrames(
  const Surface& tube, const Eigen::MatrixX3d& normal, double offset)
{
  constexpr double Pi = 3.14159265358979323846;
  const double angleA = 0.0, angleB = Pi + offset;
  const std::complex<double> zetaA = std::polar(1.0, angleA), zetaB = std::polar(1.0, angleB);
  Eigen::MatrixX3d U(tube.F.rows(), 3);
  for (int f = 0; f < tube.F.rows(); ++f)
  {
    const Eigen::Vector3d c =
      (tube.V.row(tube.F(f, 0)) + tube.V.row(tube.F(f, 1)) + tube.V.row(tube.F(f, 2))) / 3.0;
    const double angle = std::atan2(c.y(), c.x());
    const std::complex<double> zeta = std::polar(std::exp(-c.z()), angle);
    const double ramp = 0.5 + 0.5 * std::tanh(c.z());
    const double theta =
      0.25 * (std::arg(zeta - zetaA) - std::arg(zeta - zetaB)) + 0.25 * (angleB - angleA) * ramp;
    const Eigen::Vector3d around(-std::sin(angle), std::cos(angle), 0.0);
    const Eigen::Vector3d axis(0.0, 0.0, 1.0);
    const Eigen::Vector3d n = normal.row(f);
    const Eigen::Vector3d u = std::cos(theta) * around + std::sin(theta) * axis;
    U.row(f) = (u - u.dot(n) * n).normalized();
  }
  return U;
}
}

#endif
