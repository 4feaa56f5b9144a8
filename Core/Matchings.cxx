#include "Matchings.h"

#include "SparseSolver.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Quarter = 0.5 * Pi;

int mod4(int r)
{
  return ((r % 4) + 4) % 4;
}

/// Rotation from f's first frame vector to g's (carried into f's plane), before matching.
double turning(const FrameGeometry& G, const Eigen::VectorXd& phi, int f, int k, int g)
{
  return wrapAngle(phi[g] + G.transport(f, k) - phi[f]);
}

/// What is left of a turning once the matching r (paper convention) is accounted for.
double residual(double turn, int r)
{
  // X_{g,0} = X_{f,-r}: g's vector is f's turned by -r quarter turns.
  return wrapAngle(turn + r * Quarter);
}

/// Position (0..2) in g of the edge g shares with f across f's edge k.
int twinEdge(const MeshTopology& topo, int f, int k, int g)
{
  const int e = topo.faceEdges(f, k);
  const int c =
    topo.edgeCorners(e, 0) == 3 * f + k ? topo.edgeCorners(e, 1) : topo.edgeCorners(e, 0);
  return c >= 0 && c / 3 == g ? c % 3 : -1;
}
}

FrameGeometry computeFrameGeometry(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  FrameGeometry G;
  G.bases = computeFaceBases(V, F, topo);
  G.transport = computeTransport(V, F, topo, G.bases);
  G.edgeAngle.resize(F.rows(), 3);
  G.edgeLength.resize(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::RowVector3d e = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      G.edgeAngle(f, k) = std::atan2(e.dot(G.bases.b2.row(f)), e.dot(G.bases.b1.row(f)));
      G.edgeLength(f, k) = e.norm();
    }
  }
  G.referenceLength = std::sqrt(surfaceArea(V, F) / 2000.0);
  G.defect = angleDefects(V, F, topo);
  return G;
}

FrameTopology computeMatchings(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU)
{
  const int nf = static_cast<int>(F.rows());
  const Eigen::VectorXd phi = vectorAngles(geometry.bases, frameU);
  Eigen::MatrixX3i matching = Eigen::MatrixX3i::Constant(nf, 3, -1);
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g < f) // each inner edge once, from its lower face; g < 0: no neighbour
      {
        continue;
      }
      // Smallest residual: g's vector is f's turned by about round(turn / quarter) quarters.
      const int turns = static_cast<int>(std::lround(turning(geometry, phi, f, k, g) / Quarter));
      const int r = mod4(-turns);
      matching(f, k) = r;
      matching(g, twinEdge(topo, f, k, g)) = mod4(-r);
    }
  }
  return evaluateMatchings(F, topo, geometry, frameU, matching);
}

