// The closest points of a whole surface (SurfaceLocator) and the quads that face against it:
// turnedQuads finds them, repairFacing turns them back without changing the connectivity (boundary
// vertices sliding along the boundary).
#include "QuadExtraction.h"
#include "QuadFacing.h"
#include "QuadMeshAdjacency.h"
#include "QuadMeshing.h"
#include "QuadQuality.h"
#include "ScaledJacobian.h"
#include "SurfaceLocator.h"
#include "TestChain.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace quadcover;

namespace
{
/// Two surfaces as one of two components (the second shifted by `offset`).
Surface joined(const Surface& a, const Surface& b, const Eigen::RowVector3d& offset)
{
  Surface s;
  s.V.resize(a.V.rows() + b.V.rows(), 3);
  s.V << a.V, b.V.rowwise() + offset;
  s.F.resize(a.F.rows() + b.F.rows(), 3);
  s.F << a.F, b.F.array() + static_cast<int>(a.V.rows());
  return s;
}

/// A hollow ball: the unit icosphere and, `gap` inside it, the same turned inward (the walls of a
/// hollow part, two components).
Surface hollowBall(double gap)
{
  const Surface outer = testSurface("sphere");
  Surface inner = outer;
  inner.V *= 1.0 - gap;
  inner.F.col(1).swap(inner.F.col(2));
  return joined(outer, inner, Eigen::RowVector3d::Zero());
}

double bruteForceDistance(const Surface& s, const Eigen::Vector3d& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (int t = 0; t < s.F.rows(); ++t)
  {
    const Eigen::Vector3d q =
      closestOnTriangle(p, s.V.row(s.F(t, 0)), s.V.row(s.F(t, 1)), s.V.row(s.F(t, 2)));
    best = std::min(best, (q - p).norm());
  }
  return best;
}

/// The quads facing against the surface or turned inside out.
std::vector<int> badQuads(const Surface& s, const QuadMesh& q)
{
  std::vector<int> list = turnedQuads(s.V, s.F, q), inverted = invertedQuads(q.V, q.Q);
  list.insert(list.end(), inverted.begin(), inverted.end());
  return list;
}
}

TEST(SurfaceLocator, FindsTheClosestPointOverEveryComponent)
{
  const Surface s =
    joined(testSurface("sphere"), testSurface("torus"), Eigen::RowVector3d(0.7, 0.2, 0.1));
  const SurfaceLocator locator(s.V, s.F);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2.5, 2.5);
  for (int i = 0; i < 300; ++i)
  {
    const Eigen::Vector3d p(coordinate(random), coordinate(random), coordinate(random));
    const SurfaceLocator::Hit hit = locator.closest(p);
    ASSERT_GE(hit.triangle, 0);
    EXPECT_NEAR(hit.distance, bruteForceDistance(s, p), 1e-12);
    EXPECT_NEAR((hit.point - p).norm(), hit.distance, 1e-12);
    const std::vector<int> ties = locator.nearlyClosest(p, 0.0);
    EXPECT_NE(std::find(ties.begin(), ties.end(), hit.triangle), ties.end());
  }
  // far outside the grid too
  const Eigen::Vector3d far(40.0, -30.0, 5.0);
  EXPECT_NEAR(locator.closest(far).distance, bruteForceDistance(s, far), 1e-12);
}

TEST(SurfaceLocator, LeavesTrianglesOfZeroAreaOut)
{
  Surface s;
  s.V = (Eigen::MatrixX3d(3, 3) << 0, 0, 0, 1, 0, 0, 2, 0, 0).finished();
  s.F = (Eigen::MatrixX3i(1, 3) << 0, 1, 2).finished();
  const SurfaceLocator locator(s.V, s.F);
  EXPECT_EQ(locator.closest(Eigen::Vector3d(0.5, 1.0, 0.0)).triangle, -1);
  EXPECT_TRUE(locator.nearlyClosest(Eigen::Vector3d(0.5, 1.0, 0.0), 1.0).empty());
}

