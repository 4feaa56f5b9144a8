// Adaptive density: the grid size asked where the surface curves sharply against the grid
// (curvatureGridScale), and the map and quads made with it (adaptiveCurvature).
#include "CurvatureSizing.h"
#include "GridMapChecks.h"
#include "QuadExtraction.h"
#include "QuadQuality.h"
#include "TestChain.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace quadcover;

TEST(CurvatureSizing, AsksForAFinerGridOnlyWhereTheRadiusIsSmallAgainstTheGrid)
{
  // the unit sphere: radius of curvature 1 everywhere
  const Surface s = makeIcosphere(1.0, 4);
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  // grid edge 1: half the radius is asked, everywhere
  const Eigen::VectorXd half = curvatureGridScale(s.V, s.F, topo, 1.0, 0.5, 8.0);
  ASSERT_EQ(half.size(), s.F.rows());
  EXPECT_GT(half.minCoeff(), 0.4);
  EXPECT_LT(half.maxCoeff(), 0.6);
  // no finer than the bound
  const Eigen::VectorXd bounded = curvatureGridScale(s.V, s.F, topo, 1.0, 0.05, 8.0);
  EXPECT_NEAR(bounded.minCoeff(), 1.0 / 8.0, 1e-12);
  EXPECT_NEAR(bounded.maxCoeff(), 1.0 / 8.0, 1e-12);
  // a grid edge of 0.3 is already finer than half the radius; off, or no refinement allowed
  EXPECT_EQ(curvatureGridScale(s.V, s.F, topo, 0.3, 0.5, 8.0).size(), 0);
  EXPECT_EQ(curvatureGridScale(s.V, s.F, topo, 1.0, 0.0, 8.0).size(), 0);
  EXPECT_EQ(curvatureGridScale(s.V, s.F, topo, 1.0, 0.5, 1.0).size(), 0);
}

TEST(CurvatureSizing, SeesTheCurvatureAtTheGridsScaleNotTheMeshNoise)
{
  // the unit sphere with its points moved in and out by up to 2% of the radius (a bumpy scan):
  // the normals of neighbouring points differ by up to ~0.4 radians over edges of ~0.08, a
  // radius of ~0.2; at a grid edge of 1 the surface is the sphere of radius 1
  Surface s = makeIcosphere(1.0, 4);
  for (Eigen::Index v = 0; v < s.V.rows(); ++v)
  {
    s.V.row(v) *= 1.0 + 0.02 * std::sin(12.9898 * static_cast<double>(v));
  }
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const Eigen::VectorXd scale = curvatureGridScale(s.V, s.F, topo, 1.0, 0.5, 8.0);
  ASSERT_EQ(scale.size(), s.F.rows());
  std::printf("bumpy sphere: scale %.3f to %.3f\n", scale.minCoeff(), scale.maxCoeff());
  EXPECT_GT(scale.minCoeff(), 0.35) << "the bumps ask for no finer grid than the sphere";
  EXPECT_LT(scale.maxCoeff(), 0.65);
}

TEST(CurvatureSizing, TheNeckOfADumbbellGetsAFinerGridAndTheBulbsKeepTheirs)
{
  // bulbs of radius 0.8, a neck of 0.12 at z = 0; grid edge 0.2: the neck asks for 0.06
  const Surface s = makeDumbbell(1.5, 0.8, 0.12, 48, 60);
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const Eigen::VectorXd scale = curvatureGridScale(s.V, s.F, topo, 0.2, 0.5, 8.0);
  ASSERT_EQ(scale.size(), s.F.rows());
  double neck = 1.0, bulb = 0.0, widest = 0.0;
  for (int f = 0; f < s.F.rows(); ++f)
  {
    const double z = (s.V(s.F(f, 0), 2) + s.V(s.F(f, 1), 2) + s.V(s.F(f, 2), 2)) / 3;
    const double r = std::hypot(s.V(s.F(f, 0), 0), s.V(s.F(f, 0), 1));
    if (std::abs(z) < 0.05)
    {
      neck = std::min(neck, scale[f]);
    }
    if (r > widest)
    {
      widest = r;
      bulb = scale[f];
    }
  }
  std::printf("neck %.3f, bulbs %.3f\n", neck, bulb);
  EXPECT_LT(neck, 0.5);
  EXPECT_EQ(bulb, 1.0);
}