FrameTopology evaluateMatchings(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, const Eigen::MatrixX3i& matching)
{
  const int nf = static_cast<int>(F.rows());
  const int nv = topo.numVertices;
  const Eigen::VectorXd phi = vectorAngles(geometry.bases, frameU);
  FrameTopology T;
  T.matching = matching;
  T.deviation = Eigen::MatrixX3d::Zero(nf, 3);
  Eigen::MatrixX3d d = Eigen::MatrixX3d::Zero(nf, 3);
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g < 0)
      {
        continue;
      }
      const int r = matching(f, k);
      const int kk = twinEdge(topo, f, k, g);
      if (r < 0 || r > 3 || kk < 0 || mod4(matching(g, kk) + r) != 0)
      {
        throw std::invalid_argument("evaluateMatchings: matchings across the edge between "
                                    "triangles " +
          std::to_string(f) + " and " + std::to_string(g) + " are not inverse");
      }
      // Once per edge, the twin the exact opposite: a residual of +-pi (two quarter turns off)
      // must cancel across the edge, or Poincare-Hopf would be off by one.
      if (f < g)
      {
        d(f, k) = residual(turning(geometry, phi, f, k, g), r);
        d(g, kk) = -d(f, k);
        T.deviation(f, k) = T.deviation(g, kk) = std::abs(d(f, k));
        T.matchingCost += T.deviation(f, k);
      }
    }
  }

  T.layerShift = Eigen::VectorXi::Zero(nv);
  T.index = Eigen::VectorXd::Zero(nv);
  for (int v = 0; v < nv; ++v)
  {
    const int begin = topo.ringOffsets[v], n = topo.valence(v);
    if (n == 0 || !topo.ringOrdered[v])
    {
      continue; // no ordered ring (non-manifold or misoriented): no index
    }
    double turn = 0.0;
    int shift = 0;
    for (int i = 0; i + 1 < n || (!topo.boundaryVertex[v] && i < n); ++i)
    {
      const int f = topo.ringFaces[begin + i];
      const int k = (MeshTopology::cornerOf(F, f, v) + 2) % 3; // edge to the next face
      turn += d(f, k);
      shift += matching(f, k);
    }
    if (!topo.boundaryVertex[v])
    {
      T.layerShift[v] = mod4(shift);
      T.index[v] = (geometry.defect[v] + turn) / (2.0 * Pi);
      const double quarters = 4.0 * T.index[v];
      T.maxIndexError = std::max(T.maxIndexError, std::abs(quarters - std::round(quarters)) / 4.0);
      T.index[v] = std::round(quarters) / 4.0;
      T.singularities += T.index[v] != 0.0 ? 1 : 0;
      T.branchPoints += T.layerShift[v] != 0 ? 1 : 0;
    }
    else
    {
      // Double the surface across its boundary: the fan and its mirror image form a full ring.
      // Crossing a boundary edge into the mirror turns a cross by twice its angle to the edge;
      // the doubled vertex's index, halved, is this vertex's share of Poincare-Hopf.
      const int first = topo.ringFaces[begin], last = topo.ringFaces[begin + n - 1];
      const double inAngle = geometry.edgeAngle(first, MeshTopology::cornerOf(F, first, v));
      const double outAngle =
        geometry.edgeAngle(last, (MeshTopology::cornerOf(F, last, v) + 2) % 3);
      const double mirrorOut = wrapQuarter(2.0 * (outAngle - phi[last]));
      const double mirrorIn = wrapQuarter(2.0 * (phi[first] - inAngle));
      T.index[v] = (geometry.defect[v] + turn + 0.5 * (mirrorOut + mirrorIn)) / (2.0 * Pi);
    }
  }
  return T;
}

