// Matchings.cxx: the geometry matchings are measured in, smallest-angle matchings, what given
// matchings imply (layer shifts, indices, costs), and the matching stage as one call.
#include "Matchings.h"

#include "MatchingAngles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadcover
{
using detail::mod4;
using detail::Pi;
using detail::Quarter;
using detail::residual;
using detail::turning;
using detail::twinEdge;

namespace
{
/// An inner point of index 3/4 or more: a quad vertex of valence 1 or less, which no map gives.
bool hasUnmappableSingularity(const MeshTopology& topo, const FrameTopology& topology)
{
  for (int v = 0; v < topo.numVertices; ++v)
  {
    if (!topo.boundaryVertex[v] && topology.index[v] > 0.75 - 1e-6)
    {
      return true;
    }
  }
  return false;
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
  const double total = surfaceArea(V, F);
  G.referenceLength = std::sqrt(total / 2000.0);
  G.componentReferenceLength = Eigen::VectorXd::Constant(F.rows(), G.referenceLength);
  if (topo.numComponents() > 1 && total > 0.0)
  {
    const std::vector<double> area = componentAreas(V, F, topo);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
    {
      const int c = topo.faceComponent[f];
      const double cells = std::max(2000.0 * area[c] / total,
        static_cast<double>(
          ReferenceComponentQuads * holesAndHandles(topo.components[c].eulerCharacteristic)));
      G.componentReferenceLength[f] = std::sqrt(area[c] / cells);
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
  forEachNeighbor(topo, [&](int f, int k, int g) {
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
  });

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
  else if (bp.splitDistance > 0 && hasUnmappableSingularity(topo, r.topology))
  {
    // Without the optimization the field keeps its own singularities, but one of index 3/4 or
    // more is still split: no map can follow a whole turn (the teapot's lid, smoothest field: one
    // +1 at the pole, around which the map's angles must add up to 0; half the lid folded over;
    // Data/dumbbell.obj: a +1 at each pole, 134 s and 8 pieces), and a quad vertex of valence 1
    // is a quad folded onto itself. A +1/2 stays (a valence-2 quad vertex; split, the
    // screwdriver's gave a map with a fold and a Hausdorff distance twice as large).
    BranchPointOptions splitOnly = bp;
    splitOnly.branchPointWeight = 0.0; // no merges
    splitOnly.splitQuarters = 3;
    r.report = optimizeBranchPoints(
      F, topo, geometry, frameU, r.topology, splitOnly, progress.part(0.1, 0.8));
    r.objectiveAfter = bp.branchPointWeight * r.topology.singularities +
      scaledMatchingCost(F, topo, geometry, r.topology, bp.lengthScaledCost);
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
