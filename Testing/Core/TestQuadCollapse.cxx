// removeTurnedQuads: a quad facing against the surface that no move of its corners mends is
// removed as an ear or collapsed along a diagonal, the mesh kept all quads, manifold, of the same
// Euler characteristic and boundary loops.
#include "QuadCollapse.h"
#include "QuadFacing.h"
#include "QuadMeshAdjacency.h"
#include "ScaledJacobian.h"
#include "SurfaceLocator.h"

#include <gtest/gtest.h>

#include <vector>

using namespace quadcover;

namespace
{
/// The plane z = 0 over [0, nx] x [0, ny], two triangles a unit square, facing +z.
struct Plane
{
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
};

Plane plane(int nx, int ny)
{
  Plane p;
  p.V.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      p.V.row(j * (nx + 1) + i) << i, j, 0.0;
    }
  }
  p.F.resize(2 * nx * ny, 3);
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
      p.F.row(2 * (j * nx + i)) << a, b, c;
      p.F.row(2 * (j * nx + i) + 1) << a, c, d;
    }
  }
  return p;
}

/// A quad mesh of the points (x, y, 0) and the quads given, on the locator's surface.
QuadMesh quadMesh(const SurfaceLocator& surface, const std::vector<Eigen::Vector2d>& points,
  const std::vector<Eigen::Vector4i>& quads)
{
  QuadMesh q;
  q.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    q.V.row(static_cast<Eigen::Index>(v)) << points[v].x(), points[v].y(), 0.0;
    q.vertexTriangle.push_back(surface.closest(q.V.row(v).transpose()).triangle);
    q.vertexPoint.push_back(-1);
  }
  q.Q.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    q.Q.row(static_cast<Eigen::Index>(i)) = quads[i].transpose();
    const Eigen::Vector3d centre =
      (q.V.row(quads[i][0]) + q.V.row(quads[i][1]) + q.V.row(quads[i][2]) + q.V.row(quads[i][3]))
        .transpose() /
      4.0;
    q.quadTriangle.push_back(surface.closest(centre).triangle);
  }
  return q;
}

/// The n x n quads of the unit grid over [0, n]^2, counterclockwise seen from +z.
QuadMesh grid(const SurfaceLocator& surface, int n)
{
  std::vector<Eigen::Vector2d> points;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      points.emplace_back(i, j);
    }
  }
  std::vector<Eigen::Vector4i> quads;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i;
      quads.emplace_back(a, a + 1, a + n + 2, a + n + 1);
    }
  }
  return quadMesh(surface, points, quads);
}

/// The quads facing against the surface or turned inside out.
std::vector<int> bad(const SurfaceLocator& surface, const QuadMesh& q)
{
  std::vector<int> list;
  for (int i = 0; i < static_cast<int>(q.Q.rows()); ++i)
  {
    if (!(quadWorstOf(surface, q, i) > 0.0))
    {
      list.push_back(i);
    }
  }
  return list;
}

void expectSameTopology(const QuadMesh& before, const QuadMesh& after);

/// removeTurnedQuads on q's one bad quad `which`: it mends it with `ears` ears and `collapsed`
/// collapses, leaving `quads` quads on `points` points, none bad, the topology q had.
void expectMended(const SurfaceLocator& surface, QuadMesh& q, int which, int ears, int collapsed,
  int quads, int points)
{
  const std::vector<int> turned = bad(surface, q);
  ASSERT_EQ(turned, std::vector<int>{ which }) << "the test needs one quad turned over";
  const QuadMesh before = q;
  const QuadCollapseResult r = removeTurnedQuads(surface, turned, q);
  EXPECT_EQ(r.ears, ears);
  EXPECT_EQ(r.collapsed, collapsed);
  EXPECT_EQ(q.Q.rows(), quads);
  EXPECT_EQ(q.V.rows(), points);
  EXPECT_TRUE(bad(surface, q).empty());
  expectSameTopology(before, q);
}

void expectSameTopology(const QuadMesh& before, const QuadMesh& after)
{
  const MeshTopology was = quadTopology(before), is = quadTopology(after);
  EXPECT_TRUE(is.isManifold());
  EXPECT_EQ(is.numComponents(), was.numComponents());
  EXPECT_EQ(is.eulerCharacteristic(), was.eulerCharacteristic());
  EXPECT_EQ(is.boundaryLoops.size(), was.boundaryLoops.size());
  EXPECT_EQ(after.quadTriangle.size(), static_cast<std::size_t>(after.Q.rows()));
  EXPECT_EQ(after.vertexTriangle.size(), static_cast<std::size_t>(after.V.rows()));
}
}

TEST(QuadCollapse, CollapsesAQuadTurnedOverAlongItsDiagonal)
{
  const Plane p = plane(4, 4);
  const SurfaceLocator surface(p.V, p.F);
  QuadMesh q = grid(surface, 4);
  // the quad over [1, 2]^2 with its corners (1, 1) and (2, 2) pushed past each other: it faces
  // -z, its neighbours stay convex
  q.V.row(6) << 1.6, 1.6, 0.0;
  q.V.row(12) << 1.4, 1.4, 0.0;
  expectMended(surface, q, 5, 0, 1, 15, 24);
}

TEST(QuadCollapse, RemovesAnEarTurnedOver)
{
  const Plane p = plane(3, 1);
  const SurfaceLocator surface(p.V, p.F);
  // two quads along x, and an ear on the edge x = 2 folded back over the second
  QuadMesh q = quadMesh(surface,
    { { 0, 0 }, { 1, 0 }, { 2, 0 }, { 0, 1 }, { 1, 1 }, { 2, 1 }, { 1.6, 0.1 }, { 1.6, 0.9 } },
    { { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 5, 2, 6, 7 } });
  expectMended(surface, q, 2, 1, 0, 2, 6);
}

TEST(QuadCollapse, LeavesAQuadNoChangeMends)
{
  const Plane p = plane(1, 1);
  const SurfaceLocator surface(p.V, p.F);
  // one quad, clockwise: facing -z, no neighbour to hang off or to collapse onto
  QuadMesh q = quadMesh(surface, { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, { { 0, 3, 2, 1 } });
  const std::vector<int> turned = bad(surface, q);
  ASSERT_EQ(turned, std::vector<int>{ 0 });
  const QuadMesh before = q;
  const QuadCollapseResult r = removeTurnedQuads(surface, turned, q);
  EXPECT_EQ(r.ears + r.collapsed, 0);
  EXPECT_EQ(q.Q, before.Q);
  EXPECT_EQ(q.V, before.V);
}
