// BranchPoints.cxx: the greedy branch-point optimization (QuadCover Sect. 4.2): singularities of
// index >= 1/2 split into quarters, then singular points cleared along their cheapest edge paths.
#include "Matchings.h"

#include "BranchPointSearch.h"
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
using namespace branchsearch;
using detail::mod4;
using detail::Pi;
using detail::Quarter;
using detail::residual;
using detail::turning;

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

/// Is another point with a's quarters (o.q) closer than `limit` to a along edge paths (a
/// Dijkstra from a that stops at that length)? Edges are as long either way, so this is whether
/// spreadLengths from those points reaches a below `limit`, up to the order the lengths are
/// summed in.
bool sameSignWithin(Optimizer& o, int a, double limit)
{
  PathSearch& S = o.search;
  S.begin(a);
  while (!S.queue.empty())
  {
    const auto [d, u] = S.queue.top();
    S.queue.pop();
    if (d > S.dist[u])
    {
      continue;
    }
    if (u != a && o.q[u] == o.q[a])
    {
      return true;
    }
    const std::vector<Step>& around = o.steps[u];
    for (int i = 0; i < static_cast<int>(around.size()); ++i)
    {
      const double nd = d + o.geometry.edgeLength(around[i].g, around[i].kg);
      if (nd < limit)
      {
        S.relax(u, i, around[i].to, nd);
      }
    }
  }
  return false;
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

namespace
{
/// Per point, the length of the shortest edge path from the inner points beside the boundary
/// (those joined to a boundary point by an edge; the paths' steps join inner points only),
/// spread while shorter than `limit` (infinity beyond).
std::vector<double> besideBoundaryLengths(
  const MeshTopology& topo, const FrameGeometry& geometry, const Steps& steps, double limit)
{
  std::vector<char> beside(topo.numVertices, 0);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    if (topo.boundaryVertex[a] != topo.boundaryVertex[b])
    {
      beside[topo.boundaryVertex[a] ? b : a] = 1;
    }
  }
  std::vector<int> front;
  for (int v = 0; v < topo.numVertices; ++v)
  {
    if (beside[v])
    {
      front.push_back(v);
    }
  }
  std::vector<double> length(topo.numVertices);
  spreadLengths(steps, geometry, limit, front, length);
  return length;
}
}

int moveCloseQuartersApart(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  double closerThan, double minLength, double boundaryCloserThan, std::vector<char>& changedFaces)
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
  // the inner points beside the boundary: a quarter closer than boundaryCloserThan to them moves,
  // and a moved quarter keeps minLength from them (a mesh edge more from the boundary)
  const std::vector<double> toBoundary =
    besideBoundaryLengths(topo, geometry, o.steps, std::max(minLength, boundaryCloserThan));
  int moved = 0;
  for (const int a : quarters)
  {
    if (std::abs(o.q[a]) != 1)
    {
      continue;
    }
    // closer than boundaryCloserThan to the inner points beside the boundary, or to another
    // singularity of the same sign within closerThan; most quarters have none, which a search from
    // the quarter itself tells at the cost of its neighbourhood (with a margin far above the
    // rounding of the sums, so that the spread below decides the rest)
    const bool byBoundary = toBoundary[a] < boundaryCloserThan; // never when it is 0
    if (!byBoundary && !sameSignWithin(o, a, closerThan * (1.0 + 1e-9)))
    {
      continue;
    }
    others.clear();
    for (int v = 0; v < nv; ++v)
    {
      if (o.q[v] == o.q[a] && v != a)
      {
        others.push_back(v);
      }
    }
    spreadLengths(o.steps, geometry, closerThan, others, near);
    const bool handles = topo.components[topo.vertexComponent[a]].genus != 0;
    if (!(near[a] < closerThan || byBoundary) ||
      (handles && !byBoundary && !disk.ballIsDisk(a, 5.0 * minLength)))
    {
      continue;
    }
    // a regular point at least minLength from every other singularity and from the inner points
    // beside the boundary, at most 4 minLength away
    others.clear();
    for (int v = 0; v < nv; ++v)
    {
      if (o.q[v] != 0 && v != a)
      {
        others.push_back(v);
      }
    }
    spreadLengths(o.steps, geometry, minLength, others, near);
    for (int v = 0; v < nv; ++v)
    {
      near[v] = std::min(near[v], toBoundary[v]);
    }
    const int delta = -o.q[a];
    const int target =
      findSplitTarget(o, a, 1, minLength, anyHops, near, pathHops, pathLength, delta);
    // beside a boundary the ball around the quarter holds the boundary's loop where it is short
    // (a spout's opening): the ball that must be a disk is the one the path stays in
    if (target < 0 || pathLength[target] > 4.0 * minLength ||
      (handles && byBoundary && !disk.ballIsDisk(a, 1.25 * pathLength[target])))
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
