// QuadMeshAdjacency.cxx: vertexQuads, quadMeshBoundary, onSurfaceBoundary, verticesNear,
// splitPinchedVertices.
#include "QuadMeshAdjacency.h"

#include "SurfaceLocator.h"
#include "UnionFind.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace quadcover
{

VertexQuads vertexQuads(const QuadMesh& mesh)
{
  const int nV = static_cast<int>(mesh.V.rows());
  const int nQ = static_cast<int>(mesh.Q.rows());
  VertexQuads r;
  r.offsets.assign(nV + 1, 0);
  r.quads.resize(4 * static_cast<std::size_t>(nQ));
  for (int i = 0; i < nQ; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      ++r.offsets[mesh.Q(i, k) + 1];
    }
  }
  for (int v = 0; v < nV; ++v)
  {
    r.offsets[v + 1] += r.offsets[v];
  }
  std::vector<int> fill(r.offsets.begin(), r.offsets.end() - 1);
  for (int i = 0; i < nQ; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      r.quads[fill[mesh.Q(i, k)]++] = i;
    }
  }
  return r;
}

std::vector<char> quadMeshBoundary(const QuadMesh& mesh)
{
  std::vector<char> boundary(mesh.V.rows(), 0);
  std::map<std::pair<int, int>, int> edgeCount;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = mesh.Q(i, k), b = mesh.Q(i, (k + 1) % 4);
      ++edgeCount[{ std::min(a, b), std::max(a, b) }];
    }
  }
  for (const auto& [edge, count] : edgeCount)
  {
    if (count != 2)
    {
      boundary[edge.first] = boundary[edge.second] = 1;
    }
  }
  return boundary;
}

bool onSurfaceBoundary(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const QuadMesh& mesh, int v)
{
  if (mesh.vertexPoint[v] >= 0)
  {
    return topo.boundaryVertex[mesh.vertexPoint[v]] != 0; // on a point of the surface
  }
  const int t = mesh.vertexTriangle[v];
  if (t < 0)
  {
    return false;
  }
  const Eigen::Vector3d p = mesh.V.row(v);
  for (int k = 0; k < 3; ++k)
  {
    if (topo.faceNeighbors(t, k) < 0)
    {
      const Eigen::Vector3d a = V.row(F(t, k)), b = V.row(F(t, (k + 1) % 3));
      if ((closestOnSegment(p, a, b) - p).norm() <= 1e-7 * (b - a).norm())
      {
        return true;
      }
    }
  }
  return false;
}

std::vector<char> verticesNear(const QuadMesh& mesh, const std::vector<int>& quads, int rings)
{
  std::vector<char> near(mesh.V.rows(), 0);
  for (const int i : quads)
  {
    for (int k = 0; k < 4; ++k)
    {
      near[mesh.Q(i, k)] = 1;
    }
  }
  // grow by quad rings: every vertex of a quad with a vertex already in
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<char> grown = near;
    for (int i = 0; i < mesh.Q.rows(); ++i)
    {
      const bool touches =
        near[mesh.Q(i, 0)] || near[mesh.Q(i, 1)] || near[mesh.Q(i, 2)] || near[mesh.Q(i, 3)];
      for (int k = 0; k < 4 && touches; ++k)
      {
        grown[mesh.Q(i, k)] = 1;
      }
    }
    near.swap(grown);
  }
  return near;
}

int splitPinchedVertices(QuadMesh& mesh)
{
  const VertexQuads around = vertexQuads(mesh);
  const int nV = static_cast<int>(mesh.V.rows());
  std::vector<int> source; // the vertex each copy copies
  for (int v = 0; v < nV; ++v)
  {
    // its quads (a degenerate one lists v twice), joined where they share an edge at v
    std::vector<int> quads(
      around.quads.begin() + around.offsets[v], around.quads.begin() + around.offsets[v + 1]);
    quads.erase(std::unique(quads.begin(), quads.end()), quads.end());
    if (quads.size() < 2)
    {
      continue;
    }
    std::vector<int> fan(quads.size());
    std::iota(fan.begin(), fan.end(), 0);
    std::map<int, int> across; // the other end of an edge at v -> the first of its quads met
    for (int i = 0; i < static_cast<int>(quads.size()); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        if (mesh.Q(quads[i], k) != v)
        {
          continue;
        }
        for (const int w : { mesh.Q(quads[i], (k + 1) % 4), mesh.Q(quads[i], (k + 3) % 4) })
        {
          const auto [at, first] = across.emplace(w, i);
          if (w != v && !first)
          {
            unite(fan, i, at->second);
          }
        }
      }
    }
    // the fan of the lowest quad keeps v; each other fan gets a copy
    std::map<int, int> copyOf; // a fan's root -> its vertex
    copyOf[findRoot(fan, 0)] = v;
    for (int i = 0; i < static_cast<int>(quads.size()); ++i)
    {
      const auto [at, added] =
        copyOf.emplace(findRoot(fan, i), nV + static_cast<int>(source.size()));
      if (added)
      {
        source.push_back(v);
      }
      for (int k = 0; k < 4; ++k)
      {
        if (mesh.Q(quads[i], k) == v)
        {
          mesh.Q(quads[i], k) = at->second;
        }
      }
    }
  }
  const int copies = static_cast<int>(source.size());
  mesh.V.conservativeResize(nV + copies, 3);
  for (int c = 0; c < copies; ++c)
  {
    mesh.V.row(nV + c) = mesh.V.row(source[c]);
    if (mesh.vertexTriangle.size() == static_cast<std::size_t>(nV) + c)
    {
      mesh.vertexTriangle.push_back(mesh.vertexTriangle[source[c]]);
    }
    if (mesh.vertexPoint.size() == static_cast<std::size_t>(nV) + c)
    {
      mesh.vertexPoint.push_back(mesh.vertexPoint[source[c]]);
    }
  }
  return copies;
}
}
