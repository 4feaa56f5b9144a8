#include "CutGraph.h"

#include <queue>
#include <stdexcept>

namespace quadcover
{

CutGraph computeCutGraph(const MeshTopology& topo, const std::vector<char>& terminal)
{
  const int nf = topo.numFaces, nv = topo.numVertices, ne = topo.numEdges();
  if (!topo.isManifold())
  {
    throw std::invalid_argument("computeCutGraph: the surface is not manifold");
  }
  if (!terminal.empty() && static_cast<int>(terminal.size()) != nv)
  {
    throw std::invalid_argument("computeCutGraph: one terminal flag per point expected");
  }
  CutGraph G;
  G.onCut.assign(ne, 0);

  // Spanning tree of the triangles across inner edges; every inner edge it does not cross is
  // cut to begin with.
  std::vector<char> crossed(ne, 0), reached(nf, 0);
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
  // Inner edges around each point; degree counts those on the cut, kept current below.
  std::vector<std::vector<std::pair<int, int>>> adjacent(nv); // (neighbour, inner edge)
  std::vector<int> degree(nv, 0);
  for (int e = 0; e < ne; ++e)
  {
    if (topo.edgeFaceCount[e] != 2)
    {
      continue;
    }
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    adjacent[a].push_back({ b, e });
    adjacent[b].push_back({ a, e });
    if (!crossed[e])
    {
      G.onCut[e] = 1;
      ++degree[a];
      ++degree[b];
    }
  }

  // Prune dangling branches: a point with one cut edge that is neither a terminal nor on the
  // boundary (where the cut surface's border already runs) lets its edge go.
  auto anchored = [&](
                    int v) { return topo.boundaryVertex[v] || (!terminal.empty() && terminal[v]); };
  std::vector<int> stack;
  for (int v = 0; v < nv; ++v)
  {
    if (degree[v] == 1 && !anchored(v))
    {
      stack.push_back(v);
    }
  }
  while (!stack.empty())
  {
    const int v = stack.back();
    stack.pop_back();
    if (degree[v] != 1 || anchored(v))
    {
      continue;
    }
    for (const auto& [w, e] : adjacent[v])
    {
      if (!G.onCut[e])
      {
        continue;
      }
      G.onCut[e] = 0;
      --degree[v];
      if (--degree[w] == 1 && !anchored(w))
      {
        stack.push_back(w);
      }
      break;
    }
  }
  // A terminal that no cut reaches (a closed disk-like component whose tree left nothing, e.g.
  // a sphere with one terminal) needs a path: join it to the cut, or to a boundary, or to the
  // component's first terminal, by the shortest edge path.
  std::vector<int> from(nv, -1), via(nv, -1), stamp(nv, -1);
  for (int v = 0; v < nv && !terminal.empty(); ++v)
  {
    if (!terminal[v] || degree[v] > 0 || topo.boundaryVertex[v])
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
      for (const auto& [w, e] : adjacent[u])
      {
        if (stamp[w] == v)
        {
          continue;
        }
        stamp[w] = v;
        from[w] = u;
        via[w] = e;
        if (degree[w] > 0 || topo.boundaryVertex[w] || (terminal[w] && w < v))
        {
          target = w;
          break;
        }
        q.push(w);
      }
    }
    for (int x = target; x >= 0 && x != v; x = from[x])
    {
      G.onCut[via[x]] = 1;
      ++degree[x];
      ++degree[from[x]];
    }
  }

  // Copies of each point once cut open, and the Euler characteristic per component.
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
  for (int f = 0; f < nf; ++f)
  {
    G.cutEuler[topo.faceComponent[f]] += 1;
  }
  return G;
}

}
