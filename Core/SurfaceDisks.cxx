// SurfaceDisks.cxx: whether the part of a surface around a point is a topological disk.
#include "SurfaceDisks.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace quadcover
{

DiskTest::DiskTest(
  const Eigen::MatrixX3i& F, const MeshTopology& topo, const Eigen::MatrixX3d& edgeLength)
  : F_(F)
  , topo_(topo)
  , edgeLength_(edgeLength)
  , dist_(topo.numVertices, std::numeric_limits<double>::infinity())
  , faceSeen_(F.rows(), 0)
  , edgeSeen_(topo.numEdges(), 0)
{}

DiskTest::Ball DiskTest::ball(int a, double radius, bool boundaryBeyond)
{
  if (topo_.vertexComponent[a] < 0 || topo_.ringOffsets[a] == topo_.ringOffsets[a + 1])
  {
    return Ball::Beyond; // a point of no triangle
  }
  const int limit = topo_.components[topo_.vertexComponent[a]].numFaces / 2;
  const bool small = grow(a, radius, limit);
  const bool beyond = !small || faces_.empty() ||
    (boundaryBeyond &&
      std::any_of(points_.begin(), points_.end(), [&](int v) { return topo_.boundaryVertex[v]; }));
  Ball result = Ball::Beyond;
  if (!beyond)
  {
    // the triangles around the points reached: a point just beyond the radius among them (edge
    // paths are longer than the surface's distances) leaves no hole
    for (const int f : faces_)
    {
      faceSeen_[f] = 2;
    }
    result = connected(faces_) && eulerCharacteristic(faces_) == 1 ? Ball::Disk : Ball::NotDisk;
  }
  for (const int v : points_)
  {
    dist_[v] = std::numeric_limits<double>::infinity();
  }
  for (const int f : faces_)
  {
    faceSeen_[f] = 0;
  }
  points_.clear();
  faces_.clear();
  return result;
}

bool DiskTest::reached(int v) const
{
  return dist_[v] < std::numeric_limits<double>::infinity();
}

/// Dijkstra from a within radius: dist_, points_ and faces_ (the faces around the points
/// reached); false when more than `limit` faces were met.
bool DiskTest::grow(int a, double radius, int limit)
{
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  dist_[a] = 0.0;
  points_.push_back(a);
  queue.push({ 0.0, a });
  while (!queue.empty())
  {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > dist_[u])
    {
      continue;
    }
    for (int i = topo_.ringOffsets[u]; i < topo_.ringOffsets[u + 1]; ++i)
    {
      const int f = topo_.ringFaces[i];
      if (!faceSeen_[f])
      {
        faceSeen_[f] = 1;
        faces_.push_back(f);
      }
      const int k = MeshTopology::cornerOf(F_, f, u);
      // edge k runs from corner k to k + 1, edge k + 2 from corner k + 2 to k
      for (const auto& [j, e] :
        { std::pair<int, int>{ (k + 1) % 3, k }, std::pair<int, int>{ (k + 2) % 3, (k + 2) % 3 } })
      {
        const int w = F_(f, j);
        const double nd = d + edgeLength_(f, e);
        if (nd <= radius && nd < dist_[w])
        {
          if (!reached(w))
          {
            points_.push_back(w);
          }
          dist_[w] = nd;
          queue.push({ nd, w });
        }
      }
    }
    if (static_cast<int>(faces_.size()) > limit)
    {
      return false;
    }
  }
  return true;
}

/// Whether the faces marked 2 in faceSeen_ are one piece across edges.
bool DiskTest::connected(const std::vector<int>& inside)
{
  std::vector<int> front{ inside.front() };
  faceSeen_[inside.front()] = 3;
  std::size_t count = 1;
  while (!front.empty())
  {
    const int f = front.back();
    front.pop_back();
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo_.faceNeighbors(f, k);
      if (g >= 0 && faceSeen_[g] == 2)
      {
        faceSeen_[g] = 3;
        ++count;
        front.push_back(g);
      }
    }
  }
  return count == inside.size();
}

long long DiskTest::eulerCharacteristic(const std::vector<int>& inside)
{
  std::vector<int> edges;
  std::vector<int> points;
  for (const int f : inside)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int e = topo_.faceEdges(f, k);
      if (!edgeSeen_[e])
      {
        edgeSeen_[e] = 1;
        edges.push_back(e);
      }
      points.push_back(F_(f, k));
    }
  }
  for (const int e : edges)
  {
    edgeSeen_[e] = 0;
  }
  std::sort(points.begin(), points.end());
  const auto distinct = std::unique(points.begin(), points.end()) - points.begin();
  return static_cast<long long>(distinct) - static_cast<long long>(edges.size()) +
    static_cast<long long>(inside.size());
}

}
