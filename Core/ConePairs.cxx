// ConePairs.cxx: cone pairs for quads of even size.
#include "ConePairs.h"

#include "BranchPointSearch.h"
#include "Parallel.h"
#include "SparseSolver.h"
#include "SurfaceDisks.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <queue>
#include <unordered_map>

namespace quadcover
{
namespace
{
using namespace branchsearch;
constexpr double Infinity = std::numeric_limits<double>::infinity();
/// Dipoles a round lists (at the faces of steepest slope, one of each length per face), and how
/// many of them (the best to first order) it measures; a dipole's cones are one of these many
/// grid edges apart (the longer one evens a wide slope, a bump's or a tube's, with one pair where
/// the shorter needs two or three).
constexpr int CandidateDipoles = 6;
constexpr std::size_t MeasuredDipoles = 3;
constexpr double DipoleLengths[] = { 3.0, 6.0 };
/// A move of one of the field's own singularities is kept where it gains this many times what a
/// new pair must: it costs no irregular vertex, but it takes the cone away from where the
/// smoothest field put it, which the model of the scale does not see (with the gain of a pair,
/// the shared meshes' median angle RSD rose 7.4 -> 7.6%).
constexpr double MoveGain = 2.0;

/// Edge-path distances over the mesh's edges.
class EdgeDistances
{
public:
  EdgeDistances(const Eigen::MatrixX3d& V, const MeshTopology& topo)
    : offsets_(topo.numVertices + 1, 0)
    , scratch_(topo.numVertices, Infinity)
  {
    for (int e = 0; e < topo.numEdges(); ++e)
    {
      ++offsets_[topo.edges(e, 0) + 1];
      ++offsets_[topo.edges(e, 1) + 1];
    }
    for (int v = 0; v < topo.numVertices; ++v)
    {
      offsets_[v + 1] += offsets_[v];
    }
    neighbours_.resize(offsets_.back());
    std::vector<int> fill(offsets_.begin(), offsets_.end() - 1);
    for (int e = 0; e < topo.numEdges(); ++e)
    {
      const int a = topo.edges(e, 0), b = topo.edges(e, 1);
      const double length = (V.row(a) - V.row(b)).norm();
      neighbours_[fill[a]++] = { b, length };
      neighbours_[fill[b]++] = { a, length };
    }
  }

  /// Lowers `distance` to the distance from the sources, where that is less than `limit`.
  void spread(const std::vector<int>& sources, double limit, std::vector<double>& distance) const
  {
    run(sources, limit, distance, nullptr);
  }

  /// The points within `limit` of a, a first.
  std::vector<int> within(int a, double limit) const
  {
    std::vector<int> list;
    run({ a }, limit, scratch_, &list);
    for (const int v : list)
    {
      scratch_[v] = Infinity;
    }
    return list;
  }

private:
  /// Dijkstra from the sources within `limit`, lowering `distance`; each point settled is listed
  /// in `settled` if given.
  void run(const std::vector<int>& sources, double limit, std::vector<double>& distance,
    std::vector<int>* settled) const
  {
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (const int s : sources)
    {
      distance[s] = 0.0;
      queue.push({ 0.0, s });
    }
    while (!queue.empty())
    {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > distance[v])
      {
        continue;
      }
      if (settled)
      {
        settled->push_back(v);
      }
      for (int j = offsets_[v]; j < offsets_[v + 1]; ++j)
      {
        const auto [w, length] = neighbours_[j];
        const double nd = d + length;
        if (nd < distance[w] && nd < limit)
        {
          distance[w] = nd;
          queue.push({ nd, w });
        }
      }
    }
  }

