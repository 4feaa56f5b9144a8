// Untangler.cxx: foldover-free untangling of flipped triangles by Newton steps.
#include "Untangler.h"

#include "Parallel.h"
#include "UnionFind.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <limits>
#include <numeric>
#include <thread>
#include <utility>

namespace quadcover
{
namespace param
{
namespace
{
/// The scalars of a triangle's energy at J: det J, chi(det J) and its derivatives, and those of
/// the second term g(det) = (det^2 + 1) / chi; the second derivatives only when asked.
struct EnergyTerms
{
  double det, root, chi, chiPrime, trace, gPrime;
  double curl = 0.0, gSecond = 0.0; // 2 chi'^2 / chi^3 - chi'' / chi^2, and g''

  EnergyTerms(const Eigen::Matrix2d& J, double eps, bool second)
    : det(J.determinant())
    , root(std::sqrt(eps * eps + det * det))
    , chi(0.5 * (det + root))
    , chiPrime(0.5 * (1.0 + det / root))
    , trace(J.squaredNorm())
    , gPrime(2.0 * det / chi - (det * det + 1) * chiPrime / (chi * chi))
  {
    if (second)
    {
      const double chiSecond = eps * eps / (2.0 * root * root * root);
      curl = 2.0 * chiPrime * chiPrime / (chi * chi * chi) - chiSecond / (chi * chi);
      gSecond = 2.0 / chi - 4.0 * det * chiPrime / (chi * chi) + (det * det + 1) * curl;
    }
  }
};
}

double triangleEnergy(const Eigen::Matrix2d& J, double eps, double theta, Eigen::Matrix2d* gradient,
  Eigen::Matrix4d* hessian)
{
  const EnergyTerms terms(J, eps, hessian != nullptr);
  const double det = terms.det, chi = terms.chi, chiPrime = terms.chiPrime, trace = terms.trace;
  const double energy = (1 - theta) * trace / chi + theta * (det * det + 1) / chi;
  if (!gradient && !hessian)
  {
    return energy;
  }
  // in the entries a = (J00, J01, J10, J11): det's gradient c and Hessian K
  const Eigen::Vector4d a(J(0, 0), J(0, 1), J(1, 0), J(1, 1));
  const Eigen::Vector4d c(J(1, 1), -J(1, 0), -J(0, 1), J(0, 0));
  const double gPrime = terms.gPrime;
  const Eigen::Vector4d da =
    (1 - theta) * (2.0 * a / chi - trace * chiPrime / (chi * chi) * c) + theta * gPrime * c;
  if (gradient)
  {
    *gradient << da[0], da[1], da[2], da[3];
  }
  if (hessian)
  {
    const double curl = terms.curl, gSecond = terms.gSecond;
    Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
    K(0, 3) = K(3, 0) = 1.0;
    K(1, 2) = K(2, 1) = -1.0;
    const Eigen::Matrix4d first = 2.0 / chi * Eigen::Matrix4d::Identity() -
      2.0 * chiPrime / (chi * chi) * (a * c.transpose() + c * a.transpose()) +
      trace * curl * c * c.transpose() - trace * chiPrime / (chi * chi) * K;
    *hessian = (1 - theta) * first + theta * (gSecond * c * c.transpose() + gPrime * K);
  }
  return energy;
}

Eigen::Matrix4d absoluteHessian(const Eigen::Matrix2d& J, double eps, double theta)
{
  // The energy is psi(t, d) of t = |J|^2 and d = det J, so its Hessian is
  //   2 psi_t I + psi_d K + 4 psi_tt a a' + 2 psi_td (a c' + c a') + psi_dd c c'
  // (a = J's entries, c = det's gradient, K = det's Hessian; psi_tt = 0). K is +1 on the
  // conformal matrices [[p, -q], [q, p]] and -1 on the anticonformal ones [[r, s], [s, -r]];
  // a and c lie in the plane of J's conformal part and J's anticonformal part. The directions
  // in each K-plane across J's part are eigenvectors (2 psi_t + psi_d, 2 psi_t - psi_d); the
  // plane of the parts holds a 2 x 2 block.
  const EnergyTerms terms(J, eps, true);
  const double chi = terms.chi, chiPrime = terms.chiPrime, trace = terms.trace;
  const double psiT = (1 - theta) / chi;
  const double psiTD = -(1 - theta) * chiPrime / (chi * chi);
  const double psiD = -(1 - theta) * trace * chiPrime / (chi * chi) + theta * terms.gPrime;
  const double psiDD = (1 - theta) * trace * terms.curl + theta * terms.gSecond;
  // unit vectors along J's conformal part (c1) and across it (c2), along its anticonformal part
  // (a1) and across it (a2); any pair in a plane where J's part is 0
  const double p = 0.5 * (J(0, 0) + J(1, 1)), q = 0.5 * (J(1, 0) - J(0, 1));
  const double r = 0.5 * (J(0, 0) - J(1, 1)), s = 0.5 * (J(0, 1) + J(1, 0));
  const double conformal = std::hypot(p, q), anticonformal = std::hypot(r, s);
  const double cp = conformal > 0 ? p / conformal : 1.0, cq = conformal > 0 ? q / conformal : 0.0;
  const double ar = anticonformal > 0 ? r / anticonformal : 1.0;
  const double as = anticonformal > 0 ? s / anticonformal : 0.0;
  const double h = std::sqrt(0.5);
  const Eigen::Vector4d c1 = h * Eigen::Vector4d(cp, -cq, cq, cp);
  const Eigen::Vector4d c2 = h * Eigen::Vector4d(-cq, -cp, cp, -cq);
  const Eigen::Vector4d a1 = h * Eigen::Vector4d(ar, as, as, -ar);
  const Eigen::Vector4d a2 = h * Eigen::Vector4d(-as, ar, ar, as);
  // a = |a_c| c1 + |a_a| a1 and c = |a_c| c1 - |a_a| a1, where |a_c| = sqrt 2 conformal
  const Eigen::Vector2d alpha(conformal / h, anticonformal / h);
  const Eigen::Vector2d beta(conformal / h, -anticonformal / h);
  Eigen::Matrix2d block = 2.0 * psiTD * (alpha * beta.transpose() + beta * alpha.transpose()) +
    psiDD * beta * beta.transpose();
  block(0, 0) += 2.0 * psiT + psiD;
  block(1, 1) += 2.0 * psiT - psiD;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen;
  eigen.computeDirect(block);
  Eigen::Matrix4d P = std::abs(2.0 * psiT + psiD) * c2 * c2.transpose() +
    std::abs(2.0 * psiT - psiD) * a2 * a2.transpose();
  for (int i = 0; i < 2; ++i)
  {
    const Eigen::Vector2d v = eigen.eigenvectors().col(i);
    const Eigen::Vector4d e = v[0] * c1 + v[1] * a1;
    P += std::abs(eigen.eigenvalues()[i]) * e * e.transpose();
  }
  return P;
}

namespace
{
using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// The faces within `rings` vertex rings of a flipped face: 1 per face of the region.
std::vector<char> regionAround(
  const MeshTopology& topo, const Eigen::MatrixX3i& F, const std::vector<int>& flipped, int rings)
{
  std::vector<char> inRegion(F.rows(), 0);
  std::vector<int> front = flipped;
  for (const int f : flipped)
  {
    inRegion[f] = 1;
  }
  for (int ring = 0; ring < rings && !front.empty(); ++ring)
  {
    std::vector<int> next;
    for (const int f : front)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int p = F(f, k);
        for (int i = topo.ringOffsets[p]; i < topo.ringOffsets[p + 1]; ++i)
        {
          const int g = topo.ringFaces[i];
          if (!inRegion[g])
          {
            inRegion[g] = 1;
            next.push_back(g);
          }
        }
      }
    }
    front.swap(next);
  }
  return inRegion;
}

/**
 * The untangling energy as a function of the free unknowns y alone: the others stay as in the
 * map it started from. The rows of the energy's faces are copied once into a compact form over
 * slots (the free unknowns first, then every fixed symbol the rows use, with its value), so that
 * an evaluation reads contiguous memory instead of D's rows scattered over the whole surface;
 * the arithmetic is D's, term by term in the same order.
 */
class LocalEnergy
{
public:
  LocalEnergy(const Untangler& untangler, std::vector<int> columns, const std::vector<int>& faces,
    const Eigen::VectorXd& x, int& evaluations)
    : untangler_(untangler)
    , columns_(std::move(columns))
    , evaluations_(evaluations)
  {
    const int m = size();
    std::vector<int> slotOf(x.size(), -1);
    std::vector<double> z;
    z.reserve(2 * columns_.size());
    for (int i = 0; i < m; ++i)
    {
      slotOf[columns_[i]] = i;
      z.push_back(x[columns_[i]]);
    }
    rowBegin_.reserve(4 * faces.size() + 1);
    rowBegin_.push_back(0);
    area_.reserve(faces.size());
    toUnitCell_.reserve(faces.size());
    for (const int f : faces)
    {
      const double scale = untangler.sqrtArea[f];
      area_.push_back(scale * scale);
      const double cell = untangler.cellScale.size() > 0 ? untangler.cellScale[f] : 1.0;
      toUnitCell_.push_back(untangler.edgeLength * cell / scale);
      for (int i = 0; i < 4; ++i)
      {
        for (RowMajorMatrix::InnerIterator it(untangler.Dr, 4 * f + i); it; ++it)
        {
          int& slot = slotOf[it.col()];
          if (slot < 0)
          {
            slot = static_cast<int>(z.size());
            z.push_back(x[it.col()]);
          }
          coefficient_.push_back(it.value());
          slot_.push_back(slot);
        }
        rowBegin_.push_back(static_cast<int>(slot_.size()));
      }
    }
    z_ = Eigen::Map<const Eigen::VectorXd>(z.data(), static_cast<Eigen::Index>(z.size()));
    gradient_ = Eigen::VectorXd::Zero(z_.size());
    this->buildHessianPattern();
  }

