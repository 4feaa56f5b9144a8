// MeshTopology.cxx: edges, one-rings, boundary loops and components of a triangle mesh.
#include "MeshTopology.h"

#include "UnionFind.h"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace quadcover
{
namespace
{
bool isDegenerate(const Eigen::MatrixX3i& F, int f)
{
  return F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 2) == F(f, 0);
}

/**
 * Groups the triangles around one vertex into fans: triangles joined through an edge at the
 * vertex that has exactly two triangles. Orientation plays no part, so a misoriented but manifold
 * neighbourhood is one fan. Cost O(valence) with a scratch array of one entry per face.
 */
class FanLabeler
{
public:
  explicit FanLabeler(int numFaces)
    : Position(numFaces, -1)
  {}

  /// Labels faces[0..n) (all containing v, none degenerate); returns the number of fans.
  /// fan[i] is in [0, count), numbered in order of first appearance.
  int Label(const MeshTopology& T, const Eigen::MatrixX3i& F, int v, const int* faces, int n,
    std::vector<int>& fan)
  {
    for (int i = 0; i < n; ++i)
    {
      this->Position[faces[i]] = i;
    }
    this->Parent.resize(n);
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
    for (int i = 0; i < n; ++i)
    {
      const int f = faces[i];
      const int k = MeshTopology::cornerOf(F, f, v);
      for (const int edge : { k, (k + 2) % 3 })
      {
        const int g = T.faceNeighbors(f, edge);
        if (g >= 0 && this->Position[g] >= 0)
        {
          unite(this->Parent, i, this->Position[g]);
        }
      }
    }
    fan.assign(n, -1);
    std::vector<int> rootLabel(n, -1);
    int count = 0;
    for (int i = 0; i < n; ++i)
    {
      const int r = findRoot(this->Parent, i);
      if (rootLabel[r] < 0)
      {
        rootLabel[r] = count++;
      }
      fan[i] = rootLabel[r];
    }
    for (int i = 0; i < n; ++i)
    {
      this->Position[faces[i]] = -1;
    }
    return count;
  }

private:
  std::vector<int> Position; // face -> index in the current list, -1 elsewhere
  std::vector<int> Parent;
};

/// Checks that every index lies in [0, numVertices) and lists the triangles that repeat a vertex
/// (T.degenerateFaces). @return #F, 1 for such a triangle
std::vector<char> findDegenerateFaces(const Eigen::MatrixX3i& F, MeshTopology& T)
{
  const int nf = T.numFaces, numVertices = T.numVertices;
  std::vector<char> degenerate(nf, 0);
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
    if (isDegenerate(F, f))
    {
      degenerate[f] = 1;
      T.degenerateFaces.push_back(f);
    }
  }
  return degenerate;
}

struct HalfEdge
{
  int a, b, corner; // a < b; corner = 3f + k
};

/// The half-edges of the non-degenerate triangles sorted by their unordered vertex pair (then by
/// corner), so that the half-edges of one edge follow each other. A triangle that repeats a vertex
/// has no edges: it would only corrupt its neighbours'. Every index is in [0, numVertices).
std::vector<HalfEdge> sortedHalfEdges(
  const Eigen::MatrixX3i& F, const std::vector<char>& degenerate, int numVertices)
{
  // bucketed by the lower vertex in corner order (a counting sort), then each bucket, a few
  // half-edges, sorted by the higher vertex and corner: the order of one sort by (a, b, corner)
  // in linear time
  const int nf = static_cast<int>(F.rows());
  std::vector<int> offset(static_cast<size_t>(numVertices) + 1, 0);
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3 && !degenerate[f]; ++k)
    {
      ++offset[std::min(F(f, k), F(f, (k + 1) % 3)) + 1];
    }
  }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<HalfEdge> he(static_cast<size_t>(offset.back()));
  std::vector<int> next(offset.begin(), offset.end() - 1);
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3 && !degenerate[f]; ++k)
    {
      const int p = F(f, k), q = F(f, (k + 1) % 3);
      he[next[std::min(p, q)]++] = { std::min(p, q), std::max(p, q), 3 * f + k };
    }
  }
  for (int v = 0; v < numVertices; ++v)
  {
    std::sort(he.begin() + offset[v], he.begin() + offset[v + 1],
      [](const HalfEdge& x, const HalfEdge& y) {
        return x.b != y.b ? x.b < y.b : x.corner < y.corner;
      });
  }
  return he;
}