TEST(QuadFacing, LeavesAValidMeshAsItIs)
{
  const Chain c = runChain(testSurface("sphere"), 800);
  QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
  ASSERT_TRUE(badQuads(c.s, q).empty());
  const QuadMesh before = q;
  const FacingRepair r = repairFacing(c.s.V, c.s.F, c.topo, SurfaceLocator(c.s.V, c.s.F), q);
  EXPECT_EQ(r.before, 0);
  EXPECT_EQ(r.after, 0);
  EXPECT_EQ(r.movedVertices, 0);
  EXPECT_EQ(q.V, before.V);
}

TEST(QuadFacing, MovesAVertexPushedOverItsNeighboursBack)
{
  for (const char* name : { "sphere", "torus", "roundedcube" })
  {
    SCOPED_TRACE(name);
    const Chain c = runChain(testSurface(name), 800);
    QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
    const QuadQuality quality = measureQuads(q.V, q.Q);
    // a regular vertex, put where the vertex two edges away along one grid line is
    int v = 0;
    while (quality.valence[v] != 4)
    {
      ++v;
    }
    int w = -1;
    for (int i = 0; i < q.Q.rows() && w < 0; ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        if (q.Q(i, k) == v)
        {
          w = q.Q(i, (k + 2) % 4); // diagonally across its quad
          break;
        }
      }
    }
    ASSERT_GE(w, 0);
    const Eigen::MatrixX4i connectivity = q.Q;
    q.V.row(v) = q.V.row(w) + 0.3 * (q.V.row(w) - q.V.row(v));
    const SurfaceLocator locator(c.s.V, c.s.F);
    q.V.row(v) = locator.closest(q.V.row(v).transpose()).point.transpose();
    q.vertexTriangle[v] = locator.closest(q.V.row(v).transpose()).triangle;
    q.vertexPoint[v] = -1;
    ASSERT_FALSE(badQuads(c.s, q).empty()) << "the test needs a folded vertex";
    const FacingRepair r = repairFacing(c.s.V, c.s.F, c.topo, locator, q);
    EXPECT_GT(r.before, 0);
    EXPECT_EQ(r.after, 0);
    EXPECT_GE(r.movedVertices, 1);
    EXPECT_TRUE(badQuads(c.s, q).empty());
    EXPECT_EQ(q.Q, connectivity);
    for (int u = 0; u < q.V.rows(); ++u)
    {
      EXPECT_LT(locator.closest(q.V.row(u).transpose()).distance, 1e-9) << "vertex " << u;
      const Eigen::Vector3d own = closestOnTriangle(q.V.row(u).transpose(),
        c.s.V.row(c.s.F(q.vertexTriangle[u], 0)), c.s.V.row(c.s.F(q.vertexTriangle[u], 1)),
        c.s.V.row(c.s.F(q.vertexTriangle[u], 2)));
      EXPECT_LT((own - q.V.row(u).transpose()).norm(), 1e-9) << "vertex " << u << " in its triangle";
    }
  }
}