  int size() const { return static_cast<int>(columns_.size()); }
  /// How often evaluate was called (a counter the caller keeps): the measure of the work done.
  int evaluations() const { return evaluations_; }
  bool spent() const { return untangler_.spent(); }

  /// The free unknowns of a full map.
  Eigen::VectorXd restrictTo(const Eigen::VectorXd& full) const
  {
    Eigen::VectorXd y(size());
    for (int i = 0; i < size(); ++i)
    {
      y[i] = full[columns_[i]];
    }
    return y;
  }

  /// Writes y into the map.
  void scatter(const Eigen::VectorXd& y, Eigen::VectorXd& full) const
  {
    for (int i = 0; i < size(); ++i)
    {
      full[columns_[i]] = y[i];
    }
  }

  /// The energy at y, and its gradient g.
  double evaluate(const Eigen::VectorXd& y, double eps, Eigen::VectorXd& g)
  {
    ++evaluations_;
    if (untangler_.work)
    {
      *untangler_.work -= static_cast<long long>(area_.size());
    }
    z_.head(size()) = y;
    gradient_.setZero();
    const double theta = untangler_.theta;
    double total = 0.0;
    for (int j = 0; j < static_cast<int>(area_.size()); ++j)
    {
      Eigen::Matrix2d dE;
      const double area = area_[j];
      total += area * triangleEnergy(jacobian(j), eps, theta, &dE, nullptr);
      for (int i = 0; i < 4; ++i)
      {
        const double gi = area * dE(i / 2, i % 2) * toUnitCell_[j];
        for (int t = rowBegin_[4 * j + i]; t < rowBegin_[4 * j + i + 1]; ++t)
        {
          gradient_[slot_[t]] += gi * coefficient_[t];
        }
      }
    }
    g = gradient_.head(size());
    return total;
  }