  std::vector<int> offsets_;
  std::vector<std::pair<int, double>> neighbours_;
  mutable std::vector<double> scratch_; ///< all infinite between calls of within
};

/// The gradient of the linear interpolation of u over triangle f (0 for a degenerate one).
Eigen::Vector3d gradient(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int f, const Eigen::VectorXd& u)
{
  const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double twiceArea2 = n.squaredNorm();
  if (!(twiceArea2 > 0))
  {
    return Eigen::Vector3d::Zero();
  }
  // sum of u_i times n x (the edge opposite i), over |n|^2
  return (u[F(f, 0)] * n.cross(c - b) + u[F(f, 1)] * n.cross(a - c) + u[F(f, 2)] * n.cross(b - a)) /
    twiceArea2;
}

/// The listed point nearest to p, -1 for none.
int nearest(const Eigen::MatrixX3d& V, const std::vector<int>& points, const Eigen::Vector3d& p)
{
  int best = -1;
  double distance = Infinity;
  for (const int v : points)
  {
    const double d = (V.row(v).transpose() - p).squaredNorm();
    if (d < distance)
    {
      distance = d;
      best = v;
    }
  }
  return best;
}

/// The cotangent Laplacian (triangles of zero area left out) with a thousandth of a millionth of
/// its mean diagonal added, 1 on the diagonal of unreferenced points; and each point's area.
Eigen::SparseMatrix<double> cotangentLaplacian(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, Eigen::VectorXd& area)
{
  const int n = static_cast<int>(V.rows());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * F.rows() + n);
  area.setZero(n);
  for (int f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int i = F(f, k), j = F(f, (k + 1) % 3), o = F(f, (k + 2) % 3);
      const Eigen::Vector3d a = V.row(i) - V.row(o), b = V.row(j) - V.row(o);
      const double cross = a.cross(b).norm();
      const double cot = cross > 0 ? a.dot(b) / cross : 0.0;
      entries.emplace_back(i, i, 0.5 * cot);
      entries.emplace_back(j, j, 0.5 * cot);
      entries.emplace_back(i, j, -0.5 * cot);
      entries.emplace_back(j, i, -0.5 * cot);
      area[i] += cross / 6.0;
    }
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  const double shift = 1e-9 * std::max(L.diagonal().cwiseAbs().mean(), 1e-300);
  for (int v = 0; v < n; ++v)
  {
    L.coeffRef(v, v) += area[v] > 0 ? shift : 1.0;
  }
  return L;
}

/// The log scale seen at the grid's scale, and how cones change it: u~ = S L^-1 (charges), with
/// S = D^-1 M the diffusion for a time of one grid edge squared (D = M + h^2 L), which takes out
/// the log peak of a cone below the grid's scale (the map's quads do not follow it there).
class ScaleModel
{
public:
  /// The two factorizations run at once when threads (0: defaultThreadCount()) is above 1.
  ScaleModel(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
    double h, int threads)
    : topo_(topo)
    , laplacian_(Factorization::Simplicial)
    , diffusion_(Factorization::Simplicial)
  {
    const Eigen::SparseMatrix<double> L = cotangentLaplacian(V, F, area_);
    Eigen::SparseMatrix<double> D = h * h * L;
    for (int v = 0; v < topo.numVertices; ++v)
    {
      D.coeffRef(v, v) += area_[v];
    }
    runBoth([&]() { laplacian_.compute(L); }, [&]() { diffusion_.compute(D); }, threads);
    ok_ = laplacian_.info() == Eigen::Success && diffusion_.info() == Eigen::Success;
    for (int v = 0; v < topo.numVertices; ++v)
    {
      totalArea_ += area_[v];
    }
  }

  bool ok() const { return ok_; }
  double totalArea() const { return totalArea_; }
  const Eigen::VectorXd& area() const { return area_; }

  /// u~ of the given charges (curvature, each point's sum zero per component); of each column
  /// of them, solved at once (one pass over each factor for all). Several threads may call it
  /// at once.
  Eigen::MatrixXd response(const Eigen::MatrixXd& charges) const
  {
    const Eigen::MatrixXd u = laplacian_.solveColumnsConcurrently(charges);
    return diffusion_.solveColumnsConcurrently(Eigen::MatrixXd(area_.asDiagonal() * u));
  }

  /// u less each component's area-weighted mean.
  Eigen::VectorXd centred(const Eigen::VectorXd& u) const
  {
    const int nc = topo_.numComponents();
    std::vector<double> sum(nc, 0.0), weight(nc, 0.0);
    for (int v = 0; v < topo_.numVertices; ++v)
    {
      const int c = topo_.vertexComponent[v];
      if (c >= 0)
      {
        sum[c] += area_[v] * u[v];
        weight[c] += area_[v];
      }
    }
    Eigen::VectorXd r = Eigen::VectorXd::Zero(u.size());
    for (int v = 0; v < topo_.numVertices; ++v)
    {
      const int c = topo_.vertexComponent[v];
      r[v] = c >= 0 && weight[c] > 0 ? u[v] - sum[c] / weight[c] : 0.0;
    }
    return r;
  }

