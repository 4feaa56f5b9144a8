// Tests of the smoothing of rough surfaces: noise found and taken out, smooth, coarse and CAD-like
// surfaces left alone, the boundary held.
#include "FrameField.h"
#include "MeshTopology.h"
#include "SurfaceSmoothing.h"
#include "Surfaces.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace quadcover;

namespace
{
double meanEdgeLength(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  double sum = 0.0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      sum += (V.row(F(f, k)) - V.row(F(f, (k + 1) % 3))).norm();
    }
  }
  return sum / (3.0 * static_cast<double>(F.rows()));
}

/// Whether any component of V, F is rough.
bool anyRough(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  const MeshTopology topo = buildTopology(F, static_cast<int>(V.rows()));
  for (const Roughness& r : componentRoughness(V, F, topo))
  {
    if (r.rough())
    {
      return true;
    }
  }
  return false;
}

/// Points whose angle defect exceeds pi/8 in size.
int sharplyCurvedPoints(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  const MeshTopology topo = buildTopology(F, static_cast<int>(V.rows()));
  const Eigen::VectorXd defect = angleDefects(V, F, topo);
  int count = 0;
  for (Eigen::Index v = 0; v < V.rows(); ++v)
  {
    count += !topo.boundaryVertex[v] && std::abs(defect[v]) > RoughDefect ? 1 : 0;
  }
  return count;
}
}

TEST(SurfaceSmoothing, ANoisySphereIsRoughAndComesOutSmoothAndRound)
{
  const Surface sphere = makeIcosphere(1.0, 5);
  const double edge = meanEdgeLength(sphere.V, sphere.F);
  Eigen::MatrixX3d V = withNoise(sphere, 0.3, 7).V;
  ASSERT_TRUE(anyRough(V, sphere.F));
  const int before = sharplyCurvedPoints(V, sphere.F);
  EXPECT_GT(before, static_cast<int>(V.rows()) / 10) << "the noise should crumple the surface";

  EXPECT_EQ(smoothRoughComponents(V, sphere.F), static_cast<int>(V.rows()));
  EXPECT_FALSE(anyRough(V, sphere.F));
  EXPECT_LT(sharplyCurvedPoints(V, sphere.F), before / 20);
  // Taubin's steps keep the size: every point within two noise deviations of the unit sphere
  for (Eigen::Index v = 0; v < V.rows(); ++v)
  {
    EXPECT_NEAR(V.row(v).norm(), 1.0, 0.6 * edge) << "point " << v;
  }
}

TEST(SurfaceSmoothing, SmoothAndCreasedSurfacesAreNotRoughAndStay)
{
  // a sphere, a rounded and a sharp cube (creases bent by 90 degrees along flat sides), a CAD
  // part and a knot tube: neither folded nor changing the sign of their curvature, and untouched
  EXPECT_FALSE(anyRough(makeIcosphere(1.0, 4).V, makeIcosphere(1.0, 4).F));
  for (const Surface& s : { makeRoundedCube(0.2, 12), makeRoundedCube(0.0, 12), makeBracket(0.05),
         makeKnotTube(2, 3, 1.0, 0.4, 0.1, 200, 12, 0.0, 0.0, 1) })
  {
    EXPECT_FALSE(anyRough(s.V, s.F)) << s.name;
    Eigen::MatrixX3d V = s.V;
    EXPECT_EQ(smoothRoughComponents(V, s.F), 0) << s.name;
    EXPECT_EQ(V, s.V) << s.name;
  }
}

