// BranchPointSearch.h: internal to Core. The edge paths along which the branch-point stages
// change matchings (BranchPoints.cxx: merges, splits, cancellations; ConePairs.cxx: pairs added):
// the steps of a path, the search, the optimizer's state and the twist check.
#ifndef quadcover_BranchPointSearch_h
#define quadcover_BranchPointSearch_h

#include "MatchingAngles.h"
#include "Matchings.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <utility>
#include <vector>

namespace quadcover
{
namespace branchsearch
{
using detail::mod4;
using detail::Pi;
using detail::Quarter;
using detail::residual;
using detail::turning;

/// The singularities in quarter turns: 4 index at an inner point, 0 on the boundary.
inline std::vector<int> quarterTurns(const MeshTopology& topo, const Eigen::VectorXd& index)
{
  std::vector<int> q(topo.numVertices, 0);
  for (int v = 0; v < topo.numVertices; ++v)
  {
    q[v] = topo.boundaryVertex[v] ? 0 : static_cast<int>(std::lround(4.0 * index[v]));
  }
  return q;
}

/// Primal adjacency over inner edges between inner vertices. Walking an edge from u to `to` and
/// adding `delta` to the matching from g to f (g: the face where the edge runs to -> u, f: where
/// it runs u -> to) adds delta to the layer shift of u and takes it from `to`.
struct Step
{
  int to, g, kg, f, kf;
};
using Steps = std::vector<std::vector<Step>>;

inline Steps pathSteps(const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  Steps steps(topo.numVertices);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (topo.edgeFaceCount[e] != 2)
    {
      continue;
    }
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    if (topo.boundaryVertex[a] || topo.boundaryVertex[b] || !topo.ringOrdered[a] ||
      !topo.ringOrdered[b])
    {
      continue;
    }
    const int f0 = topo.edgeFaces(e, 0), f1 = topo.edgeFaces(e, 1);
    const int k0 = topo.edgeCorners(e, 0) % 3, k1 = topo.edgeCorners(e, 1) % 3;
    // In f0 the edge runs F(f0,k0) -> F(f0,k0+1).
    const int from0 = F(f0, k0);
    // u = from0, w = the other: f = f0 (runs u -> w), g = f1.
    steps[from0].push_back({ from0 == a ? b : a, f1, k1, f0, k0 });
    steps[from0 == a ? b : a].push_back({ from0, f0, k0, f1, k1 });
  }
  return steps;
}

/// What one edge's deviation counts for (BranchPointOptions::lengthScaled).
inline double edgeWeight(const FrameGeometry& geometry, const Step& s, bool lengthScaled)
{
  const double reference = referenceLengthAt(geometry, s.g);
  if (!lengthScaled || !(reference > 0) || geometry.edgeLength.rows() == 0)
  {
    return 1.0;
  }
  return geometry.edgeLength(s.g, s.kg) / reference;
}

/// Dijkstra over the steps from one point at a time. Its arrays serve every search of an
/// optimization: an entry belongs to the current search where stamp says so.
struct PathSearch
{
  using Item = std::pair<double, int>;
  std::vector<double> dist;
  std::vector<int> cameFrom, stepIndex, stamp;
  int search = 0;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;

  explicit PathSearch(int nv)
    : dist(nv, 0.0)
    , cameFrom(nv, -1)
    , stepIndex(nv, -1)
    , stamp(nv, -1)
  {}

  /// Starts a new search from a.
  void begin(int a)
  {
    ++search;
    queue = decltype(queue)();
    dist[a] = 0.0;
    stamp[a] = search;
    cameFrom[a] = -1;
    queue.push({ 0.0, a });
  }

  /// Reaching `to` by u's step i at distance nd: kept (and queued) when it is the first way
  /// there in this search or a shorter one.
  bool relax(int u, int i, int to, double nd)
  {
    if (stamp[to] != search || nd < dist[to])
    {
      stamp[to] = search;
      dist[to] = nd;
      cameFrom[to] = u;
      stepIndex[to] = i;
      queue.push({ nd, to });
      return true;
    }
    return false;
  }

