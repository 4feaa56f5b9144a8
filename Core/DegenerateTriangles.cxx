// DegenerateTriangles.cxx: flat caps (a corner on the opposite edge) removed by edge flips.
#include "DegenerateTriangles.h"

#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace quadcover
{
namespace
{
/// The triangles of a mesh found by their directed edges, kept up to date through flips.
class DirectedEdges
{
public:
  explicit DirectedEdges(const Eigen::MatrixX3i& F)
  {
    this->Face.reserve(3 * static_cast<std::size_t>(F.rows()));
    for (int f = 0; f < F.rows(); ++f)
    {
      this->Add(F, f);
    }
  }

  /// The triangle with the edge from u to v, -1 if none.
  int Find(int u, int v) const
  {
    const auto it = this->Face.find(Key(u, v));
    return it == this->Face.end() ? -1 : it->second;
  }

  void Add(const Eigen::MatrixX3i& F, int f)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Face.emplace(Key(F(f, k), F(f, (k + 1) % 3)), f);
    }
  }

  void Remove(const Eigen::MatrixX3i& F, int f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const auto it = this->Face.find(Key(F(f, k), F(f, (k + 1) % 3)));
      if (it != this->Face.end() && it->second == f)
      {
        this->Face.erase(it);
      }
    }
  }

private:
  static std::uint64_t Key(int u, int v)
  {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) |
      static_cast<std::uint32_t>(v);
  }

  std::unordered_map<std::uint64_t, int> Face;
};

Eigen::Vector3d corner(const Eigen::MatrixX3d& V, int p)
{
  return V.row(p).transpose();
}

Eigen::Vector3d normalOf(const Eigen::MatrixX3d& V, int a, int b, int c)
{
  return (corner(V, b) - corner(V, a)).cross(corner(V, c) - corner(V, a));
}

bool flat(const Eigen::MatrixX3d& V, int a, int b, int c)
{
  return isDegenerateTriangle(corner(V, a), corner(V, b), corner(V, c), FlatTriangleRatio);
}

bool flat(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int f)
{
  return flat(V, F(f, 0), F(f, 1), F(f, 2));
}

/// Flips the longest edge of the flat triangle f where flipDegenerateTriangles allows it;
/// returns the neighbour the flip split (now the second new triangle), -1 if none.
int flipCap(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, DirectedEdges& edges,
  std::vector<int>& source, int f)
{
  int k = 0; // the longest edge: F(f, k) -> F(f, k + 1)
  double longest = -1.0;
  for (int j = 0; j < 3; ++j)
  {
    const double length = (corner(V, F(f, (j + 1) % 3)) - corner(V, F(f, j))).squaredNorm();
    if (length > longest)
    {
      longest = length;
      k = j;
    }
  }
  const int u = F(f, k), v = F(f, (k + 1) % 3), m = F(f, (k + 2) % 3);
  const int g = edges.Find(v, u);
  if (g < 0 || g == f || flat(V, F, g))
  {
    return -1;
  }
  int d = F(g, 0);
  for (int j = 0; j < 3; ++j)
  {
    d = F(g, j) != u && F(g, j) != v ? F(g, j) : d;
  }
  if (d == m || edges.Find(m, d) >= 0 || edges.Find(d, m) >= 0)
  {
    return -1;
  }
  const Eigen::Vector3d facing = normalOf(V, v, u, d);
  const Eigen::RowVector3i first(m, u, d), second(d, v, m);
  for (const Eigen::RowVector3i& t : { first, second })
  {
    if (flat(V, t[0], t[1], t[2]) || !(normalOf(V, t[0], t[1], t[2]).dot(facing) > 0.0))
    {
      return -1;
    }
  }
  edges.Remove(F, f);
  edges.Remove(F, g);
  F.row(f) = first;
  F.row(g) = second;
  edges.Add(F, f);
  edges.Add(F, g);
  source[f] = source[g];
  return g;
}
}

DegenerateFlips flipDegenerateTriangles(const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F)
{
  DegenerateFlips out;
  out.triangleSource.resize(static_cast<std::size_t>(F.rows()));
  std::iota(out.triangleSource.begin(), out.triangleSource.end(), 0);
  std::vector<int> work; // flat triangles to try, the last first
  for (int f = static_cast<int>(F.rows()) - 1; f >= 0; --f)
  {
    if (flat(V, F, f))
    {
      work.push_back(f);
    }
  }
  if (work.empty())
  {
    return out;
  }
  DirectedEdges edges(F);
  // each flip removes one flat triangle and makes none, so there are at most as many flips as
  // flat triangles; after one, the flat neighbours of its two new triangles are tried again
  // (a row of caps goes from its proper end, one flip making the next one possible)
  while (!work.empty())
  {
    const int f = work.back();
    work.pop_back();
    const int g = flat(V, F, f) ? flipCap(V, F, edges, out.triangleSource, f) : -1;
    if (g < 0)
    {
      continue;
    }
    ++out.flippedEdges;
    for (const int t : { f, g })
    {
      for (int k = 0; k < 3; ++k)
      {
        const int across = edges.Find(F(t, (k + 1) % 3), F(t, k));
        if (across >= 0 && flat(V, F, across))
        {
          work.push_back(across);
        }
      }
    }
  }
  return out;
}

}
