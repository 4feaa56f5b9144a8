// IntegerRounding.cxx: the integer-grid map's solves: the continuous minimizer (and the edge
// length corrected by its area), its integer unknowns rounded, the re-solve with them fixed.
#include "ParameterizationSteps.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace quadcover
{
namespace param
{
namespace
{
/// Factors A (symmetric positive definite) and solves for the right-hand sides B.
Eigen::MatrixXd solveSpd(const SparseMatrix& A, const Eigen::MatrixXd& B, const char* what)
{
  SpdSolver<double> solver;
  solver.compute(A);
  if (solver.info() != Eigen::Success)
  {
    throw std::runtime_error(std::string("the ") + what +
      " system could not be factored (is a component without any fixed point?)");
  }
  Eigen::MatrixXd X(A.rows(), B.cols());
  constexpr Eigen::Index Block = 64; // right-hand sides per solve call (bounded memory)
  for (Eigen::Index c = 0; c < B.cols(); c += Block)
  {
    const Eigen::Index n = std::min(Block, B.cols() - c);
    X.middleCols(c, n) = solver.solve(B.middleCols(c, n));
  }
  return X;
}

/// factor.S: the integer block of H^-1, column block by column block.
void integerBlockOfInverse(
  const SeamlessSystem& sys, HessianFactor& factor, const Progress& progress)
{
  const int n = sys.numColumns();
  const int numInteger = sys.numInteger;
  factor.S.resize(numInteger, numInteger);
  constexpr int Block = 64; // right-hand sides per solve (bounded memory)
  for (int c = 0; c < numInteger; c += Block)
  {
    progress.report(static_cast<double>(c) / numInteger);
    const int k = std::min(Block, numInteger - c);
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, k);
    for (int j = 0; j < k; ++j)
    {
      E(sys.numReal + c + j, j) = 1.0;
    }
    factor.S.middleCols(c, k) = Eigen::MatrixXd(factor.solver.solve(E)).bottomRows(numInteger);
  }
}

/// Two branch points of one triangle must not land on the same grid point (their triangles
/// would collapse): the differences of their (u, v), in integer unknowns.
class BranchPairs
{
public:
  BranchPairs(
    const Inputs& in, const Field& field, const Parameterization& out, const SeamlessSystem& sys)
    : sys_(sys)
    , pairsOf_(sys.numInteger)
  {
    if (!in.options.pureQuads)
    {
      return;
    }
    for (int f = 0; f < in.numFaces(); ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int sa = out.cornerSector[3 * f + k];
        const int sb = out.cornerSector[3 * f + (k + 1) % 3];
        if (field.branch[in.F(f, k)] && field.branch[in.F(f, (k + 1) % 3)])
        {
          add({ difference(sys.sectorExpr[2 * sa], sys.sectorExpr[2 * sb]),
            difference(sys.sectorExpr[2 * sa + 1], sys.sectorExpr[2 * sb + 1]) });
        }
      }
    }
  }

  /// Fixing j to `value`, the others fixed so far (`fixed`) at `values`: does it complete a
  /// pair at the same point?
  bool collides(
    int j, double value, const std::vector<char>& fixed, const Eigen::VectorXd& values) const
  {
    for (const int p : pairsOf_[j])
    {
      bool complete = true;
      double du = 0.0;
      double dv = 0.0;
      for (int c = 0; c < 2; ++c)
      {
        for (const auto& t : c == 0 ? pairs_[p].du : pairs_[p].dv)
        {
          complete = complete && (fixed[t.first] || t.first == j);
          (c == 0 ? du : dv) += t.second * (t.first == j ? value : values[t.first]);
        }
      }
      if (complete && std::abs(du) < 0.5 && std::abs(dv) < 0.5)
      {
        return true;
      }
    }
    return false;
  }

private:
  struct Pair
  {
    Expr du, dv;
  };

  /// a - b (in symbols) in integer unknowns: index j for column numReal + j, so that a real
  /// column has a negative index.
  Expr difference(const Expr& a, const Expr& b) const
  {
    Expr d;
    for (const auto& [e, sign] : { std::pair<const Expr*, double>{ &a, 1.0 }, { &b, -1.0 } })
    {
      for (const auto& t : *e)
      {
        if (t.first < sys_.numReal)
        {
          d.emplace_back(t.first, sign * t.second);
          continue;
        }
        for (const auto& c : sys_.symbolColumns[t.first - sys_.numReal])
        {
          d.emplace_back(c.first, sign * t.second * c.second);
        }
      }
    }
    normalize(d);
    for (auto& t : d)
    {
      t.first -= sys_.numReal;
    }
    return d;
  }

  /// Keeps the pair when it depends on integer unknowns alone.
  void add(Pair pair)
  {
    bool integral = true;
    for (const Expr* e : { &pair.du, &pair.dv })
    {
      for (const auto& t : *e)
      {
        integral = integral && t.first >= 0;
      }
    }
    if (!integral)
    {
      return;
    }
    for (const Expr* e : { &pair.du, &pair.dv })
    {
      for (const auto& t : *e)
      {
        pairsOf_[t.first].push_back(static_cast<int>(pairs_.size()));
      }
    }
    pairs_.push_back(std::move(pair));
  }

  const SeamlessSystem& sys_;
  std::vector<Pair> pairs_;
  std::vector<std::vector<int>> pairsOf_; ///< per integer unknown, the pairs it is in
};

/// The unfixed unknown closest to an integer (`otherwise` when none is closer than 2).
int closestToInteger(const Eigen::VectorXd& xi, const std::vector<char>& fixed, int otherwise)
{
  int best = otherwise;
  double bestDistance = 2.0;
  for (int j = 0; j < static_cast<int>(xi.size()); ++j)
  {
    const double distance = std::abs(xi[j] - std::round(xi[j]));
    if (!fixed[j] && distance < bestDistance)
    {
      best = j;
      bestDistance = distance;
    }
  }
  return best;
}

/// Fixes xi[j] to `value` and conditions the others on it (S: their covariance, updated).
void condition(Eigen::MatrixXd& S, Eigen::VectorXd& xi, int j, double value)
{
  const double pivot = S(j, j);
  if (pivot > 1e-14 * std::max(1.0, S.diagonal().cwiseAbs().maxCoeff()))
  {
    const Eigen::VectorXd col = S.col(j);
    xi -= col * ((xi[j] - value) / pivot);
    S.noalias() -= col * (col.transpose() / pivot);
  }
  xi[j] = value;
}
}

