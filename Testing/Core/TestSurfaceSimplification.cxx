// Tests of the simplification of a surface finer than its quads need: topology, boundaries,
// creases, components and orientation kept, the surface close to the input.
#include "MeshTopology.h"
#include "SurfaceLocator.h"
#include "SurfaceSimplification.h"
#include "Surfaces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace quadcover;

namespace
{
/// Twice the area vector of triangle f.
Eigen::Vector3d areaVector(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int f)
{
  const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
  return (b - a).cross(c - a);
}

/// The largest distance from a point of `points` to the surface V, F.
double farthest(
  const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  const SurfaceLocator locator(V, F);
  double d = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    d = std::max(d, locator.closest(points.row(i).transpose()).distance);
  }
  return d;
}

/// Checks what every simplification keeps: a manifold, oriented surface of the input's Euler
/// characteristic and components, made of input points, with no repeated triangle.
void expectSameTopology(
  const Surface& in, const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const Simplification& s)
{
  const MeshTopology before = buildTopology(in.F, static_cast<int>(in.V.rows()));
  const MeshTopology after = buildTopology(F, static_cast<int>(V.rows()));
  EXPECT_TRUE(after.isManifold()) << after.describeDefects();
  EXPECT_TRUE(after.isOriented()) << after.describeDefects();
  EXPECT_EQ(after.eulerCharacteristic(), before.eulerCharacteristic());
  EXPECT_EQ(after.numComponents(), before.numComponents());
  EXPECT_EQ(after.boundaryLoops.size(), before.boundaryLoops.size());
  ASSERT_EQ(static_cast<Eigen::Index>(s.pointSource.size()), V.rows());
  ASSERT_EQ(static_cast<Eigen::Index>(s.triangleSource.size()), F.rows());
  for (Eigen::Index p = 0; p < V.rows(); ++p)
  {
    ASSERT_EQ(V.row(p), in.V.row(s.pointSource[p])) << "the points are the input's";
  }
  std::set<std::vector<int>> seen;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    std::vector<int> corners = { F(f, 0), F(f, 1), F(f, 2) };
    std::sort(corners.begin(), corners.end());
    EXPECT_TRUE(seen.insert(corners).second) << "triangle " << f << " repeats another";
  }
}
}

TEST(SurfaceSimplification, ATorusKeepsItsTopologyShapeAndFacing)
{
  const Surface torus = makeTorus(1.0, 0.4, 96, 48); // 9,216 triangles
  Eigen::MatrixX3d V = torus.V;
  Eigen::MatrixX3i F = torus.F;
  const Simplification s = simplifySurface(V, F, 2000);
  EXPECT_LE(F.rows(), 2000);
  EXPECT_GE(F.rows(), 1990);
  EXPECT_EQ(s.collapsedEdges, (torus.F.rows() - F.rows()) / 2); // closed: two triangles each
  expectSameTopology(torus, V, F, s);
  // close to the input both ways (the diagonal is about 2.9; 2,000 evenly spread triangles would
  // leave chords about 0.005 inside the tube), every triangle facing outward
  EXPECT_LT(farthest(torus.V, V, F), 0.02);
  EXPECT_LT(farthest(V, torus.V, torus.F), 1e-12);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    const Eigen::Vector3d centre = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))) / 3.0;
    const Eigen::Vector3d axis(centre.x(), centre.y(), 0.0);
    const Eigen::Vector3d outward = centre - axis.normalized();
    EXPECT_GT(areaVector(V, F, static_cast<int>(f)).normalized().dot(outward.normalized()), 0.5)
      << "triangle " << f << " turned";
  }
}

TEST(SurfaceSimplification, BoundaryPointsStayOnTheRims)
{
  const Surface cylinder = makeCylinder(0.5, 2.0, 64, 60);
  Eigen::MatrixX3d V = cylinder.V;
  Eigen::MatrixX3i F = cylinder.F;
  const Simplification s = simplifySurface(V, F, 1500);
  EXPECT_LE(F.rows(), 1500);
  expectSameTopology(cylinder, V, F, s);
  const MeshTopology after = buildTopology(F, static_cast<int>(V.rows()));
  for (const std::vector<int>& loop : after.boundaryLoops)
  {
    EXPECT_GE(loop.size(), 8u) << "a rim is kept as a loop of several points";
    for (const int p : loop)
    {
      EXPECT_NEAR(std::abs(V(p, 2)), 1.0, 1e-12) << "a boundary point left its rim";
    }
  }
}

TEST(SurfaceSimplification, CreasesStayOnTheSurface)
{
  // a CAD-like part of right-angle creases: straight creases simplified along themselves only
  // keep every input point of a crease on the simplified surface
  const Surface part = makeBracket(0.05);
  Eigen::MatrixX3d V = part.V;
  Eigen::MatrixX3i F = part.F;
  const Simplification s = simplifySurface(V, F, part.F.rows() / 6);
  EXPECT_LE(F.rows(), part.F.rows() / 6 + 2);
  expectSameTopology(part, V, F, s);
  const MeshTopology topo = buildTopology(part.F, static_cast<int>(part.V.rows()));
  std::vector<int> creasePoints;
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    const int f0 = topo.edgeFaces(e, 0), f1 = topo.edgeFaces(e, 1);
    if (f0 >= 0 && f1 >= 0 &&
      areaVector(part.V, part.F, f0).normalized().dot(areaVector(part.V, part.F, f1).normalized()) <
        0.5)
    {
      creasePoints.push_back(topo.edges(e, 0));
      creasePoints.push_back(topo.edges(e, 1));
    }
  }
  ASSERT_GT(creasePoints.size(), 100u);
  Eigen::MatrixX3d onCreases(creasePoints.size(), 3);
  for (std::size_t i = 0; i < creasePoints.size(); ++i)
  {
    onCreases.row(static_cast<Eigen::Index>(i)) = part.V.row(creasePoints[i]);
  }
  EXPECT_LT(farthest(onCreases, V, F), 1e-9);
  EXPECT_LT(farthest(part.V, V, F), 1e-9) << "a part of flat faces is kept exactly";
}

