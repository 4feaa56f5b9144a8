// FrameFit.cxx: turning the frames so that they agree with given matchings (one sparse solve).
#include "Matchings.h"

#include "MatchingAngles.h"
#include "SparseSolver.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <stdexcept>
#include <vector>

namespace quadcover
{
using detail::residual;
using detail::turning;

Eigen::VectorXd fitFramesToMatchings(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3i& matching, const Eigen::VectorXd& weight, double lambda,
  const std::vector<char>& held)
{
  const int nF = static_cast<int>(F.rows());
  if (frameU.rows() != nF || matching.rows() != nF || topo.numFaces != nF ||
    (weight.size() != 0 && weight.size() != nF) ||
    (!held.empty() && static_cast<Eigen::Index>(held.size()) != F.rows()))
  {
    throw std::invalid_argument("fitFramesToMatchings: sizes do not match");
  }
  if (!(lambda > 0.0 && lambda <= 1.0))
  {
    throw std::invalid_argument("fitFramesToMatchings: lambda must lie in (0, 1]");
  }
  const Eigen::VectorXd phi = vectorAngles(geometry.bases, frameU);
  Eigen::VectorXd area(nF);
  std::vector<Eigen::Vector3d> centre(nF);
  for (int f = 0; f < nF; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 1)) - V.row(F(f, 0));
    const Eigen::Vector3d b = V.row(F(f, 2)) - V.row(F(f, 0));
    area[f] = 0.5 * a.cross(b).norm();
    centre[f] = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))) / 3.0;
  }
  // The unknowns: the free frames (a held one keeps alpha = 0), so that a fit held but near a
  // few changed edges solves a system of that neighbourhood's size.
  std::vector<int> unknown(nF, -1);
  int n = 0;
  for (int f = 0; f < nF; ++f)
  {
    if (held.empty() || !held[f])
    {
      unknown[f] = n++;
    }
  }
  // Diagonal: the alignment term, plus a tiny multiple of the area so that the system stays
  // definite where no frame is weighted (the field is then fixed up to a common turn).
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(n) * 7);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (int f = 0; f < nF; ++f)
  {
    if (unknown[f] >= 0)
    {
      const double w = weight.size() ? weight[f] : 0.0;
      t.emplace_back(unknown[f], unknown[f], (1.0 - lambda) * area[f] * w + 1e-9 * area[f]);
    }
  }
  // Each edge's weight (at corner 3f + k of its face f < g): its length over the distance between
  // its triangles' centres, scaled so that the weights sum to what the areas (A_f + A_g) / 3 of
  // smoothFrames' energy sum to (the balance with the alignment term stays). Weighted by the areas,
  // a triangulation whose diagonals lean one way turns the fitted field: the teapot's body by 25
  // degrees, which sheared its quads (Benchmarks/README.md, 2026-12-05).
  std::vector<double> edgeWeight(3 * static_cast<std::size_t>(nF), 0.0);
  double areaSum = 0.0, weightSum = 0.0;
  forEachNeighbor(topo, [&](int f, int k, int g) {
    if (g > f)
    {
      const double distance = (centre[f] - centre[g]).norm();
      const double w =
        distance > 0 ? (V.row(F(f, (k + 1) % 3)) - V.row(F(f, k))).norm() / distance : 0.0;
      edgeWeight[3 * static_cast<std::size_t>(f) + k] = w;
      areaSum += (area[f] + area[g]) / 3.0;
      weightSum += w;
    }
  });
  const double scale = weightSum > 0 ? areaSum / weightSum : 0.0;
  forEachNeighbor(topo, [&](int f, int k, int g) {
    const int a = unknown[f], b = unknown[g];
    if (g < f || matching(f, k) < 0 || (a < 0 && b < 0))
    {
      return;
    }
    // residual after the rotations: delta + alpha_g - alpha_f
    const double delta = residual(turning(geometry, phi, f, k, g), matching(f, k));
    const double c = 8.0 * lambda * scale * edgeWeight[3 * static_cast<std::size_t>(f) + k];
    if (a >= 0)
    {
      t.emplace_back(a, a, c);
      rhs[a] += c * delta;
    }
    if (b >= 0)
    {
      t.emplace_back(b, b, c);
      rhs[b] -= c * delta;
    }
    if (a >= 0 && b >= 0)
    {
      t.emplace_back(a, b, -c);
      t.emplace_back(b, a, -c);
    }
  });
  Eigen::VectorXd alpha = Eigen::VectorXd::Zero(nF);
  if (n == 0)
  {
    return alpha;
  }
  Eigen::SparseMatrix<double> H(n, n);
  H.setFromTriplets(t.begin(), t.end());
  SpdSolver<double> solver{ Factorization::Automatic };
  solver.compute(H);
  if (solver.info() != Eigen::Success)
  {
    throw std::runtime_error("fitFramesToMatchings: the system could not be factored");
  }
  const Eigen::VectorXd free = solver.solve(rhs);
  for (int f = 0; f < nF; ++f)
  {
    if (unknown[f] >= 0)
    {
      alpha[f] = free[unknown[f]];
    }
  }
  return alpha;
}

}