Eigen::VectorXd solveContinuous(const SeamlessSystem& sys, bool greedy, HessianFactor& factor,
  Parameterization& out, const Progress& progress)
{
  const auto start = std::chrono::steady_clock::now();
  const int n = sys.numColumns();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  if (n > 0)
  {
    factor.solver.compute(sys.H);
    if (factor.solver.info() != Eigen::Success)
    {
      throw std::runtime_error("the Poisson system could not be factored");
    }
    progress.report(greedy ? 0.4 : 0.9);
    x = factor.solver.solve(Eigen::VectorXd(sys.P.transpose() * (sys.D.transpose() * sys.rhs)));
    if (greedy)
    {
      integerBlockOfInverse(sys, factor, progress.part(0.45, 1.0));
    }
  }
  out.solveSeconds.push_back(seconds(start));
  progress.report(1.0);
  return x;
}

void correctEdgeLength(
  const Inputs& in, SeamlessSystem& sys, Eigen::VectorXd& x, Parameterization& out)
{
  if (in.options.targetEdgeLength != 0.0 || sys.numColumns() == 0)
  {
    return;
  }
  // The constraints are homogeneous, so the minimizer is linear in the right-hand side
  // (1 / edgeLength); H and S do not depend on it.
  const Eigen::MatrixX2d uv = sys.uv(x);
  double cells = 0.0;
  for (int f = 0; f < in.numFaces(); ++f)
  {
    cells += 0.5 * twiceUVArea(uv, out.cornerSector, f);
  }
  if (cells > 0 && std::isfinite(cells))
  {
    // bounded: folds cancel area, and a badly folded map must not ask for 100x the quads
    const double factor = std::clamp(std::sqrt(in.options.targetQuadCount / cells), 0.5, 4.0);
    x *= factor;
    sys.rhs *= factor;
    sys.energyNorm *= factor * factor;
    out.edgeLength /= factor;
  }
}

