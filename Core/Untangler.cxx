// Untangler.cxx: foldover-free untangling of flipped triangles with L-BFGS.
#include "Untangler.h"

#include "Parallel.h"
#include "UnionFind.h"

#include <Eigen/LU>

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
      toUnitCell_.push_back(untangler.edgeLength / scale);
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
      const Eigen::Matrix2d J = jacobian(j);
      const double det = J.determinant();
      const double root = std::sqrt(eps * eps + det * det);
      const double chi = 0.5 * (det + root);
      const double chiPrime = 0.5 * (1.0 + det / root);
      const double trace = J.squaredNorm();
      const double area = area_[j];
      total += area * ((1 - theta) * trace / chi + theta * (det * det + 1) / chi);
      Eigen::Matrix2d dDet;
      dDet << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
      const Eigen::Matrix2d dE =
        (1 - theta) * (2.0 * J / chi - trace * chiPrime / (chi * chi) * dDet) +
        theta * (2.0 * det / chi - (det * det + 1) * chiPrime / (chi * chi)) * dDet;
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

  const Untangler& untangler_;
  const std::vector<int> columns_;
  std::vector<double> area_;        // per face of the energy: its area
  std::vector<double> toUnitCell_;  // per face: edgeLength / sqrt(area), J relative to the cell
  std::vector<int> rowBegin_;       // per row (4 per face): where its terms begin
  std::vector<double> coefficient_; // per term: D's coefficient
  std::vector<int> slot_;           // per term: the slot of its symbol
  Eigen::VectorXd z_;               // per slot: the free unknowns, then the fixed symbols
  Eigen::VectorXd gradient_;        // per slot
  int& evaluations_;
};

/// The L-BFGS direction for gradient g from the pairs (S, Y) (the two-loop recursion).
Eigen::VectorXd lbfgsDirection(const std::vector<Eigen::VectorXd>& S,
  const std::vector<Eigen::VectorXd>& Y, const Eigen::VectorXd& g)
{
  Eigen::VectorXd d = -g;
  std::vector<double> alpha(S.size());
  for (int j = static_cast<int>(S.size()) - 1; j >= 0; --j)
  {
    alpha[j] = S[j].dot(d) / Y[j].dot(S[j]);
    d -= alpha[j] * Y[j];
  }
  if (!S.empty())
  {
    d *= S.back().dot(Y.back()) / Y.back().squaredNorm();
  }
  for (std::size_t j = 0; j < S.size(); ++j)
  {
    const double beta = Y[j].dot(d) / Y[j].dot(S[j]);
    d += S[j] * (alpha[j] - beta);
  }
  return d;
}

/// Minimizes the energy (with eps fixed) from y: L-BFGS, 8 pairs, Armijo backtracking, at most
/// 200 iterations. Returns the energy at the new y.
double minimize(LocalEnergy& energy, Eigen::VectorXd& y, double eps, const Progress& progress)
{
  constexpr int Iterations = 200;
  std::vector<Eigen::VectorXd> S, Y;
  Eigen::VectorXd g;
  double e = energy.evaluate(y, eps, g);
  for (int it = 0; it < Iterations && !energy.spent(); ++it)
  {
    // how many rounds and iterations it takes is not known beforehand: a fraction that
    // approaches 1 with the evaluations done
    progress.report(energy.evaluations() / (energy.evaluations() + 100.0));
    Eigen::VectorXd d = lbfgsDirection(S, Y, g);
    double slope = g.dot(d);
    if (!(slope < 0))
    {
      d = -g;
      slope = -g.squaredNorm();
      S.clear();
      Y.clear();
    }
    double step = S.empty() ? std::min(1.0, 1.0 / std::max(1e-300, g.norm())) : 1.0;
    Eigen::VectorXd gNew;
    double eNew = e;
    Eigen::VectorXd yNew;
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
    S.push_back(yNew - y);
    Y.push_back(gNew - g);
    if (S.back().dot(Y.back()) <= 1e-300)
    {
      S.pop_back();
      Y.pop_back();
    }
    if (S.size() > 8)
    {
      S.erase(S.begin());
      Y.erase(Y.begin());
    }
    const double change = e - eNew;
    y = yNew;
    g = gNew;
    e = eNew;
    if (change <= 1e-9 * std::abs(e))
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
    const double lowest = energy.folds(y).first;
    const double eps = lowest < 0 ? std::sqrt(1e-8 + 0.04 * lowest * lowest) : 1e-8;
    const double e = minimize(energy, y, eps, progress);
    const std::pair<double, int> after = energy.folds(y);
    // settled: unfolded, and a round at the final eps gained little over the one before. Only
    // energies of the same eps compare: a smaller eps raises the energy of the same map, which
    // once stopped a run that had just unfolded its last triangle to a determinant of 0.002.
    const bool finalEps = !(lowest < 0);
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
  // pieces that share no free unknown are untangled each on its own: in one L-BFGS the folds of
  // one piece set every piece's eps and keep all of them iterating.
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
  const int threads = std::min(numberOfThreads > 0 ? numberOfThreads : defaultThreadCount(),
    static_cast<int>(list.size()));
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