TEST(SurfaceSimplification, EveryComponentKeepsItsShare)
{
  // fifty spheres and tori of radii 0.1 to 10: the small ones, whose share of the triangles by
  // area is 256 or fewer, keep 256 (or all of theirs); none vanishes
  const Surface many = makeComponents(50, 0.1, 10.0);
  Eigen::MatrixX3d V = many.V;
  Eigen::MatrixX3i F = many.F;
  const Simplification s = simplifySurface(V, F, many.F.rows() / 4);
  expectSameTopology(many, V, F, s);
  EXPECT_GT(s.collapsedEdges, 0);
  EXPECT_LT(F.rows(), many.F.rows());
  const MeshTopology before = buildTopology(many.F, static_cast<int>(many.V.rows()));
  const MeshTopology after = buildTopology(F, static_cast<int>(V.rows()));
  ASSERT_EQ(before.numComponents(), after.numComponents());
  for (int c = 0; c < before.numComponents(); ++c)
  {
    // components are numbered alike: the triangles keep their order
    EXPECT_GE(after.components[c].numFaces, std::min(before.components[c].numFaces, 256))
      << "component " << c;
    EXPECT_EQ(after.components[c].eulerCharacteristic, before.components[c].eulerCharacteristic);
  }
}

TEST(SurfaceSimplification, NothingChangesBelowTheBudget)
{
  const Surface sphere = makeIcosphere(1.0, 3);
  for (const long long budget : { 0LL, static_cast<long long>(sphere.F.rows()), 1000000LL })
  {
    Eigen::MatrixX3d V = sphere.V;
    Eigen::MatrixX3i F = sphere.F;
    const Simplification s = simplifySurface(V, F, budget);
    EXPECT_EQ(s.collapsedEdges, 0);
    EXPECT_EQ(V, sphere.V);
    EXPECT_EQ(F, sphere.F);
  }
  EXPECT_EQ(simplificationBudget(0.0), 0);
  EXPECT_EQ(simplificationBudget(3000.0), 100000);
  EXPECT_EQ(simplificationBudget(10000.0), 160000);
}

TEST(SurfaceSimplification, ASmallClosedSurfaceStaysASurface)
{
  // brought far down, a sphere must not collapse into a tetrahedron's doubled triangles
  const Surface sphere = makeIcosphere(1.0, 4); // 5,120 triangles
  Eigen::MatrixX3d V = sphere.V;
  Eigen::MatrixX3i F = sphere.F;
  const Simplification s = simplifySurface(V, F, 300);
  EXPECT_LE(F.rows(), 300);
  expectSameTopology(sphere, V, F, s);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    const Eigen::Vector3d centre = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))) / 3.0;
    EXPECT_GT(areaVector(V, F, static_cast<int>(f)).dot(centre), 0.0) << "triangle " << f;
  }
}

TEST(SurfaceSimplification, PolesOfThousandsOfTrianglesStayASurface)
{
  // a sphere of 4 rings of 4,000 points and two poles of valence 4,000 (each step looks at the
  // two points' rings: linear in their valence)
  const int around = 4000, rings = 4;
  Surface s;
  s.V.resize(2 + around * rings, 3);
  s.V.row(0) << 0, 0, 1;
  s.V.row(1) << 0, 0, -1;
  for (int r = 0; r < rings; ++r)
  {
    const double theta = 3.14159265358979323846 * (r + 1) / (rings + 1);
    for (int i = 0; i < around; ++i)
    {
      const double phi = 2 * 3.14159265358979323846 * i / around;
      s.V.row(2 + r * around + i) << std::sin(theta) * std::cos(phi),
        std::sin(theta) * std::sin(phi), std::cos(theta);
    }
  }
  std::vector<Eigen::Vector3i> faces;
  auto at = [&](int r, int i) { return 2 + r * around + (i % around); };
  for (int i = 0; i < around; ++i)
  {
    faces.emplace_back(0, at(0, i), at(0, i + 1));
    faces.emplace_back(1, at(rings - 1, i + 1), at(rings - 1, i));
    for (int r = 0; r + 1 < rings; ++r)
    {
      faces.emplace_back(at(r, i), at(r + 1, i), at(r + 1, i + 1));
      faces.emplace_back(at(r, i), at(r + 1, i + 1), at(r, i + 1));
    }
  }
  s.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    s.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  }
  Eigen::MatrixX3d V = s.V;
  Eigen::MatrixX3i F = s.F;
  const Simplification result = simplifySurface(V, F, s.F.rows() / 4);
  EXPECT_GT(result.collapsedEdges, 0);
  expectSameTopology(s, V, F, result);
}
