#include "MeshTopology.h"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace quadcover
{
namespace
{
int findRoot(std::vector<int>& parent, int x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void unite(std::vector<int>& parent, int a, int b)
{
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a != b)
  {
    parent[std::max(a, b)] = std::min(a, b);
  }
}
}

int MeshTopology::eulerCharacteristic() const
{
  int chi = 0;
  for (const ComponentInfo& c : components)
  {
    chi += c.eulerCharacteristic;
  }
  return chi;
}

std::string MeshTopology::describeDefects() const
{
  std::ostringstream os;
  const char* sep = "";
  auto item = [&](size_t n, const char* what) {
    if (n > 0)
    {
      os << sep << n << ' ' << what;
      sep = ", ";
    }
  };
  item(degenerateFaces.size(), "triangles that repeat a vertex");
  item(nonManifoldEdges.size(), "non-manifold edges (more than two triangles)");
  item(nonManifoldVertices.size(), "non-manifold vertices");
  item(misorientedEdges.size(), "edges between inconsistently oriented triangles");
  return os.str();
}

MeshTopology buildTopology(const Eigen::MatrixX3i& F, int numVertices)
{
  if (numVertices < 0)
  {
    throw std::invalid_argument("buildTopology: negative vertex count");
  }
  MeshTopology T;
  T.numVertices = numVertices;
  T.numFaces = static_cast<int>(F.rows());
  const int nf = T.numFaces;
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (F(f, k) < 0 || F(f, k) >= numVertices)
      {
        throw std::invalid_argument("buildTopology: triangle " + std::to_string(f) +
          " refers to vertex " + std::to_string(F(f, k)) + " of " + std::to_string(numVertices));
      }
    }
    if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 2) == F(f, 0))
    {
      T.degenerateFaces.push_back(f);
    }
  }

  // Edges: sort the 3F half-edges by their unordered vertex pair.
  struct HalfEdge
  {
    int a, b, corner; // a < b; corner = 3f + k
  };
  std::vector<HalfEdge> he(3 * static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int p = F(f, k), q = F(f, (k + 1) % 3);
      he[3 * f + k] = { std::min(p, q), std::max(p, q), 3 * f + k };
    }
  }
  std::sort(he.begin(), he.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.corner < y.corner);
  });

  T.faceEdges.setConstant(nf, 3, -1);
  T.faceNeighbors.setConstant(nf, 3, -1);
  std::vector<Eigen::Vector2i> edgeList;
  std::vector<Eigen::Vector2i> edgeFaceList;
  std::vector<int> edgeCount;
  edgeList.reserve(he.size() / 2 + 1);
  for (size_t i = 0; i < he.size();)
  {
    size_t j = i;
    while (j < he.size() && he[j].a == he[i].a && he[j].b == he[i].b)
    {
      ++j;
    }
    if (he[i].a == he[i].b)
    {
      i = j; // an edge of a degenerate triangle: no edge, recorded in degenerateFaces
      continue;
    }
    const int e = static_cast<int>(edgeList.size());
    edgeList.emplace_back(he[i].a, he[i].b);
    const int count = static_cast<int>(j - i);
    edgeCount.push_back(count);
    Eigen::Vector2i ef(-1, -1);
    for (size_t h = i; h < j; ++h)
    {
      T.faceEdges(he[h].corner / 3, he[h].corner % 3) = e;
      if (h - i < 2)
      {
        ef[static_cast<int>(h - i)] = he[h].corner / 3;
      }
    }
    edgeFaceList.push_back(ef);
    if (count > 2)
    {
      T.nonManifoldEdges.push_back(e);
    }
    else if (count == 2)
    {
      const int c0 = he[i].corner, c1 = he[i + 1].corner;
      const int f0 = c0 / 3, f1 = c1 / 3;
      if (F(f0, c0 % 3) == F(f1, c1 % 3))
      {
        T.misorientedEdges.push_back(e);
      }
      if (f0 != f1)
      {
        T.faceNeighbors(f0, c0 % 3) = f1;
        T.faceNeighbors(f1, c1 % 3) = f0;
      }
    }
    i = j;
  }
  const int ne = static_cast<int>(edgeList.size());
  T.edges.resize(ne, 2);
  T.edgeFaces.resize(ne, 2);
  T.edgeFaceCount.resize(ne);
  for (int e = 0; e < ne; ++e)
  {
    T.edges.row(e) = edgeList[e].transpose();
    T.edgeFaces.row(e) = edgeFaceList[e].transpose();
    T.edgeFaceCount[e] = edgeCount[e];
  }

  // Incident corners per vertex (CSR), then the ordered one-rings.
  std::vector<int> offsets(numVertices + 1, 0);
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++offsets[F(f, k) + 1];
    }
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<int> incident(offsets.back());
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int f = 0; f < nf; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        incident[fill[F(f, k)]++] = f;
      }
    }
  }
  T.ringOffsets = offsets;
  T.ringFaces.assign(incident.size(), -1);
  T.boundaryVertex.assign(numVertices, 0);
  std::vector<char> degenerate(nf, 0);
  for (int f : T.degenerateFaces)
  {
    degenerate[f] = 1;
  }
  for (int v = 0; v < numVertices; ++v)
  {
    const int begin = offsets[v], end = offsets[v + 1];
    if (begin == end)
    {
      T.unreferencedVertices.push_back(v);
      continue;
    }
    // Around v, the next face counterclockwise is across edge (k+2) of f, the previous across
    // edge k, where k is v's corner in f.
    int start = incident[begin];
    int starts = 0;
    bool usable = true;
    for (int i = begin; i < end; ++i)
    {
      const int f = incident[i];
      const int k = MeshTopology::cornerOf(F, f, v);
      if (degenerate[f])
      {
        usable = false;
        continue;
      }
      if (T.faceNeighbors(f, k) < 0)
      {
        ++starts;
        start = f;
      }
    }
    if (starts > 0)
    {
      T.boundaryVertex[v] = 1;
    }
    int count = 0;
    if (usable && starts <= 1)
    {
      int f = start;
      do
      {
        T.ringFaces[begin + count++] = f;
        const int k = MeshTopology::cornerOf(F, f, v);
        f = T.faceNeighbors(f, (k + 2) % 3);
      } while (f >= 0 && f != start && count < end - begin);
      if ((f == start) == (starts == 1))
      {
        usable = false; // a closed walk around a boundary vertex, or an open one around an inner
      }
    }
    if (!usable || starts > 1 || count != end - begin)
    {
      T.nonManifoldVertices.push_back(v);
      std::copy(incident.begin() + begin, incident.begin() + end, T.ringFaces.begin() + begin);
    }
  }

  // Boundary loops: follow boundary half-edges tail to head.
  {
    std::vector<int> outgoing(numVertices, -1); // boundary corner 3f+k leaving the vertex
    std::vector<int> boundaryCorners;
    for (int f = 0; f < nf; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int e = T.faceEdges(f, k);
        if (e >= 0 && T.edgeFaceCount[e] == 1)
        {
          boundaryCorners.push_back(3 * f + k);
          int& o = outgoing[F(f, k)];
          if (o < 0)
          {
            o = 3 * f + k;
          }
        }
      }
    }
    std::vector<char> used(3 * static_cast<size_t>(nf), 0);
    for (int c0 : boundaryCorners)
    {
      if (used[c0])
      {
        continue;
      }
      std::vector<int> loop;
      int c = c0;
      while (c >= 0 && !used[c])
      {
        used[c] = 1;
        const int f = c / 3, k = c % 3;
        loop.push_back(F(f, k));
        const int next = F(f, (k + 1) % 3);
        c = outgoing[next];
        if (c >= 0 && used[c])
        {
          // At a non-manifold vertex two loops touch; look for an unused outgoing corner.
          c = -1;
          for (int i = offsets[next]; i < offsets[next + 1] && c < 0; ++i)
          {
            const int g = incident[i];
            const int kk = MeshTopology::cornerOf(F, g, next);
            const int e = T.faceEdges(g, kk);
            if (e >= 0 && T.edgeFaceCount[e] == 1 && !used[3 * g + kk])
            {
              c = 3 * g + kk;
            }
          }
        }
      }
      T.boundaryLoops.push_back(std::move(loop));
    }
  }

  // Components over vertices joined by triangle edges.
  std::vector<int> parent(numVertices);
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < nf; ++f)
  {
    unite(parent, F(f, 0), F(f, 1));
    unite(parent, F(f, 0), F(f, 2));
  }
  T.vertexComponent.setConstant(numVertices, -1);
  std::vector<int> rootToComponent(numVertices, -1);
  int nc = 0;
  for (int v = 0; v < numVertices; ++v)
  {
    if (offsets[v + 1] == offsets[v])
    {
      continue;
    }
    const int r = findRoot(parent, v);
    if (rootToComponent[r] < 0)
    {
      rootToComponent[r] = nc++;
    }
    T.vertexComponent[v] = rootToComponent[r];
  }
  T.components.assign(nc, ComponentInfo());
  T.faceComponent.resize(nf);
  for (int v = 0; v < numVertices; ++v)
  {
    if (T.vertexComponent[v] >= 0)
    {
      ++T.components[T.vertexComponent[v]].numVertices;
    }
  }
  for (int f = 0; f < nf; ++f)
  {
    T.faceComponent[f] = T.vertexComponent[F(f, 0)];
    ++T.components[T.faceComponent[f]].numFaces;
  }
  for (int e = 0; e < ne; ++e)
  {
    ++T.components[T.vertexComponent[T.edges(e, 0)]].numEdges;
  }
  for (const auto& loop : T.boundaryLoops)
  {
    ++T.components[T.vertexComponent[loop.front()]].numBoundaryLoops;
  }
  for (int f : T.degenerateFaces)
  {
    T.components[T.faceComponent[f]].manifold = false;
  }
  for (int e : T.nonManifoldEdges)
  {
    T.components[T.vertexComponent[T.edges(e, 0)]].manifold = false;
  }
  for (int v : T.nonManifoldVertices)
  {
    T.components[T.vertexComponent[v]].manifold = false;
  }
  for (int e : T.misorientedEdges)
  {
    T.components[T.vertexComponent[T.edges(e, 0)]].oriented = false;
  }
  for (ComponentInfo& c : T.components)
  {
    c.eulerCharacteristic = c.numVertices - c.numEdges + c.numFaces;
    const int twiceGenus = 2 - c.eulerCharacteristic - c.numBoundaryLoops;
    c.genus =
      (c.manifold && c.oriented && twiceGenus >= 0 && twiceGenus % 2 == 0) ? twiceGenus / 2 : -1;
  }
  return T;
}