  /// The area-weighted variance of u about each component's mean.
  double variance(const Eigen::VectorXd& u) const
  {
    const Eigen::VectorXd r = centred(u);
    return totalArea_ > 0 ? r.dot(area_.cwiseProduct(r)) / totalArea_ : 0.0;
  }

  /// Per point x, what a unit charge at x adds to the variance of u to first order, over 2: with
  /// r = u less its means, <r, S L^-1 e_x>_M / total area = (L^-1 M D^-1 M r)_x / total area
  /// (L, D and M symmetric).
  Eigen::VectorXd firstOrder(const Eigen::VectorXd& u) const
  {
    const Eigen::VectorXd r = centred(u);
    const Eigen::VectorXd smoothed = diffusion_.solve(Eigen::VectorXd(area_.cwiseProduct(r)));
    return laplacian_.solve(Eigen::VectorXd(area_.cwiseProduct(smoothed))) /
      std::max(totalArea_, 1e-300);
  }

private:
  const MeshTopology& topo_;
  Eigen::VectorXd area_;
  double totalArea_ = 0.0;
  SpdSolver<double> laplacian_, diffusion_;
  bool ok_ = false;
};

/// A +1/4 cone at `plus` and a -1/4 at `minus`, and what it lowers the variance by.
struct Dipole
{
  int plus, minus;
  double gain;
  int from = -1; ///< the singularity a move takes away (plus or minus), -1 for a new pair
};

/// The points within a fixed distance of each point asked, each list searched once (the moves'
/// reach is the same every round: armadillo's 150 quarters searched again in each of its nine
/// rounds took a fifth of the cone pairs' time).
class Reach
{
public:
  Reach(const EdgeDistances& distances, double limit)
    : distances_(distances)
    , limit_(limit)
  {}

  /// The points within the limit of a, a first (EdgeDistances::within).
  const std::vector<int>& of(int a)
  {
    auto found = lists_.find(a);
    if (found == lists_.end())
    {
      found = lists_.emplace(a, distances_.within(a, limit_)).first;
    }
    return found->second;
  }

private:
  const EdgeDistances& distances_;
  const double limit_;
  std::unordered_map<int, std::vector<int>> lists_;
};

/// Moves of the field's quarter singularities down the slope of w: for each inner quarter s (q[s]
/// = +-1) not `pinned`, the free point t within `reach` of it where the move gains most to first
/// order (a +1/4 from s to t is a dipole +1/4 at t, -1/4 at s).
std::vector<Dipole> movesDownTheSlope(const Eigen::VectorXd& w, const std::vector<int>& q,
  const std::vector<double>& blocked, const std::vector<char>& pinned, double separation,
  Reach& reach)
{
  std::vector<Dipole> list;
  for (int v = 0; v < static_cast<int>(q.size()); ++v)
  {
    if (std::abs(q[v]) != 1 || pinned[v])
    {
      continue;
    }
    Dipole best{ -1, -1, 0.0, v };
    for (const int t : reach.of(v))
    {
      const double gain = q[v] > 0 ? -Pi * (w[t] - w[v]) : -Pi * (w[v] - w[t]);
      if (!(blocked[t] < separation) && !pinned[t] && gain > best.gain)
      {
        best = q[v] > 0 ? Dipole{ t, v, gain, v } : Dipole{ v, t, gain, v };
      }
    }
    if (best.plus >= 0)
    {
      list.push_back(best);
    }
  }
  return list;
}