TEST(QuadFacing, SlidesABoundaryVertexBackAlongTheBoundary)
{
  const Chain c = runChain(testSurface("cylinder"), 800);
  QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
  ASSERT_TRUE(badQuads(c.s, q).empty());
  // a vertex on the upper circle and its neighbour along it
  const std::vector<char> boundary = quadMeshBoundary(q);
  int v = -1, w = -1;
  for (int i = 0; i < q.Q.rows() && w < 0; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = q.Q(i, k), b = q.Q(i, (k + 1) % 4);
      if (boundary[a] && boundary[b] && q.V(a, 2) > 0.99 && q.V(b, 2) > 0.99)
      {
        v = a;
        w = b;
        break;
      }
    }
  }
  ASSERT_GE(w, 0);
  // v moved along the circle past w, by a third of their distance: its quads turn inside out
  const double from = std::atan2(q.V(v, 1), q.V(v, 0)), to = std::atan2(q.V(w, 1), q.V(w, 0));
  constexpr double TwoPi = 6.28318530717958647692;
  const auto turn = [&](double a) { return a - TwoPi * std::round(a / TwoPi); };
  const double step = turn(to - from);
  const double angle = to + step / 3.0;
  const SurfaceLocator locator(c.s.V, c.s.F);
  const SurfaceLocator::Hit hit =
    locator.closest(Eigen::Vector3d(0.5 * std::cos(angle), 0.5 * std::sin(angle), 1.0));
  q.V.row(v) = hit.point.transpose();
  q.vertexTriangle[v] = hit.triangle;
  q.vertexPoint[v] = -1;
  ASSERT_TRUE(onSurfaceBoundary(c.s.V, c.s.F, c.topo, q, v));
  ASSERT_FALSE(badQuads(c.s, q).empty()) << "the test needs a quad turned inside out";
  const Eigen::MatrixX4i connectivity = q.Q;
  const FacingRepair r = repairFacing(c.s.V, c.s.F, c.topo, locator, q);
  EXPECT_GT(r.before, 0);
  EXPECT_EQ(r.after, 0);
  EXPECT_TRUE(badQuads(c.s, q).empty());
  EXPECT_EQ(q.Q, connectivity);
  // back on its own side of w (interior vertices alone can untwist its quads otherwise)
  EXPECT_GT(turn(std::atan2(q.V(w, 1), q.V(w, 0)) - std::atan2(q.V(v, 1), q.V(v, 0))) * step, 0.0);
  for (int u = 0; u < q.V.rows(); ++u)
  {
    if (boundary[u])
    {
      EXPECT_TRUE(onSurfaceBoundary(c.s.V, c.s.F, c.topo, q, u)) << "vertex " << u;
      EXPECT_NEAR(std::abs(q.V(u, 2)), 1.0, 1e-12) << "vertex " << u;
    }
  }
}

TEST(QuadFacing, LiftsQuadsWhoseCentreLiesNearerAnotherComponent)
{
  // 400 quads a sphere: a quad's centre lies about 0.008 inside the outer sphere, nearer the inner
  // one, 0.005 inside it and facing the other way; as extracted, most of the outer sphere's quads
  // face against the surface closest to their centre
  const Chain c = runChain(hollowBall(0.005), 800);
  const QuadMesh extracted = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
  ASSERT_GT(turnedQuads(c.s.V, c.s.F, extracted).size(), 100u) << "the test needs such quads";
  const QuadMeshResult r =
    buildQuadMesh(c.s.V, c.s.F, c.topo, c.map.cornerUV, QuadMeshOptions(), Progress());
  EXPECT_GT(r.liftedVertices, 100);
  EXPECT_EQ(r.turnedQuads, 0);
  EXPECT_EQ(r.invertedFinal, 0);
  // over the whole surface, as an evaluator that knows no components measures them
  EXPECT_TRUE(turnedQuads(c.s.V, c.s.F, r.mesh).empty());
  // the quads keep their shape, and the lifted vertices stay within a tenth of an edge
  EXPECT_GT(r.quality.scaledJacobian.minCoeff(), 0.5);
  const double edge = edgeLengthForQuadCount(c.s.V, c.s.F, 800);
  const SurfaceLocator locator(c.s.V, c.s.F);
  for (int v = 0; v < r.mesh.V.rows(); ++v)
  {
    EXPECT_LT(locator.closest(r.mesh.V.row(v).transpose()).distance, 0.1 * edge) << v;
  }
  // walls far apart: nothing is lifted, nothing faces against the surface
  const Chain far = runChain(hollowBall(0.5), 800);
  const QuadMeshResult apart =
    buildQuadMesh(far.s.V, far.s.F, far.topo, far.map.cornerUV, QuadMeshOptions(), Progress());
  EXPECT_EQ(apart.liftedVertices, 0);
  EXPECT_EQ(apart.turnedQuads, 0);
  // the figure as extracted counts the quads to lift, as the evaluator does
  EXPECT_EQ(r.turnedExtracted, static_cast<int>(turnedQuads(c.s.V, c.s.F, extracted).size()));
}

