// NearbyPoints.h: internal to Core: pairs of points that may lie within a reach of each other,
// by a grid of cells that wide (so that a long boundary does not cost every pair of its edges).
#ifndef quadcover_NearbyPoints_h
#define quadcover_NearbyPoints_h

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace quadcover
{
/// A hash of a grid cell's three indices (FNV-1a over them), for unordered maps of cells: a
/// collision of two cells only adds candidates to a search.
inline std::uint64_t cellHash(const std::array<std::int64_t, 3>& c)
{
  std::uint64_t h = 1469598103934665603ULL;
  for (const std::int64_t x : c)
  {
    h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ULL;
  }
  return h;
}

/// For each point, the later ones (in order) in its own or a neighbouring cell of a grid of cells
/// `reach` wide: every later point within `reach` of it, and some farther. Without a positive
/// finite reach, every later point.
inline std::vector<std::vector<int>> nearbyPoints(
  const std::vector<Eigen::Vector3d>& points, double reach)
{
  const bool grid = reach > 0 && std::isfinite(reach); // else one cell: every pair
  using Cell = std::array<long long, 3>;
  auto cellOf = [&](const Eigen::Vector3d& p) {
    Cell c{ 0, 0, 0 };
    for (int d = 0; grid && d < 3; ++d)
    {
      c[d] = static_cast<long long>(std::floor(p[d] / reach));
    }
    return c;
  };
  std::map<Cell, std::vector<int>> cells;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    cells[cellOf(points[i])].push_back(static_cast<int>(i));
  }
  std::vector<std::vector<int>> near(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Cell c = cellOf(points[i]);
    for (long long dx = -1; dx <= 1; ++dx)
    {
      for (long long dy = -1; dy <= 1; ++dy)
      {
        for (long long dz = -1; dz <= 1; ++dz)
        {
          const auto it = cells.find({ c[0] + dx, c[1] + dy, c[2] + dz });
          if (it == cells.end())
          {
            continue;
          }
          for (const int j : it->second)
          {
            if (j > static_cast<int>(i))
            {
              near[i].push_back(j);
            }
          }
        }
      }
    }
    std::sort(near[i].begin(), near[i].end()); // in order
  }
  return near;
}
}

#endif