/// Dipoles across the steepest slopes of w (firstOrder), until `count` are listed (or one more:
/// up to one of each length per face): at the faces where it changes fastest (their points free,
/// each at least `separation` from the others), for each length in `apart` (grid edges), the +1/4
/// that far down the slope from the -1/4; gain to first order.
std::vector<Dipole> dipolesAcrossSlopes(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const EdgeDistances& distances, const Eigen::VectorXd& w, const std::vector<double>& blocked,
  double separation, const std::vector<double>& apart, double h, int count)
{
  const auto free = [&](int v) { return !(blocked[v] < separation); };
  std::vector<std::pair<double, int>> slopes;
  for (int f = 0; f < F.rows(); ++f)
  {
    if (free(F(f, 0)) && free(F(f, 1)) && free(F(f, 2)))
    {
      const double slope = gradient(V, F, f, w).norm();
      if (std::isfinite(slope) && slope > 0)
      {
        slopes.emplace_back(-slope, f);
      }
    }
  }
  // in order of steepness: the steepest few hundred sorted first, the rest only when those run
  // out (the faces near one taken are skipped, and on a fine mesh the steepest hundreds may all
  // lie around two or three places)
  std::vector<Dipole> list;
  std::vector<char> taken(V.rows(), 0);
  const auto first = slopes.begin() + std::min<std::size_t>(64 * count, slopes.size());
  std::partial_sort(slopes.begin(), first, slopes.end());
  for (auto it = slopes.begin(); it != slopes.end() && static_cast<int>(list.size()) < count; ++it)
  {
    if (it == first)
    {
      std::sort(it, slopes.end());
    }
    const int f = it->second;
    if (taken[F(f, 0)] || taken[F(f, 1)] || taken[F(f, 2)])
    {
      continue;
    }
    const Eigen::Vector3d centre =
      (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))).transpose() / 3.0;
    const Eigen::Vector3d down = -gradient(V, F, f, w).normalized();
    for (const double length : apart)
    {
      // within the length along the surface, so as not to reach across a thin part
      const std::vector<int> around = distances.within(F(f, 0), length * h);
      const int a = nearest(V, around, centre + 0.5 * length * h * down);
      const int b = nearest(V, around, centre - 0.5 * length * h * down);
      if (a >= 0 && b >= 0 && a != b && free(a) && free(b))
      {
        list.push_back({ a, b, -Pi * (w[a] - w[b]) });
      }
    }
    for (const int x : distances.within(F(f, 0), separation))
    {
      taken[x] = 1;
    }
  }
  return list;
}

/// Per point, 1 within `radius` of an edge flagged in `edges` (#E or empty).
std::vector<char> nearEdges(const EdgeDistances& distances, const MeshTopology& topo,
  const std::vector<char>& edges, double radius)
{
  std::vector<int> sources;
  for (int e = 0; e < static_cast<int>(edges.size()) && e < topo.numEdges(); ++e)
  {
    if (edges[e])
    {
      sources.push_back(topo.edges(e, 0));
      sources.push_back(topo.edges(e, 1));
    }
  }
  std::vector<double> distance(topo.numVertices, Infinity);
  distances.spread(sources, radius, distance);
  std::vector<char> near(topo.numVertices, 0);
  for (int v = 0; v < topo.numVertices; ++v)
  {
    near[v] = distance[v] < radius;
  }
  return near;
}

/// Whether the shortest path over regular inner points from a reaches b (edge lengths; no
/// residual wrapped past +-pi with delta quarter turns, see findMergeTarget); the path is the
/// search's.
bool findPathTo(Optimizer& o, int a, int b, int delta)
{
  PathSearch& S = o.search;
  S.begin(a);
  int visited = 0;
  while (!S.queue.empty() && visited < o.options.maximumSearchSize)
  {
    const auto [d, u] = S.queue.top();
    S.queue.pop();
    if (d > S.dist[u])
    {
      continue;
    }
    ++visited;
    if (u == b)
    {
      return true;
    }
    if (u != a && o.q[u] != 0)
    {
      continue; // paths through another singularity would disturb it
    }
    for (int i = 0; i < static_cast<int>(o.steps[u].size()); ++i)
    {
      const Step& s = o.steps[u][i];
      double added = 0.0;
      if (o.stepCost(s, delta, added))
      {
        S.relax(u, i, s.to, d + o.geometry.edgeLength(s.g, s.kg));
      }
    }
  }
  return false;
}
}