TEST(QuadMeshAdjacency, SplitsPinchedVerticesIntoTheirFans)
{
  // two quads joined through an edge, a third touching them only at point 2; a fourth quad
  // touching the third only at point 7, alone in a piece of its own otherwise
  QuadMesh q;
  q.V = Eigen::MatrixX3d::Random(12, 3);
  q.Q.resize(4, 4);
  q.Q << 0, 1, 2, 3, 1, 4, 5, 2, 2, 6, 7, 8, 7, 9, 10, 11;
  for (int v = 0; v < 12; ++v)
  {
    q.vertexTriangle.push_back(100 + v);
    q.vertexPoint.push_back(v % 2 == 0 ? v : -1);
  }
  const QuadMesh before = q;
  EXPECT_EQ(splitPinchedVertices(q), 2);
  ASSERT_EQ(q.V.rows(), 14);
  // the fan of the lowest quad keeps the point; the other fans get the copies, in order
  EXPECT_EQ(q.Q.row(0), before.Q.row(0));
  EXPECT_EQ(q.Q.row(1), before.Q.row(1));
  EXPECT_EQ(q.Q(2, 0), 12);
  EXPECT_EQ(q.Q(3, 0), 13);
  EXPECT_EQ(q.Q(2, 2), 7);
  EXPECT_TRUE(q.V.row(12).isApprox(before.V.row(2)));
  EXPECT_TRUE(q.V.row(13).isApprox(before.V.row(7)));
  EXPECT_EQ(q.vertexTriangle[12], 102);
  EXPECT_EQ(q.vertexPoint[13], -1);
  // no vertex is shared by two fans any more: splitting again adds nothing
  EXPECT_EQ(splitPinchedVertices(q), 0);
  // a closed mesh (the cube's six faces) is manifold everywhere: nothing to split
  QuadMesh cube;
  cube.V = Eigen::MatrixX3d::Random(8, 3);
  cube.Q.resize(6, 4);
  cube.Q << 0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7;
  cube.vertexTriangle.assign(8, 0);
  cube.vertexPoint.assign(8, -1);
  const Eigen::MatrixX4i faces = cube.Q;
  EXPECT_EQ(splitPinchedVertices(cube), 0);
  EXPECT_EQ(cube.Q, faces);
  EXPECT_EQ(cube.V.rows(), 8);
}

TEST(QuadMeshAdjacency, ReadsTheQuadsOwnTopology)
{
  // a pillow: two quads glued along all four edges, a sphere; both have the corners 0 and 2
  // opposite, where two triangles a quad would put one diagonal into four triangles
  QuadMesh pillow;
  pillow.V = Eigen::MatrixX3d::Random(4, 3);
  pillow.Q.resize(2, 4);
  pillow.Q << 0, 1, 2, 3, 0, 3, 2, 1;
  const MeshTopology sphere = quadTopology(pillow);
  EXPECT_TRUE(sphere.isManifold());
  EXPECT_TRUE(sphere.isOriented());
  EXPECT_EQ(sphere.eulerCharacteristic(), 2);
  EXPECT_TRUE(sphere.boundaryLoops.empty());
  EXPECT_EQ(sphere.numComponents(), 1);
  // a strip of three quads, then a fourth quad on the edge 1-5 between the first two
  QuadMesh strip;
  strip.V = Eigen::MatrixX3d::Random(10, 3);
  strip.Q.resize(3, 4);
  strip.Q << 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6;
  const MeshTopology disk = quadTopology(strip);
  EXPECT_TRUE(disk.isManifold());
  EXPECT_EQ(disk.eulerCharacteristic(), 1);
  EXPECT_EQ(disk.boundaryLoops.size(), 1u);
  ASSERT_EQ(disk.boundaryLoops[0].size(), 8u);
  for (const int v : disk.boundaryLoops[0])
  {
    EXPECT_LT(v, 8); // the quads' points: the centres are inner points
  }
  strip.Q.conservativeResize(4, 4);
  strip.Q.row(3) << 1, 5, 9, 8;
  EXPECT_EQ(quadTopology(strip).nonManifoldEdges.size(), 1u);
}

