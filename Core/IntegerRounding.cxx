// IntegerRounding.cxx: the integer-grid map's solves: the continuous minimizer (and the edge
// length corrected by its area), its integer unknowns rounded, the re-solve with them fixed.
#include "NearbyPoints.h"
#include "ParameterizationSteps.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
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
  if (factor.solver.inverseOfLast(numInteger, factor.S))
  {
    return;
  }
  factor.S.resize(numInteger, numInteger);
  // right-hand sides per solve: 64, down to 16 where they would take more than 8 MB (three
  // copies of them live at once: E, CHOLMOD's solution and its copy; at 64 they were 133 MB of
  // armadillo's 307 MB peak, now 242 MB; its outputs and the others' stayed byte-identical)
  const int Block = std::clamp((1 << 20) / std::max(1, n), 16, 64);
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

/**
 * Pairs that the rounding must keep apart. Two branch points of one triangle must not land on
 * the same grid point (their triangles would collapse). Two boundary lines that face each other
 * across a thin hole or a thin strip of the surface (less than 1.5 grid cells apart, overlapping
 * along their direction, near on the surface) must neither meet nor cross: met, the hole closes
 * or the strip is cut through (the truck's body at 6,500 quads: slots of a grille and slits
 * 0.4 cells wide closed, and 17 of its 39 holes were lost). Each pair is its differences in
 * integer unknowns: (u, v) for branch points, the constant coordinate for lines.
 */
class KeptApart
{
public:
  KeptApart(const Inputs& in, const Field& field, const Parameterization& out,
    const SeamlessSystem& sys, const Eigen::VectorXd& x, bool aroundPoints)
    : sys_(sys)
    , pairsOf_(sys.numInteger)
  {
    if (in.options.pureQuads)
    {
      addBranchPairs(in, field, out, aroundPoints);
    }
    addLinePairs(in, out, sys.uv(x));
  }

  /// Fixing j to `value`, the others fixed so far (`fixed`) at `values`: does it complete a
  /// pair that meets (or, for lines, crosses)?
  bool collides(
    int j, double value, const std::vector<char>& fixed, const Eigen::VectorXd& values) const
  {
    for (const int p : pairsOf_[j])
    {
      const Pair& pair = pairs_[p];
      bool complete = true;
      double d[2] = { 0.0, 0.0 };
      for (int c = 0; c < pair.dims; ++c)
      {
        for (const auto& t : pair.d[c])
        {
          complete = complete && (fixed[t.first] || t.first == j);
          d[c] += t.second * (t.first == j ? value : values[t.first]);
        }
      }
      const bool met =
        pair.dims == 2 ? std::abs(d[0]) < 0.5 && std::abs(d[1]) < 0.5 : pair.order * d[0] < 0.5;
      if (complete && met)
      {
        return true;
      }
    }
    return false;
  }

  /// Is j in a pair of boundary lines (else of branch points)?
  bool isLine(int j) const
  {
    return std::any_of(
      pairsOf_[j].begin(), pairsOf_[j].end(), [&](int p) { return pairs_[p].dims == 1; });
  }

private:
  struct Pair
  {
    Expr d[2];
    int dims = 2;       ///< 2: branch points (u and v), 1: boundary lines (their coordinate)
    double order = 0.0; ///< lines: the sign of d[0] in the continuous map, which is kept
  };

  /// A boundary edge on a grid line: which coordinate is constant, its value (in symbols and in
  /// the continuous map), the range of the other coordinate, its middle on the surface.
  struct LineEdge
  {
    int c;
    const Expr* expr;
    double value, lo, hi, length;
    Eigen::Vector3d middle;
  };

