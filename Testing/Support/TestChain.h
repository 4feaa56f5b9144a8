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

/// Curvature frames, smoothing (`smoothing`), matchings (the filters' defaults, buildMatchings),
/// then the map with edge length sqrt(area / quads) (or options.targetEdgeLength).
inline Chain runChain(Surface s, double quads,
  ParameterizationOptions options = ParameterizationOptions(),
  const SmootherOptions& smoothing = SmootherOptions())
{
  Chain r{ std::move(s), {}, {}, {}, {}, {} };
  r.topo = buildTopology(r.s.F, static_cast<int>(r.s.V.rows()));
  r.geometry = computeFrameGeometry(r.s.V, r.s.F, r.topo);
  const CurvatureField c = computeCurvatureField(r.s.V, r.s.F, r.topo);
  const SmootherResult smooth =
    smoothFrames(r.s.V, r.s.F, r.topo, r.geometry, c.frameU, c.frameV, c.weight, smoothing);
  const MatchingResult m = buildMatchings(
    r.s.V, r.s.F, r.topo, r.geometry, smooth.frameU, smooth.frameV, c.weight, smooth.constrained);
  r.frameU = m.frameU;
  r.field = m.topology;
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