/// Edges and what hangs on them: T.edges, faceEdges, faceNeighbors, edgeFaces, edgeCorners,
/// edgeFaceCount, nonManifoldEdges and misorientedEdges.
void buildEdges(const Eigen::MatrixX3i& F, const std::vector<char>& degenerate, MeshTopology& T)
{
  const int nf = T.numFaces;
  const std::vector<HalfEdge> he = sortedHalfEdges(F, degenerate, T.numVertices);
  T.faceEdges.setConstant(nf, 3, -1);
  T.faceNeighbors.setConstant(nf, 3, -1);
  std::vector<Eigen::Vector2i> edgeList;
  std::vector<Eigen::Vector2i> edgeFaceList, edgeCornerList;
  std::vector<int> edgeCount;
  edgeList.reserve(he.size() / 2 + 1);
  for (size_t i = 0; i < he.size();)
  {
    size_t j = i;
    while (j < he.size() && he[j].a == he[i].a && he[j].b == he[i].b)
    {
      ++j;
    }
    const int e = static_cast<int>(edgeList.size());
    edgeList.emplace_back(he[i].a, he[i].b);
    const int count = static_cast<int>(j - i);
    edgeCount.push_back(count);
    Eigen::Vector2i ef(-1, -1), ec(-1, -1);
    for (size_t h = i; h < j; ++h)
    {
      T.faceEdges(he[h].corner / 3, he[h].corner % 3) = e;
      if (h - i < 2)
      {
        ef[static_cast<int>(h - i)] = he[h].corner / 3;
        ec[static_cast<int>(h - i)] = he[h].corner;
      }
    }
    edgeFaceList.push_back(ef);
    edgeCornerList.push_back(ec);
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
      T.faceNeighbors(f0, c0 % 3) = f1;
      T.faceNeighbors(f1, c1 % 3) = f0;
    }
    i = j;
  }
  const int ne = static_cast<int>(edgeList.size());
  T.edges.resize(ne, 2);
  T.edgeFaces.resize(ne, 2);
  T.edgeCorners.resize(ne, 2);
  T.edgeFaceCount.resize(ne);
  for (int e = 0; e < ne; ++e)
  {
    T.edges.row(e) = edgeList[e].transpose();
    T.edgeFaces.row(e) = edgeFaceList[e].transpose();
    T.edgeCorners.row(e) = edgeCornerList[e].transpose();
    T.edgeFaceCount[e] = edgeCount[e];
  }
}

/// The non-degenerate faces around each vertex in index order, as CSR (T.ringOffsets and
/// T.ringFaces). @return #V, 1 for a vertex some triangle (degenerate or not) refers to
std::vector<char> incidentFaces(
  const Eigen::MatrixX3i& F, const std::vector<char>& degenerate, MeshTopology& T)
{
  const int nf = T.numFaces, numVertices = T.numVertices;
  std::vector<int> offsets(numVertices + 1, 0);
  std::vector<char> referenced(numVertices, 0);
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      referenced[F(f, k)] = 1;
      if (!degenerate[f])
      {
        ++offsets[F(f, k) + 1];
      }
    }
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<int> incident(offsets.back());
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int f = 0; f < nf; ++f)
    {
      for (int k = 0; !degenerate[f] && k < 3; ++k)
      {
        incident[fill[F(f, k)]++] = f;
      }
    }
  }
  T.ringOffsets = offsets;
  T.ringFaces = incident;
  return referenced;
}

/**
 * Walks the n triangles around v counterclockwise: the next face is across edge k+2 (k = v's
 * corner), the previous across edge k; a boundary fan starts where there is no previous face.
 * A walk that visits all n faces once and ends where it should proves one fan.
 * @param[in] faces   the n faces around v (in index order)
 * @param[in] visited #F scratch marks, all 0 (and left so)
 * @param[out] ring   the faces in walking order
 * @return whether the walk proved one fan
 */
bool walkRing(const MeshTopology& T, const Eigen::MatrixX3i& F, int v, const int* faces, int n,
  std::vector<char>& visited, std::vector<int>& ring)
{
  int start = faces[0], starts = 0;
  for (int i = 0; i < n; ++i)
  {
    const int f = faces[i];
    if (T.faceNeighbors(f, MeshTopology::cornerOf(F, f, v)) < 0)
    {
      ++starts;
      start = f;
    }
  }
  ring.clear();
  if (starts > 1)
  {
    return false;
  }
  ring.reserve(n);
  int f = start;
  while (f >= 0 && !visited[f] && static_cast<int>(ring.size()) < n)
  {
    visited[f] = 1;
    ring.push_back(f);
    f = T.faceNeighbors(f, (MeshTopology::cornerOf(F, f, v) + 2) % 3);
  }
  for (int g : ring)
  {
    visited[g] = 0;
  }
  return static_cast<int>(ring.size()) == n && (starts == 0 ? f == start : f < 0);
}