  /// The step by which the search reached x.
  const Step& stepTo(const Steps& steps, int x) const { return steps[cameFrom[x]][stepIndex[x]]; }
};

/// What the optimization works on: the frames' angles, the steps of paths, the matchings it
/// changes and the singularities in quarter turns (q = 4 index, 0 on the boundary).
struct Optimizer
{
  const Eigen::MatrixX3i& F;
  const MeshTopology& topo;
  const FrameGeometry& geometry;
  const BranchPointOptions& options;
  const Eigen::VectorXd phi;
  const Steps steps;
  Eigen::MatrixX3i& M;
  std::vector<int> q;
  PathSearch search;

  Optimizer(const Eigen::MatrixX3i& F_, const MeshTopology& topo_, const FrameGeometry& geometry_,
    const Eigen::MatrixX3d& frameU, FrameTopology& topology, const BranchPointOptions& options_)
    : F(F_)
    , topo(topo_)
    , geometry(geometry_)
    , options(options_)
    , phi(vectorAngles(geometry_.bases, frameU))
    , steps(pathSteps(F_, topo_))
    , M(topology.matching)
    , q(quarterTurns(topo_, topology.index))
    , search(topo_.numVertices)
  {}

  /// The deviation across the step's edge with its matching changed by delta quarter turns.
  double deviationWith(const Step& s, int delta) const
  {
    const int r = mod4(M(s.g, s.kg) + delta);
    return std::abs(residual(turning(geometry, phi, s.g, s.kg, s.f), r));
  }

  /// Would changing the step's matching by delta quarter turns wrap its residual past +-pi (and
  /// so move a whole turn of index onto a point between)? If not, what it adds to the deviation.
  bool stepCost(const Step& s, int delta, double& added) const
  {
    const double r0 = residual(turning(geometry, phi, s.g, s.kg, s.f), M(s.g, s.kg));
    if (!(std::abs(r0 + delta * Quarter) < Pi))
    {
      return false;
    }
    added = (std::abs(r0 + delta * Quarter) - std::abs(r0)) *
      edgeWeight(geometry, s, options.lengthScaledCost);
    return true;
  }

  /// Changes the matchings along the path the last search found from start to end by delta
  /// quarter turns: delta more at start, delta less at end.
  void changePath(int start, int end, int delta)
  {
    for (int x = end; x != start; x = search.cameFrom[x])
    {
      const Step& s = search.stepTo(steps, x);
      M(s.g, s.kg) = mod4(M(s.g, s.kg) + delta);
      M(s.f, s.kf) = mod4(-M(s.g, s.kg));
    }
    q[start] += delta;
    q[end] -= delta;
  }
};

/**
 * A component between two or more boundary loops (a tube, say) whose last singularities a merge
 * removes: its frames must then carry the same frame family along every loop whose frames follow
 * it, or no grid can have all of its loops on grid lines (a tube whose field turns a quarter from
 * one end to the other). The pair that absorbed the quarter turn stays.
 */
class TwistCheck
{
public:
  explicit TwistCheck(const Optimizer& o)
    : O(o)
    , EdgeLoop(o.topo.numEdges(), -1)
    , Label(o.F.rows(), -1)
  {
    const MeshTopology& topo = o.topo;
    std::vector<int> vertexLoop(topo.numVertices, -1);
    for (int l = 0; l < static_cast<int>(topo.boundaryLoops.size()); ++l)
    {
      for (const int v : topo.boundaryLoops[l])
      {
        vertexLoop[v] = l;
      }
    }
    for (int e = 0; e < topo.numEdges(); ++e)
    {
      if (topo.edgeFaceCount[e] == 1)
      {
        EdgeLoop[e] = vertexLoop[topo.edges(e, 0)];
      }
    }
  }