  /// The Newton direction at y (g: the gradient there): the energy's Hessian, each face's
  /// part with its eigenvalues made positive (absoluteHessian), solved for -g. Empty when the
  /// Hessian cannot be factored.
  Eigen::VectorXd newtonDirection(const Eigen::VectorXd& y, double eps, const Eigen::VectorXd& g)
  {
    if (untangler_.work)
    {
      *untangler_.work -= HessianCost * static_cast<long long>(area_.size());
    }
    z_.head(size()) = y;
    double* value = hessian_.valuePtr();
    std::fill(value, value + hessian_.nonZeros(), 0.0);
    for (int j = 0; j < static_cast<int>(area_.size()); ++j)
    {
      const Eigen::Matrix<double, 4, Eigen::Dynamic>& R = jacobianOfFree_[j];
      const int k = static_cast<int>(R.cols());
      if (k == 0)
      {
        continue;
      }
      const double scale = toUnitCell_[j];
      const Eigen::Matrix4d HJ =
        absoluteHessian(jacobian(j), eps, untangler_.theta) * (area_[j] * scale * scale);
      const Eigen::MatrixXd local = R.transpose() * HJ * R;
      int entry = entryBegin_[j];
      for (int b = 0; b < k; ++b)
      {
        for (int a = b; a < k; ++a)
        {
          value[entries_[entry++]] += local(a, b);
        }
      }
    }
    double mean = 0.0;
    for (int i = 0; i < size(); ++i)
    {
      mean += value[diagonal_[i]];
    }
    mean = std::max(mean / std::max(1, size()), 1e-300);
    if (!analyzed_)
    {
      solver_.analyzePattern(hessian_);
      analyzed_ = true;
    }
    // the faces' parts are semidefinite; a small shift makes their sum definite
    double shifted = 0.0;
    for (double shift = 1e-9; shift < 1.0; shift *= 1e3)
    {
      for (int i = 0; i < size(); ++i)
      {
        value[diagonal_[i]] += (shift - shifted) * mean;
      }
      shifted = shift;
      solver_.factorize(hessian_);
      if (solver_.info() == Eigen::Success)
      {
        Eigen::VectorXd d = solver_.solve(-g);
        if (d.allFinite())
        {
          return d;
        }
      }
    }
    return Eigen::VectorXd();
  }

