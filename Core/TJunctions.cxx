// TJunctions.cxx: T-junctions closed by splitting the boundary edges their points lie on.
#include "TJunctions.h"

#include "DegenerateTriangles.h"
#include "EdgeGroups.h"
#include "NearbyPoints.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace quadcover
{
namespace
{
/// An edge of exactly one triangle: a -> b as in its triangle f, c that triangle's third corner.
struct BoundaryEdge
{
  int a, b, c, f;
};

/// The edges of exactly one triangle (of every triangle, repeats included), but those of
/// degenerate triangles (DegenerateAreaRatio) and of non-finite points: a stray flat triangle
/// must not join the surface through its points.
std::vector<BoundaryEdge> boundaryEdges(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  const EdgeGroups groups = groupEdges(F);
  std::vector<BoundaryEdge> out;
  for (std::size_t g = 0; g + 1 < groups.offsets.size(); ++g)
  {
    if (groups.offsets[g + 1] - groups.offsets[g] != 1)
    {
      continue;
    }
    const int c = groups.corners[groups.offsets[g]], f = c / 3, k = c % 3;
    const Eigen::Vector3d a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(),
                          d = V.row(F(f, 2)).transpose();
    if (a.allFinite() && b.allFinite() && d.allFinite() && !isDegenerateTriangle(a, b, d))
    {
      out.push_back({ F(f, k), F(f, (k + 1) % 3), F(f, (k + 2) % 3), f });
    }
  }
  return out;
}

/// Points hashed in cubic cells `width` wide; near(x) visits those of x's cell and of the 26
/// around it (a collision of keys only adds candidates).
class PointCells
{
public:
  PointCells(const Eigen::MatrixX3d& V, const std::vector<int>& points, double width)
    : Width(width)
  {
    for (const int p : points)
    {
      this->Cells[cellHash(this->CellOf(V.row(p).transpose()))].push_back(p);
    }
  }

  template<typename Visit>
  void near(const Eigen::Vector3d& x, Visit visit) const
  {
    const std::array<std::int64_t, 3> c = this->CellOf(x);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz)
        {
          const auto it = this->Cells.find(cellHash({ c[0] + dx, c[1] + dy, c[2] + dz }));
          if (it != this->Cells.end())
          {
            for (const int p : it->second)
            {
              visit(p);
            }
          }
        }
  }

private:
  std::array<std::int64_t, 3> CellOf(const Eigen::Vector3d& x) const
  {
    std::array<std::int64_t, 3> c;
    for (int d = 0; d < 3; ++d)
    {
      c[d] = static_cast<std::int64_t>(std::clamp(std::floor(x[d] / this->Width), -4e18, 4e18));
    }
    return c;
  }

  double Width;
  std::unordered_map<std::uint64_t, std::vector<int>> Cells;
};

using Edge = std::pair<int, int>; // (lower point, higher point)
/// The points an edge gets: with their place along it from its lower point; whether a crack's.
struct EdgeSplit
{
  std::vector<std::pair<double, int>> points;
  bool crack = false;
};
using Splits = std::map<Edge, EdgeSplit>;

/// The cells' width: the boundary's median edge, or a quarter of its mean where a few long
/// edges would make the walk along them long (0 when every edge has zero length).
double cellWidth(const Eigen::MatrixX3d& V, const std::vector<BoundaryEdge>& edges)
{
  std::vector<double> lengths;
  double total = 0.0;
  for (const BoundaryEdge& e : edges)
  {
    lengths.push_back((V.row(e.b) - V.row(e.a)).norm());
    total += lengths.back();
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double width = std::max(lengths[lengths.size() / 2], total / (4.0 * lengths.size()));
  return std::isfinite(width) ? width : 0.0;
}

/// Per boundary point, its neighbours through boundary edges.
using Neighbours = std::unordered_map<int, std::vector<int>>;

Neighbours boundaryNeighbours(const std::vector<BoundaryEdge>& edges)
{
  Neighbours next;
  for (const BoundaryEdge& e : edges)
  {
    next[e.a].push_back(e.b);
    next[e.b].push_back(e.a);
  }
  return next;
}

/// The inner points of a crack along e (closeTJunctions), in order from e.a; empty if none.
std::vector<int> crackAlong(
  const Eigen::MatrixX3d& V, const BoundaryEdge& e, const Neighbours& next)
{
  const Eigen::Vector3d a = V.row(e.a).transpose(), b = V.row(e.b).transpose(), d = b - a;
  const double length = d.norm();
  std::vector<int> path;
  // depth first from e.a: (point, place along e, path length so far, next neighbour to try)
  struct Step
  {
    int p;
    double t, walked;
    std::size_t tried;
  };
  std::vector<Step> stack{ { e.a, 0.0, 0.0, 0 } };
  for (int steps = 0; !stack.empty() && steps < MaximumCrackSteps; ++steps)
  {
    Step& top = stack.back();
    const std::vector<int>& around = next.at(top.p);
    if (top.tried == around.size())
    {
      stack.pop_back();
      continue;
    }
    const int q = around[top.tried++];
    const Eigen::Vector3d x = V.row(q).transpose(), from = V.row(top.p).transpose();
    const double walked = top.walked + (x - from).norm();
    if (q == e.b && stack.size() > 1 && walked <= CrackLength * length)
    {
      for (std::size_t i = 1; i < stack.size(); ++i)
      {
        path.push_back(stack[i].p);
      }
      break;
    }
    const double t = (x - a).dot(d) / (length * length);
    if (q == e.b || q == e.c || !(t > top.t && t < 1.0) ||
      !((x - a - t * d).norm() <= CrackWidth * length) ||
      !(walked + (b - x).norm() <= CrackLength * length) ||
      static_cast<int>(stack.size()) > MaximumCrackPoints)
    {
      continue;
    }
    stack.push_back({ q, t, walked, 0 });
  }
  return path;
}

/// The boundary points that lie on each boundary edge, or on a crack along it
/// (closeTJunctions' rule).
Splits findSplits(
  const Eigen::MatrixX3d& V, const std::vector<BoundaryEdge>& edges, double tolerance)
{
  Splits splits;
  const double width = cellWidth(V, edges);
  if (!(width > 0.0))
  {
    return splits;
  }
  std::vector<int> points;
  for (const BoundaryEdge& e : edges)
  {
    points.push_back(e.a);
    points.push_back(e.b);
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  const PointCells cells(V, points, width);
  const Neighbours next = boundaryNeighbours(edges);
  for (const BoundaryEdge& e : edges)
  {
    const Eigen::Vector3d a = V.row(e.a).transpose(), d = V.row(e.b).transpose() - a;
    const double length = d.norm();
    if (!(length > 2.0 * tolerance))
    {
      continue;
    }
    std::vector<std::pair<double, int>> found;
    const auto test = [&](int p) {
      const Eigen::Vector3d x = V.row(p).transpose();
      const double t = (x - a).dot(d) / (length * length);
      if (p == e.a || p == e.b || p == e.c || !(t > 0.0 && t < 1.0) ||
        !((x - a - t * d).norm() <= tolerance) || !(t * length > tolerance) ||
        !((1.0 - t) * length > tolerance))
      {
        return;
      }
      found.emplace_back(e.a < e.b ? t : 1.0 - t, p);
    };
    // samples a cell apart along the edge: every point within a cell of it is near one
    const int samples = static_cast<int>(std::min(1e7, std::ceil(length / width)));
    for (int s = 0; s <= samples; ++s)
    {
      cells.near(a + d * (static_cast<double>(s) / std::max(1, samples)), test);
    }
    const bool crack = found.empty();
    if (crack)
    {
      for (const int p : crackAlong(V, e, next))
      {
        const double t = (V.row(p).transpose() - a).dot(d) / (length * length);
        found.emplace_back(e.a < e.b ? t : 1.0 - t, p);
      }
    }
    if (!found.empty())
    {
      std::sort(found.begin(), found.end());
      found.erase(std::unique(found.begin(), found.end()), found.end());
      splits[{ std::min(e.a, e.b), std::max(e.a, e.b) }] = { std::move(found), crack };
    }
  }
  return splits;
}

/// The points `splits` gives the edge from x to y, in order from x (none that is a corner of
/// the triangle, or in `taken`: a point goes into one edge of a triangle only).
std::vector<int> chainOf(int x, int y, const Eigen::RowVector3i& t, const Splits& splits,
  std::vector<int>& taken, bool& crack)
{
  std::vector<int> chain;
  const auto it = splits.find({ std::min(x, y), std::max(x, y) });
  if (it == splits.end())
  {
    return chain;
  }
  crack = it->second.crack;
  for (const auto& [place, p] : it->second.points)
  {
    if (p != t[0] && p != t[1] && p != t[2] &&
      std::find(taken.begin(), taken.end(), p) == taken.end())
    {
      chain.push_back(p);
      taken.push_back(p);
    }
  }
  if (x > y) // the places run from the lower point
  {
    std::reverse(chain.begin(), chain.end());
  }
  return chain;
}

/// Triangle t split at the points `splits` gives its own three edges: a fan from the corner
/// opposite the first such edge, then for each part that has one of the other two edges, a fan
/// along it. The parts, when each is proper and faces as t, else t itself, go to `out`; returns
/// the points put in, and adds those of cracks to `crackPoints`.
int splitTriangle(const Eigen::MatrixX3d& V, const Eigen::RowVector3i& t, const Splits& splits,
  std::vector<Eigen::RowVector3i>& out, int& crackPoints)
{
  std::array<std::vector<int>, 3> chain; // per edge k of t, from t[k] to t[k + 1]
  std::vector<int> taken;
  int ofCracks = 0;
  for (int k = 0; k < 3; ++k)
  {
    bool crack = false;
    chain[k] = chainOf(t[k], t[(k + 1) % 3], t, splits, taken, crack);
    ofCracks += crack ? static_cast<int>(chain[k].size()) : 0;
  }
  // parts with, per edge, the edge of t it is (-1: none, or split already)
  std::vector<std::pair<Eigen::RowVector3i, std::array<int, 3>>> work{ { t, { 0, 1, 2 } } };
  std::vector<Eigen::RowVector3i> parts;
  while (!work.empty())
  {
    const auto [tri, of] = work.back();
    work.pop_back();
    int k = 0;
    while (k < 3 && (of[k] < 0 || chain[of[k]].empty()))
    {
      ++k;
    }
    if (k == 3)
    {
      parts.push_back(tri);
      continue;
    }
    std::vector<int> run{ tri[k] };
    run.insert(run.end(), chain[of[k]].begin(), chain[of[k]].end());
    run.push_back(tri[(k + 1) % 3]);
    const int z = tri[(k + 2) % 3];
    for (std::size_t j = 0; j + 1 < run.size(); ++j)
    {
      work.push_back({ Eigen::RowVector3i(run[j], run[j + 1], z),
        { -1, j + 2 == run.size() ? of[(k + 1) % 3] : -1, j == 0 ? of[(k + 2) % 3] : -1 } });
    }
  }
  const auto normal = [&](const Eigen::RowVector3i& r) {
    const Eigen::Vector3d a = V.row(r[0]).transpose();
    return Eigen::Vector3d((V.row(r[1]).transpose() - a).cross(V.row(r[2]).transpose() - a));
  };
  const Eigen::Vector3d facing = normal(t);
  for (const Eigen::RowVector3i& r : parts)
  {
    if (isDegenerateTriangle(V.row(r[0]), V.row(r[1]), V.row(r[2])) ||
      !(normal(r).dot(facing) > 0.0))
    {
      out.push_back(t);
      return 0;
    }
  }
  out.insert(out.end(), parts.begin(), parts.end());
  crackPoints += ofCracks;
  return static_cast<int>(parts.size()) - 1;
}
}

TJunctionSplits closeTJunctions(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, double tolerance)
{
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
  {
    throw std::invalid_argument("closeTJunctions: the tolerance must be finite and >= 0");
  }
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows()))
  {
    throw std::invalid_argument("closeTJunctions: a point index is out of range");
  }
  TJunctionSplits out;
  const std::vector<BoundaryEdge> edges = boundaryEdges(V, F);
  const Splits splits = edges.empty() ? Splits() : findSplits(V, edges, tolerance);
  out.triangleSource.resize(static_cast<std::size_t>(F.rows()));
  for (int f = 0; f < F.rows(); ++f)
  {
    out.triangleSource[f] = f;
  }
  if (splits.empty())
  {
    return out;
  }
  std::vector<char> touched(static_cast<std::size_t>(F.rows()), 0);
  for (const BoundaryEdge& e : edges)
  {
    touched[e.f] |= splits.count({ std::min(e.a, e.b), std::max(e.a, e.b) }) > 0;
  }
  std::vector<Eigen::RowVector3i> triangles;
  out.triangleSource.clear();
  for (int f = 0; f < F.rows(); ++f)
  {
    const std::size_t before = triangles.size();
    if (touched[f])
    {
      out.closed += splitTriangle(V, F.row(f), splits, triangles, out.crackPoints);
    }
    else
    {
      triangles.push_back(F.row(f));
    }
    out.triangleSource.insert(out.triangleSource.end(), triangles.size() - before, f);
  }
  F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    F.row(static_cast<Eigen::Index>(i)) = triangles[i];
  }
  return out;
}

}
