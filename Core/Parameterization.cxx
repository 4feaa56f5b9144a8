// Parameterization.cxx: the integer-grid map (computeParameterization).
#include "Parameterization.h"

#include "Eliminator.h"
#include "FrameField.h"
#include "SparseSolver.h"
#include "UnionFind.h"
#include "Untangler.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

int mod4(int r)
{
  return ((r % 4) + 4) % 4;
}

using param::Eliminator;
using param::Expr;
using param::normalize;
using param::Untangler;

double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

using SparseMatrix = Eigen::SparseMatrix<double>;

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
}

double edgeLengthForQuadCount(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, double quads)
{
  if (!(quads > 0))
  {
    throw std::invalid_argument("the quad count must be positive");
  }
  return std::sqrt(surfaceArea(V, F) / quads);
}

Parameterization computeParameterization(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3i& matching, const ParameterizationOptions& options,
  const Progress& progress)
{
  progress.report(0.0);
  const int nF = static_cast<int>(F.rows());
  const int nV = static_cast<int>(V.rows());
  if (topo.numFaces != nF || topo.numVertices != nV || frameU.rows() != nF ||
    matching.rows() != nF || geometry.bases.b1.rows() != nF)
  {
    throw std::invalid_argument("computeParameterization: sizes do not match");
  }
  const bool fromQuadCount = options.targetEdgeLength == 0.0;
  if (!(options.targetEdgeLength >= 0) || !std::isfinite(options.targetEdgeLength) ||
    (fromQuadCount && !(options.targetQuadCount > 0 && std::isfinite(options.targetQuadCount))))
  {
    throw std::invalid_argument("computeParameterization: the target edge length must be positive "
                                "or 0 with a positive target quad count");
  }
  if (!topo.isManifold() || !topo.isOriented())
  {
    throw std::invalid_argument("computeParameterization: " + topo.describeDefects());
  }
  Parameterization out;
  out.edgeLength = fromQuadCount ? edgeLengthForQuadCount(V, F, options.targetQuadCount)
                                 : options.targetEdgeLength;
#ifdef QUADCOVER_HAVE_CHOLMOD
  out.solver = "CHOLMOD supernodal LLT";
#else
  out.solver = "Eigen SimplicialLDLT";
#endif

  // ---- the singular points and a cut through them ----
  const FrameTopology ft = evaluateMatchings(F, topo, geometry, frameU, matching);
  std::vector<char> terminal(nV, 0);
  std::vector<char> branch(nV, 0);
  for (int v = 0; v < nV; ++v)
  {
    if (!topo.boundaryVertex[v])
    {
      branch[v] = ft.layerShift[v] != 0;
      terminal[v] = branch[v] || std::abs(ft.index[v]) > 1e-6;
      out.branchPoints += branch[v];
    }
  }
  out.cut = computeCutGraph(topo, terminal);
  const std::vector<char>& onCut = out.cut.onCut;
  out.seamEdges = out.cut.numCutEdges;

  // ---- comb: quarter turns so that matchings vanish across every edge off the cut ----
  out.comb = Eigen::VectorXi::Constant(nF, -1);
  for (int seed = 0; seed < nF; ++seed)
  {
    if (out.comb[seed] >= 0)
    {
      continue;
    }
    out.comb[seed] = 0;
    std::deque<int> queue{ seed };
    while (!queue.empty())
    {
      const int f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo.faceNeighbors(f, k);
        if (g >= 0 && !onCut[topo.faceEdges(f, k)] && out.comb[g] < 0)
        {
          out.comb[g] = mod4(matching(f, k) + out.comb[f]);
          queue.push_back(g);
        }
      }
    }
  }
  out.combedMatching.resize(nF, 3);
  out.seam = Eigen::MatrixX3i::Zero(nF, 3);
  for (int f = 0; f < nF; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      const int e = topo.faceEdges(f, k);
      out.combedMatching(f, k) = g < 0 ? -1 : mod4(matching(f, k) + out.comb[f] - out.comb[g]);
      out.seam(f, k) = onCut[e] ? 1 : 0;
      if (g >= 0 && !onCut[e] && out.combedMatching(f, k) != 0)
      {
        throw std::logic_error("computeParameterization: the frames cannot be combed off the cut "
                               "(a singular point is not on it)");
      }
    }
  }

  // ---- sectors: the corners of a point between cut (or boundary) edges ----
  std::vector<int> parent(3 * nF);
  for (int c = 0; c < 3 * nF; ++c)
  {
    parent[c] = c;
  }
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (topo.edgeFaceCount[e] != 2 || onCut[e])
    {
      continue;
    }
    const int c0 = topo.edgeCorners(e, 0);
    const int f = c0 / 3;
    const int g = topo.edgeCorners(e, 1) / 3;
    for (int end = 0; end < 2; ++end)
    {
      const int p = F(f, (c0 % 3 + end) % 3);
      unite(parent, 3 * f + (c0 % 3 + end) % 3, 3 * g + MeshTopology::cornerOf(F, g, p));
    }
  }
  out.cornerSector.assign(3 * nF, -1);
  for (int c = 0; c < 3 * nF; ++c)
  {
    const int root = findRoot(parent, c);
    if (root == c)
    {
      out.cornerSector[c] = static_cast<int>(out.sectorPoint.size());
      out.sectorPoint.push_back(F(c / 3, c % 3));
    }
    out.cornerSector[c] = out.cornerSector[root];
  }
  const int nS = static_cast<int>(out.sectorPoint.size());
  auto sectorOf = [&](int f, int p) {
    return out.cornerSector[3 * f + MeshTopology::cornerOf(F, f, p)];
  };

  // ---- unknowns and constraints ----
  Eliminator elim;
  for (int s = 0; s < nS; ++s)
  {
    const bool integer = options.pureQuads && branch[out.sectorPoint[s]];
    elim.add(integer); // u = 2s
    elim.add(integer); // v = 2s + 1
  }
  // z_B - i^r z_A - t_e = 0 at both ends of every cut edge (f = side A, g = side B).
  std::vector<std::vector<int>> cutAt(nV);
  std::vector<int> translation(topo.numEdges(), -1);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (onCut[e])
    {
      translation[e] = elim.add(true);
      elim.add(true);
      cutAt[topo.edges(e, 0)].push_back(e);
      cutAt[topo.edges(e, 1)].push_back(e);
    }
  }
  for (int p = 0; p < nV; ++p)
  {
    for (const int e : cutAt[p])
    {
      const int c0 = topo.edgeCorners(e, 0);
      const int f = c0 / 3;
      const int g = topo.edgeCorners(e, 1) / 3;
      const int r = out.combedMatching(f, c0 % 3);
      const int a = sectorOf(f, p);
      const int b = sectorOf(g, p);
      // i^r (uA + i vA): r = 0: (uA, vA), 1: (-vA, uA), 2: (-uA, -vA), 3: (vA, -uA)
      const int reU = (r % 2 == 0) ? 2 * a : 2 * a + 1;
      const double reS = (r == 0 || r == 3) ? 1.0 : -1.0;
      const int imU = (r % 2 == 0) ? 2 * a + 1 : 2 * a;
      const double imS = (r == 0 || r == 1) ? 1.0 : -1.0;
      elim.constrain({ { 2 * b, 1.0 }, { reU, -reS }, { translation[e], -1.0 } });
      elim.constrain({ { 2 * b + 1, 1.0 }, { imU, -imS }, { translation[e] + 1, -1.0 } });
    }
  }
  // Boundary edges along a combed frame direction: the other coordinate is an integer line.
  const Eigen::VectorXd theta = vectorAngles(geometry.bases, frameU);
  std::vector<char> onLine(2 * static_cast<std::size_t>(nS), 0); // u or v of a sector on a line
  if (options.alignToBoundary)
  {
    const double tolerance = options.boundaryTolerance * Pi / 180.0;
    for (int e = 0; e < topo.numEdges(); ++e)
    {
      if (topo.edgeFaceCount[e] != 1)
      {
        continue;
      }
      const int c0 = topo.edgeCorners(e, 0);
      const int f = c0 / 3;
      const int k = c0 % 3;
      const Eigen::Vector3d d = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      const double alpha = std::atan2(
        d.dot(geometry.bases.b2.row(f).transpose()), d.dot(geometry.bases.b1.row(f).transpose()));
      double delta = wrapAngle(alpha - theta[f] - out.comb[f] * Pi / 2);
      // delta modulo pi in (-pi/2, pi/2]: near 0 along u (v constant), near +-pi/2 along v
      if (delta > Pi / 2)
      {
        delta -= Pi;
      }
      else if (delta <= -Pi / 2)
      {
        delta += Pi;
      }
      int component = -1;
      if (std::abs(delta) <= tolerance)
      {
        component = 1;
      }
      else if (Pi / 2 - std::abs(delta) <= tolerance)
      {
        component = 0;
      }
      if (component < 0)
      {
        continue;
      }
      ++out.alignedBoundaryEdges;
      const int line = elim.add(true);
      for (int end = 0; end < 2; ++end)
      {
        const int s = out.cornerSector[3 * f + (k + end) % 3];
        elim.constrain({ { 2 * s + component, 1.0 }, { line, -1.0 } });
        onLine[2 * s + component] = 1;
      }
    }
  }
  // One point per component fixed at (0, 0): the map is defined up to translation. The point is
  // one that is on the grid anyway (a branch point, else a boundary corner on two grid lines),
  // so that the fixing costs nothing; only without either is a regular point put on the grid.
  {
    std::vector<int> pin(topo.numComponents(), -1);
    std::vector<int> rank(topo.numComponents(), 3);
    for (int f = 0; f < nF; ++f)
    {
      const int c = topo.faceComponent[f];
      for (int k = 0; k < 3 && c >= 0; ++k)
      {
        const int s = out.cornerSector[3 * f + k];
        const int r = branch[F(f, k)] ? 0 : (onLine[2 * s] && onLine[2 * s + 1] ? 1 : 2);
        if (r < rank[c])
        {
          rank[c] = r;
          pin[c] = s;
        }
      }
    }
    for (const int s : pin)
    {
      if (s >= 0)
      {
        elim.constrain({ { 2 * s, 1.0 } });
        elim.constrain({ { 2 * s + 1, 1.0 } });
      }
    }
  }
  out.constraints = elim.Constraints;
  out.nonUnitPivots = elim.NonUnitPivots;

  // Columns: real unknowns first, then integer ones.
  std::vector<int> column(elim.size(), -1);
  int numReal = 0;
  int numInteger = 0;
  for (int x = 0; x < elim.size(); ++x)
  {
    if (!elim.isEliminated(x) && !elim.isInteger(x))
    {
      column[x] = numReal++;
    }
  }
  for (int x = 0; x < elim.size(); ++x)
  {
    if (!elim.isEliminated(x) && elim.isInteger(x))
    {
      column[x] = numReal + numInteger++;
    }
  }
  const int n = numReal + numInteger;
  out.unknowns = n;
  out.integerUnknowns = numInteger;
  // Symbols: the real unknowns (columns 0..numReal-1), then every integer unknown a sector
  // refers to, eliminated or not. Sectors are short in symbols; P maps symbols to columns (an
  // eliminated integer unknown may be a long sum: a seam's translation sums the branch points
  // beyond it).
  std::vector<int> symbolOf(elim.size(), -1);
  std::vector<Expr> symbolColumns; // integer symbols' expressions in columns
  std::vector<Expr> sectorExpr(2 * nS);
  for (int x = 0; x < 2 * nS; ++x)
  {
    sectorExpr[x] = elim.resolveReals(x);
    for (auto& t : sectorExpr[x])
    {
      if (!elim.isInteger(t.first))
      {
        t.first = column[t.first];
        continue;
      }
      if (symbolOf[t.first] < 0)
      {
        symbolOf[t.first] = numReal + static_cast<int>(symbolColumns.size());
        Expr e = elim.resolve(t.first);
        for (auto& c : e)
        {
          c.first = column[c.first];
        }
        symbolColumns.push_back(std::move(e));
      }
      t.first = symbolOf[t.first];
    }
  }
  const int numSymbols = numReal + static_cast<int>(symbolColumns.size());
  SparseMatrix P(numSymbols, n);
  {
    std::vector<Eigen::Triplet<double>> t;
    for (int j = 0; j < numReal; ++j)
    {
      t.emplace_back(j, j, 1.0);
    }
    for (std::size_t k = 0; k < symbolColumns.size(); ++k)
    {
      for (const auto& c : symbolColumns[k])
      {
        t.emplace_back(numReal + static_cast<int>(k), c.first, c.second);
      }
    }
    P.setFromTriplets(t.begin(), t.end());
  }

  // ---- the energy: 4 rows per triangle, sqrt(A) (grad u - U'/h, grad v - V'/h) ----
  const double scale = 1.0 / out.edgeLength;
  double totalArea = 0.0;
  Eigen::VectorXd faceArea = Eigen::VectorXd::Zero(nF);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(nF) * 14);
  std::vector<Eigen::Triplet<double>> hessian;
  hessian.reserve(static_cast<std::size_t>(nF) * 26);
  Expr row[4];
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(4 * static_cast<Eigen::Index>(nF));
  for (int f = 0; f < nF; ++f)
  {
    Eigen::Vector2d p[3];
    const Eigen::Vector3d b1 = geometry.bases.b1.row(f).transpose();
    const Eigen::Vector3d b2 = geometry.bases.b2.row(f).transpose();
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d d = V.row(F(f, k)) - V.row(F(f, 0));
      p[k] = Eigen::Vector2d(d.dot(b1), d.dot(b2));
    }
    const double twiceArea =
      (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
    if (!(twiceArea > 0))
    {
      continue;
    }
    totalArea += 0.5 * twiceArea;
    faceArea[f] = 0.5 * twiceArea;
    const double w = std::sqrt(0.5 * twiceArea);
    const double angle = theta[f] + out.comb[f] * Pi / 2;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    rhs[4 * f + 0] = w * scale * c;  // grad u . x = U'.x
    rhs[4 * f + 1] = w * scale * s;  // grad u . y
    rhs[4 * f + 2] = w * scale * -s; // grad v . x = V'.x
    rhs[4 * f + 3] = w * scale * c;  // grad v . y
    for (int r = 0; r < 4; ++r)
    {
      row[r].clear();
    }
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector2d edge = p[(k + 2) % 3] - p[(k + 1) % 3];
      const Eigen::Vector2d grad = Eigen::Vector2d(-edge.y(), edge.x()) * (w / twiceArea);
      const int sector = out.cornerSector[3 * f + k];
      for (int uv = 0; uv < 2; ++uv)
      {
        for (const auto& t : sectorExpr[2 * sector + uv])
        {
          row[2 * uv].emplace_back(t.first, grad.x() * t.second);
          row[2 * uv + 1].emplace_back(t.first, grad.y() * t.second);
        }
      }
    }
    // D's rows, and H = D^T D assembled from each row's outer product (much faster than the
    // sparse product)
    for (int r = 0; r < 4; ++r)
    {
      for (const auto& a : row[r])
      {
        triplets.emplace_back(4 * f + r, a.first, a.second);
        for (const auto& b : row[r])
        {
          if (b.first <= a.first)
          {
            hessian.emplace_back(a.first, b.first, a.second * b.second);
          }
        }
      }
    }
  }
  // D: rows over symbols; H = P^T (D^T D) P
  SparseMatrix D(4 * static_cast<Eigen::Index>(nF), numSymbols);
  D.setFromTriplets(triplets.begin(), triplets.end());
  triplets.clear();
  triplets.shrink_to_fit();
  SparseMatrix H;
  {
    SparseMatrix lower(numSymbols, numSymbols);
    lower.setFromTriplets(hessian.begin(), hessian.end());
    hessian.clear();
    hessian.shrink_to_fit();
    const SparseMatrix full = lower.selfadjointView<Eigen::Lower>();
    H = P.transpose() * full * P;
  }
  double energyNorm = 2.0 * scale * scale * std::max(totalArea, 1e-300);
  auto energyOf = [&](const Eigen::VectorXd& x) {
    return (D * (P * x) - rhs).squaredNorm() / energyNorm;
  };

  auto uvOf = [&](const Eigen::VectorXd& columns) {
    const Eigen::VectorXd x = P * columns;
    Eigen::MatrixX2d uv(nS, 2);
    for (int s = 0; s < nS; ++s)
    {
      for (int c = 0; c < 2; ++c)
      {
        double value = 0.0;
        for (const auto& t : sectorExpr[2 * s + c])
        {
          value += t.second * x[t.first];
        }
        uv(s, c) = value;
      }
    }
    return uv;
  };
  auto flippedFaces = [&](const Eigen::MatrixX2d& uv) {
    std::vector<int> flipped;
    for (int f = 0; f < nF; ++f)
    {
      const Eigen::Vector2d a = uv.row(out.cornerSector[3 * f]).transpose();
      const Eigen::Vector2d b = uv.row(out.cornerSector[3 * f + 1]).transpose();
      const Eigen::Vector2d c = uv.row(out.cornerSector[3 * f + 2]).transpose();
      const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      if (!(area > 0))
      {
        flipped.push_back(f);
      }
    }
    return flipped;
  };

  // ---- the continuous minimizer ----
  auto start = std::chrono::steady_clock::now();
  const bool round = options.roundingMode != RoundingMode::None && numInteger > 0;
  const bool greedy = round && options.roundingMode == RoundingMode::Greedy;
  SpdSolver<double> solver;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd S; // the integer block of H^-1 (Greedy)
  if (n > 0)
  {
    solver.compute(H);
    if (solver.info() != Eigen::Success)
    {
      throw std::runtime_error("the Poisson system could not be factored");
    }
    x = solver.solve(Eigen::VectorXd(P.transpose() * (D.transpose() * rhs)));
    if (greedy)
    {
      S.resize(numInteger, numInteger);
      constexpr int Block = 64; // right-hand sides per solve (bounded memory)
      for (int c = 0; c < numInteger; c += Block)
      {
        const int k = std::min(Block, numInteger - c);
        Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, k);
        for (int j = 0; j < k; ++j)
        {
          E(numReal + c + j, j) = 1.0;
        }
        S.middleCols(c, k) = Eigen::MatrixXd(solver.solve(E)).bottomRows(numInteger);
      }
    }
  }
  out.solveSeconds.push_back(seconds(start));
  if (fromQuadCount && n > 0)
  {
    // The constraints are homogeneous, so the minimizer is linear in the right-hand side
    // (1 / edgeLength); H and S do not depend on it.
    const Eigen::MatrixX2d uv = uvOf(x);
    double cells = 0.0;
    for (int f = 0; f < nF; ++f)
    {
      const Eigen::Vector2d a = uv.row(out.cornerSector[3 * f]).transpose();
      const Eigen::Vector2d b = uv.row(out.cornerSector[3 * f + 1]).transpose();
      const Eigen::Vector2d c = uv.row(out.cornerSector[3 * f + 2]).transpose();
      cells += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    }
    if (cells > 0 && std::isfinite(cells))
    {
      // bounded: folds cancel area, and a badly folded map must not ask for 100x the quads
      const double factor = std::clamp(std::sqrt(options.targetQuadCount / cells), 0.5, 4.0);
      x *= factor;
      rhs *= factor;
      energyNorm *= factor * factor;
      out.edgeLength /= factor;
    }
  }
  out.energyContinuous = energyOf(x);
  out.flippedContinuous = static_cast<int>(flippedFaces(uvOf(x)).size());

  // ---- rounding: the integer unknowns' values are Gaussian given the ones fixed so far; fixing
  // one conditions the others exactly (x -= S_j (x_j - c_j) / S_jj, S -= S_j S_j^T / S_jj with
  // S the integer block of H^-1), which is the re-solve with the same factorization ----
  Eigen::VectorXd fixedValues;
  const Eigen::MatrixXd S0 = S;
  if (round)
  {
    Eigen::VectorXd xi = x.tail(numInteger);
    // Two branch points of one triangle must not land on the same grid point (their triangles
    // would collapse): the differences of their (u, v), in integer unknowns.
    struct Pair
    {
      Expr du, dv;
    };
    std::vector<Pair> pairs;
    std::vector<std::vector<int>> pairsOf(numInteger);
    if (options.pureQuads)
    {
      auto local = [&](const Expr& a, const Expr& b) {
        Expr d;
        for (const auto& [e, sign] : { std::pair<const Expr*, double>{ &a, 1.0 }, { &b, -1.0 } })
        {
          for (const auto& t : *e)
          {
            if (t.first < numReal)
            {
              d.emplace_back(t.first, sign * t.second);
              continue;
            }
            for (const auto& c : symbolColumns[t.first - numReal])
            {
              d.emplace_back(c.first, sign * t.second * c.second);
            }
          }
        }
        normalize(d);
        for (auto& t : d)
        {
          t.first -= numReal;
        }
        return d;
      };
      for (int f = 0; f < nF; ++f)
      {
        for (int k = 0; k < 3; ++k)
        {
          const int sa = out.cornerSector[3 * f + k];
          const int sb = out.cornerSector[3 * f + (k + 1) % 3];
          if (!branch[F(f, k)] || !branch[F(f, (k + 1) % 3)])
          {
            continue;
          }
          Pair pair{ local(sectorExpr[2 * sa], sectorExpr[2 * sb]),
            local(sectorExpr[2 * sa + 1], sectorExpr[2 * sb + 1]) };
          bool integral = true;
          for (const Expr* e : { &pair.du, &pair.dv })
          {
            for (const auto& t : *e)
            {
              integral = integral && t.first >= 0;
            }
          }
          if (integral)
          {
            for (const Expr* e : { &pair.du, &pair.dv })
            {
              for (const auto& t : *e)
              {
                pairsOf[t.first].push_back(static_cast<int>(pairs.size()));
              }
            }
            pairs.push_back(std::move(pair));
          }
        }
      }
    }
    std::vector<char> fixed(numInteger, 0);
    // Fixing j to `value`: does it complete a pair at the same point?
    auto collides = [&](int j, double value) {
      for (const int p : pairsOf[j])
      {
        bool complete = true;
        double du = 0.0;
        double dv = 0.0;
        for (int c = 0; c < 2; ++c)
        {
          for (const auto& t : c == 0 ? pairs[p].du : pairs[p].dv)
          {
            complete = complete && (fixed[t.first] || t.first == j);
            (c == 0 ? du : dv) += t.second * (t.first == j ? value : fixedValues[t.first]);
          }
        }
        if (complete && std::abs(du) < 0.5 && std::abs(dv) < 0.5)
        {
          return true;
        }
      }
      return false;
    };
    // The nearest integer, or the next nearest when the nearest collapses a pair.
    auto choose = [&](int j, double x) {
      const double nearest = std::round(x);
      if (!collides(j, nearest))
      {
        return nearest;
      }
      ++out.separatedBranchPoints;
      return x >= nearest ? nearest + 1.0 : nearest - 1.0;
    };
    fixedValues = xi.array().round().matrix();
    for (int step = 0; step < numInteger; ++step)
    {
      int best = step; // Simple: in order, each from the continuous minimizer
      if (greedy)
      {
        double bestDistance = 2.0;
        for (int j = 0; j < numInteger; ++j)
        {
          const double distance = std::abs(xi[j] - std::round(xi[j]));
          if (!fixed[j] && distance < bestDistance)
          {
            best = j;
            bestDistance = distance;
          }
        }
      }
      const double value = choose(best, xi[best]);
      fixed[best] = 1;
      fixedValues[best] = value;
      if (greedy)
      {
        const double pivot = S(best, best);
        if (pivot > 1e-14 * std::max(1.0, S.diagonal().cwiseAbs().maxCoeff()))
        {
          const Eigen::VectorXd col = S.col(best);
          xi -= col * ((xi[best] - value) / pivot);
          S.noalias() -= col * (col.transpose() / pivot);
        }
        xi[best] = value;
      }
    }
  }

  // ---- the real unknowns with the integers fixed, then flipped triangles untangled ----
  // Simple rounding: the real unknowns solved again with the integers fixed (H's real block).
  auto solveFixed = [&]() {
    const auto started = std::chrono::steady_clock::now();
    Eigen::VectorXd result(n);
    result.tail(numInteger) = fixedValues;
    if (numReal > 0)
    {
      const SparseMatrix Dreal = D.leftCols(numReal); // the real symbols are the real columns
      Eigen::VectorXd integers = Eigen::VectorXd::Zero(n);
      integers.tail(numInteger) = fixedValues;
      const Eigen::VectorXd r = rhs - D * (P * integers);
      const SparseMatrix Hreal = H.topLeftCorner(numReal, numReal);
      result.head(numReal) =
        solveSpd(Hreal, Eigen::MatrixXd(Dreal.transpose() * r), "Poisson").col(0);
    }
    out.solveSeconds.push_back(seconds(started));
    return result;
  };
  if (greedy)
  {
    // the minimizer with x_I = c: x0 - H^-1 E_I S0^-1 (x0_I - c), one more solve
    const auto started = std::chrono::steady_clock::now();
    Eigen::VectorXd shift = Eigen::VectorXd::Zero(n);
    shift.tail(numInteger) = S0.ldlt().solve(Eigen::VectorXd(x.tail(numInteger) - fixedValues));
    x -= solver.solve(shift);
    x.tail(numInteger) = fixedValues;
    out.solveSeconds.push_back(seconds(started));
  }
  else if (round)
  {
    x = solveFixed();
  }
  out.energyRounded = energyOf(x);
  std::vector<int> flipped = flippedFaces(uvOf(x));
  out.flippedRounded = static_cast<int>(flipped.size());
  // Winding: around every inner point the map's angles must add up to 2 pi (1 - index). A
  // least-squares map puts the extra quarter turn of a negative cone into one triangle, which
  // flips; untangled the wrong way, the fan closes up into 90 degrees (index +3/4) next to a
  // point wound twice. Such fans are laid out again before they are untangled.
  auto wrongWindings = [&](const Eigen::MatrixX2d& uv) {
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(nV);
    for (int f = 0; f < nF; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Eigen::Vector2d z = uv.row(out.cornerSector[3 * f + k]).transpose();
        const Eigen::Vector2d a = uv.row(out.cornerSector[3 * f + (k + 1) % 3]).transpose() - z;
        const Eigen::Vector2d b = uv.row(out.cornerSector[3 * f + (k + 2) % 3]).transpose() - z;
        sum[F(f, k)] += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      }
    }
    std::vector<int> wrong;
    for (int p = 0; p < nV; ++p)
    {
      if (!topo.boundaryVertex[p] && topo.ringOrdered[p] &&
        std::abs(sum[p] - 2 * Pi * (1 - ft.index[p])) > 1e-3)
      {
        wrong.push_back(p);
      }
    }
    return wrong;
  };
  // Lays the fan of p out again: ring points at their distance in grid units, the corner angles
  // at p the triangle's own scaled to add up to 2 pi (1 - index), turning with the charts across
  // cut edges. A ring point moves when its (u, v) are two real unknowns (a 2 x 2 system).
  auto layOut = [&](int p, Eigen::VectorXd& xs, std::vector<char>& frozen) {
    const int begin = topo.ringOffsets[p];
    const int n = topo.ringOffsets[p + 1] - begin;
    double total = 0.0;
    for (int i = 0; i < n; ++i)
    {
      const int f = topo.ringFaces[begin + i];
      const int k = MeshTopology::cornerOf(F, f, p);
      const Eigen::Vector3d a = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      const Eigen::Vector3d b = V.row(F(f, (k + 2) % 3)) - V.row(F(f, k));
      total += std::atan2(a.cross(b).norm(), a.dot(b));
    }
    const double stretch = 2 * Pi * (1 - ft.index[p]) / total;
    if (!(stretch > 0))
    {
      return; // index 1 or more: no fan can close up around it
    }
    auto value = [&](int sector, int c) {
      double v = 0.0;
      for (const auto& t : sectorExpr[2 * sector + c])
      {
        v += t.second * xs[t.first];
      }
      return v;
    };
    // the first face's edge from p to its next corner keeps its direction
    int f = topo.ringFaces[begin];
    int k = MeshTopology::cornerOf(F, f, p);
    const int s0 = out.cornerSector[3 * f + k];
    const int s1 = out.cornerSector[3 * f + (k + 1) % 3];
    double direction = std::atan2(value(s1, 1) - value(s0, 1), value(s1, 0) - value(s0, 0));
    for (int i = 0; i < n; ++i)
    {
      f = topo.ringFaces[begin + i];
      k = MeshTopology::cornerOf(F, f, p);
      const int cone = out.cornerSector[3 * f + k];
      const Eigen::Vector3d a = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      const Eigen::Vector3d b = V.row(F(f, (k + 2) % 3)) - V.row(F(f, k));
      direction += stretch * std::atan2(a.cross(b).norm(), a.dot(b));
      // place the face's other ring point (corner k + 2) in this face's chart
      const int ring = out.cornerSector[3 * f + (k + 2) % 3];
      const double radius = b.norm() / out.edgeLength;
      const Eigen::Vector2d target(value(cone, 0) + radius * std::cos(direction),
        value(cone, 1) + radius * std::sin(direction));
      int sym[2] = { -1, -1 };
      Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
      Eigen::Vector2d rest = target;
      bool movable = true;
      for (int c = 0; c < 2; ++c)
      {
        for (const auto& t : sectorExpr[2 * ring + c])
        {
          if (t.first >= numReal)
          {
            rest[c] -= t.second * xs[t.first];
            continue;
          }
          int slot = sym[0] == t.first ? 0 : (sym[1] == t.first ? 1 : (sym[0] < 0 ? 0 : 1));
          if (sym[slot] >= 0 && sym[slot] != t.first)
          {
            movable = false;
          }
          sym[slot] = t.first;
          M(c, slot) += t.second;
        }
      }
      if (movable && sym[0] >= 0 && sym[1] >= 0 && std::abs(M.determinant()) > 1e-9)
      {
        const Eigen::Vector2d solved = M.inverse() * rest;
        xs[sym[0]] = solved[0];
        xs[sym[1]] = solved[1];
        frozen[sym[0]] = frozen[sym[1]] = 1;
      }
      else if (movable && sym[0] >= 0 && sym[1] < 0 && M.col(0).squaredNorm() > 1e-18)
      {
        // one coordinate on a boundary line: move along it
        xs[sym[0]] = M.col(0).dot(rest) / M.col(0).squaredNorm();
        frozen[sym[0]] = 1;
      }
      // into the next face's chart: the edge p -> ring turns with the chart across the edge
      const int g = topo.faceNeighbors(f, (k + 2) % 3);
      if (g >= 0)
      {
        direction += out.combedMatching(f, (k + 2) % 3) * Pi / 2;
      }
    }
  };
  std::vector<int> wrong = wrongWindings(uvOf(x));
  if ((!flipped.empty() || !wrong.empty()) && options.maximumUntangleRounds > 0)
  {
    const auto started = std::chrono::steady_clock::now();
    const Eigen::SparseMatrix<double, Eigen::RowMajor> Dr = D;
    Eigen::VectorXd sqrtArea = Eigen::VectorXd::Zero(nF);
    for (int f = 0; f < nF; ++f)
    {
      sqrtArea[f] = std::sqrt(std::max(0.0, faceArea[f]));
    }
    // in symbols; only the real ones move, and they are the real columns
    const Untangler untangler{ Dr, D, sqrtArea, out.edgeLength, numReal };
    // kept in case the repair leaves more flipped triangles and wrong fans than it found
    const Eigen::VectorXd before = x;
    const std::vector<int> flippedBefore = flipped, wrongBefore = wrong;
    const std::size_t defectsBefore = flipped.size() + wrong.size();
    // The state after the first attempt has laid out and held its fans, before everything
    // untangles: where the held run (below) starts from.
    struct Snapshot
    {
      Eigen::VectorXd xs, xr;
      std::vector<int> fl;
      std::vector<char> frozen;
      bool taken = false;
    } firstHeld;
    auto untangleAll = [&](Eigen::VectorXd& xs, Eigen::VectorXd& xr, std::vector<int>& fl,
                         const std::vector<char>& frozen, int& regions) {
      for (int rings = 2; rings <= 16 && !fl.empty(); rings *= 2)
      {
        ++regions;
        untangler.run(topo, F, fl, rings, options.maximumUntangleRounds, xs, frozen);
        xr.head(numReal) = xs.head(numReal);
        fl = flippedFaces(uvOf(xr));
      }
    };
    // Three attempts: the fans wound the wrong way are laid out again (cones first, then in
    // later attempts every point listed) and held while their surroundings untangle; then
    // everything untangles, those fans free again.
    Eigen::VectorXd xs = P * x;
    for (int attempt = 0; attempt < 3 && (!flipped.empty() || !wrong.empty()); ++attempt)
    {
      // cones first: a point wound twice is usually the neighbour of a cone closed up into
      // 90 degrees, and comes right with it
      std::stable_sort(wrong.begin(), wrong.end(),
        [&](int a, int b) { return (ft.layerShift[a] != 0) > (ft.layerShift[b] != 0); });
      std::vector<char> frozen(xs.size(), 0);
      for (const int p : wrong)
      {
        if (ft.layerShift[p] != 0 || attempt > 0)
        {
          layOut(p, xs, frozen);
        }
      }
      x.head(numReal) = xs.head(numReal);
      // the new fans held first, so that their winding stays, then everything
      if (!wrong.empty())
      {
        flipped = flippedFaces(uvOf(x));
        for (int rings = 2; rings <= 8 && !flipped.empty(); rings *= 2)
        {
          untangler.run(topo, F, flipped, rings, options.maximumUntangleRounds, xs, frozen);
          x.head(numReal) = xs.head(numReal);
          flipped = flippedFaces(uvOf(x));
        }
      }
      if (attempt == 0)
      {
        firstHeld = { xs, x, flipped, frozen, true };
      }
      untangleAll(xs, x, flipped, std::vector<char>(), out.untangleRegions);
      wrong = wrongWindings(uvOf(x));
    }
    const std::size_t left = flipped.size() + wrong.size();
    // (with no cone among the fans wound the wrong way nothing would be held: the held run would
    // repeat the first attempt)
    const bool cones = std::any_of(
      wrongBefore.begin(), wrongBefore.end(), [&](int p) { return ft.layerShift[p] != 0; });
    if (left > 0 && left <= 8 && cones && firstHeld.taken)
    {
      // Freed, a fan laid out again can close up once more as its surroundings untangle (on
      // fine meshes a cone's fan is small against a grid cell); held, it cannot, though its
      // surroundings may then keep folds. The run with fewer defects wins. Only for a handful
      // left: where many are, holding their fans blocks the untangling (spot refined 64 times:
      // 20 wrong fans, and 50 s more for nothing).
      Eigen::VectorXd& held = firstHeld.xr;
      std::vector<int>& heldFlipped = firstHeld.fl;
      int heldRegions = 0;
      untangleAll(firstHeld.xs, held, heldFlipped, firstHeld.frozen, heldRegions);
      const std::vector<int> heldWrong = wrongWindings(uvOf(held));
      if (heldFlipped.size() + heldWrong.size() < flipped.size() + wrong.size())
      {
        x = held;
        flipped = heldFlipped;
        wrong = heldWrong;
        out.untangleRegions = heldRegions;
      }
    }
    if (flipped.size() + wrong.size() > defectsBefore)
    {
      x = before;
      flipped = flippedBefore;
      wrong = wrongBefore;
    }
    out.untangleSeconds = seconds(started);
  }
  out.wrongWindings = static_cast<int>(wrong.size());
  out.flipped = static_cast<int>(flipped.size());
  out.energyFinal = energyOf(x);

  // ---- the map per corner, and how well it meets the grid ----
  out.sectorUV = uvOf(x);
  out.cornerUV.resize(nF, 6);
  for (int f = 0; f < nF; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      out.cornerUV.block<1, 2>(f, 2 * k) = out.sectorUV.row(out.cornerSector[3 * f + k]);
    }
  }
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (!onCut[e])
    {
      continue;
    }
    const int c0 = topo.edgeCorners(e, 0);
    const int f = c0 / 3;
    const int g = topo.edgeCorners(e, 1) / 3;
    const int r = out.combedMatching(f, c0 % 3);
    for (int end = 0; end < 2; ++end)
    {
      const int p = topo.edges(e, end);
      const Eigen::Vector2d a = out.sectorUV.row(sectorOf(f, p)).transpose();
      const Eigen::Vector2d b = out.sectorUV.row(sectorOf(g, p)).transpose();
      Eigen::Vector2d rotated = a;
      for (int q = 0; q < r; ++q)
      {
        rotated = Eigen::Vector2d(-rotated.y(), rotated.x());
      }
      const Eigen::Vector2d t = b - rotated;
      out.maxSeamError =
        std::max(out.maxSeamError, (t - t.array().round().matrix()).cwiseAbs().maxCoeff());
    }
  }
  for (int s = 0; s < nS; ++s)
  {
    const int p = out.sectorPoint[s];
    if (branch[p])
    {
      const Eigen::RowVector2d uv = out.sectorUV.row(s);
      if ((uv - uv.array().round().matrix()).cwiseAbs().maxCoeff() < 1e-6)
      {
        branch[p] = 0; // count each point once
        ++out.branchPointsOnGrid;
      }
    }
  }
  return out;
}

}