std::vector<int> splitNonManifoldVertices(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F)
{
  const MeshTopology T = buildTopology(F, static_cast<int>(V.rows()));
  std::vector<int> copies;
  int next = static_cast<int>(V.rows());
  std::vector<int> parent;
  std::vector<char> onNonManifoldEdge(V.rows(), 0);
  for (int e : T.nonManifoldEdges)
  {
    onNonManifoldEdge[T.edges(e, 0)] = onNonManifoldEdge[T.edges(e, 1)] = 1;
  }
  for (int v : T.nonManifoldVertices)
  {
    if (onNonManifoldEdge[v])
    {
      continue; // splitting here would cut the edge open: left for the caller to refuse
    }
    const int begin = T.ringOffsets[v], end = T.ringOffsets[v + 1];
    const int n = end - begin;
    // Join incident triangles that share an edge at v.
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0);
    for (int i = 0; i < n; ++i)
    {
      const int f = T.ringFaces[begin + i];
      const int k = MeshTopology::cornerOf(F, f, v);
      if (k < 0)
      {
        continue;
      }
      for (const int edge : { k, (k + 2) % 3 })
      {
        const int g = T.faceNeighbors(f, edge);
        for (int j = 0; g >= 0 && j < n; ++j)
        {
          if (T.ringFaces[begin + j] == g)
          {
            unite(parent, i, j);
          }
        }
      }
    }
    // Fan of the first triangle keeps v; every other fan gets a copy.
    std::vector<int> fanVertex(n, -1);
    for (int i = 0; i < n; ++i)
    {
      const int root = findRoot(parent, i);
      if (fanVertex[root] < 0)
      {
        fanVertex[root] = root == 0 ? v : next++;
        if (root != 0)
        {
          copies.push_back(v);
        }
      }
      const int f = T.ringFaces[begin + i];
      for (int k = 0; k < 3; ++k)
      {
        if (F(f, k) == v)
        {
          F(f, k) = fanVertex[root];
        }
      }
    }
  }
  if (!copies.empty())
  {
    const Eigen::Index old = V.rows();
    V.conservativeResize(old + static_cast<Eigen::Index>(copies.size()), 3);
    for (size_t i = 0; i < copies.size(); ++i)
    {
      V.row(old + static_cast<Eigen::Index>(i)) = V.row(copies[i]);
    }
  }
  return copies;
}

}