// The integer unknowns' values are Gaussian given the ones fixed so far; fixing one conditions
// the others exactly (x -= S_j (x_j - c_j) / S_jj, S -= S_j S_j^T / S_jj with S the integer
// block of H^-1), which is the re-solve with the same factorization.
Eigen::VectorXd roundIntegers(const Inputs& in, const Field& field, const SeamlessSystem& sys,
  const Eigen::VectorXd& x, const HessianFactor& factor, bool greedy, Parameterization& out,
  const Progress& progress)
{
  const int numInteger = sys.numInteger;
  Eigen::VectorXd xi = x.tail(numInteger);
  Eigen::MatrixXd S = factor.S;
  const BranchPairs pairs(in, field, out, sys);
  std::vector<char> fixed(numInteger, 0);
  Eigen::VectorXd values = xi.array().round().matrix();
  for (int step = 0; step < numInteger; ++step)
  {
    reportEvery(progress, step, numInteger);
    // Simple: in order, each from the continuous minimizer
    const int best = greedy ? closestToInteger(xi, fixed, step) : step;
    // the nearest integer, or the next nearest when the nearest collapses a pair
    double value = std::round(xi[best]);
    if (pairs.collides(best, value, fixed, values))
    {
      ++out.separatedBranchPoints;
      value = xi[best] >= value ? value + 1.0 : value - 1.0;
    }
    fixed[best] = 1;
    values[best] = value;
    if (greedy)
    {
      condition(S, xi, best, value);
    }
  }
  progress.report(1.0);
  return values;
}

void solveWithIntegersFixed(const SeamlessSystem& sys, const HessianFactor& factor,
  const Eigen::VectorXd& integers, bool greedy, Eigen::VectorXd& x, Parameterization& out)
{
  const auto started = std::chrono::steady_clock::now();
  const int n = sys.numColumns();
  const int numReal = sys.numReal;
  const int numInteger = sys.numInteger;
  if (greedy)
  {
    // the minimizer with x_I = c: x0 - H^-1 E_I S0^-1 (x0_I - c), one more solve
    Eigen::VectorXd shift = Eigen::VectorXd::Zero(n);
    shift.tail(numInteger) = factor.S.ldlt().solve(Eigen::VectorXd(x.tail(numInteger) - integers));
    x -= factor.solver.solve(shift);
    x.tail(numInteger) = integers;
  }
  else
  {
    // Simple rounding: the real unknowns solved again with the integers fixed (H's real block).
    Eigen::VectorXd result(n);
    result.tail(numInteger) = integers;
    if (numReal > 0)
    {
      const SparseMatrix Dreal = sys.D.leftCols(numReal); // the real symbols are the real columns
      Eigen::VectorXd fixed = Eigen::VectorXd::Zero(n);
      fixed.tail(numInteger) = integers;
      const Eigen::VectorXd r = sys.rhs - sys.D * (sys.P * fixed);
      const SparseMatrix Hreal = sys.H.topLeftCorner(numReal, numReal);
      result.head(numReal) =
        solveSpd(Hreal, Eigen::MatrixXd(Dreal.transpose() * r), "Poisson").col(0);
    }
    x = result;
  }
  out.solveSeconds.push_back(seconds(started));
}
}
}