namespace
{
/// Primal adjacency over inner edges between inner vertices. Walking an edge from u to `to` and
/// adding `delta` to the matching from g to f (g: the face where the edge runs to -> u, f: where
/// it runs u -> to) adds delta to the layer shift of u and takes it from `to`.
struct Step
{
  int to, g, kg, f, kf;
};

std::vector<std::vector<Step>> pathSteps(const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  std::vector<std::vector<Step>> steps(topo.numVertices);
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

/// Changes the matchings along the path that cameFrom/stepIndex record from `start` to `end` by
/// delta quarter turns.
void changePath(const std::vector<std::vector<Step>>& steps, const std::vector<int>& cameFrom,
  const std::vector<int>& stepIndex, int start, int end, int delta, Eigen::MatrixX3i& M)
{
  for (int x = end; x != start; x = cameFrom[x])
  {
    const Step& s = steps[cameFrom[x]][stepIndex[x]];
    M(s.g, s.kg) = mod4(M(s.g, s.kg) + delta);
    M(s.f, s.kf) = mod4(-M(s.g, s.kg));
  }
}

/// What one edge's deviation counts for (BranchPointOptions::lengthScaled).
double edgeWeight(const FrameGeometry& geometry, const Step& s, bool lengthScaled)
{
  if (!lengthScaled || !(geometry.referenceLength > 0) || geometry.edgeLength.rows() == 0)
  {
    return 1.0;
  }
  return geometry.edgeLength(s.g, s.kg) / geometry.referenceLength;
}

/// Would changing the step's matching by delta quarter turns wrap its residual past +-pi (and so
/// move a whole turn of index onto a point between)? If not, what it adds to the deviation.
bool stepCost(const FrameGeometry& geometry, const Eigen::VectorXd& phi, const Eigen::MatrixX3i& M,
  const Step& s, int delta, double& added, bool lengthScaled)
{
  const double r0 = residual(turning(geometry, phi, s.g, s.kg, s.f), M(s.g, s.kg));
  if (!(std::abs(r0 + delta * Quarter) < Pi))
  {
    return false;
  }
  added = (std::abs(r0 + delta * Quarter) - std::abs(r0)) * edgeWeight(geometry, s, lengthScaled);
  return true;
}
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
        cost += topology.deviation(f, k) * geometry.edgeLength(f, k) / geometry.referenceLength;
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
  const int nv = topo.numVertices;
  const double lambda = options.branchPointWeight;
  const Eigen::VectorXd phi = vectorAngles(geometry.bases, frameU);
  BranchPointReport report;
  report.before = topology.branchPoints;
  report.singularitiesBefore = topology.singularities;
  report.costBefore = lambda * topology.singularities +
    scaledMatchingCost(F, topo, geometry, topology, options.lengthScaledCost);
  const std::vector<std::vector<Step>> steps = pathSteps(F, topo);
  Eigen::MatrixX3i& M = topology.matching;
  std::vector<double> dist(nv, 0.0);
  std::vector<int> cameFrom(nv, -1), stepIndex(nv, -1), stamp(nv, -1);
  int search = 0;

  // Split every inner singularity of index >= 1/2 into quarters: no grid can follow a field
  // that turns once around a point (index 1 maps to a corner of angle 0), and index 1/2 makes
  // a quad vertex of valence 2. Each quarter moves along the cheapest path to a regular point at
  // least splitDistance edges from the singularity, from the quarters placed before and from
  // other singularities.
  std::vector<int> q(nv, 0);
  for (int v = 0; v < nv; ++v)
  {
    q[v] = topo.boundaryVertex[v] ? 0 : static_cast<int>(std::lround(4.0 * topology.index[v]));
  }
  if (options.splitDistance > 0)
  {
    // hops from the nearest singular point (and later from each placed quarter)
    std::vector<int> hops(nv, std::numeric_limits<int>::max());
    auto spreadHops = [&](std::vector<int> front) {
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
            if (hops[u] + 1 < hops[s.to] && hops[u] + 1 < options.splitDistance)
            {
              hops[s.to] = hops[u] + 1;
              next.push_back(s.to);
            }
          }
        }
        front.swap(next);
      }
    };
    std::vector<int> high;
    for (int v = 0; v < nv; ++v)
    {
      if (q[v] >= 2)
      {
        high.push_back(v);
      }
    }
    std::vector<int> pathHops(nv, 0);
    for (const int a : high)
    {
      report.split += 1; // quarters that find no place are counted in splitFailed
      while (q[a] > 0)
      {
        // targets: regular, splitDistance edges from a along the path, and outside every other
        // singular point's (and placed quarter's) neighbourhood
        std::fill(hops.begin(), hops.end(), std::numeric_limits<int>::max());
        std::vector<int> others;
        for (int v = 0; v < nv; ++v)
        {
          if (q[v] != 0 && v != a)
          {
            others.push_back(v);
          }
        }
        spreadHops(others);
        ++search;
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
        dist[a] = 0.0;
        stamp[a] = search;
        cameFrom[a] = -1;
        pathHops[a] = 0;
        queue.push({ 0.0, a });
        int visited = 0;
        int target = -1;
        while (!queue.empty() && visited < options.maximumSearchSize && target < 0)
        {
          const auto [d, u] = queue.top();
          queue.pop();
          if (d > dist[u])
          {
            continue;
          }
          ++visited;
          if (u != a && pathHops[u] >= options.splitDistance &&
            hops[u] == std::numeric_limits<int>::max())
          {
            target = u;
            break;
          }
          for (int i = 0; i < static_cast<int>(steps[u].size()); ++i)
          {
            const Step& s = steps[u][i];
            double added = 0.0;
            if (q[s.to] != 0 || !stepCost(geometry, phi, M, s, -1, added, options.lengthScaledCost))
            {
              continue;
            }
            const double nd = d + std::max(0.0, added) + 1e-9; // ties: fewer edges
            if (stamp[s.to] != search || nd < dist[s.to])
            {
              stamp[s.to] = search;
              dist[s.to] = nd;
              cameFrom[s.to] = u;
              stepIndex[s.to] = i;
              pathHops[s.to] = pathHops[u] + 1;
              queue.push({ nd, s.to });
            }
          }
        }
        if (target < 0)
        {
          ++report.splitFailed;
          break;
        }
        changePath(steps, cameFrom, stepIndex, a, target, -1, M);
        q[a] -= 1;
        q[target] += 1;
        ++report.pathsChanged;
      }
    }
  }
  if (!(lambda > 0.0))
  {
    topology = evaluateMatchings(F, topo, geometry, frameU, M);
    report.after = topology.branchPoints;
    report.singularitiesAfter = topology.singularities;
    report.costAfter = lambda * topology.singularities +
      scaledMatchingCost(F, topo, geometry, topology, options.lengthScaledCost);
    return report;
  }

  auto deviationWith = [&](const Step& s, int delta) {
    const int r = mod4(M(s.g, s.kg) + delta);
    return std::abs(residual(turning(geometry, phi, s.g, s.kg, s.f), r));
  };
  // A component between two or more boundary loops (a tube, say) whose last singularities a
  // merge removes: its frames must then carry the same frame family along every loop whose
  // frames follow it, or no grid can have all of its loops on grid lines (a tube whose field
  // turns a quarter from one end to the other). The pair that absorbed the quarter turn stays.
  std::vector<int> edgeLoop(topo.numEdges(), -1);
  {
    std::vector<int> vertexLoop(nv, -1);
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
        edgeLoop[e] = vertexLoop[topo.edges(e, 0)];
      }
    }
  }
  std::vector<int> label(F.rows(), -1);
  std::set<std::pair<int, int>> twistRejected; // pairs whose merge was undone
  auto twisted = [&](int component) {
    if (component < 0 || component >= static_cast<int>(topo.components.size()))
    {
      return false;
    }
    const ComponentInfo& info = topo.components[component];
    if (info.numBoundaryLoops < 2 || info.genus != 0)
    {
      return false;
    }
    for (int v = 0; v < nv; ++v)
    {
      if (q[v] != 0 && topo.vertexComponent[v] == component)
      {
        return false; // singularities left: the frame family is not the same along every path
      }
    }
    // L(f): which of f's frame vectors is the root's X_0, carried across the matchings
    int root = -1;
    for (int f = 0; f < static_cast<int>(F.rows()) && root < 0; ++f)
    {
      root = topo.faceComponent[f] == component ? f : -1;
    }
    if (root < 0)
    {
      return false;
    }
    std::fill(label.begin(), label.end(), -1);
    std::vector<int> stack = { root };
    label[root] = 0;
    std::map<int, int> loopFamily; // loop -> parity, or -1 where the loop mixes families
    const double tolerance = options.boundaryTolerance * Pi / 180.0;
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo.faceNeighbors(f, k);
        if (g >= 0)
        {
          if (label[g] < 0 && M(f, k) >= 0)
          {
            label[g] = mod4(label[f] + M(f, k));
            stack.push_back(g);
          }
          continue;
        }
        const int loop = edgeLoop[topo.faceEdges(f, k)];
        if (loop < 0)
        {
          continue;
        }
        const double along = geometry.edgeAngle(f, k) - phi[f];
        const double quarters = std::round(along / Quarter);
        if (std::abs(wrapAngle(along - quarters * Quarter)) > tolerance)
        {
          continue; // the frame does not follow this edge
        }
        const int family = ((static_cast<int>(quarters) - label[f]) % 2 + 2) % 2;
        const auto [it, inserted] = loopFamily.insert({ loop, family });
        if (!inserted && it->second != family)
        {
          it->second = -1;
        }
      }
    }
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
  };

  // Work in quarter turns: q = 4 index. Changing the matchings along a path from a to b by
  // delta adds delta to q(a) and takes it from q(b).
  for (int pass = 0; pass < options.maximumPasses; ++pass)
  {
    int changed = 0;
    for (int a = 0; a < nv; ++a)
    {
      // A singularity of index +-1/4 or +-1/2 can be cleared by one path.
      if (q[a] == 0 || std::abs(q[a]) > 2 || topo.boundaryVertex[a])
      {
        continue;
      }
      const int delta = -q[a];
      ++search;
      using Item = std::pair<double, int>;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
      dist[a] = 0.0;
      stamp[a] = search;
      cameFrom[a] = -1;
      queue.push({ 0.0, a });
      int visited = 0, best = -1;
      double bestGain = 0.0;
      while (!queue.empty() && visited < options.maximumSearchSize)
      {
        const auto [d, u] = queue.top();
        queue.pop();
        if (d > dist[u] || d >= 2.0 * lambda)
        {
          continue; // stale, or no path this long can pay for itself
        }
        ++visited;
        if (u != a && q[u] != 0 && twistRejected.count({ std::min(a, u), std::max(a, u) }) == 0)
        {
          // Ending here: a becomes regular; u only if the two cancel. Accept only paths that
          // make u's index smaller (never merge into a higher-order singularity).
          const int after = q[u] - delta;
          if (std::abs(after) < std::abs(q[u]))
          {
            const int removed = 1 + (after == 0 ? 1 : 0);
            double pathCost = 0.0; // the true cost (the search ran on costs clipped at zero)
            for (int x = u; x != a; x = cameFrom[x])
            {
              const Step& s = steps[cameFrom[x]][stepIndex[x]];
              pathCost += (deviationWith(s, delta) - deviationWith(s, 0)) *
                edgeWeight(geometry, s, options.lengthScaledCost);
            }
            const double gain = lambda * removed - pathCost;
            if (gain > bestGain + 1e-12)
            {
              bestGain = gain;
              best = u;
            }
          }
          continue; // paths through another singularity would disturb it
        }
        for (int i = 0; i < static_cast<int>(steps[u].size()); ++i)
        {
          const Step& s = steps[u][i];
          // Changing this edge by delta quarter turns must move exactly delta/4 of index along
          // the path: not if its residual would wrap past +-pi (possible for delta = +-2, or on
          // an edge an earlier path changed), which would put a whole turn on a point between.
          double added = 0.0;
          if (!stepCost(geometry, phi, M, s, delta, added, options.lengthScaledCost))
          {
            continue;
          }
          const double nd = d + std::max(0.0, added);
          if (stamp[s.to] != search || nd < dist[s.to])
          {
            stamp[s.to] = search;
            dist[s.to] = nd;
            cameFrom[s.to] = u;
            stepIndex[s.to] = i;
            queue.push({ nd, s.to });
          }
        }
      }
      if (best < 0)
      {
        continue;
      }
      changePath(steps, cameFrom, stepIndex, a, best, delta, M);
      q[a] = 0;
      q[best] -= delta;
      if (twisted(topo.vertexComponent[a]))
      {
        changePath(steps, cameFrom, stepIndex, a, best, -delta, M);
        q[a] = -delta;
        q[best] += delta;
        ++report.twistsAvoided;
        twistRejected.insert({ std::min(a, best), std::max(a, best) }); // the next best, next pass
        ++changed;
        continue;
      }
      ++changed;
      ++report.pathsChanged;
    }
    if (changed == 0)
    {
      break;
    }
  }
  topology = evaluateMatchings(F, topo, geometry, frameU, M);
  report.after = topology.branchPoints;
  report.singularitiesAfter = topology.singularities;
  report.costAfter = lambda * topology.singularities +
    scaledMatchingCost(F, topo, geometry, topology, options.lengthScaledCost);
  return report;
}