/// Boundary vertices, ordered rings where the faces around a vertex form one fan, and the
/// unreferenced and non-manifold vertices. Where the walk fails, the fans are labelled
/// (orientation aside) to tell a non-manifold vertex from a misoriented one.
/// @return #V, 1 for a vertex some triangle refers to
std::vector<char> buildRings(
  const Eigen::MatrixX3i& F, const std::vector<char>& degenerate, MeshTopology& T)
{
  const int nf = T.numFaces, numVertices = T.numVertices;
  std::vector<char> referenced = incidentFaces(F, degenerate, T);
  const std::vector<int> incident = T.ringFaces; // replaced by the ordered ring where there is one
  T.ringOrdered.assign(numVertices, 0);
  T.boundaryVertex.assign(numVertices, 0);
  for (int e = 0; e < T.numEdges(); ++e)
  {
    if (T.edgeFaceCount[e] == 1)
    {
      T.boundaryVertex[T.edges(e, 0)] = T.boundaryVertex[T.edges(e, 1)] = 1;
    }
  }
  FanLabeler fans(nf);
  std::vector<int> fan, ring;
  std::vector<char> visited(nf, 0);
  for (int v = 0; v < numVertices; ++v)
  {
    const int begin = T.ringOffsets[v], n = T.ringOffsets[v + 1] - T.ringOffsets[v];
    if (!referenced[v])
    {
      T.unreferencedVertices.push_back(v);
      continue;
    }
    if (n == 0)
    {
      continue; // only degenerate triangles here: reported as such
    }
    if (walkRing(T, F, v, incident.data() + begin, n, visited, ring))
    {
      std::copy(ring.begin(), ring.end(), T.ringFaces.begin() + begin);
      T.ringOrdered[v] = 1;
    }
    else if (fans.Label(T, F, v, incident.data() + begin, n, fan) > 1)
    {
      T.nonManifoldVertices.push_back(v);
    }
  }
  return referenced;
}

/// Boundary loops: walk boundary edges vertex to vertex until back at the start vertex. The walk
/// keeps the triangles' direction where it can; on a non-orientable surface (a Moebius strip) the
/// boundary edges' directions flip, so it goes by adjacency, not by direction.
void buildBoundaryLoops(const Eigen::MatrixX3i& F, MeshTopology& T)
{
  const int nf = T.numFaces;
  std::vector<std::vector<int>> atVertex(T.numVertices); // boundary corners touching a vertex
  std::vector<int> boundaryCorners;
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int e = T.faceEdges(f, k);
      if (e >= 0 && T.edgeFaceCount[e] == 1)
      {
        boundaryCorners.push_back(3 * f + k);
        atVertex[F(f, k)].push_back(3 * f + k);
        atVertex[F(f, (k + 1) % 3)].push_back(3 * f + k);
      }
    }
  }
  auto tail = [&](int c) { return F(c / 3, c % 3); };
  auto head = [&](int c) { return F(c / 3, (c % 3 + 1) % 3); };
  std::vector<char> used(3 * static_cast<size_t>(nf), 0);
  for (int c0 : boundaryCorners)
  {
    if (used[c0])
    {
      continue;
    }
    used[c0] = 1;
    const int start = tail(c0);
    std::vector<int> loop = { start };
    int current = head(c0);
    while (current != start)
    {
      loop.push_back(current);
      int next = -1;
      for (int c : atVertex[current])
      {
        if (!used[c] && (next < 0 || tail(c) == current))
        {
          next = c; // any unused edge, preferably one leaving in the triangles' direction
        }
      }
      if (next < 0)
      {
        break; // an open path: only next to defects that are reported anyway
      }
      used[next] = 1;
      current = tail(next) == current ? head(next) : tail(next);
    }
    T.boundaryLoops.push_back(std::move(loop));
  }
}

/// Components over vertices joined by triangle edges (T.vertexComponent, faceComponent), numbered
/// in order of their lowest referenced vertex; their ComponentInfo is left empty.
void labelComponents(
  const Eigen::MatrixX3i& F, const std::vector<char>& referenced, MeshTopology& T)
{
  const int nf = T.numFaces, numVertices = T.numVertices;
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
    if (!referenced[v])
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
  for (int f = 0; f < nf; ++f)
  {
    T.faceComponent[f] = T.vertexComponent[F(f, 0)];
  }
}

/// Each component's counts, defects, Euler characteristic and genus.
void describeComponents(MeshTopology& T)
{
  for (int v = 0; v < T.numVertices; ++v)
  {
    if (T.vertexComponent[v] >= 0)
    {
      ++T.components[T.vertexComponent[v]].numVertices;
    }
  }
  for (int f = 0; f < T.numFaces; ++f)
  {
    ++T.components[T.faceComponent[f]].numFaces;
  }
  for (int e = 0; e < T.numEdges(); ++e)
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
  const std::vector<char> degenerate = findDegenerateFaces(F, T);
  buildEdges(F, degenerate, T);
  const std::vector<char> referenced = buildRings(F, degenerate, T);
  buildBoundaryLoops(F, T);
  labelComponents(F, referenced, T);
  describeComponents(T);
  return T;
}

}
