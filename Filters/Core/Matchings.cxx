#include "Matchings.h"

#include <cmath>
#include <functional>
#include <queue>
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
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::RowVector3d e = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      G.edgeAngle(f, k) = std::atan2(e.dot(G.bases.b2.row(f)), e.dot(G.bases.b1.row(f)));
    }
  }
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

BranchPointReport optimizeBranchPoints(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  const BranchPointOptions& options)
{
  const int nv = topo.numVertices;
  const double lambda = options.weight;
  const Eigen::VectorXd phi = vectorAngles(geometry.bases, frameU);
  BranchPointReport report;
  report.before = topology.branchPoints;
  report.singularitiesBefore = topology.singularities;
  report.costBefore = lambda * topology.singularities + topology.matchingCost;
  if (!(lambda > 0.0))
  {
    report.after = report.before;
    report.singularitiesAfter = report.singularitiesBefore;
    report.costAfter = report.costBefore;
    return report;
  }

  // Primal adjacency over inner edges between inner vertices. Walking an edge from u to w and
  // adding `delta` to the matching from g to f (g: the face where the edge runs w -> u, f: where
  // it runs u -> w) adds delta to the layer shift of u and takes it from w.
  struct Step
  {
    int to, g, kg, f, kf;
  };
  std::vector<std::vector<Step>> steps(nv);
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

  Eigen::MatrixX3i& M = topology.matching;
  auto deviationWith = [&](const Step& s, int delta) {
    const int r = mod4(M(s.g, s.kg) + delta);
    return std::abs(residual(turning(geometry, phi, s.g, s.kg, s.f), r));
  };
  // Work in quarter turns: q = 4 index. Changing the matchings along a path from a to b by
  // delta adds delta to q(a) and takes it from q(b).
  std::vector<int> q(nv, 0);
  for (int v = 0; v < nv; ++v)
  {
    q[v] = topo.boundaryVertex[v] ? 0 : static_cast<int>(std::lround(4.0 * topology.index[v]));
  }

  std::vector<double> dist(nv, 0.0);
  std::vector<int> cameFrom(nv, -1), stepIndex(nv, -1), stamp(nv, -1);
  int search = 0;
  for (int pass = 0; pass < options.maxPasses; ++pass)
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
      while (!queue.empty() && visited < options.maxVisited)
      {
        const auto [d, u] = queue.top();
        queue.pop();
        if (d > dist[u] || d >= 2.0 * lambda)
        {
          continue; // stale, or no path this long can pay for itself
        }
        ++visited;
        if (u != a && q[u] != 0)
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
              pathCost += deviationWith(s, delta) - deviationWith(s, 0);
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
          const double r0 = residual(turning(geometry, phi, s.g, s.kg, s.f), M(s.g, s.kg));
          if (!(std::abs(r0 + delta * Quarter) < Pi))
          {
            continue;
          }
          // No wrap, so the changed residual is r0 + delta quarter turns.
          const double w = std::max(0.0, std::abs(r0 + delta * Quarter) - std::abs(r0));
          const double nd = d + w;
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
      for (int x = best; x != a; x = cameFrom[x])
      {
        const Step& s = steps[cameFrom[x]][stepIndex[x]];
        M(s.g, s.kg) = mod4(M(s.g, s.kg) + delta);
        M(s.f, s.kf) = mod4(-M(s.g, s.kg));
      }
      q[a] = 0;
      q[best] -= delta;
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
  report.costAfter = lambda * topology.singularities + topology.matchingCost;
  return report;
}

}
