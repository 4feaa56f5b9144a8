// TJunctions.cxx: T-junctions closed by splitting the boundary edges their points lie on.
#include "TJunctions.h"

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

std::vector<BoundaryEdge> boundaryEdges(const Eigen::MatrixX3i& F)
{
  // per side: its points as one key (lower, higher), and its corner 3 f + k
  std::vector<std::pair<std::uint64_t, int>> sides;
  sides.reserve(3 * static_cast<std::size_t>(F.rows()));
  for (int f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      sides.emplace_back((static_cast<std::uint64_t>(std::min(a, b)) << 32) |
          static_cast<std::uint32_t>(std::max(a, b)),
        3 * f + k);
    }
  }
  std::sort(sides.begin(), sides.end());
  std::vector<BoundaryEdge> out;
  for (std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    for (j = i + 1; j < sides.size() && sides[j].first == sides[i].first;)
    {
      ++j;
    }
    if (j == i + 1)
    {
      const int f = sides[i].second / 3, k = sides[i].second % 3;
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
      this->Cells[Key(this->CellOf(V.row(p).transpose()))].push_back(p);
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
          const auto it = this->Cells.find(Key({ c[0] + dx, c[1] + dy, c[2] + dz }));
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

  static std::uint64_t Key(const std::array<std::int64_t, 3>& c)
  {
    std::uint64_t h = 1469598103934665603ULL;
    for (const std::int64_t x : c)
    {
      h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ULL;
    }
    return h;
  }

  double Width;
  std::unordered_map<std::uint64_t, std::vector<int>> Cells;
};

using Edge = std::pair<int, int>; // (lower point, higher point)
/// per edge with T-junctions: their points, with their place along it from its lower point
using Splits = std::map<Edge, std::vector<std::pair<double, int>>>;

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

/// Per point, its neighbours through boundary edges.
std::vector<std::vector<int>> boundaryNeighbours(
  const Eigen::MatrixX3d& V, const std::vector<BoundaryEdge>& edges)
{
  std::vector<std::vector<int>> next(static_cast<std::size_t>(V.rows()));
  for (const BoundaryEdge& e : edges)
  {
    next[e.a].push_back(e.b);
    next[e.b].push_back(e.a);
  }
  return next;
}

/// The inner points of a crack along e (closeTJunctions), in order from e.a; empty if none.
std::vector<int> crackAlong(
  const Eigen::MatrixX3d& V, const BoundaryEdge& e, const std::vector<std::vector<int>>& next)
{
  const Eigen::Vector3d a = V.row(e.a).transpose(), b = V.row(e.b).transpose(),
                        c = V.row(e.c).transpose(), d = b - a;
  const double length = d.norm();
  const Eigen::Vector3d facing = d.cross(c - a);
  std::vector<int> path;
  // depth first from e.a: (point, place along e, path length so far, next neighbour to try)
  struct Step
  {
    int p;
    double t, walked;
    std::size_t tried;
  };
  std::vector<Step> stack{ { e.a, 0.0, 0.0, 0 } };
  while (!stack.empty())
  {
    Step& top = stack.back();
    if (top.tried == next[top.p].size())
    {
      stack.pop_back();
      continue;
    }
    const int q = next[top.p][top.tried++];
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
  // the fan from e.c over the crack's points must face as e's triangle
  int last = e.a;
  path.push_back(e.b);
  for (const int p : path)
  {
    const Eigen::Vector3d u = V.row(last).transpose(), w = V.row(p).transpose();
    if (!((w - u).cross(c - u).dot(facing) > 0.0))
    {
      return {};
    }
    last = p;
  }
  path.pop_back();
  return path;
}

/// The boundary points that lie on each boundary edge, or on a crack along it
/// (closeTJunctions' rule); `crackPoints` counts the latter.
Splits findSplits(const Eigen::MatrixX3d& V, const std::vector<BoundaryEdge>& edges,
  double tolerance, int& crackPoints)
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
  const std::vector<std::vector<int>> next = boundaryNeighbours(V, edges);
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
    if (found.empty())
    {
      for (const int p : crackAlong(V, e, next))
      {
        const double t = (V.row(p).transpose() - a).dot(d) / (length * length);
        found.emplace_back(e.a < e.b ? t : 1.0 - t, p);
        ++crackPoints;
      }
    }
    if (!found.empty())
    {
      std::sort(found.begin(), found.end());
      found.erase(std::unique(found.begin(), found.end()), found.end());
      splits[{ std::min(e.a, e.b), std::max(e.a, e.b) }] = std::move(found);
    }
  }
  return splits;
}

/// Triangle t split at the points of its edges in `splits`: a fan from the corner opposite the
/// first such edge, again for the parts' other edges. The parts go to `out`.
void splitTriangle(
  const Eigen::RowVector3i& t, const Splits& splits, std::vector<Eigen::RowVector3i>& out)
{
  std::vector<Eigen::RowVector3i> work{ t };
  while (!work.empty())
  {
    const Eigen::RowVector3i tri = work.back();
    work.pop_back();
    int k = 0;
    auto it = splits.end();
    for (; k < 3 && it == splits.end(); ++k)
    {
      const int x = tri[k], y = tri[(k + 1) % 3];
      it = splits.find({ std::min(x, y), std::max(x, y) });
    }
    if (it == splits.end())
    {
      out.push_back(tri);
      continue;
    }
    --k;
    const int x = tri[k], y = tri[(k + 1) % 3], z = tri[(k + 2) % 3];
    std::vector<int> chain{ x };
    for (const auto& [place, p] : it->second)
    {
      chain.push_back(p);
    }
    if (x > y) // the places run from the lower point
    {
      std::reverse(chain.begin() + 1, chain.end());
    }
    chain.push_back(y);
    for (std::size_t j = 0; j + 1 < chain.size(); ++j)
    {
      work.emplace_back(chain[j], chain[j + 1], z);
    }
  }
}
}

TJunctionSplits closeTJunctions(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, double tolerance)
{
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
  {
    throw std::invalid_argument("closeTJunctions: the tolerance must be finite and >= 0");
  }
  TJunctionSplits out;
  const std::vector<BoundaryEdge> edges = boundaryEdges(F);
  const Splits splits = edges.empty() ? Splits() : findSplits(V, edges, tolerance, out.crackPoints);
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
  for (const auto& [edge, points] : splits)
  {
    out.closed += static_cast<int>(points.size());
  }
  std::vector<Eigen::RowVector3i> triangles;
  out.triangleSource.clear();
  for (int f = 0; f < F.rows(); ++f)
  {
    const std::size_t before = triangles.size();
    if (touched[f])
    {
      splitTriangle(F.row(f), splits, triangles);
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