  /// The branch points of one triangle, pairwise; with `aroundPoints`, those of the faces around
  /// each point that lie in one of its sectors (one chart: no cut between them): also those two
  /// edges apart (packed cones, where one grid point for both closed one of them up).
  void addBranchPairs(
    const Inputs& in, const Field& field, const Parameterization& out, bool aroundPoints)
  {
    std::set<std::pair<int, int>> seen; // sector pairs
    for (int r = 0; r < in.numVertices(); ++r)
    {
      std::vector<std::array<int, 4>> found; // r's sector, the branch point, its sector, the face
      for (int i = in.topo.ringOffsets[r]; i < in.topo.ringOffsets[r + 1]; ++i)
      {
        const int f = in.topo.ringFaces[i];
        const int around = out.cornerSector[3 * f + MeshTopology::cornerOf(in.F, f, r)];
        for (int k = 0; k < 3; ++k)
        {
          if (field.branch[in.F(f, k)])
          {
            found.push_back({ around, in.F(f, k), out.cornerSector[3 * f + k], f });
          }
        }
      }
      for (std::size_t a = 0; a < found.size(); ++a)
      {
        for (std::size_t b = a + 1; b < found.size(); ++b)
        {
          const int sa = found[a][2], sb = found[b][2];
          const bool oneTriangle = found[a][3] == found[b][3];
          if (found[a][0] != found[b][0] || found[a][1] == found[b][1] ||
            !(aroundPoints || oneTriangle) ||
            !seen.insert({ std::min(sa, sb), std::max(sa, sb) }).second)
          {
            continue;
          }
          Pair pair;
          pair.d[0] = difference(sys_.sectorExpr[2 * sa], sys_.sectorExpr[2 * sb]);
          pair.d[1] = difference(sys_.sectorExpr[2 * sa + 1], sys_.sectorExpr[2 * sb + 1]);
          add(std::move(pair));
        }
      }
    }
  }