TEST(QuadMeshAdjacency, DropsQuadsHangingByACornerOffTheirComponent)
{
  // A 3 x 3 block of quads (points 0..15, p = 4 j + i) on component 0, and around it: a quad
  // hanging off its corner 15 and another off that one; two quads joined through an edge off its
  // corner 3; three quads in a row off its corner 12, and a quad off their far end; a quad of
  // component 1 touching it at 0; a quad of component 0 touching nothing.
  std::vector<Eigen::Vector4i> quads;
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const int p = 4 * j + i;
      quads.emplace_back(p, p + 1, p + 5, p + 4);
    }
  }
  const std::vector<Eigen::Vector4i> around = { { 15, 16, 17, 18 }, { 17, 19, 20, 21 }, // chain
    { 3, 22, 23, 24 }, { 22, 25, 26, 23 },                                              // a pair
    { 12, 27, 28, 29 }, { 27, 30, 31, 28 }, { 30, 32, 33, 31 }, // three in a row
    { 33, 34, 35, 36 },                                         // off the three
    { 0, 37, 38, 39 },                                          // component 1
    { 40, 41, 42, 43 } };                                       // alone
  quads.insert(quads.end(), around.begin(), around.end());
  QuadMesh q;
  q.V = Eigen::MatrixX3d::Random(44, 3);
  q.Q.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    q.Q.row(static_cast<Eigen::Index>(i)) = quads[i].transpose();
    q.quadTriangle.push_back(i == 17 ? 1 : 0);
  }
  for (int v = 0; v < 44; ++v)
  {
    q.vertexTriangle.push_back(100 + v);
    q.vertexPoint.push_back(v);
  }
  const Eigen::VectorXi component = (Eigen::VectorXi(2) << 0, 1).finished();
  // at most 2 quads: the chain and the pair go (the block has 9 quads, 4 and 8 times theirs); the
  // three in a row are larger, so they do not join the block's group, and the quad off them
  // (three is not four times one) stays, as do the other component's quad and the lone one
  QuadMesh dropped = q;
  EXPECT_EQ(dropPinchedFragments(dropped, component, 2), 4);
  ASSERT_EQ(dropped.Q.rows(), 15);
  ASSERT_EQ(dropped.V.rows(), 44 - 11); // 16..26 were theirs alone
  std::vector<int> kept = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 13, 14, 15, 16, 17, 18 };
  ASSERT_EQ(dropped.quadTriangle.size(), kept.size());
  for (int i = 0; i < 15; ++i)
  {
    EXPECT_EQ(dropped.quadTriangle[i], kept[i] == 17 ? 1 : 0);
    for (int k = 0; k < 4; ++k)
    {
      const int v = dropped.Q(i, k), was = q.Q(kept[i], k);
      EXPECT_TRUE(dropped.V.row(v) == q.V.row(was)) << "quad " << i << " corner " << k;
      EXPECT_EQ(dropped.vertexPoint[v], was);
      EXPECT_EQ(dropped.vertexTriangle[v], 100 + was);
    }
  }
  // nothing more to drop; at most 1 quad: only the chain
  EXPECT_EQ(dropPinchedFragments(dropped, component, 2), 0);
  QuadMesh one = q;
  EXPECT_EQ(dropPinchedFragments(one, component, 1), 2);
  EXPECT_EQ(one.Q.rows(), 17);
  // per-vertex arrays shorter than V are cleared, not filled with made-up entries
  QuadMesh bare = q;
  bare.vertexTriangle.clear();
  bare.vertexPoint.resize(10);
  EXPECT_EQ(dropPinchedFragments(bare, component, 2), 4);
  EXPECT_TRUE(bare.vertexTriangle.empty());
  EXPECT_TRUE(bare.vertexPoint.empty());
}