  /// The smallest Jacobian determinant of the energy's faces at y, and how many are not
  /// positive.
  std::pair<double, int> folds(const Eigen::VectorXd& y)
  {
    z_.head(size()) = y;
    double lowest = std::numeric_limits<double>::max();
    int count = 0;
    for (int j = 0; j < static_cast<int>(area_.size()); ++j)
    {
      const double det = jacobian(j).determinant();
      lowest = std::min(lowest, det);
      count += det <= 0;
    }
    return { lowest, count };
  }

private:
  /// The Jacobian of the energy's face j at the slots' values, relative to the unit cell.
  Eigen::Matrix2d jacobian(int j) const
  {
    Eigen::Matrix2d J;
    for (int i = 0; i < 4; ++i)
    {
      double value = 0.0;
      for (int t = rowBegin_[4 * j + i]; t < rowBegin_[4 * j + i + 1]; ++t)
      {
        value += coefficient_[t] * z_[slot_[t]];
      }
      J(i / 2, i % 2) = value * toUnitCell_[j];
    }
    return J;
  }

  /// The Hessian's pattern over the free slots (lower triangle) and where each face's entries
  /// go (entryBegin_, entries_, diagonal_), and each face's jacobianOfFree_.
  void buildHessianPattern()
  {
    const int m = size();
    const int nf = static_cast<int>(area_.size());
    std::vector<int> freeSlots;                   // per face: the free slots its rows use
    std::vector<int> freeBegin(1, 0);             // per face: where its free slots begin
    std::vector<int> termLocal(slot_.size(), -1); // per term: its slot's index among its face's
    jacobianOfFree_.resize(nf);
    std::vector<Eigen::Triplet<double>> pattern;
    for (int i = 0; i < m; ++i)
    {
      pattern.emplace_back(i, i, 0.0);
    }
    for (int j = 0; j < nf; ++j)
    {
      const int begin = static_cast<int>(freeSlots.size());
      for (int t = rowBegin_[4 * j]; t < rowBegin_[4 * j + 4]; ++t)
      {
        if (slot_[t] >= m)
        {
          continue;
        }
        const auto end = freeSlots.end();
        const auto found = std::find(freeSlots.begin() + begin, end, slot_[t]);
        termLocal[t] = static_cast<int>(found - freeSlots.begin()) - begin;
        if (found == end)
        {
          freeSlots.push_back(slot_[t]);
        }
      }
      freeBegin.push_back(static_cast<int>(freeSlots.size()));
      for (int b = begin; b < freeBegin.back(); ++b)
      {
        for (int a = b; a < freeBegin.back(); ++a)
        {
          const int r = std::max(freeSlots[a], freeSlots[b]);
          const int c = std::min(freeSlots[a], freeSlots[b]);
          pattern.emplace_back(r, c, 0.0);
        }
      }
      Eigen::Matrix<double, 4, Eigen::Dynamic>& R = jacobianOfFree_[j];
      R.setZero(4, freeBegin.back() - begin);
      for (int i = 0; i < 4; ++i)
      {
        for (int t = rowBegin_[4 * j + i]; t < rowBegin_[4 * j + i + 1]; ++t)
        {
          if (termLocal[t] >= 0)
          {
            R(i, termLocal[t]) += coefficient_[t];
          }
        }
      }
    }
    hessian_.resize(m, m);
    hessian_.setFromTriplets(pattern.begin(), pattern.end());
    hessian_.makeCompressed();
    auto offset = [&](int r, int c) {
      const int* inner = hessian_.innerIndexPtr();
      const int* first = inner + hessian_.outerIndexPtr()[c];
      const int* last = inner + hessian_.outerIndexPtr()[c + 1];
      return static_cast<int>(std::lower_bound(first, last, r) - inner);
    };
    diagonal_.resize(m);
    for (int i = 0; i < m; ++i)
    {
      diagonal_[i] = offset(i, i);
    }
    entryBegin_.assign(1, 0);
    for (int j = 0; j < nf; ++j)
    {
      for (int b = freeBegin[j]; b < freeBegin[j + 1]; ++b)
      {
        for (int a = b; a < freeBegin[j + 1]; ++a)
        {
          entries_.push_back(
            offset(std::max(freeSlots[a], freeSlots[b]), std::min(freeSlots[a], freeSlots[b])));
        }
      }
      entryBegin_.push_back(static_cast<int>(entries_.size()));
    }
  }

