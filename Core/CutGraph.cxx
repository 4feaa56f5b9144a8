// CutGraph.cxx: the cut graph, grown from a spanning tree of the triangles and pruned.
#include "CutGraph.h"

#include <algorithm>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
/// Breadth-first spanning trees of the triangles across inner edges, one per component, each
/// grown from its lowest triangle. @return #E, 1 for an edge a tree crosses
std::vector<char> spanningTreeEdges(const MeshTopology& topo)
{
  const int nf = topo.numFaces;
  std::vector<char> crossed(topo.numEdges(), 0), reached(nf, 0);
  std::queue<int> queue;
  for (int seed = 0; seed < nf; ++seed)
  {
    if (reached[seed])
    {
      continue;
    }
    reached[seed] = 1;
    queue.push(seed);
    while (!queue.empty())
    {
      const int f = queue.front();
      queue.pop();
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo.faceNeighbors(f, k);
        if (g >= 0 && !reached[g])
        {
          reached[g] = 1;
          crossed[topo.faceEdges(f, k)] = 1;
          queue.push(g);
        }
      }
    }
  }
  return crossed;
}

/// The cut while it is being shaped: the inner edges around each point, and how many of them are
/// on the cut.
struct CutState
{
  const MeshTopology& topo;
  const std::vector<char>& terminal;
  std::vector<char>& onCut;
  std::vector<std::vector<std::pair<int, int>>> adjacent; ///< #V (neighbour, inner edge)
  std::vector<int> degree;                                ///< #V cut edges at the point

  /// A point where a cut may end: on the boundary (where the cut surface's border already runs)
  /// or a terminal.
  bool anchored(int v) const
  {
    return topo.boundaryVertex[v] || (!terminal.empty() && terminal[v]);
  }

  /// Puts the inner edge e between a and b on the cut.
  void cut(int e, int a, int b)
  {
    onCut[e] = 1;
    ++degree[a];
    ++degree[b];
  }
};

/// Every inner edge the spanning trees do not cross is cut to begin with.
void cutAllButTree(CutState& S, const std::vector<char>& crossed)
{
  const MeshTopology& topo = S.topo;
  S.adjacent.assign(topo.numVertices, {});
  S.degree.assign(topo.numVertices, 0);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (topo.edgeFaceCount[e] != 2)
    {
      continue;
    }
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    S.adjacent[a].push_back({ b, e });
    S.adjacent[b].push_back({ a, e });
    if (!crossed[e])
    {
      S.cut(e, a, b);
    }
  }
}

/// Prunes dangling branches: a point with one cut edge that is not anchored lets its edge go.
void pruneDanglingBranches(CutState& S)
{
  std::vector<int> stack;
  for (int v = 0; v < S.topo.numVertices; ++v)
  {
    if (S.degree[v] == 1 && !S.anchored(v))
    {
      stack.push_back(v);
    }
  }
  while (!stack.empty())
  {
    const int v = stack.back();
    stack.pop_back();
    if (S.degree[v] != 1 || S.anchored(v))
    {
      continue;
    }
    for (const auto& [w, e] : S.adjacent[v])
    {
      if (!S.onCut[e])
      {
        continue;
      }
      S.onCut[e] = 0;
      --S.degree[v];
      if (--S.degree[w] == 1 && !S.anchored(w))
      {
        stack.push_back(w);
      }
      break;
    }
  }
}

/// A terminal that no cut reaches (a closed disk-like component whose tree left nothing, e.g. a
/// sphere with one terminal) needs a path: join it to the cut, or to a boundary, or to the
/// component's first terminal, by the shortest edge path.
void joinLoneTerminals(CutState& S)
{
  const MeshTopology& topo = S.topo;
  const int nv = topo.numVertices;
  std::vector<int> from(nv, -1), via(nv, -1), stamp(nv, -1);
  for (int v = 0; v < nv && !S.terminal.empty(); ++v)
  {
    if (!S.terminal[v] || S.degree[v] > 0 || topo.boundaryVertex[v])
    {
      continue;
    }
    // Breadth-first from v to the nearest point already on the cut, on the boundary, or an
    // earlier terminal of the same component.
    std::queue<int> q;
    q.push(v);
    stamp[v] = v;
    int target = -1;
    while (!q.empty() && target < 0)
    {
      const int u = q.front();
      q.pop();
      for (const auto& [w, e] : S.adjacent[u])
      {
        if (stamp[w] == v)
        {
          continue;
        }
        stamp[w] = v;
        from[w] = u;
        via[w] = e;
        if (S.degree[w] > 0 || topo.boundaryVertex[w] || (S.terminal[w] && w < v))
        {
          target = w;
          break;
        }
        q.push(w);
      }
    }
    for (int x = target; x >= 0 && x != v; x = from[x])
    {
      S.cut(via[x], x, from[x]);
    }
  }
}

/// The number of cut edges, the copies of each point once cut open, and the Euler
/// characteristic of the cut surface per component.
void countCutSurface(const MeshTopology& topo, const std::vector<int>& degree, CutGraph& G)
{
  const int nv = topo.numVertices, ne = topo.numEdges();
  G.copies.assign(nv, 0);
  for (int e = 0; e < ne; ++e)
  {
    G.numCutEdges += G.onCut[e];
  }
  for (int v = 0; v < nv; ++v)
  {
    if (topo.valence(v) == 0)
    {
      continue;
    }
    // Around an inner point c cut edges make c sectors (one if none); on the boundary the fan
    // is already open, so c cuts make c + 1.
    G.copies[v] = topo.boundaryVertex[v] ? degree[v] + 1 : std::max(degree[v], 1);
  }
  G.cutEuler.assign(topo.numComponents(), 0);
  for (int v = 0; v < nv; ++v)
  {
    if (topo.vertexComponent[v] >= 0)
    {
      G.cutEuler[topo.vertexComponent[v]] += G.copies[v];
    }
  }
  for (int e = 0; e < ne; ++e)
  {
    G.cutEuler[topo.vertexComponent[topo.edges(e, 0)]] -= 1 + G.onCut[e];
  }
  for (int f = 0; f < topo.numFaces; ++f)
  {
    G.cutEuler[topo.faceComponent[f]] += 1;
  }
}
}

CutGraph computeCutGraph(const MeshTopology& topo, const std::vector<char>& terminal)
{
  if (!topo.isManifold())
  {
    throw std::invalid_argument("computeCutGraph: the surface is not manifold");
  }
  if (!terminal.empty() && static_cast<int>(terminal.size()) != topo.numVertices)
  {
    throw std::invalid_argument("computeCutGraph: one terminal flag per point expected");
  }
  CutGraph G;
  G.onCut.assign(topo.numEdges(), 0);
  CutState S{ topo, terminal, G.onCut, {}, {} };
  cutAllButTree(S, spanningTreeEdges(topo));
  pruneDanglingBranches(S);
  joinLoneTerminals(S);
  countCutSurface(topo, S.degree, G);
  return G;
}

}