Eigen::VectorXd fitFramesToMatchings(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3i& matching, const Eigen::VectorXd& weight, double lambda,
  const std::vector<char>& held)
{
  const int nF = static_cast<int>(F.rows());
  if (frameU.rows() != nF || matching.rows() != nF || topo.numFaces != nF ||
    (weight.size() != 0 && weight.size() != nF) ||
    (!held.empty() && static_cast<Eigen::Index>(held.size()) != F.rows()))
  {
    throw std::invalid_argument("fitFramesToMatchings: sizes do not match");
  }
  if (!(lambda > 0.0 && lambda <= 1.0))
  {
    throw std::invalid_argument("fitFramesToMatchings: lambda must lie in (0, 1]");
  }
  const Eigen::VectorXd phi = vectorAngles(geometry.bases, frameU);
  Eigen::VectorXd area(nF);
  for (int f = 0; f < nF; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 1)) - V.row(F(f, 0));
    const Eigen::Vector3d b = V.row(F(f, 2)) - V.row(F(f, 0));
    area[f] = 0.5 * a.cross(b).norm();
  }
  // Diagonal: the alignment term, plus a tiny multiple of the area so that the system stays
  // definite where no frame is weighted (the field is then fixed up to a common turn).
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(nF) * 7);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nF);
  for (int f = 0; f < nF; ++f)
  {
    const double w = weight.size() ? weight[f] : 0.0;
    // a held frame: a stiff spring to its angle (alpha = 0)
    const double hold = !held.empty() && held[f] ? 1e6 * 8.0 * lambda * area[f] : 0.0;
    t.emplace_back(f, f, (1.0 - lambda) * area[f] * w + 1e-9 * area[f] + hold);
  }
  for (int f = 0; f < nF; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g < 0 || g < f || matching(f, k) < 0)
      {
        continue;
      }
      // residual after the rotations: delta + alpha_g - alpha_f
      const double delta = residual(turning(geometry, phi, f, k, g), matching(f, k));
      const double c = 8.0 * lambda * (area[f] + area[g]) / 3.0;
      t.emplace_back(f, f, c);
      t.emplace_back(g, g, c);
      t.emplace_back(f, g, -c);
      t.emplace_back(g, f, -c);
      rhs[f] += c * delta;
      rhs[g] -= c * delta;
    }
  }
  Eigen::SparseMatrix<double> H(nF, nF);
  H.setFromTriplets(t.begin(), t.end());
  SpdSolver<double> solver;
  solver.compute(H);
  if (solver.info() != Eigen::Success)
  {
    throw std::runtime_error("fitFramesToMatchings: the system could not be factored");
  }
  return solver.solve(rhs);
}
std::string checkMatching(const MeshTopology& topo, const Eigen::MatrixX3i& matching)
{
  if (matching.rows() != topo.numFaces)
  {
    return "the matchings have " + std::to_string(matching.rows()) + " rows for " +
      std::to_string(topo.numFaces) + " triangles";
  }
  for (int f = 0; f < topo.numFaces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int r = matching(f, k);
      const bool boundary = topo.faceNeighbors(f, k) < 0;
      if (boundary ? r != -1 : (r < 0 || r > 3))
      {
        return "the matching of triangle " + std::to_string(f) + ", edge " + std::to_string(k) +
          " is " + std::to_string(r) + "; it must be 0, 1, 2 or 3 (-1 on the boundary)";
      }
    }
  }
  return "";
}