  /// What a Hessian costs, in energy evaluations of as many faces (debited to the budget).
  static constexpr long long HessianCost = 12;
  const Untangler& untangler_;
  const std::vector<int> columns_;
  std::vector<double> area_;        // per face of the energy: its area
  std::vector<double> toUnitCell_;  // per face: edgeLength cellScale / sqrt(area), J to the cell
  std::vector<int> rowBegin_;       // per row (4 per face): where its terms begin
  std::vector<double> coefficient_; // per term: D's coefficient
  std::vector<int> slot_;           // per term: the slot of its symbol
  Eigen::VectorXd z_;               // per slot: the free unknowns, then the fixed symbols
  Eigen::VectorXd gradient_;        // per slot
  std::vector<int> entryBegin_;     // per face: where its Hessian entries begin in entries_
  /// per face: d(J's 4 entries) / d(its free slots), the same for every Newton step
  std::vector<Eigen::Matrix<double, 4, Eigen::Dynamic>> jacobianOfFree_;
  std::vector<int> entries_;        // per pair of a face's free slots: its place in hessian_
  std::vector<int> diagonal_;       // per free slot: its diagonal entry's place in hessian_
  Eigen::SparseMatrix<double> hessian_; // lower triangle
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> solver_;
  bool analyzed_ = false;
  int& evaluations_;
};

/// Minimizes the energy (with eps fixed) from y by Newton's method on the faces' absolute
/// Hessians with Armijo backtracking, until a step gains less than 1e-5 of the energy, at most
/// 20 steps. Returns the energy at the new y. Where folds are, the faces' Hessians are
/// indefinite and the steps gain linearly, not quadratically; run to 1e-9 and 50 steps, the
/// repairs of eight shared surfaces ended the same in up to twice the time. With the
/// negative eigenvalues dropped instead of turned positive, the steps crawled along a saddle (a
/// refined spot's fans held around its cones: 1e-6 of the energy a step for 40 steps before
/// the region unfolded) and stopped there.
double minimize(LocalEnergy& energy, Eigen::VectorXd& y, double eps, const Progress& progress)
{
  constexpr int Iterations = 20;
  constexpr double Tolerance = 1e-5;
  Eigen::VectorXd g;
  double e = energy.evaluate(y, eps, g);
  for (int it = 0; it < Iterations && !energy.spent(); ++it)
  {
    progress.report(energy.evaluations() / (energy.evaluations() + 100.0));
    Eigen::VectorXd d = energy.newtonDirection(y, eps, g);
    double slope = d.size() ? g.dot(d) : 0.0;
    if (!(slope < 0))
    {
      d = -g;
      slope = -g.squaredNorm();
    }
    double step = 1.0;
    Eigen::VectorXd gNew, yNew;
    double eNew = e;
    bool moved = false;
    for (int tries = 0; tries < 40; ++tries, step *= 0.5)
    {
      yNew = y + step * d;
      eNew = energy.evaluate(yNew, eps, gNew);
      if (std::isfinite(eNew) && eNew <= e + 1e-4 * step * slope)
      {
        moved = true;
        break;
      }
    }
    if (!moved)
    {
      break;
    }
    const double change = e - eNew;
    y = yNew;
    g = gNew;
    e = eNew;
    if (change <= Tolerance * std::abs(e))
    {
      break;
    }
  }
  return e;
}

/// Rounds of minimize with eps shrinking with the most negative determinant, until the energy's
/// faces are unfolded and the energy settles, maxRounds are done or the rounds stall.
void untangle(LocalEnergy& energy, Eigen::VectorXd& y, int maxRounds, const Progress& progress)
{
  double previous = std::numeric_limits<double>::max();
  // A run that stalls stops: when for Patience rounds in a row no triangle came right and the
  // most negative determinant did not rise by 1%, more rounds of the same region rarely help
  // (they repeated the same minimum up to maxRounds); the caller's next, larger region may.
  constexpr int Patience = 3;
  std::pair<double, int> best = energy.folds(y);
  int stalled = 0;
  for (int round = 0; round < maxRounds && energy.size() > 0 && !energy.spent(); ++round)
  {
    // a triangle flattened to a determinant of 0 is a fold, whose eps is not the final one
    // (at 1e-8 its energy is 1e8 times a good triangle's and the steps out of it tiny)
    const double lowest = energy.folds(y).first;
    const double eps = lowest <= 0 ? std::sqrt(1e-8 + 0.04 * lowest * lowest) : 1e-8;
    const double e = minimize(energy, y, eps, progress);
    const std::pair<double, int> after = energy.folds(y);
    // settled: unfolded, and a round at the final eps gained little over the one before. Only
    // energies of the same eps compare: a smaller eps raises the energy of the same map, which
    // once stopped a run that had just unfolded its last triangle to a determinant of 0.002.
    const bool finalEps = !(lowest <= 0);
    if (after.first > 0 && finalEps && previous - e <= 1e-3 * std::abs(e))
    {
      break;
    }
    previous = finalEps ? e : std::numeric_limits<double>::max();
    const bool better =
      after.second < best.second || after.first > best.first + 0.01 * std::abs(best.first);
    best = { std::max(best.first, after.first), std::min(best.second, after.second) };
    stalled = better ? 0 : stalled + 1;
    if (stalled >= Patience)
    {
      break;
    }
  }
}
}