namespace
{
/// Adds a block of nx x ny unit quads at (x0, y0, z) to q (counterclockwise seen from +z), on
/// triangle `triangle`, leaving out the quads (i, j) that `skip` says.
template<typename Skip>
void addBlock(QuadMesh& q, int nx, int ny, double x0, double y0, double z, int triangle, Skip skip)
{
  const int base = static_cast<int>(q.V.rows());
  q.V.conservativeResize(base + (nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      q.V.row(base + j * (nx + 1) + i) << x0 + i, y0 + j, z;
    }
  }
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      if (skip(i, j))
      {
        continue;
      }
      const int p = base + j * (nx + 1) + i;
      q.Q.conservativeResize(q.Q.rows() + 1, 4);
      q.Q.row(q.Q.rows() - 1) << p, p + 1, p + nx + 2, p + nx + 1;
      q.quadTriangle.push_back(triangle);
    }
  }
}
}

TEST(QuadMeshAdjacency, DropsDisksCutOffLyingAgainstTheRest)
{
  // component 0: a 6 x 4 block of unit quads at z = 0 (the rest); a strip of 3 quads 0.1 above
  // it (a tongue cut off, lying on the rest: dropped); the same strip 0.5 above (sticking out:
  // kept); a ring of 8 quads around a hole 0.1 above (not a disk: kept). Component 1: a strip 0.1
  // above, its component's only piece (kept).
  QuadMesh q;
  q.V.resize(0, 3);
  q.Q.resize(0, 4);
  auto none = [](int, int) { return false; };
  addBlock(q, 6, 4, 0.0, 0.0, 0.0, 0, none);
  addBlock(q, 3, 1, 0.5, 0.5, 0.1, 0, none);
  addBlock(q, 3, 1, 0.5, 2.5, 0.5, 0, none);
  addBlock(q, 3, 3, 2.5, 0.5, 0.1, 0, [](int i, int j) { return i == 1 && j == 1; });
  addBlock(q, 3, 1, 0.5, 1.5, 0.1, 1, none);
  const Eigen::VectorXi component = (Eigen::VectorXi(2) << 0, 1).finished();
  ASSERT_EQ(q.Q.rows(), 24 + 3 + 3 + 8 + 3);
  QuadMesh dropped = q;
  EXPECT_EQ(dropPiecesAgainstRest(dropped, component, 0.25), 3);
  ASSERT_EQ(dropped.Q.rows(), q.Q.rows() - 3);
  EXPECT_EQ(dropped.V.rows(), q.V.rows() - 8);
  for (Eigen::Index i = 0; i < dropped.Q.rows(); ++i)
  {
    const int was = i < 24 ? static_cast<int>(i) : static_cast<int>(i) + 3;
    for (int k = 0; k < 4; ++k)
    {
      EXPECT_TRUE(dropped.V.row(dropped.Q(i, k)) == q.V.row(q.Q(was, k))) << i << " " << k;
    }
    EXPECT_EQ(dropped.quadTriangle[i], q.quadTriangle[was]);
  }
  // nothing more to drop; a reach of 0.05 edges drops nothing, one of 0.6 the far strip too
  EXPECT_EQ(dropPiecesAgainstRest(dropped, component, 0.25), 0);
  QuadMesh nearer = q;
  EXPECT_EQ(dropPiecesAgainstRest(nearer, component, 0.05), 0);
  QuadMesh farther = q;
  EXPECT_EQ(dropPiecesAgainstRest(farther, component, 0.6), 6);
  // without a triangle a quad the pieces' components are unknown: nothing is dropped
  QuadMesh bare = q;
  bare.quadTriangle.clear();
  EXPECT_EQ(dropPiecesAgainstRest(bare, component, 0.25), 0);
}
