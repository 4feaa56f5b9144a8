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
  for (int f = 0; f < nF; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 1)) - V.row(F(f, 0));
    const Eigen::Vector3d b = V.row(F(f, 2)) - V.row(F(f, 0));
    area[f] = 0.5 * a.cross(b).norm();
  }
  // Diagonal: the alignment term, plus a tiny multiple of the area so that the system stays
  // definite where no frame is weighted (the field is then fixed up to a common turn).
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(nF) * 7);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nF);
  for (int f = 0; f < nF; ++f)
  {
    const double w = weight.size() ? weight[f] : 0.0;
    // a held frame: a stiff spring to its angle (alpha = 0)
    const double hold = !held.empty() && held[f] ? 1e6 * 8.0 * lambda * area[f] : 0.0;
    t.emplace_back(f, f, (1.0 - lambda) * area[f] * w + 1e-9 * area[f] + hold);
  }
  forEachNeighbor(topo, [&](int f, int k, int g) {
    if (g < f || matching(f, k) < 0)
    {
      return;
    }
    // residual after the rotations: delta + alpha_g - alpha_f
    const double delta = residual(turning(geometry, phi, f, k, g), matching(f, k));
    const double c = 8.0 * lambda * (area[f] + area[g]) / 3.0;
    t.emplace_back(f, f, c);
    t.emplace_back(g, g, c);
    t.emplace_back(f, g, -c);
    t.emplace_back(g, f, -c);
    rhs[f] += c * delta;
    rhs[g] -= c * delta;
  });
  Eigen::SparseMatrix<double> H(nF, nF);
  H.setFromTriplets(t.begin(), t.end());
  SpdSolver<double> solver;
  solver.compute(H);
  if (solver.info() != Eigen::Success)
  {
    throw std::runtime_error("fitFramesToMatchings: the system could not be factored");
  }
  return solver.solve(rhs);
}

}
