#include "SurfaceSimplification.h"

#include "UnionFind.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

namespace quadcover
{

long long simplificationBudget(double quads, const SimplificationOptions& options)
{
  if (!(quads > 0.0))
  {
    return 0;
  }
  const double budget = std::max(static_cast<double>(options.minimumTriangleCount),
    static_cast<double>(options.trianglesPerQuad) * quads);
  return budget < 9e18 ? static_cast<long long>(std::ceil(budget)) : 0;
}

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Unqueued = std::numeric_limits<double>::infinity();

/// A symmetric 4x4 quadric of planes n.x + d = 0: x^T A x + 2 b.x + c.
struct Quadric
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double c = 0.0;

  void addPlane(const Eigen::Vector3d& n, double d, double weight)
  {
    A += weight * n * n.transpose();
    b += weight * d * n;
    c += weight * d * d;
  }
  Quadric& operator+=(const Quadric& q)
  {
    A += q.A;
    b += q.b;
    c += q.c;
    return *this;
  }
  double operator()(const Eigen::Vector3d& x) const
  {
    return std::max(0.0, x.dot(A * x) + 2.0 * b.dot(x) + c);
  }
};

/// 1 for an equilateral triangle, 0 for a degenerate one.
double quality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return squares > 0.0 ? 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / squares : 0.0;
}

/// The points in the order of a Morton curve through their bounding box (ties by index).
std::vector<int> spatialOrder(const Eigen::MatrixX3d& V)
{
  const Eigen::RowVector3d low = V.colwise().minCoeff(), high = V.colwise().maxCoeff();
  const double side = (high - low).maxCoeff();
  std::vector<std::pair<std::uint64_t, int>> keys(V.rows());
  for (Eigen::Index p = 0; p < V.rows(); ++p)
  {
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double t = side > 0.0 ? (V(p, axis) - low(axis)) / side : 0.0;
      const auto cell = static_cast<std::uint64_t>(std::min(std::max(t, 0.0), 1.0) * 2097151.0);
      for (int bit = 0; bit < 21; ++bit)
      {
        key |= ((cell >> bit) & 1u) << (3 * bit + axis);
      }
    }
    keys[p] = { key, static_cast<int>(p) };
  }
  std::sort(keys.begin(), keys.end());
  std::vector<int> order(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    order[i] = keys[i].second;
  }
  return order;
}