ConePairs conePairsForEvenScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::VectorXd& defect, const Eigen::VectorXd& index,
  double edgeLength, const std::vector<char>& sharp, const ConePairOptions& options)
{
  ConePairs result;
  const int n = topo.numVertices;
  if (!(options.minimumGain > 0) || options.maximumPairs <= 0 || !(edgeLength > 0) || n == 0)
  {
    return result;
  }
  const double h = edgeLength, separation = options.separation * edgeLength;
  const ScaleModel model(V, F, topo, h, options.numberOfThreads);
  if (!model.ok())
  {
    return result;
  }
  Eigen::VectorXd charges(n);
  for (int v = 0; v < n; ++v)
  {
    charges[v] = model.area()[v] > 0 ? 2.0 * Pi * index[v] - defect[v] : 0.0;
  }
  Eigen::VectorXd u = model.response(charges).col(0);
  // points no new cone may take: near a singularity or the boundary, or where the ring is not a
  // disk
  const EdgeDistances distances(V, topo);
  std::vector<int> blocks;
  for (int v = 0; v < n; ++v)
  {
    if ((std::abs(index[v]) > 0.1 && !topo.boundaryVertex[v]) || topo.boundaryVertex[v] ||
      !topo.ringOrdered[v] || !(model.area()[v] > 0))
    {
      blocks.push_back(v);
    }
  }
  std::vector<double> blocked(n, Infinity);
  distances.spread(blocks, separation, blocked);
  // the singularities in quarter turns, as pairs and moves change them; those near a sharp edge
  // (and points there) pinned
  std::vector<int> q = quarterTurns(topo, index);
  const std::vector<char> pinned = nearEdges(distances, topo, sharp, separation);
  // the gain asked of a pair, as a lowered variance: minimumGain over the grid's cells
  const double minimumGain = options.minimumGain / std::max(model.totalArea() / (h * h), 1.0);
  double variance = model.variance(u);
  result.deviationBefore = std::sqrt(variance);
  // measures the dipoles (the variance each leaves alone), reading u and variance only
  using Measured = std::vector<std::pair<Dipole, Eigen::VectorXd>>;
  const auto measure = [&](const std::vector<Dipole>& dipoles) {
    const int m = static_cast<int>(dipoles.size());
    Eigen::MatrixXd charge = Eigen::MatrixXd::Zero(n, m);
    for (int i = 0; i < m; ++i)
    {
      charge(dipoles[i].plus, i) = Pi / 2;
      charge(dipoles[i].minus, i) = -Pi / 2;
    }
    const Eigen::MatrixXd responses = model.response(charge);
    Measured measured;
    for (int i = 0; i < m; ++i)
    {
      Eigen::VectorXd response = responses.col(i);
      const double gain = variance - model.variance(u + response);
      measured.push_back(
        { { dipoles[i].plus, dipoles[i].minus, gain, dipoles[i].from }, std::move(response) });
    }
    return measured;
  };
  // keeps the best measured, and each other one that still gains enough with those kept
  // before it and is not near them; returns how many it kept
  const auto keepMeasured = [&](Measured measured) {
    std::stable_sort(measured.begin(), measured.end(),
      [](const auto& a, const auto& b) { return a.first.gain > b.first.gain; });
    int kept = 0;
    for (auto& [dipole, response] : measured)
    {
      const int to = dipole.from == dipole.plus ? dipole.minus : dipole.plus;
      if (static_cast<int>(result.pairs.size()) >= options.maximumPairs ||
        (dipole.from < 0 && blocked[dipole.plus] < separation) ||
        (dipole.from < 0 && blocked[dipole.minus] < separation) ||
        (dipole.from >= 0 && (blocked[to] < separation || std::abs(q[dipole.from]) != 1)))
      {
        continue;
      }
      const double after = model.variance(u + response);
      if (!(variance - after >= (dipole.from >= 0 ? MoveGain : 1.0) * minimumGain))
      {
        continue;
      }
      u += response;
      variance = after;
      result.pairs.emplace_back(dipole.plus, dipole.minus);
      result.from.push_back(dipole.from);
      distances.spread({ dipole.plus, dipole.minus }, separation, blocked);
      if (dipole.from >= 0)
      {
        q[to] = q[dipole.from];
        q[dipole.from] = 0;
      }
      else
      {
        q[dipole.plus] = 1;
        q[dipole.minus] = -1;
      }
      ++kept;
    }
    return kept;
  };
  const std::vector<double> lengths(std::begin(DipoleLengths), std::end(DipoleLengths));
  Reach reach(distances, lengths.back() * h);
  while (static_cast<int>(result.pairs.size()) < options.maximumPairs)
  {
    const Eigen::VectorXd w = model.firstOrder(u);
    std::vector<Dipole> dipoles =
      dipolesAcrossSlopes(V, F, distances, w, blocked, separation, lengths, h, CandidateDipoles);
    const std::vector<Dipole> moves = movesDownTheSlope(w, q, blocked, pinned, separation, reach);
    dipoles.insert(dipoles.end(), moves.begin(), moves.end());
    std::sort(dipoles.begin(), dipoles.end(),
      [](const Dipole& a, const Dipole& b) { return a.gain > b.gain; });
    // the best few by the first order measured; the next few only if none of them is kept (a
    // long dipole that looks best to first order may overshoot where a short one would not),
    // while any left could be kept: a measured gain is the first order's less the variance of
    // the change, never more
    std::vector<char> canFollow(dipoles.size() + 1, 0);
    for (std::size_t i = dipoles.size(); i-- > 0;)
    {
      canFollow[i] = canFollow[i + 1] ||
        dipoles[i].gain >= (dipoles[i].from >= 0 ? MoveGain : 1.0) * minimumGain;
    }
    const auto batch = [&](std::size_t first) {
      const std::size_t last = std::min(dipoles.size(), first + MeasuredDipoles);
      return std::vector<Dipole>(dipoles.begin() + first, dipoles.begin() + last);
    };
    const auto follows = [&](std::size_t first) {
      return first < dipoles.size() && canFollow[first];
    };
    // the first few alone (mostly one is kept); after them, on two threads, two batches
    // measured at once, the second kept from only when the first keeps none (then u and the
    // variance it was measured against are unchanged: the same as one after the other)
    const bool twoAtOnce = threadCount(options.numberOfThreads) > 1;
    int kept = follows(0) ? keepMeasured(measure(batch(0))) : 0;
    for (std::size_t first = MeasuredDipoles; kept == 0 && follows(first);
         first += (twoAtOnce ? 2 : 1) * MeasuredDipoles)
    {
      const std::size_t second = first + MeasuredDipoles;
      Measured a, b;
      if (twoAtOnce && follows(second))
      {
        runBoth([&]() { a = measure(batch(first)); }, [&]() { b = measure(batch(second)); },
          options.numberOfThreads);
      }
      else
      {
        a = measure(batch(first));
      }
      kept = keepMeasured(std::move(a));
      if (kept == 0 && !b.empty())
      {
        kept = keepMeasured(std::move(b));
      }
    }
    if (kept == 0)
    {
      break;
    }
  }
  result.deviationAfter = std::sqrt(std::max(variance, 0.0));
  return result;
}