  /// The boundary edges, and with featureLines the inner ones (each once), whose two ends share a
  /// coordinate that is an integer unknown: the edges on boundary and feature lines.
  std::vector<LineEdge> lineEdges(
    const Inputs& in, const Parameterization& out, const Eigen::MatrixX2d& uv) const
  {
    std::vector<LineEdge> edges;
    for (int f = 0; f < in.numFaces(); ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int g = in.topo.faceNeighbors(f, k);
        if (g >= 0 && (!in.options.featureLines || g < f))
        {
          continue;
        }
        const int sa = out.cornerSector[3 * f + k];
        const int sb = out.cornerSector[3 * f + (k + 1) % 3];
        for (int c = 0; c < 2; ++c)
        {
          const Expr& e = sys_.sectorExpr[2 * sa + c];
          const bool integral =
            std::all_of(e.begin(), e.end(), [&](const auto& t) { return t.first >= sys_.numReal; });
          if (e.empty() || !integral || e != sys_.sectorExpr[2 * sb + c])
          {
            continue;
          }
          const Eigen::Vector3d a = in.V.row(in.F(f, k)).transpose();
          const Eigen::Vector3d b = in.V.row(in.F(f, (k + 1) % 3)).transpose();
          edges.push_back({ c, &e, uv(sa, c), std::min(uv(sa, 1 - c), uv(sb, 1 - c)),
            std::max(uv(sa, 1 - c), uv(sb, 1 - c)), (b - a).norm(), 0.5 * (a + b) });
        }
      }
    }
    return edges;
  }

  /// Pairs of boundary or feature lines that face each other less than a grid cell apart (two
  /// creases of a thin rib, say).
  void addLinePairs(const Inputs& in, const Parameterization& out, const Eigen::MatrixX2d& uv)
  {
    const std::vector<LineEdge> edges = lineEdges(in, out, uv);
    std::set<std::pair<const Expr*, const Expr*>> seen;
    const double h = out.edgeLength;
    const std::vector<std::vector<int>> near = nearbyEdges(edges, h);
    for (std::size_t i = 0; i < edges.size(); ++i)
    {
      for (const int j : near[i])
      {
        const LineEdge& a = edges[i];
        const LineEdge& b = edges[j];
        const double gap = a.value - b.value;
        // overlapping along the lines by more than a sliver: not two ends of a step
        const double overlap = std::min(a.hi, b.hi) - std::max(a.lo, b.lo);
        if (a.c != b.c || !(std::abs(gap) < 1.5) || std::abs(gap) < 1e-6 || overlap < 0.05 ||
          (a.middle - b.middle).norm() > 2 * h + 0.5 * (a.length + b.length))
        {
          continue;
        }
        Pair pair;
        pair.dims = 1;
        pair.order = gap > 0 ? 1.0 : -1.0;
        pair.d[0] = difference(*a.expr, *b.expr);
        if (!pair.d[0].empty() && seen.insert({ a.expr, b.expr }).second)
        {
          add(std::move(pair));
        }
      }
    }
  }

  /// For each boundary line edge, the later ones (in order) whose middles may lie within
  /// 2 h + their half lengths of its own, the test addLinePairs makes (nearbyPoints).
  static std::vector<std::vector<int>> nearbyEdges(const std::vector<LineEdge>& edges, double h)
  {
    double longest = 0.0;
    std::vector<Eigen::Vector3d> middles;
    middles.reserve(edges.size());
    for (const LineEdge& e : edges)
    {
      longest = std::max(longest, e.length);
      middles.push_back(e.middle);
    }
    return nearbyPoints(middles, 2 * h + longest);
  }

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
    for (int c = 0; c < pair.dims; ++c)
    {
      for (const auto& t : pair.d[c])
      {
        integral = integral && t.first >= 0;
      }
    }
    if (!integral)
    {
      return;
    }
    for (int c = 0; c < pair.dims; ++c)
    {
      for (const auto& t : pair.d[c])
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

/// The integer nearest to x that keeps the pairs of j apart, among the 2 MaximumShift + 1
/// nearest; the next nearest when none does.
double apartValue(const KeptApart& pairs, int j, double x, const std::vector<char>& fixed,
  const Eigen::VectorXd& values)
{
  constexpr int MaximumShift = 2;
  const double nearest = std::round(x);
  const double side = x >= nearest ? 1.0 : -1.0; // the next nearest is on x's side
  for (int shift = 1; shift <= MaximumShift; ++shift)
  {
    for (const double value : { nearest + side * shift, nearest - side * shift })
    {
      if (!pairs.collides(j, value, fixed, values))
      {
        return value;
      }
    }
  }
  return nearest + side;
}

/**
 * The greedy rounding's unfixed integer unknowns: their values and their covariance S (the
 * integer block of H^-1), conditioned on the ones fixed so far. They are kept compact, the
 * unfixed first: fixing one moves the last unfixed into its place, so that conditioning costs
 * the square of how many are left, not of all (a third of the work over the whole rounding).
 * Each entry gets the same arithmetic, in the same order, as over the whole matrix.
 */
class UnfixedUnknowns
{
public:
  UnfixedUnknowns(const Eigen::VectorXd& xi, const Eigen::MatrixXd& S)
    : xi_(xi)
    , S_(S)
    , index_(xi.size())
    , count_(static_cast<int>(xi.size()))
  {
    for (int i = 0; i < count_; ++i)
    {
      index_[i] = i;
    }
  }

  /// The position of the unknown closest to an integer (the lowest index among equals).
  int closestToInteger() const
  {
    int best = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int i = 0; i < count_; ++i)
    {
      const double distance = std::abs(xi_[i] - std::round(xi_[i]));
      if (distance < bestDistance || (distance == bestDistance && index_[i] < index_[best]))
      {
        best = i;
        bestDistance = distance;
      }
    }
    return best;
  }

  int index(int i) const { return index_[i]; }
  double value(int i) const { return xi_[i]; }

  /// Fixes the unknown at position i to `value`: conditions the others on it
  /// (xi -= S_i (xi_i - value) / S_ii, S -= S_i S_i^T / S_ii) and drops it.
  void fix(int i, double value)
  {
    const int m = count_;
    const double pivot = S_(i, i);
    const double largest = S_.diagonal().head(m).cwiseAbs().maxCoeff();
    if (pivot > 1e-14 * std::max(1.0, largest))
    {
      const Eigen::VectorXd col = S_.col(i).head(m);
      xi_.head(m) -= col * ((xi_[i] - value) / pivot);
      S_.topLeftCorner(m, m).noalias() -= col * (col.transpose() / pivot);
    }
    const int last = m - 1;
    if (i != last)
    {
      S_.row(i).head(m).swap(S_.row(last).head(m));
      S_.col(i).head(m).swap(S_.col(last).head(m));
      std::swap(xi_[i], xi_[last]);
      std::swap(index_[i], index_[last]);
    }
    count_ = last;
  }

private:
  Eigen::VectorXd xi_;
  Eigen::MatrixXd S_;
  std::vector<int> index_; ///< per position, the unknown there
  int count_;              ///< how many are left unfixed (the first positions)
};
}