// row-major: a point's or a triangle's coordinates in one cache line
using RowPoints = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using RowTriangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// The mesh being simplified, with what each collapse needs.
class Simplifier
{
public:
  Simplifier(RowPoints V, RowTriangles F, const SimplificationOptions& options)
    : V_(std::move(V))
    , F_(std::move(F))
    , cosTurn_(std::cos(options.maximumNormalTurn * Pi / 180.0))
    , minimumQuality_(options.minimumQuality)
    , facesOf_(V_.rows())
    , lines_(V_.rows())
    , quadrics_(V_.rows())
    , key_(V_.rows(), Unqueued)
    , removed_(V_.rows(), 0)
    , alive_(F_.rows(), 1)
    , blocked_(V_.rows(), 0)
    , mark_(V_.rows(), 0)
    , source_(F_.rows(), 3)
  {
    for (Eigen::Index f = 0; f < F_.rows(); ++f)
    {
      source_.row(f) =
        this->normal(static_cast<int>(f), -1, -1).normalized().transpose().cast<float>();
    }
    for (Eigen::Index f = 0; f < F_.rows(); ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        facesOf_[F_(f, k)].push_back(static_cast<int>(f));
      }
    }
    this->findLines(options.featureAngle);
    this->addPlanes();
  }

  /// Components and their shares of `maximumTriangles`.
  void setBudgets(long long maximumTriangles)
  {
    std::vector<int> sets(F_.rows());
    for (std::size_t f = 0; f < sets.size(); ++f)
    {
      sets[f] = static_cast<int>(f);
    }
    for (std::size_t p = 0; p < facesOf_.size(); ++p)
    {
      for (std::size_t i = 1; i < facesOf_[p].size(); ++i)
      {
        unite(sets, facesOf_[p][0], facesOf_[p][i]); // a manifold's points join as its edges
      }
    }
    component_.assign(F_.rows(), -1);
    std::vector<int> root(F_.rows(), -1);
    std::vector<double> area;
    double total = 0.0;
    for (Eigen::Index f = 0; f < F_.rows(); ++f)
    {
      int& c = root[findRoot(sets, static_cast<int>(f))];
      if (c < 0)
      {
        c = static_cast<int>(count_.size());
        count_.push_back(0);
        area.push_back(0.0);
      }
      component_[f] = c;
      ++count_[c];
      const double a = this->normal(static_cast<int>(f), -1, -1).norm() / 2.0;
      area[c] += a;
      total += a;
    }
    for (std::size_t c = 0; c < count_.size(); ++c)
    {
      const double share = total > 0.0 ? static_cast<double>(maximumTriangles) * area[c] / total
                                       : static_cast<double>(count_[c]);
      // a small component keeps what a map needs (SurfaceRefinement's minimum), all of its own
      // if it has fewer
      floor_.push_back(share <= 256.0 ? std::min<long long>(count_[c], 256)
                                      : static_cast<long long>(std::ceil(share)));
    }
  }

  int run(long long maximumTriangles)
  {
    long long faces = F_.rows();
    for (int u = 0; u < static_cast<int>(V_.rows()); ++u)
    {
      this->update(u);
    }
    int collapsed = 0;
    while (faces > maximumTriangles && !heap_.empty())
    {
      const Entry top = heap_.top();
      heap_.pop();
      if (removed_[top.u] || top.cost != key_[top.u])
      {
        continue;
      }
      double cost = 0.0;
      if (this->cheapestTarget(top.u, cost) >= 0 && cost > top.cost)
      {
        this->queue(top.u, cost); // it took in a neighbour's quadric since
        continue;
      }
      const int v = this->bestTarget(top.u, cost);
      if (v < 0)
      {
        key_[top.u] = Unqueued; // until a collapse next to it changes its ring
        continue;
      }
      if (cost > top.cost)
      {
        this->queue(top.u, cost, true); // the cheaper ones could not be made
        continue;
      }
      faces -= this->collapse(top.u, v);
      ++collapsed;
    }
    return collapsed;
  }

  const std::vector<char>& alive() const { return alive_; }
  int corner(int f, int k) const { return F_(f, k); }
  const std::vector<char>& removed() const { return removed_; }

