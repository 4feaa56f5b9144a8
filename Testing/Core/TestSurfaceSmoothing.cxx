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
  const double edge = meanEdgeLength(sphere);
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
  // part and a knot tube: their curvature is their shape, and they are left as they are
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

TEST(SurfaceSmoothing, ShapeIsNotRoughNoiseIs)
{
  const auto roughness = [](const Surface& s) {
    const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
    return componentRoughness(s.V, s.F, topo)[0];
  };
  // a pleated sheet folds a third of its edges by 127 degrees, but it is developable: no
  // curvature to take away
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
  const Roughness sheet = roughness(pleats);
  EXPECT_EQ(sheet.curvedPoints, 0);
  EXPECT_FALSE(sheet.rough());

  // a coarse torus and a jittered, slightly noisy knot tube (Data/knot.obj's): their curvature
  // changes sign from point to point, but it is their shape, and most of it stays
  for (const Surface& s :
    { makeTorus(1.0, 0.4, 8, 6), makeKnotTube(2, 3, 1.0, 0.4, 0.15, 300, 24, 0.3, 0.03, 2007) })
  {
    const Roughness r = roughness(s);
    EXPECT_GT(r.curvatureLeft, RoughCurvatureLeft * r.curvature) << s.name;
    EXPECT_FALSE(r.rough()) << s.name;
  }

  // noise of a fifth of an edge on a sphere: nearly all its curvature goes
  const Roughness noisy = roughness(withNoise(makeIcosphere(1.0, 5), 0.2, 3));
  EXPECT_LT(noisy.curvatureLeft, 0.5 * RoughCurvatureLeft * noisy.curvature)
    << noisy.curvatureLeft << " of " << noisy.curvature << ", " << noisy.curvedPoints;
  EXPECT_TRUE(noisy.rough());
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