MatchingResult buildMatchings(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3d& frameV, const Eigen::VectorXd& weight,
  const std::vector<char>& constrained, const MatchingOptions& options, const Progress& progress)
{
  const int nF = static_cast<int>(F.rows());
  if (frameU.rows() != nF || (frameV.rows() != 0 && frameV.rows() != nF) ||
    (weight.size() != 0 && weight.size() != nF) ||
    (!constrained.empty() && static_cast<int>(constrained.size()) != nF))
  {
    throw std::invalid_argument("buildMatchings: sizes do not match");
  }
  const BranchPointOptions& bp = options.branchPoints;
  MatchingResult r;
  r.topology = computeMatchings(F, topo, geometry, frameU);
  r.branchPointsBefore = r.topology.branchPoints;
  r.matchingCostBefore = r.topology.matchingCost;
  r.objectiveBefore = bp.branchPointWeight * r.topology.singularities +
    scaledMatchingCost(F, topo, geometry, r.topology, bp.lengthScaledCost);
  r.objectiveAfter = r.objectiveBefore;
  progress.report(0.1);
  if (options.optimizeBranchPoints)
  {
    r.report =
      optimizeBranchPoints(F, topo, geometry, frameU, r.topology, bp, progress.part(0.1, 0.8));
    r.objectiveAfter = r.report.costAfter;
  }
  r.frameU = frameU;
  r.frameV = frameV;
  if (frameV.rows() == 0)
  {
    r.frameV.resize(nF, 3);
    for (int f = 0; f < nF; ++f)
    {
      r.frameV.row(f) = geometry.bases.normal.row(f).cross(frameU.row(f));
    }
  }
  if (!options.fitFramesToMatchings || r.report.pathsChanged == 0)
  {
    return r;
  }
  std::vector<char> held(constrained.empty() ? 0 : nF, 0);
  for (std::size_t f = 0; f < held.size(); ++f)
  {
    const int i = static_cast<int>(f);
    held[f] = constrained[f] &&
      (topo.faceNeighbors(i, 0) < 0 || topo.faceNeighbors(i, 1) < 0 ||
        topo.faceNeighbors(i, 2) < 0);
  }
  const Eigen::VectorXd w = weight.array().isFinite().select(weight, 0.0);
  const Eigen::VectorXd alpha = fitFramesToMatchings(
    V, F, topo, geometry, frameU, r.topology.matching, w, options.fitSmoothingWeight, held);
  rotateFrames(geometry.bases, alpha, r.frameU, r.frameV);
  r.topology = evaluateMatchings(F, topo, geometry, r.frameU, r.topology.matching);
  r.framesFitted = true;
  progress.report(1.0);
  return r;
}

}