  /// Whether the component, between two or more loops, has no singularity left and its frames
  /// follow different frame families along different loops.
  bool twisted(int component)
  {
    const MeshTopology& topo = O.topo;
    if (component < 0 || component >= static_cast<int>(topo.components.size()))
    {
      return false;
    }
    const ComponentInfo& info = topo.components[component];
    if (info.numBoundaryLoops < 2 || info.genus != 0)
    {
      return false;
    }
    for (int v = 0; v < topo.numVertices; ++v)
    {
      if (O.q[v] != 0 && topo.vertexComponent[v] == component)
      {
        return false; // singularities left: the frame family is not the same along every path
      }
    }
    int root = -1;
    for (int f = 0; f < static_cast<int>(O.F.rows()) && root < 0; ++f)
    {
      root = topo.faceComponent[f] == component ? f : -1;
    }
    return root >= 0 && familiesDiffer(loopFamilies(root));
  }

private:
  /// Carries the root's X_0 across the matchings (Label(f): which of f's frame vectors it is) and
  /// reads, for each loop, the parity of the frame vector that follows its edges: loop -> parity,
  /// or -1 where the loop mixes families.
  std::map<int, int> loopFamilies(int root)
  {
    const MeshTopology& topo = O.topo;
    std::fill(Label.begin(), Label.end(), -1);
    std::vector<int> stack = { root };
    Label[root] = 0;
    std::map<int, int> loopFamily;
    const double tolerance = O.options.boundaryTolerance * Pi / 180.0;
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo.faceNeighbors(f, k);
        if (g >= 0)
        {
          if (Label[g] < 0 && O.M(f, k) >= 0)
          {
            Label[g] = mod4(Label[f] + O.M(f, k));
            stack.push_back(g);
          }
          continue;
        }
        const int loop = EdgeLoop[topo.faceEdges(f, k)];
        if (loop < 0)
        {
          continue;
        }
        const double along = O.geometry.edgeAngle(f, k) - O.phi[f];
        const double quarters = std::round(along / Quarter);
        if (std::abs(wrapAngle(along - quarters * Quarter)) > tolerance)
        {
          continue; // the frame does not follow this edge
        }
        const int family = ((static_cast<int>(quarters) - Label[f]) % 2 + 2) % 2;
        const auto [it, inserted] = loopFamily.insert({ loop, family });
        if (!inserted && it->second != family)
        {
          it->second = -1;
        }
      }
    }
    return loopFamily;
  }

  /// Do two loops that each follow one family follow different ones?
  static bool familiesDiffer(const std::map<int, int>& loopFamily)
  {
    int seen = -1;
    for (const auto& entry : loopFamily)
    {
      if (entry.second < 0)
      {
        continue;
      }
      if (seen >= 0 && entry.second != seen)
      {
        return true;
      }
      seen = entry.second;
    }
    return false;
  }

  const Optimizer& O;
  std::vector<int> EdgeLoop; // #E the boundary loop of a boundary edge, else -1
  std::vector<int> Label;    // #F scratch of loopFamilies
};

/// Changes the matchings along the path the last search found from a to u by delta quarter
/// turns, and marks the faces on both sides of its edges in changedFaces; undone (false) when
/// that leaves a's component twisted.
inline bool changeUntwisted(
  Optimizer& o, TwistCheck& twist, int a, int u, int delta, std::vector<char>& changedFaces)
{
  o.changePath(a, u, delta);
  if (twist.twisted(o.topo.vertexComponent[a]))
  {
    o.changePath(a, u, -delta);
    return false;
  }
  for (int x = u; x != a; x = o.search.cameFrom[x])
  {
    const Step& s = o.search.stepTo(o.steps, x);
    changedFaces[s.g] = changedFaces[s.f] = 1;
  }
  return true;
}

}
}

#endif