std::vector<int> Untangler::freeColumns(
  const std::vector<char>& inRegion, const std::vector<char>& frozen) const
{
  std::vector<int> columns;
  std::vector<char> isFree(Dc.cols(), 0);
  for (int f = 0; f < static_cast<int>(inRegion.size()); ++f)
  {
    if (!inRegion[f] || sqrtArea[f] <= 0)
    {
      continue;
    }
    for (int i = 0; i < 4; ++i)
    {
      for (RowMajorMatrix::InnerIterator it(Dr, 4 * f + i); it; ++it)
      {
        if (it.col() < numReal && !isFree[it.col()] && (frozen.empty() || !frozen[it.col()]))
        {
          isFree[it.col()] = 1;
          columns.push_back(static_cast<int>(it.col()));
        }
      }
    }
  }
  return columns;
}

std::vector<int> Untangler::facesUsing(const std::vector<int>& columns) const
{
  std::vector<char> inEnergy(sqrtArea.size(), 0);
  std::vector<int> faces;
  for (const int c : columns)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(Dc, c); it; ++it)
    {
      const int f = static_cast<int>(it.row() / 4);
      if (!inEnergy[f] && sqrtArea[f] > 0)
      {
        inEnergy[f] = 1;
        faces.push_back(f);
      }
    }
  }
  return faces;
}