private:
  /// A point's cost in the queue, a lower bound of its cheapest collapse: entries are never
  /// updated; one whose cost is not its point's key is stale, and one that pops is checked.
  struct Entry
  {
    double cost;
    int u;
    bool operator<(const Entry& e) const // std::priority_queue keeps the largest on top
    {
      return cost != e.cost ? cost > e.cost : u > e.u;
    }
  };

  Eigen::Vector3d point(int p) const { return V_.row(p).transpose(); }
  bool hasCorner(int f, int p) const { return F_(f, 0) == p || F_(f, 1) == p || F_(f, 2) == p; }

  /// Twice the area vector of triangle f, with its corner `from` read as `to`.
  Eigen::Vector3d normal(int f, int from, int to) const
  {
    Eigen::Vector3d x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = this->point(F_(f, k) == from ? to : F_(f, k));
    }
    return (x[1] - x[0]).cross(x[2] - x[0]);
  }

  /// Boundary edges and edges bent more than `angle` degrees: each end lists the other.
  void findLines(double angle)
  {
    std::vector<std::array<std::int64_t, 2>> halfEdges;
    halfEdges.reserve(3 * F_.rows());
    const std::int64_t n = V_.rows();
    for (Eigen::Index f = 0; f < F_.rows(); ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const std::int64_t a = F_(f, k), b = F_(f, (k + 1) % 3);
        halfEdges.push_back({ std::min(a, b) * n + std::max(a, b), f });
      }
    }
    std::sort(halfEdges.begin(), halfEdges.end());
    const double cosAngle = std::cos(angle * Pi / 180.0);
    for (std::size_t i = 0; i < halfEdges.size();)
    {
      std::size_t j = i + 1;
      while (j < halfEdges.size() && halfEdges[j][0] == halfEdges[i][0])
      {
        ++j;
      }
      bool line = j - i != 2;
      if (!line)
      {
        const Eigen::Vector3d n0 = this->normal(static_cast<int>(halfEdges[i][1]), -1, -1);
        const Eigen::Vector3d n1 = this->normal(static_cast<int>(halfEdges[i + 1][1]), -1, -1);
        line = n0.dot(n1) < cosAngle * n0.norm() * n1.norm();
      }
      if (line)
      {
        const int a = static_cast<int>(halfEdges[i][0] / n),
                  b = static_cast<int>(halfEdges[i][0] % n);
        lines_[a].push_back(b);
        lines_[b].push_back(a);
        if (j - i == 1)
        {
          boundary_.push_back({ a, b, static_cast<int>(halfEdges[i][1]) });
        }
      }
      i = j;
    }
  }

  /// Each point's quadric: its triangles' planes by area, and planes across its boundary edges
  /// (upright on their triangle, weighted by the edge's squared length) that keep a boundary in
  /// place along the surface.
  void addPlanes()
  {
    for (Eigen::Index f = 0; f < F_.rows(); ++f)
    {
      const Eigen::Vector3d n = this->normal(static_cast<int>(f), -1, -1);
      const double twice = n.norm();
      if (twice <= 0.0)
      {
        continue;
      }
      const Eigen::Vector3d unit = n / twice;
      Quadric q;
      q.addPlane(unit, -unit.dot(this->point(F_(f, 0))), twice / 2.0);
      for (int k = 0; k < 3; ++k)
      {
        quadrics_[F_(f, k)] += q;
      }
    }
    for (const std::array<int, 3>& e : boundary_)
    {
      const Eigen::Vector3d along = this->point(e[1]) - this->point(e[0]);
      const Eigen::Vector3d across = along.cross(this->normal(e[2], -1, -1));
      if (across.norm() <= 0.0)
      {
        continue;
      }
      const Eigen::Vector3d unit = across.normalized();
      Quadric q;
      q.addPlane(unit, -unit.dot(this->point(e[0])), along.squaredNorm());
      quadrics_[e[0]] += q;
      quadrics_[e[1]] += q;
    }
  }

  /// The points joined to p by an edge, in `ring` (unsorted, each once).
  /// Linear in p's triangles: each point met is marked with this call's stamp, p too (the
  /// marks stay until the next call: canCollapse counts the common neighbours by them).
  void neighbours(int p, std::vector<int>& ring) const
  {
    ring.clear();
    const int stamp = ++markStamp_;
    mark_[p] = stamp;
    for (const int f : facesOf_[p])
    {
      for (int k = 0; k < 3; ++k)
      {
        const int q = F_(f, k);
        if (mark_[q] != stamp)
        {
          mark_[q] = stamp;
          ring.push_back(q);
        }
      }
    }
  }

  /// The points u may move onto: any neighbour off the lines, its two neighbours along a line
  /// through it, none where a line ends or lines meet.
  const std::vector<int>& targets(int u) const
  {
    if (lines_[u].empty())
    {
      this->neighbours(u, targets_);
      return targets_;
    }
    targets_.clear();
    return lines_[u].size() == 2 ? lines_[u] : targets_;
  }

  /// The cheapest point u may move onto, whether the collapse can be made or not; -1 for none.
  int cheapestTarget(int u, double& cost) const
  {
    int best = -1;
    for (const int v : this->targets(u))
    {
      const double c = quadrics_[u](this->point(v));
      if (best < 0 || c < cost || (c == cost && v < best))
      {
        best = v;
        cost = c;
      }
    }
    return best;
  }

  /// The cheapest point u may move onto by a collapse that can be made; -1 for none.
  int bestTarget(int u, double& cost) const
  {
    candidates_.clear();
    for (const int v : this->targets(u))
    {
      candidates_.push_back({ quadrics_[u](this->point(v)), v });
    }
    std::sort(candidates_.begin(), candidates_.end());
    for (const std::pair<double, int>& c : candidates_)
    {
      if (this->canCollapse(u, c.second))
      {
        cost = c.first;
        return c.second;
      }
    }
    return -1;
  }

  /// Queues u again where its cheapest collapse, unchecked, costs less than its key.
  void update(int u)
  {
    double cost = 0.0;
    if (!removed_[u] && this->cheapestTarget(u, cost) >= 0 && cost < key_[u])
    {
      this->queue(u, cost);
    }
  }

  /// Queues w, a neighbour of v that v just took in another point of: only its collapse onto v
  /// may be new or cheaper (w's quadric and the points did not move); one with no queued
  /// collapse, or whose key was raised because its cheaper collapses could not be made
  /// (blocked_: the change of its ring may have freed them), is looked at whole.
  void updateToward(int w, int v)
  {
    if (key_[w] == Unqueued || blocked_[w])
    {
      this->update(w);
      return;
    }
    // v is among w's targets: any neighbour off the lines, one of its two along a line
    const std::vector<int>& line = lines_[w];
    if (line.empty() || (line.size() == 2 && (line[0] == v || line[1] == v)))
    {
      const double cost = quadrics_[w](this->point(v));
      if (cost < key_[w])
      {
        this->queue(w, cost);
      }
    }
  }

  void queue(int u, double cost, bool blocked = false)
  {
    key_[u] = cost;
    blocked_[u] = blocked ? 1 : 0;
    heap_.push({ cost, u });
  }

  bool canCollapse(int u, int v) const
  {
    int shared = 0;
    for (const int f : facesOf_[u])
    {
      shared += this->hasCorner(f, v);
    }
    if (shared == 0 ||
      count_[component_[facesOf_[u][0]]] - shared < floor_[component_[facesOf_[u][0]]])
    {
      return false;
    }
    // the link condition: u and v have exactly the corners of their shared triangles in common
    this->neighbours(u, ringU_);
    this->neighbours(v, ringV_); // marks v's neighbours (and v) with the latest stamp
    int common = 0;
    for (const int p : ringU_)
    {
      common += p != v && mark_[p] == markStamp_;
    }
    if (common != shared)
    {
      return false;
    }
    for (const int f : facesOf_[u])
    {
      if (this->hasCorner(f, v))
      {
        continue;
      }
      if (!this->keepsShape(f, u, v) || this->repeats(f, u, v))
      {
        return false;
      }
    }
    return true;
  }

  /// Whether triangle f, its corner u moved onto v, turns little and stays well shaped.
  bool keepsShape(int f, int u, int v) const
  {
    const Eigen::Vector3d before = this->normal(f, -1, -1), after = this->normal(f, u, v);
    if (after.dot(before) < cosTurn_ * after.norm() * before.norm() || after.norm() <= 0.0 ||
      after.dot(source_.row(f).transpose().cast<double>()) <= 0.0)
    {
      return false; // turned too far in one step, or against the input triangle it was
    }
    Eigen::Vector3d x[3], y[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = this->point(F_(f, k));
      y[k] = this->point(F_(f, k) == u ? v : F_(f, k));
    }
    const double q = quality(y[0], y[1], y[2]);
    return q >= minimumQuality_ || q >= quality(x[0], x[1], x[2]);
  }

  /// Whether triangle f, its corner u moved onto v, repeats a triangle of v (a tetrahedron's).
  bool repeats(int f, int u, int v) const
  {
    int others[2], n = 0;
    for (int k = 0; k < 3; ++k)
    {
      if (F_(f, k) != u)
      {
        others[n++] = F_(f, k);
      }
    }
    for (const int g : facesOf_[v])
    {
      if (this->hasCorner(g, others[0]) && this->hasCorner(g, others[1]))
      {
        return true;
      }
    }
    return false;
  }

  /// Moves u onto v; returns the triangles removed.
  int collapse(int u, int v)
  {
    this->neighbours(u, ringU_);
    int gone = 0;
    for (const int f : facesOf_[u])
    {
      if (this->hasCorner(f, v))
      {
        alive_[f] = 0;
        ++gone;
        for (int k = 0; k < 3; ++k)
        {
          if (F_(f, k) != u)
          {
            std::vector<int>& list = facesOf_[F_(f, k)];
            list.erase(std::find(list.begin(), list.end(), f));
          }
        }
      }
      else
      {
        for (int k = 0; k < 3; ++k)
        {
          F_(f, k) = F_(f, k) == u ? v : F_(f, k);
        }
        facesOf_[v].push_back(f);
      }
    }
    count_[component_[facesOf_[u][0]]] -= gone;
    facesOf_[u].clear();
    facesOf_[u].shrink_to_fit();
    removed_[u] = 1;
    quadrics_[v] += quadrics_[u];
    for (const int w : lines_[u]) // a line through u now runs through v
    {
      std::vector<int>& list = lines_[w];
      list.erase(std::find(list.begin(), list.end(), u));
      if (w != v && std::find(list.begin(), list.end(), v) == list.end())
      {
        list.push_back(v);
        lines_[v].push_back(w);
      }
    }
    lines_[u].clear();
    // costs change for v (its quadric, its ring) and its neighbours (v for u among their targets)
    this->neighbours(v, ringV_);
    for (const int w : ringV_)
    {
      this->updateToward(w, v);
    }
    this->update(v);
    return gone;
  }

  const RowPoints V_;
  RowTriangles F_;
  double cosTurn_;
  double minimumQuality_;
  std::vector<std::vector<int>> facesOf_;
  std::vector<std::vector<int>> lines_;
  std::vector<std::array<int, 3>> boundary_; // a boundary edge's two points and its triangle
  std::vector<Quadric> quadrics_;
  std::vector<double> key_;
  std::vector<char> removed_;
  mutable std::vector<int> targets_, ringU_, ringV_; // scratch
  mutable std::vector<std::pair<double, int>> candidates_;
  std::vector<char> alive_;
  /// 1 where a point's key is the cost of a collapse that could be made while cheaper ones could
  /// not: any change of its ring may free those, so it is looked at whole (updateToward)
  std::vector<char> blocked_;
  mutable std::vector<int> mark_; // neighbours' stamps
  mutable int markStamp_ = 0;
  /// each triangle's unit normal as the input had it (no collapse turns a triangle against it)
  Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> source_;
  std::vector<int> component_;
  std::vector<long long> count_;
  std::vector<long long> floor_;
  std::priority_queue<Entry> heap_;
};
}

