// The whole core pipeline as the filters run it, for the core tests of the later stages.
#ifndef quadcover_TestChain_h
#define quadcover_TestChain_h

#include "CurvatureFrames.h"
#include "FrameField.h"
#include "FrameSmoother.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "Parameterization.h"
#include "Surfaces.h"

namespace quadcover
{
struct Chain
{
  Surface s;
  MeshTopology topo;
  FrameGeometry geometry;
  Eigen::MatrixX3d frameU;
  FrameTopology field;
  Parameterization map;
};

/// Curvature frames, smoothing, matchings with branch-point optimization and the frames fitted
/// to them (the filters' defaults), then the map with edge length sqrt(area / quads) (or options.targetEdgeLength).
inline Chain runChain(
  Surface s, double quads, ParameterizationOptions options = ParameterizationOptions())
{
  Chain r{ std::move(s), {}, {}, {}, {}, {} };
  r.topo = buildTopology(r.s.F, static_cast<int>(r.s.V.rows()));
  r.geometry = computeFrameGeometry(r.s.V, r.s.F, r.topo);
  const CurvatureField c = computeCurvatureField(r.s.V, r.s.F, r.topo);
  const SmootherResult smooth =
    smoothFrames(r.s.V, r.s.F, r.topo, r.geometry, c.frameU, c.frameV, c.weight);
  r.frameU = smooth.frameU;
  r.field = computeMatchings(r.s.F, r.topo, r.geometry, r.frameU);
  const BranchPointReport report =
    optimizeBranchPoints(r.s.F, r.topo, r.geometry, r.frameU, r.field);
  if (report.pathsChanged > 0)
  {
    std::vector<char> held(smooth.constrained.size(), 0); // the boundary's, as the filter does
    for (std::size_t f = 0; f < held.size(); ++f)
    {
      const int i = static_cast<int>(f);
      held[f] = smooth.constrained[f] &&
        (r.topo.faceNeighbors(i, 0) < 0 || r.topo.faceNeighbors(i, 1) < 0 ||
          r.topo.faceNeighbors(i, 2) < 0);
    }
    const Eigen::VectorXd alpha = fitFramesToMatchings(
      r.s.V, r.s.F, r.topo, r.geometry, r.frameU, r.field.matching, c.weight, 0.97, held);
    Eigen::MatrixX3d V = r.frameU;
    rotateFrames(r.geometry.bases, alpha, r.frameU, V);
    r.field = evaluateMatchings(r.s.F, r.topo, r.geometry, r.frameU, r.field.matching);
  }
  // a fixed edge length (no correction by the map's area) unless the options give one
  if (options.targetEdgeLength == 0.0)
  {
    options.targetEdgeLength = edgeLengthForQuadCount(r.s.V, r.s.F, quads);
  }
  r.map =
    computeParameterization(r.s.V, r.s.F, r.topo, r.geometry, r.frameU, r.field.matching, options);
  return r;
}
}

#endif
