// The cut graph: one disk per component, through every terminal, no dangling branch.
#include "CurvatureFrames.h"
#include "CutGraph.h"
#include "FrameSmoother.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "Surfaces.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

using namespace quadcover;

namespace
{
/// The singular points of the default smoothed field (what the solver will pass as terminals).
std::vector<char> singularPoints(const Surface& s, const MeshTopology& topo)
{
  const FrameGeometry g = computeFrameGeometry(s.V, s.F, topo);
  const CurvatureField c = computeCurvatureField(s.V, s.F, topo);
  const SmootherResult r = smoothFrames(s.V, s.F, topo, g, c.frameU, c.frameV, c.weight);
  FrameTopology t = computeMatchings(s.F, topo, g, r.frameU);
  optimizeBranchPoints(s.F, topo, g, r.frameU, t);
  std::vector<char> terminal(topo.numVertices, 0);
  for (int v = 0; v < topo.numVertices; ++v)
  {
    terminal[v] = !topo.boundaryVertex[v] && t.index[v] != 0.0;
  }
  return terminal;
}

void expectDiskThroughTerminals(
  const MeshTopology& topo, const CutGraph& cut, const std::vector<char>& terminal)
{
  for (int c = 0; c < topo.numComponents(); ++c)
  {
    EXPECT_EQ(cut.cutEuler[c], 1) << "component " << c;
  }
  std::vector<int> degree(topo.numVertices, 0);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (cut.onCut[e])
    {
      ASSERT_EQ(topo.edgeFaceCount[e], 2) << "boundary edges are never cut";
      ++degree[topo.edges(e, 0)];
      ++degree[topo.edges(e, 1)];
    }
  }
  for (int v = 0; v < topo.numVertices; ++v)
  {
    if (!terminal.empty() && terminal[v])
    {
      EXPECT_TRUE(degree[v] > 0 || topo.boundaryVertex[v]) << "terminal " << v << " not reached";
    }
    else if (!topo.boundaryVertex[v])
    {
      EXPECT_NE(degree[v], 1) << "dangling branch ends at " << v;
    }
  }
}
}

TEST(CutGraph, ClosedSurfacesBecomeDisksThroughTheirSingularities)
{
  for (const char* name : { "sphere", "torus", "knot", "roundedcube" })
  {
    const Surface s = testSurface(name);
    const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
    const std::vector<char> terminal = singularPoints(s, topo);
    const CutGraph cut = computeCutGraph(topo, terminal);
    SCOPED_TRACE(name);
    expectDiskThroughTerminals(topo, cut, terminal);
    EXPECT_GT(cut.numCutEdges, 0);
  }
}

TEST(CutGraph, GenusNeedsLoopsAndBoundariesNeedPaths)
{
  // A torus without terminals keeps two generating loops; an annulus one path between its
  // boundaries; a disk nothing at all.
  {
    const Surface s = makeTorus(1.0, 0.4, 24, 12);
    const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
    const CutGraph cut = computeCutGraph(topo, {});
    expectDiskThroughTerminals(topo, cut, {});
    EXPECT_GE(cut.numCutEdges, 12 + 6); // at least two loops around the torus
  }
  {
    const Surface s = makeCylinder(0.5, 2.0, 24, 10);
    const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
    const CutGraph cut = computeCutGraph(topo, {});
    expectDiskThroughTerminals(topo, cut, {});
    EXPECT_GE(cut.numCutEdges, 10); // one path from rim to rim
  }
  {
    const Surface s = makeSaddle(1.0, 0.5, 10);
    const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
    const CutGraph cut = computeCutGraph(topo, {});
    expectDiskThroughTerminals(topo, cut, {});
    EXPECT_EQ(cut.numCutEdges, 0);
  }
}

TEST(CutGraph, SphereWithoutTerminalsStaysWholeAndSeveralComponentsEachBecomeDisks)
{
  const Surface sphere = makeIcosphere(1.0, 2);
  const MeshTopology t1 = buildTopology(sphere.F, static_cast<int>(sphere.V.rows()));
  const CutGraph none = computeCutGraph(t1, {});
  EXPECT_EQ(none.numCutEdges, 0);
  EXPECT_EQ(none.cutEuler[0], 2); // documented: the caller decides
  // Two terminals: a path between them.
  std::vector<char> two(t1.numVertices, 0);
  two[0] = two[5] = 1;
  expectDiskThroughTerminals(t1, computeCutGraph(t1, two), two);

  // A torus and a cylinder in one mesh.
  const Surface a = makeTorus(1.0, 0.4, 24, 12), b = makeCylinder(0.5, 2.0, 24, 10);
  Eigen::MatrixX3i F(a.F.rows() + b.F.rows(), 3);
  F << a.F, (b.F.array() + static_cast<int>(a.V.rows())).matrix();
  const MeshTopology topo = buildTopology(F, static_cast<int>(a.V.rows() + b.V.rows()));
  const CutGraph cut = computeCutGraph(topo, {});
  ASSERT_EQ(cut.cutEuler.size(), 2u);
  expectDiskThroughTerminals(topo, cut, {});
}

TEST(CutGraph, RefusesNonManifoldSurfaces)
{
  Eigen::MatrixX3i F(3, 3);
  F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  EXPECT_THROW(computeCutGraph(buildTopology(F, 5), {}), std::invalid_argument);
  const Surface s = makeIcosphere(1.0, 1);
  EXPECT_THROW(computeCutGraph(buildTopology(s.F, static_cast<int>(s.V.rows())), { 1, 0 }),
    std::invalid_argument);
}