Simplification simplifySurface(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, long long maximumTriangles,
  const SimplificationOptions& options)
{
  Simplification result;
  if (maximumTriangles <= 0 || maximumTriangles >= F.rows())
  {
    result.pointSource.resize(V.rows());
    result.triangleSource.resize(F.rows());
    std::iota(result.pointSource.begin(), result.pointSource.end(), 0);
    std::iota(result.triangleSource.begin(), result.triangleSource.end(), 0);
    return result;
  }
  // the work runs on the points in a space-filling curve's order, the triangles by their first
  // point: neighbours lie near each other in memory
  const std::vector<int> pointOrder = spatialOrder(V);
  std::vector<int> newPoint(V.rows());
  for (std::size_t i = 0; i < pointOrder.size(); ++i)
  {
    newPoint[pointOrder[i]] = static_cast<int>(i);
  }
  std::vector<std::array<int, 2>> byPoint(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    byPoint[f] = { std::min({ newPoint[F(f, 0)], newPoint[F(f, 1)], newPoint[F(f, 2)] }),
      static_cast<int>(f) };
  }
  std::sort(byPoint.begin(), byPoint.end());
  RowPoints Vp(V.rows(), 3);
  for (Eigen::Index p = 0; p < V.rows(); ++p)
  {
    Vp.row(p) = V.row(pointOrder[p]);
  }
  RowTriangles Fp(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      Fp(f, k) = newPoint[F(byPoint[f][1], k)];
    }
  }
  Simplifier simplifier(std::move(Vp), std::move(Fp), options);
  simplifier.setBudgets(maximumTriangles);
  result.collapsedEdges = simplifier.run(maximumTriangles);
  std::vector<int> index(V.rows(), -1);
  for (Eigen::Index p = 0; p < V.rows(); ++p)
  {
    if (!simplifier.removed()[newPoint[p]])
    {
      index[p] = static_cast<int>(result.pointSource.size());
      result.pointSource.push_back(static_cast<int>(p));
    }
  }
  std::vector<int> newFace(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    newFace[byPoint[f][1]] = static_cast<int>(f);
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    if (simplifier.alive()[newFace[f]])
    {
      result.triangleSource.push_back(static_cast<int>(f));
    }
  }
  Eigen::MatrixX3d keptV(result.pointSource.size(), 3);
  for (std::size_t i = 0; i < result.pointSource.size(); ++i)
  {
    keptV.row(static_cast<Eigen::Index>(i)) = V.row(result.pointSource[i]);
  }
  Eigen::MatrixX3i keptF(result.triangleSource.size(), 3);
  for (std::size_t i = 0; i < result.triangleSource.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      keptF(static_cast<Eigen::Index>(i), k) =
        index[pointOrder[simplifier.corner(newFace[result.triangleSource[i]], k)]];
    }
  }
  V = std::move(keptV);
  F = std::move(keptF);
  return result;
}

}