Eigen::VectorXd solveContinuous(const SeamlessSystem& sys, bool greedy, HessianFactor& factor,
  Parameterization& out, const Progress& progress)
{
  const auto start = std::chrono::steady_clock::now();
  const int n = sys.numColumns();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  if (n > 0)
  {
    // the integers ordered last: the greedy rounding's block of H^-1 then comes off the factor
    factor.solver.analyzePatternWithLast(sys.H, greedy ? sys.numInteger : 0);
    factor.solver.factorize(sys.H);
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

double countedCells(const Inputs& in, const SeamlessSystem& sys, const Eigen::VectorXd& x,
  const Parameterization& out)
{
  const Eigen::MatrixX2d uv = sys.uv(x);
  double cells = 0.0;
  for (int f = 0; f < in.numFaces(); ++f)
  {
    // a thin strip's finer grid's cells count as the cells of the uniform grid they replace
    const double cell = sys.countedCell.size() > 0 ? sys.countedCell[f] : sys.cell(f);
    cells += 0.5 * twiceUVArea(uv, out.cornerSector, f) * cell * cell;
  }
  return cells;
}

void refineGrid(double factor, SeamlessSystem& sys, Eigen::VectorXd& x, Parameterization& out)
{
  x *= factor;
  sys.rhs *= factor;
  sys.energyNorm *= factor * factor;
  out.edgeLength /= factor;
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
  const double cells = countedCells(in, sys, x, out);
  if (cells > 0 && std::isfinite(cells))
  {
    // bounded: folds cancel area, and a badly folded map must not ask for 100x the quads
    refineGrid(std::clamp(std::sqrt(in.options.targetQuadCount / cells), 0.5, 4.0), sys, x, out);
  }
}

// The integer unknowns' values are Gaussian given the ones fixed so far; fixing one conditions
// the others exactly (x -= S_j (x_j - c_j) / S_jj, S -= S_j S_j^T / S_jj with S the integer
// block of H^-1), which is the re-solve with the same factorization.
Eigen::VectorXd roundIntegers(const Inputs& in, const Field& field, const SeamlessSystem& sys,
  const Eigen::VectorXd& x, const HessianFactor& factor, bool greedy, Parameterization& out,
  const Progress& progress, bool packedCones)
{
  const int numInteger = sys.numInteger;
  const Eigen::VectorXd xi = x.tail(numInteger);
  const KeptApart pairs(in, field, out, sys, x, packedCones);
  std::vector<char> fixed(numInteger, 0);
  Eigen::VectorXd values = xi.array().round().matrix();
  // Greedy: the one closest to an integer first, from the minimizer given those fixed so far;
  // simple: in order, each from the continuous minimizer
  std::optional<UnfixedUnknowns> unfixed;
  if (greedy)
  {
    unfixed.emplace(xi, factor.S);
  }
  for (int step = 0; step < numInteger; ++step)
  {
    reportEvery(progress, step, numInteger);
    const int position = greedy ? unfixed->closestToInteger() : step;
    const int best = greedy ? unfixed->index(position) : step;
    const double continuous = greedy ? unfixed->value(position) : xi[best];
    // the nearest integer, or the nearest that keeps its pairs apart
    double value = std::round(continuous);
    if (pairs.collides(best, value, fixed, values))
    {
      ++(pairs.isLine(best) ? out.separatedBoundaryLines : out.separatedBranchPoints);
      value = apartValue(pairs, best, continuous, fixed, values);
    }
    fixed[best] = 1;
    values[best] = value;
    if (greedy)
    {
      unfixed->fix(position, value);
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