int addConePairs(const Eigen::MatrixX3i& F, const MeshTopology& topo, const FrameGeometry& geometry,
  const Eigen::MatrixX3d& frameU, FrameTopology& topology, const ConePairs& chosen,
  std::vector<char>& changedFaces, int& moved)
{
  moved = 0;
  changedFaces.assign(F.rows(), 0);
  if (chosen.pairs.empty() || geometry.edgeLength.rows() == 0)
  {
    return 0;
  }
  const BranchPointOptions options;
  Optimizer o(F, topo, geometry, frameU, topology, options);
  TwistCheck twist(o);
  DiskTest disk(F, topo, geometry.edgeLength);
  int added = 0;
  std::vector<char> skipped(topo.numVertices, 0);
  for (std::size_t i = 0; i < chosen.pairs.size(); ++i)
  {
    const auto [plus, minus] = chosen.pairs[i];
    const int from = i < chosen.from.size() ? chosen.from[i] : -1;
    // a new pair, or a move: a -1/4 at plus or a +1/4 at minus taken to the other point
    const bool pair = from < 0;
    const bool asChosen = pair ? o.q[plus] == 0 && o.q[minus] == 0
                               : (from == plus && o.q[plus] == -1 && o.q[minus] == 0) ||
        (from == minus && o.q[plus] == 0 && o.q[minus] == 1);
    if (skipped[plus] || skipped[minus] || !asChosen || topo.boundaryVertex[plus] ||
      topo.boundaryVertex[minus] || !findPathTo(o, plus, minus, 1))
    {
      skipped[plus] = skipped[minus] = 1;
      continue;
    }
    // with handles, only inside a disk around the path (see cancelClosePairs)
    if ((topo.components[topo.vertexComponent[plus]].genus != 0 &&
          !disk.ballIsDisk(plus, 2.0 * o.search.dist[minus])) ||
      !changeUntwisted(o, twist, plus, minus, 1, changedFaces))
    {
      skipped[plus] = skipped[minus] = 1;
      continue;
    }
    ++(pair ? added : moved);
  }
  if (added + moved > 0)
  {
    topology = evaluateMatchings(F, topo, geometry, frameU, topology.matching);
  }
  return added;
}

}