std::vector<std::pair<std::vector<int>, std::vector<int>>> Untangler::pieces(
  const std::vector<int>& columns, const std::vector<int>& faces) const
{
  // free unknowns are joined when a face's rows use both
  std::vector<int> indexOf(Dc.cols(), -1);
  for (int i = 0; i < static_cast<int>(columns.size()); ++i)
  {
    indexOf[columns[i]] = i;
  }
  std::vector<int> parent(columns.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> faceColumn(faces.size(), -1);
  for (std::size_t j = 0; j < faces.size(); ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      for (RowMajorMatrix::InnerIterator it(Dr, 4 * faces[j] + i); it; ++it)
      {
        const int c = indexOf[it.col()];
        if (c >= 0)
        {
          faceColumn[j] < 0 ? void(faceColumn[j] = c) : unite(parent, faceColumn[j], c);
        }
      }
    }
  }
  // in the order of their first column, columns and faces each in their order
  std::vector<int> pieceOf(columns.size(), -1);
  std::vector<std::pair<std::vector<int>, std::vector<int>>> result;
  for (int i = 0; i < static_cast<int>(columns.size()); ++i)
  {
    const int root = findRoot(parent, i);
    if (pieceOf[root] < 0)
    {
      pieceOf[root] = static_cast<int>(result.size());
      result.emplace_back();
    }
    result[pieceOf[root]].first.push_back(columns[i]);
  }
  for (std::size_t j = 0; j < faces.size(); ++j)
  {
    if (faceColumn[j] >= 0)
    {
      result[pieceOf[findRoot(parent, faceColumn[j])]].second.push_back(faces[j]);
    }
  }
  return result;
}

void Untangler::run(const MeshTopology& topo, const Eigen::MatrixX3i& F,
  const std::vector<int>& flipped, int rings, int maxRounds, Eigen::VectorXd& x,
  const std::vector<char>& frozen, const Progress& progress) const
{
  // free unknowns: the real ones the region's rows use; energy: every face they touch. The
  // pieces that share no free unknown are untangled each on its own: in one minimization the folds
  // of one piece set every piece's eps and keep all of them iterating.
  const std::vector<int> columns = freeColumns(regionAround(topo, F, flipped, rings), frozen);
  std::vector<std::pair<std::vector<int>, std::vector<int>>> list =
    pieces(columns, facesUsing(columns));
  // Each piece reads only its own free unknowns and symbols no piece moves, and writes only its
  // own: the pieces run on several threads with the result of one. Each gets a share of the
  // work left in proportion to its faces, fixed beforehand, so that what a piece may spend does
  // not depend on the order the threads take them in.
  std::size_t totalFaces = 0;
  for (const auto& piece : list)
  {
    totalFaces += piece.second.size();
  }
  std::vector<long long> share(list.size(), 0);
  for (std::size_t i = 0; i < list.size() && work; ++i)
  {
    share[i] = std::max(1LL,
      static_cast<long long>(static_cast<double>(*work) * list[i].second.size() /
        std::max<std::size_t>(1, totalFaces)));
  }
  const std::vector<long long> given = share;
  // the largest first, so that no thread is left with a large piece at the end
  std::vector<int> order(list.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](int a, int b) { return list[a].second.size() > list[b].second.size(); });
  // the calling thread, the one that reports, takes the largest piece (its progress then does
  // not depend on how the threads share the pieces) and counts its evaluations across its pieces
  // (its fractions only grow)
  std::atomic<int> next{ 1 };
  std::atomic<bool> stop{ false };
  auto untanglePieces = [&](int n, const Progress& report) {
    int evaluations = 0;
    for (; n < static_cast<int>(order.size()) && !stop; n = next++)
    {
      const int i = order[n];
      Untangler own = *this;
      own.work = work ? &share[i] : nullptr;
      LocalEnergy energy(own, std::move(list[i].first), list[i].second, x, evaluations);
      Eigen::VectorXd y = energy.restrictTo(x);
      untangle(energy, y, maxRounds, report);
      energy.scatter(y, x);
    }
  };
  const int threads = std::min(threadCount(numberOfThreads), static_cast<int>(list.size()));
  std::vector<std::exception_ptr> failed(std::max(1, threads));
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
  {
    workers.emplace_back([&, t]() {
      try
      {
        untanglePieces(next++, Progress()); // only the calling thread reports
      }
      catch (...)
      {
        failed[t] = std::current_exception();
        stop = true;
      }
    });
  }
  try
  {
    untanglePieces(0, progress);
  }
  catch (...)
  {
    failed[0] = std::current_exception();
    stop = true;
  }
  for (std::thread& w : workers)
  {
    w.join();
  }
  for (const std::exception_ptr& e : failed)
  {
    if (e)
    {
      std::rethrow_exception(e);
    }
  }
  for (std::size_t i = 0; i < list.size() && this->work; ++i)
  {
    *this->work -= given[i] - share[i];
  }
}
}
}