TEST(CurvatureSizing, AdaptiveQuadsKeepTheTopologyAndTheCountAndPutMoreRowsOnTheNeck)
{
  const Surface dumbbell = makeDumbbell(1.5, 0.8, 0.12, 48, 60);
  int neckQuads[2] = { 0, 0 }, allQuads[2] = { 0, 0 };
  for (const double adaptive : { 0.0, 0.5 })
  {
    ParameterizationOptions options;
    options.adaptiveCurvature = adaptive;
    const Chain c = runChain(dumbbell, 500, options);
    // the finer grid's map is still an integer-grid map: seamless, branch points on the grid,
    // and Poincare-Hopf (the sphere's chi) for the singularities it follows
    EXPECT_EQ(checks::seamViolations(c.s.F, c.topo, c.map.cornerUV, 1e-6), 0);
    EXPECT_EQ(checks::branchPointsOffGrid(c.s.F, c.topo, c.map.layerShift, c.map.cornerUV), 0);
    EXPECT_NEAR(c.map.singularityIndex.sum(), 2.0, 1e-9);
    EXPECT_EQ(c.map.branchPointsOnGrid, c.map.branchPoints);
    const QuadMesh quads = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
    const QuadQuality q = measureQuads(quads.V, quads.Q);
    EXPECT_EQ(q.quads, q.faces);
    EXPECT_EQ(q.eulerCharacteristic, 2);
    EXPECT_EQ(q.boundaryEdges, 0);
    EXPECT_EQ(q.nonManifoldEdges, 0);
    EXPECT_EQ(c.map.flipped, 0);
    allQuads[adaptive > 0 ? 1 : 0] = q.quads;
    int& neck = neckQuads[adaptive > 0 ? 1 : 0];
    for (int i = 0; i < quads.Q.rows(); ++i)
    {
      double z = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        z += quads.V(quads.Q(i, k), 2) / 4;
      }
      neck += std::abs(z) < 0.3;
    }
    std::printf("adaptive %.1f: %d quads, %d on the neck (|z| < 0.3), edge RSD %.1f%%\n", adaptive,
      q.quads, neck, 100 * q.edgeLengthRSD);
  }
  EXPECT_GT(neckQuads[1], 1.5 * neckQuads[0]) << "more rows along the neck";
  // the neck's quads count against the quads asked for: the bulbs' are larger (not all of them:
  // the quad count follows the map's area before rounding)
  EXPECT_LT(allQuads[1], 1.35 * allQuads[0]);
}

TEST(CurvatureSizing, CreasesAreNoThinParts)
{
  // the sharp cube [-1,1]^3: its twelve edges bend by 90 degrees within a mesh edge, which reads
  // as a tiny radius; given as creases they ask for nothing, and the flat faces neither
  const Surface s = makeRoundedCube(0.0, 16);
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  std::vector<char> creases(static_cast<std::size_t>(topo.numEdges()), 0);
  int count = 0;
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    const int f0 = topo.edgeFaces(e, 0), f1 = topo.edgeFaces(e, 1);
    auto normal = [&](int f) {
      const Eigen::Vector3d a = s.V.row(s.F(f, 0)), b = s.V.row(s.F(f, 1)), c = s.V.row(s.F(f, 2));
      return Eigen::Vector3d((b - a).cross(c - a).normalized());
    };
    if (f0 >= 0 && f1 >= 0 && normal(f0).dot(normal(f1)) < 0.5)
    {
      creases[e] = 1;
      ++count;
    }
  }
  ASSERT_EQ(count, 12 * 16) << "twelve edges of 16 mesh edges each";
  const Eigen::VectorXd without = curvatureGridScale(s.V, s.F, topo, 0.5, 0.5, 8.0);
  ASSERT_EQ(without.size(), s.F.rows());
  EXPECT_LT(without.minCoeff(), 0.75) << "without the creases the cube's edges read as thin";
  const Eigen::VectorXd with = curvatureGridScale(s.V, s.F, topo, 0.5, 0.5, 8.0, creases);
  EXPECT_TRUE(with.size() == 0 || with.minCoeff() == 1.0)
    << "finest " << (with.size() ? with.minCoeff() : 1.0);
}
