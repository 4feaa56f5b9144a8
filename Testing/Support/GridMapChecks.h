// Checks of an integer-grid map that read only the mesh and the map's corner values (u, v),
// shared by the core and filter tests: seamlessness, flips, branch points on the grid.
#ifndef quadcover_GridMapChecks_h
#define quadcover_GridMapChecks_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <cmath>
#include <complex>

namespace quadcover
{
namespace checks
{
using Complex = std::complex<double>;

/// (u, v) of corner k of triangle f as u + i v; cornerUV is #F x 6.
inline Complex cornerZ(const Eigen::MatrixXd& cornerUV, int f, int k)
{
  return { cornerUV(f, 2 * k), cornerUV(f, 2 * k + 1) };
}

inline bool isInteger(double x, double tolerance = 1e-6)
{
  return std::abs(x - std::round(x)) <= tolerance;
}

/// Inner edges across which no quarter turn r and integer t give z_g = i^r z_f + t at both
/// shared points (translationTolerance: how far t may be from Z^2).
inline int seamViolations(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const Eigen::MatrixXd& cornerUV, double translationTolerance = 1e-6)
{
  int bad = 0;
  for (int f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g < 0)
      {
        continue;
      }
      const Complex fa = cornerZ(cornerUV, f, k);
      const Complex fb = cornerZ(cornerUV, f, (k + 1) % 3);
      const Complex za = cornerZ(cornerUV, g, MeshTopology::cornerOf(F, g, F(f, k)));
      const Complex zb = cornerZ(cornerUV, g, MeshTopology::cornerOf(F, g, F(f, (k + 1) % 3)));
      bool ok = false;
      Complex turn(1, 0);
      for (int q = 0; q < 4 && !ok; ++q, turn *= Complex(0, 1))
      {
        const Complex ta = za - turn * fa;
        const Complex tb = zb - turn * fb;
        ok = std::abs(ta - tb) < 1e-6 && isInteger(ta.real(), translationTolerance) &&
          isInteger(ta.imag(), translationTolerance);
      }
      bad += !ok;
    }
  }
  return bad;
}

/// Triangles whose (u, v) image has a non-positive area.
inline int flippedTriangles(const Eigen::MatrixXd& cornerUV)
{
  int flipped = 0;
  for (int f = 0; f < cornerUV.rows(); ++f)
  {
    const Complex a = cornerZ(cornerUV, f, 0);
    const Complex b = cornerZ(cornerUV, f, 1);
    const Complex c = cornerZ(cornerUV, f, 2);
    flipped += !(std::imag(std::conj(b - a) * (c - a)) > 0);
  }
  return flipped;
}

/// Corners at inner points with a non-zero layer shift whose (u, v) is not integer.
inline int branchPointsOffGrid(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const Eigen::VectorXi& layerShift, const Eigen::MatrixXd& cornerUV, double tolerance = 1e-6)
{
  int off = 0;
  for (int f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int p = F(f, k);
      if (!topo.boundaryVertex[p] && layerShift[p] != 0)
      {
        const Complex z = cornerZ(cornerUV, f, k);
        off += !(isInteger(z.real(), tolerance) && isInteger(z.imag(), tolerance));
      }
    }
  }
  return off;
}

/// Inner points whose (u, v) corner angles do not add up to 2 pi (1 - index): the map must wind
/// around every point as its frame field does (a cone of index k/4 keeps its 2 pi (1 - k/4)).
inline int windingErrors(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const Eigen::VectorXd& index, const Eigen::MatrixXd& cornerUV, double tolerance = 1e-6)
{
  constexpr double Pi = 3.14159265358979323846;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(index.size());
  for (int f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Complex z = cornerZ(cornerUV, f, k);
      const Complex a = cornerZ(cornerUV, f, (k + 1) % 3) - z;
      const Complex b = cornerZ(cornerUV, f, (k + 2) % 3) - z;
      // signed angle from a to b; 0 (not NaN) for a collapsed corner, which then shows
      sum[F(f, k)] += std::atan2(std::imag(std::conj(a) * b), std::real(std::conj(a) * b));
    }
  }
  int wrong = 0;
  for (int p = 0; p < index.size(); ++p)
  {
    wrong += !topo.boundaryVertex[p] && std::abs(sum[p] - 2 * Pi * (1 - index[p])) > tolerance;
  }
  return wrong;
}
}
}

#endif