TEST(SurfaceSmoothing, EachCriterionAloneIsNotEnough)
{
  // a pleated sheet folds a third of its edges by 127 degrees, but it is developable: no angle
  // defect, so no sign change
  const int n = 40, m = 10;
  Surface pleats;
  pleats.V.resize((n + 1) * (m + 1), 3);
  pleats.F.resize(2 * n * m, 3);
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= m; ++j)
    {
      pleats.V.row(i * (m + 1) + j) << i, j, i % 2 == 0 ? 0.0 : 2.0;
    }
  }
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const int a = i * (m + 1) + j, b = a + m + 1;
      pleats.F.row(2 * (i * m + j)) << a, b, b + 1;
      pleats.F.row(2 * (i * m + j) + 1) << a, b + 1, a + 1;
    }
  }
  const MeshTopology sheet = buildTopology(pleats.F, static_cast<int>(pleats.V.rows()));
  const Roughness r = componentRoughness(pleats.V, pleats.F, sheet)[0];
  EXPECT_GT(r.foldedEdges, r.innerEdges / 4);
  EXPECT_EQ(r.signChanges, 0);
  EXPECT_FALSE(r.rough());

  // a coarse torus: its curvature changes sign along a fifth of its edges, but nothing folds
  const Surface coarse = makeTorus(1.0, 0.4, 8, 6);
  const MeshTopology ring = buildTopology(coarse.F, static_cast<int>(coarse.V.rows()));
  const Roughness t = componentRoughness(coarse.V, coarse.F, ring)[0];
  EXPECT_GT(t.signChanges, RoughSignChangeShare * t.edges);
  EXPECT_EQ(t.foldedEdges, 0);
  EXPECT_FALSE(t.rough());

  // a small noisy sphere (80 triangles) is over both shares but under the floor of 32 folds: a
  // few folds of a small part are its shape
  const Surface small = withNoise(makeIcosphere(1.0, 1), 0.5, 7);
  const MeshTopology ball = buildTopology(small.F, static_cast<int>(small.V.rows()));
  const Roughness s = componentRoughness(small.V, small.F, ball)[0];
  EXPECT_GT(s.foldedEdges, RoughFoldedShare * s.innerEdges);
  EXPECT_GT(s.signChanges, RoughSignChangeShare * s.edges);
  EXPECT_LT(s.foldedEdges, RoughMinimumEdges);
  EXPECT_FALSE(s.rough());
}

TEST(SurfaceSmoothing, OnlyTheRoughComponentMovesAndTheBoundaryStays)
{
  // a noisy open saddle beside a clean sphere: the saddle smoothed inside, its boundary held;
  // the sphere untouched
  const Surface saddle = makeSaddle(2.0, 1.0, 60);
  const Surface sphere = makeIcosphere(0.5, 4);
  Eigen::MatrixX3d V(saddle.V.rows() + sphere.V.rows(), 3);
  V << withNoise(saddle, 0.3, 3).V, sphere.V.rowwise() + Eigen::RowVector3d(3.0, 0.0, 0.0);
  Eigen::MatrixX3i F(saddle.F.rows() + sphere.F.rows(), 3);
  F << saddle.F, sphere.F.array() + static_cast<int>(saddle.V.rows());
  const MeshTopology topo = buildTopology(F, static_cast<int>(V.rows()));
  const std::vector<Roughness> roughness = componentRoughness(V, F, topo);
  ASSERT_EQ(roughness.size(), 2u);
  EXPECT_TRUE(roughness[topo.vertexComponent[0]].rough());
  EXPECT_FALSE(roughness[topo.vertexComponent[saddle.V.rows()]].rough());

  const Eigen::MatrixX3d before = V;
  const int moved = smoothRoughComponents(V, F);
  int inner = 0;
  for (Eigen::Index v = 0; v < saddle.V.rows(); ++v)
  {
    inner += topo.boundaryVertex[v] ? 0 : 1;
    if (topo.boundaryVertex[v])
    {
      EXPECT_EQ(V.row(v), before.row(v)) << "boundary point " << v;
    }
  }
  EXPECT_EQ(moved, inner);
  EXPECT_EQ(V.bottomRows(sphere.V.rows()), before.bottomRows(sphere.V.rows()));
  EXPECT_FALSE(anyRough(V.topRows(saddle.V.rows()), saddle.F));
}
