// BranchPoints.cxx: the greedy branch-point optimization (QuadCover Sect. 4.2): singularities of
// index >= 1/2 split into quarters, then singular points cleared along their cheapest edge paths.
#include "Matchings.h"

#include "MatchingAngles.h"
#include "SurfaceDisks.h"

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
namespace
{
using detail::mod4;
using detail::Pi;
using detail::Quarter;
using detail::residual;
using detail::turning;

/// Primal adjacency over inner edges between inner vertices. Walking an edge from u to `to` and
/// adding `delta` to the matching from g to f (g: the face where the edge runs to -> u, f: where
/// it runs u -> to) adds delta to the layer shift of u and takes it from `to`.
struct Step
{
  int to, g, kg, f, kf;
};
using Steps = std::vector<std::vector<Step>>;

Steps pathSteps(const Eigen::MatrixX3i& F, const MeshTopology& topo)
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
double edgeWeight(const FrameGeometry& geometry, const Step& s, bool lengthScaled)
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
    , q(topo_.numVertices, 0)
    , search(topo_.numVertices)
  {
    for (int v = 0; v < topo.numVertices; ++v)
    {
      q[v] = topo.boundaryVertex[v] ? 0 : static_cast<int>(std::lround(4.0 * topology.index[v]));
    }
  }

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

/// Hops from the points in front (0 there), spread while fewer than `limit`; the points beyond
/// keep what hops had.
void spreadHops(const Steps& steps, int limit, std::vector<int> front, std::vector<int>& hops)
{
  for (const int v : front)
  {
    hops[v] = 0;
  }
  while (!front.empty())
  {
    std::vector<int> next;
    for (const int u : front)
    {
      for (const Step& s : steps[u])
      {
        if (hops[u] + 1 < hops[s.to] && hops[u] + 1 < limit)
        {
          hops[s.to] = hops[u] + 1;
          next.push_back(s.to);
        }
      }
    }
    front.swap(next);
  }
}

/// Length of the shortest edge path from the points in front (0 there), spread while shorter
/// than `limit`; the points beyond get infinity.
void spreadLengths(const Steps& steps, const FrameGeometry& geometry, double limit,
  const std::vector<int>& front, std::vector<double>& length)
{
  std::fill(length.begin(), length.end(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (const int v : front)
  {
    length[v] = 0.0;
    queue.push({ 0.0, v });
  }
  while (!queue.empty())
  {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > length[u])
    {
      continue;
    }
    for (const Step& s : steps[u])
    {
      const double nd = d + geometry.edgeLength(s.g, s.kg);
      if (nd < length[s.to] && nd < limit)
      {
        length[s.to] = nd;
        queue.push({ nd, s.to });
      }
    }
  }
}

/// Where one quarter of a's index can go: the end of the cheapest path (ties: fewer edges) over
/// regular points to one at least `distance` edges and `length` long from a along the path and
/// outside every neighbourhood `hops` and `near` mark; -1 when the search finds none. delta is
/// the quarter turns the path's matchings change by: -1 takes a positive quarter from a, +1 a
/// negative one.
int findSplitTarget(Optimizer& o, int a, int distance, double length, const std::vector<int>& hops,
  const std::vector<double>& near, std::vector<int>& pathHops, std::vector<double>& pathLength,
  int delta = -1)
{
  PathSearch& S = o.search;
  S.begin(a);
  pathHops[a] = 0;
  pathLength[a] = 0.0;
  int visited = 0;
  while (!S.queue.empty() && visited < o.options.maximumSearchSize)
  {
    const auto [d, u] = S.queue.top();
    S.queue.pop();
    if (d > S.dist[u])
    {
      continue;
    }
    ++visited;
    if (u != a && pathHops[u] >= distance && pathLength[u] >= length &&
      hops[u] == std::numeric_limits<int>::max() && near[u] >= length)
    {
      return u;
    }
    for (int i = 0; i < static_cast<int>(o.steps[u].size()); ++i)
    {
      const Step& s = o.steps[u][i];
      double added = 0.0;
      if (o.q[s.to] != 0 || !o.stepCost(s, delta, added))
      {
        continue;
      }
      if (S.relax(u, i, s.to, d + std::max(0.0, added) + 1e-9)) // ties: fewer edges
      {
        pathHops[s.to] = pathHops[u] + 1;
        pathLength[s.to] = pathLength[u] + o.geometry.edgeLength(s.g, s.kg);
      }
    }
  }
  return -1;
}

/// Splits every inner singularity of index >= 1/2 into quarters: no grid can follow a field that
/// turns once around a point (index 1 maps to a corner of angle 0), and index 1/2 makes a quad
/// vertex of valence 2. Each quarter moves along the cheapest path to a regular point at least
/// splitDistance edges from the singularity, from the quarters placed before and from other
/// singularities, and with lengthScaledCost as far along the surface: splitDistance reference
/// lengths along its path and from the others. Where there is no such point (a coarse surface), a
/// quarter of what is still 3/4 or more goes one edge (and one reference length) nearer, down to
/// one (a +1/2 stays: a valence-2 quad vertex is valid, and quarters one or two edges apart
/// distort the grid around them: decimated-knight's edge RSD went from 26% to 45%).
void splitHighSingularities(Optimizer& o, BranchPointReport& report, const Progress& progress)
{
  const int nv = o.topo.numVertices;
  std::vector<int> high;
  for (int v = 0; v < nv; ++v)
  {
    if (o.q[v] >= o.options.splitQuarters)
    {
      high.push_back(v);
    }
  }
  // hops from the nearest other singular point or placed quarter
  std::vector<int> hops(nv, std::numeric_limits<int>::max());
  std::vector<int> pathHops(nv, 0);
  std::vector<double> near(nv), pathLength(nv, 0.0);
  // With length-scaled costs the distance is one of the surface too, in reference lengths of the
  // component (about the edges of a 4,000-triangle mesh of it). Counted in edges alone, 4 edges of
  // a fan of slivers (the poles of Data/dumbbell.obj, of VTK's sphere source at 200 x 100) put the
  // quarters within three quads of the pole at 6,500 quads; the map between them folded, and quads
  // faced against the surface there.
  const bool scaled = o.options.lengthScaledCost && o.geometry.edgeLength.rows() > 0;
  for (std::size_t i = 0; i < high.size(); ++i)
  {
    const int a = high[i];
    // the reference length of a's component (a is an inner point: it has faces)
    const double unit =
      scaled ? referenceLengthAt(o.geometry, o.topo.ringFaces[o.topo.ringOffsets[a]]) : 0.0;
    report.split += 1; // quarters that find no place are counted in splitFailed
    while (o.q[a] > 0)
    {
      progress.report(static_cast<double>(i) / static_cast<double>(high.size()));
      std::vector<int> others;
      for (int v = 0; v < nv; ++v)
      {
        if (o.q[v] != 0 && v != a)
        {
          others.push_back(v);
        }
      }
      // a quarter of a point of index 3/4 or more (a quad vertex of valence 1 or 0: no quad mesh
      // has one) goes nearer where it must; one of a +1/2 (valence 2, valid) stays there
      const int nearest = o.q[a] >= 3 ? 1 : o.options.splitDistance;
      int target = -1;
      for (int distance = o.options.splitDistance; distance >= nearest && target < 0; --distance)
      {
        std::fill(hops.begin(), hops.end(), std::numeric_limits<int>::max());
        spreadHops(o.steps, distance, others, hops);
        spreadLengths(o.steps, o.geometry, distance * unit, others, near);
        target = findSplitTarget(o, a, distance, distance * unit, hops, near, pathHops, pathLength);
      }
      if (target < 0)
      {
        ++report.splitFailed;
        break;
      }
      o.changePath(a, target, -1);
      ++report.pathsChanged;
    }
  }
}

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

/// The true added deviation along the path the last search found from a to u, with delta quarter
/// turns (the search ran on costs clipped at zero).
double pathCost(const Optimizer& o, int a, int u, int delta)
{
  double cost = 0.0;
  for (int x = u; x != a; x = o.search.cameFrom[x])
  {
    const Step& s = o.search.stepTo(o.steps, x);
    cost += (o.deviationWith(s, delta) - o.deviationWith(s, 0)) *
      edgeWeight(o.geometry, s, o.options.lengthScaledCost);
  }
  return cost;
}

/// The singular point where the path from a that lowers the cost most ends: changing the
/// matchings along it by delta = -q(a) clears a and makes the end's index strictly smaller.
/// -1 when no path pays for itself. Pairs in twistRejected are passed through as if regular.
int findMergeTarget(
  Optimizer& o, int a, int delta, const std::set<std::pair<int, int>>& twistRejected)
{
  const double lambda = o.options.branchPointWeight;
  PathSearch& S = o.search;
  S.begin(a);
  int visited = 0, best = -1;
  double bestGain = 0.0;
  while (!S.queue.empty() && visited < o.options.maximumSearchSize)
  {
    const auto [d, u] = S.queue.top();
    S.queue.pop();
    if (d > S.dist[u] || d >= 2.0 * lambda)
    {
      continue; // stale, or no path this long can pay for itself
    }
    ++visited;
    if (u != a && o.q[u] != 0 && twistRejected.count({ std::min(a, u), std::max(a, u) }) == 0)
    {
      // Ending here: a becomes regular; u only if the two cancel. Accept only paths that make
      // u's index smaller (never merge into a higher-order singularity).
      const int after = o.q[u] - delta;
      if (std::abs(after) < std::abs(o.q[u]))
      {
        const int removed = 1 + (after == 0 ? 1 : 0);
        const double gain = lambda * removed - pathCost(o, a, u, delta);
        if (gain > bestGain + 1e-12)
        {
          bestGain = gain;
          best = u;
        }
      }
      continue; // paths through another singularity would disturb it
    }
    for (int i = 0; i < static_cast<int>(o.steps[u].size()); ++i)
    {
      const Step& s = o.steps[u][i];
      // Changing this edge by delta quarter turns must move exactly delta/4 of index along the
      // path: not if its residual would wrap past +-pi (possible for delta = +-2, or on an edge
      // an earlier path changed), which would put a whole turn on a point between.
      double added = 0.0;
      if (o.stepCost(s, delta, added))
      {
        S.relax(u, i, s.to, d + std::max(0.0, added));
      }
    }
  }
  return best;
}

/// One pass over the inner singular points of index +-1/4 or +-1/2 (one path can clear those),
/// in index order: each takes its best path, undone when that leaves its component twisted.
/// @return the number of paths changed or undone (0: nothing left to do)
int mergePass(Optimizer& o, TwistCheck& twist, std::set<std::pair<int, int>>& twistRejected,
  BranchPointReport& report, const Progress& progress)
{
  const int nv = o.topo.numVertices;
  int changed = 0;
  for (int a = 0; a < nv; ++a)
  {
    if (o.q[a] == 0 || std::abs(o.q[a]) > 2 || o.topo.boundaryVertex[a])
    {
      continue;
    }
    progress.report(static_cast<double>(a) / nv);
    const int delta = -o.q[a];
    const int best = findMergeTarget(o, a, delta, twistRejected);
    if (best < 0)
    {
      continue;
    }
    o.changePath(a, best, delta);
    ++changed;
    if (twist.twisted(o.topo.vertexComponent[a]))
    {
      o.changePath(a, best, -delta);
      ++report.twistsAvoided;
      twistRejected.insert({ std::min(a, best), std::max(a, best) }); // the next best, next pass
      continue;
    }
    ++report.pathsChanged;
  }
  return changed;
}

/// Passes until one changes nothing, or maximumPasses. The passes share the progress in halves
/// (the first has most to do).
void mergeSingularities(Optimizer& o, BranchPointReport& report, const Progress& progress)
{
  TwistCheck twist(o);
  std::set<std::pair<int, int>> twistRejected; // pairs whose merge was undone
  for (int pass = 0; pass < o.options.maximumPasses; ++pass)
  {
    const Progress passProgress =
      progress.part(1.0 - std::ldexp(1.0, -pass), 1.0 - std::ldexp(1.0, -pass - 1));
    if (mergePass(o, twist, twistRejected, report, passProgress) == 0)
    {
      break;
    }
  }
}

/// lambda * (singular inner points) + scaledMatchingCost: what the optimization lowers.
double objective(const Eigen::MatrixX3i& F, const MeshTopology& topo, const FrameGeometry& geometry,
  const FrameTopology& topology, const BranchPointOptions& options)
{
  return options.branchPointWeight * topology.singularities +
    scaledMatchingCost(F, topo, geometry, topology, options.lengthScaledCost);
}

/// Changes the matchings along the path the last search found from a to u by delta quarter
/// turns, and marks the faces on both sides of its edges in changedFaces; undone (false) when
/// that leaves a's component twisted.
bool changeUntwisted(
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

/// The nearest point (along edge paths over regular points, at most maxLength long) where a
/// path from a with delta = -q(a) quarter turns cancels a singularity of the opposite index; -1
/// when there is none. Ties: the first the search reaches.
int findCancelPartner(
  Optimizer& o, int a, double maxLength, const std::set<std::pair<int, int>>& twistRejected)
{
  const int delta = -o.q[a];
  PathSearch& S = o.search;
  S.begin(a);
  int visited = 0;
  while (!S.queue.empty() && visited < o.options.maximumSearchSize)
  {
    const auto [d, u] = S.queue.top();
    S.queue.pop();
    if (d > S.dist[u] || d > maxLength)
    {
      continue; // stale, or too far
    }
    ++visited;
    if (u != a && o.q[u] != 0)
    {
      if (o.q[u] == delta && twistRejected.count({ std::min(a, u), std::max(a, u) }) == 0)
      {
        return u;
      }
      continue; // paths through another singularity would disturb it
    }
    for (int i = 0; i < static_cast<int>(o.steps[u].size()); ++i)
    {
      const Step& s = o.steps[u][i];
      double added = 0.0;
      if (o.stepCost(s, delta, added)) // no residual wrapped past +-pi (see findMergeTarget)
      {
        S.relax(u, i, s.to, d + o.geometry.edgeLength(s.g, s.kg));
      }
    }
  }
  return -1;
}
}

int cancelClosePairs(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  double maxLength, std::vector<char>& changedFaces)
{
  changedFaces.assign(F.rows(), 0);
  if (!(maxLength > 0) || topology.singularities < 2 || geometry.edgeLength.rows() == 0)
  {
    return 0;
  }
  const BranchPointOptions options;
  Optimizer o(F, topo, geometry, frameU, topology, options);
  TwistCheck twist(o);
  DiskTest disk(F, topo, geometry.edgeLength);
  std::set<std::pair<int, int>> twistRejected;
  // On a component with handles only inside a disk around the pair: a path that a handle's loop
  // must cross also turns the field along that loop, which no index accounts for (the smoothest
  // field's small tori in Data/components.obj, cancelled down to a pair or none, kept folds on
  // every grid).
  // The closest pairs first: each quarter's distance to its nearest partner, then in that order.
  std::vector<std::pair<double, int>> order;
  for (int a = 0; a < topo.numVertices; ++a)
  {
    if (std::abs(o.q[a]) == 1 && !topo.boundaryVertex[a])
    {
      const int u = findCancelPartner(o, a, maxLength, twistRejected);
      if (u >= 0 &&
        (topo.components[topo.vertexComponent[a]].genus == 0 ||
          disk.ballIsDisk(a, 2.0 * maxLength)))
      {
        order.emplace_back(o.search.dist[u], a);
      }
    }
  }
  std::sort(order.begin(), order.end());
  int cancelled = 0;
  for (const auto& [distance, a] : order)
  {
    if (std::abs(o.q[a]) != 1)
    {
      continue; // cancelled with an earlier one
    }
    const int u = findCancelPartner(o, a, maxLength, twistRejected);
    if (u < 0)
    {
      continue;
    }
    if (!changeUntwisted(o, twist, a, u, -o.q[a], changedFaces))
    {
      twistRejected.insert({ std::min(a, u), std::max(a, u) });
      continue;
    }
    ++cancelled;
  }
  if (cancelled > 0)
  {
    topology = evaluateMatchings(F, topo, geometry, frameU, topology.matching);
  }
  return cancelled;
}

int moveCloseQuartersApart(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  double closerThan, double minLength, std::vector<char>& changedFaces)
{
  changedFaces.assign(F.rows(), 0);
  if (!(closerThan > 0) || !(minLength > 0) || topology.singularities < 2 ||
    geometry.edgeLength.rows() == 0)
  {
    return 0;
  }
  const BranchPointOptions options;
  Optimizer o(F, topo, geometry, frameU, topology, options);
  TwistCheck twist(o);
  DiskTest disk(F, topo, geometry.edgeLength);
  const int nv = topo.numVertices;
  std::vector<int> quarters, others, pathHops(nv, 0);
  const std::vector<int> anyHops(nv, std::numeric_limits<int>::max());
  std::vector<double> near(nv), pathLength(nv, 0.0);
  for (int a = 0; a < nv; ++a)
  {
    if (std::abs(o.q[a]) == 1 && !topo.boundaryVertex[a])
    {
      quarters.push_back(a);
    }
  }
  int moved = 0;
  for (const int a : quarters)
  {
    if (std::abs(o.q[a]) != 1)
    {
      continue;
    }
    // the nearest other singularity of the same sign, within closerThan
    others.clear();
    for (int v = 0; v < nv; ++v)
    {
      if (o.q[v] == o.q[a] && v != a)
      {
        others.push_back(v);
      }
    }
    spreadLengths(o.steps, geometry, closerThan, others, near);
    if (!(near[a] < closerThan) ||
      (topo.components[topo.vertexComponent[a]].genus != 0 && !disk.ballIsDisk(a, 5.0 * minLength)))
    {
      continue;
    }
    // a regular point at least minLength from every other singularity, at most 4 minLength away
    others.clear();
    for (int v = 0; v < nv; ++v)
    {
      if (o.q[v] != 0 && v != a)
      {
        others.push_back(v);
      }
    }
    spreadLengths(o.steps, geometry, minLength, others, near);
    const int delta = -o.q[a];
    const int target =
      findSplitTarget(o, a, 1, minLength, anyHops, near, pathHops, pathLength, delta);
    if (target < 0 || pathLength[target] > 4.0 * minLength)
    {
      continue;
    }
    if (changeUntwisted(o, twist, a, target, delta, changedFaces))
    {
      ++moved;
    }
  }
  if (moved > 0)
  {
    topology = evaluateMatchings(F, topo, geometry, frameU, topology.matching);
  }
  return moved;
}

double scaledMatchingCost(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const FrameTopology& topology, bool lengthScaled)
{
  if (!lengthScaled || !(geometry.referenceLength > 0))
  {
    return topology.matchingCost;
  }
  double cost = 0.0;
  for (int f = 0; f < static_cast<int>(F.rows()); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g > f)
      {
        cost +=
          topology.deviation(f, k) * geometry.edgeLength(f, k) / referenceLengthAt(geometry, f);
      }
    }
  }
  return cost;
}

BranchPointReport optimizeBranchPoints(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  const BranchPointOptions& options, const Progress& progress)
{
  progress.report(0.0);
  BranchPointReport report;
  report.before = topology.branchPoints;
  report.singularitiesBefore = topology.singularities;
  report.costBefore = objective(F, topo, geometry, topology, options);
  Optimizer o(F, topo, geometry, frameU, topology, options);
  if (options.splitDistance > 0)
  {
    splitHighSingularities(o, report, progress.part(0.0, 0.2));
  }
  if (options.branchPointWeight > 0.0)
  {
    mergeSingularities(o, report, progress.part(0.2, 0.95));
  }
  topology = evaluateMatchings(F, topo, geometry, frameU, topology.matching);
  report.after = topology.branchPoints;
  report.singularitiesAfter = topology.singularities;
  report.costAfter = objective(F, topo, geometry, topology, options);
  progress.report(1.0);
  return report;
}

}
