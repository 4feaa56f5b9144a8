// Matchings, layer shifts and indices: Poincare-Hopf for any field, the cube's corners, twins,
// and branch-point optimization.
#include "CurvatureFrames.h"
#include "FrameField.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "Surfaces.h"
#include "TestSurfaces.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <random>
#include <string>

using namespace quadcover;

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Mesh
{
  Surface s;
  MeshTopology topo;
  FrameGeometry geometry;
};

Mesh prepare(Surface s)
{
  MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  FrameGeometry g = computeFrameGeometry(s.V, s.F, topo);
  return { std::move(s), std::move(topo), std::move(g) };
}

Eigen::MatrixX3d randomFrames(const Mesh& m, unsigned seed)
{
  std::mt19937 rng(seed);
  Eigen::VectorXd a(m.s.F.rows());
  for (Eigen::Index f = 0; f < a.size(); ++f)
  {
    a[f] = 2.0 * Pi * (rng() / 4294967296.0);
  }
  return angleVectors(m.geometry.bases, a);
}

/// On the cube: in each face the first cube axis lying in it, a field along the cube's edges.
Eigen::MatrixX3d cubeAxisField(const Mesh& m)
{
  Eigen::MatrixX3d U(m.s.F.rows(), 3);
  for (Eigen::Index f = 0; f < U.rows(); ++f)
  {
    const Eigen::Vector3d n = m.geometry.bases.normal.row(f);
    U.row(f) = std::abs(n.x()) < 0.5 ? Eigen::RowVector3d(1, 0, 0) : Eigen::RowVector3d(0, 1, 0);
  }
  return U;
}

double indexSum(const FrameTopology& t)
{
  return t.index.sum();
}
}

TEST(Matchings, TransportAroundAVertexIsMinusTheAngleDefect)
{
  const Mesh m = prepare(testSurface("sphere"));
  for (int v = 0; v < m.topo.numVertices; v += 37)
  {
    double sum = 0.0;
    const int b = m.topo.ringOffsets[v], n = m.topo.valence(v);
    for (int i = 0; i < n; ++i)
    {
      const int f = m.topo.ringFaces[b + i];
      sum += m.geometry.transport(f, (MeshTopology::cornerOf(m.s.F, f, v) + 2) % 3);
    }
    EXPECT_NEAR(wrapAngle(sum + m.geometry.defect[v]), 0.0, 1e-9) << v;
  }
  // Gauss-Bonnet.
  EXPECT_NEAR(m.geometry.defect.sum(), 4.0 * Pi, 1e-9);
}

TEST(Matchings, PoincareHopfHoldsForRandomFieldsOnEverySurface)
{
  for (const char* name : { "sphere", "torus", "knot", "roundedcube", "cylinder", "saddle" })
  {
    const Mesh m = prepare(testSurface(name));
    const int chi = m.topo.eulerCharacteristic();
    for (unsigned seed : { 1u, 2u })
    {
      const FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, randomFrames(m, seed));
      SCOPED_TRACE(name);
      EXPECT_NEAR(indexSum(t), chi, 1e-9);
      EXPECT_LT(t.maxIndexError, 1e-9);
      for (int v = 0; v < m.topo.numVertices; ++v)
      {
        if (!m.topo.boundaryVertex[v])
        {
          // Layer shift = 4 index mod 4 (the paper's remark after Def. 5).
          const int quarters = static_cast<int>(std::lround(4.0 * t.index[v]));
          ASSERT_EQ(t.layerShift[v], ((quarters % 4) + 4) % 4) << v;
        }
      }
      // Twins are inverse, boundary edges are -1.
      for (int f = 0; f < m.topo.numFaces; ++f)
      {
        for (int k = 0; k < 3; ++k)
        {
          const int g = m.topo.faceNeighbors(f, k);
          if (g < 0)
          {
            ASSERT_EQ(t.matching(f, k), -1);
            continue;
          }
          for (int kk = 0; kk < 3; ++kk)
          {
            if (m.topo.faceNeighbors(g, kk) == f)
            {
              ASSERT_EQ((t.matching(f, k) + t.matching(g, kk)) % 4, 0);
            }
          }
        }
      }
    }
  }
}

TEST(Matchings, CubeCornersAreBranchPointsOfLayerShiftOne)
{
  // The paper's Fig. 4: a field along the cube's edges has a branch point at every corner.
  const Mesh m = prepare(makeRoundedCube(0.0, 6));
  const Eigen::MatrixX3d U = cubeAxisField(m);
  const FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  EXPECT_EQ(t.branchPoints, 8);
  EXPECT_EQ(t.singularities, 8);
  for (int v = 0; v < m.topo.numVertices; ++v)
  {
    const bool corner = m.s.V.row(v).cwiseAbs().minCoeff() > 1.0 - 1e-12;
    EXPECT_EQ(t.layerShift[v], corner ? 1 : 0) << v;
    EXPECT_DOUBLE_EQ(t.index[v], corner ? 0.25 : 0.0) << v;
  }
  EXPECT_NEAR(t.matchingCost, 0.0, 1e-9);
}

TEST(Matchings, HalfTurnResidualsCancelAcrossTheirEdge)
{
  // The cube's edge-aligned field has residuals of (almost exactly) zero; changing one edge's
  // matching by two quarter turns leaves a residual of +-pi there, which must cancel between the
  // edge's two sides for Poincare-Hopf to hold (index +-1/2 at the edge's two points).
  const Mesh m = prepare(makeRoundedCube(0.0, 6));
  const Eigen::MatrixX3d U = cubeAxisField(m);
  FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  for (int f = 0; f < m.topo.numFaces; f += 7)
  {
    const int g = m.topo.faceNeighbors(f, 0);
    Eigen::MatrixX3i changed = t.matching;
    changed(f, 0) = (changed(f, 0) + 2) % 4;
    for (int kk = 0; kk < 3; ++kk)
    {
      if (m.topo.faceNeighbors(g, kk) == f)
        changed(g, kk) = (changed(g, kk) + 2) % 4;
    }
    const FrameTopology u = evaluateMatchings(m.s.F, m.topo, m.geometry, U, changed);
    ASSERT_NEAR(u.index.sum(), 2.0, 1e-9) << f;
    ASSERT_LT(u.maxIndexError, 1e-9);
  }
}

TEST(Matchings, TorusCurvatureFramesHaveNoSingularities)
{
  const Mesh m = prepare(testSurface("torus"));
  const CurvatureField c = computeCurvatureField(m.s.V, m.s.F, m.topo);
  const FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, c.frameU);
  EXPECT_EQ(t.singularities, 0);
  EXPECT_EQ(t.branchPoints, 0);
}

TEST(Matchings, BoundaryAlignedFieldOnADiskHasQuarterIndicesAtCorners)
{
  // The saddle patch is a square: a field along its grid lines is aligned with the boundary,
  // the four corners carry 1/4 each and nothing else is singular.
  const Mesh m = prepare(makeSaddle(1.0, 0.5, 12));
  Eigen::MatrixX3d U(m.s.F.rows(), 3);
  for (Eigen::Index f = 0; f < U.rows(); ++f)
  {
    // Along the grid's x lines: the tangent of (1, 0, x/a) at the centroid.
    const double x = (m.s.V(m.s.F(f, 0), 0) + m.s.V(m.s.F(f, 1), 0) + m.s.V(m.s.F(f, 2), 0)) / 3;
    U.row(f) = Eigen::RowVector3d(1.0, 0.0, x).normalized();
  }
  const FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  EXPECT_NEAR(t.index.sum(), 1.0, 1e-9);
  int corners = 0;
  for (int v = 0; v < m.topo.numVertices; ++v)
  {
    const bool corner = std::abs(std::abs(m.s.V(v, 0)) - 0.5) < 1e-12 &&
      std::abs(std::abs(m.s.V(v, 1)) - 0.5) < 1e-12;
    corners += corner ? 1 : 0;
    EXPECT_NEAR(t.index[v], corner ? 0.25 : 0.0, 0.02) << v;
  }
  EXPECT_EQ(corners, 4);
}

TEST(Matchings, BranchPointOptimizationLowersTheCostAndKeepsPoincareHopf)
{
  for (const char* name : { "sphere", "torus", "knot" })
  {
    const Mesh m = prepare(testSurface(name));
    const Eigen::MatrixX3d U = randomFrames(m, 5);
    FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
    BranchPointOptions opt;
    opt.branchPointWeight = 1.0;
    opt.splitDistance = 0; // the merges alone (splits add singular points on purpose)
    const BranchPointReport r = optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, t, opt);
    SCOPED_TRACE(name);
    std::printf("[ %s, random field ] singularities %d -> %d, cost %.2f -> %.2f\n", name,
      r.singularitiesBefore, r.singularitiesAfter, r.costBefore, r.costAfter);
    EXPECT_LT(r.singularitiesAfter, r.singularitiesBefore);
    EXPECT_LE(r.after, r.before);
    EXPECT_LE(r.costAfter, r.costBefore + 1e-9);
    EXPECT_EQ(r.after, t.branchPoints);
    EXPECT_EQ(r.singularitiesAfter, t.singularities);
    EXPECT_NEAR(t.index.sum(), m.topo.eulerCharacteristic(), 1e-9);
    EXPECT_LT(t.maxIndexError, 1e-9);
    // A zero weight changes nothing.
    FrameTopology u = computeMatchings(m.s.F, m.topo, m.geometry, U);
    opt.branchPointWeight = 0.0;
    EXPECT_EQ(optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, u, opt).pathsChanged, 0);
  }
}

TEST(Matchings, BranchPointOptimizationNeverCreatesSingularities)
{
  // With long paths allowed (weight 10) a path may cross edges whose residual would wrap past
  // +-pi if changed; such an edge would move a whole turn of index onto a point in between.
  // Whatever the weight, no regular point may become singular and no index may grow past the
  // largest the field had.
  for (const char* name : { "sphere", "torus", "knot", "saddle" })
  {
    const Mesh m = prepare(testSurface(name));
    for (unsigned seed : { 3u, 4u })
    {
      // A field that is smooth with noise: random fields are all singularities.
      Eigen::VectorXd a(m.s.F.rows());
      std::mt19937 rng(seed);
      for (Eigen::Index f = 0; f < a.size(); ++f)
      {
        const Eigen::Vector3d c = (m.s.V.row(m.s.F(f, 0)) + m.s.V.row(m.s.F(f, 1))) / 2.0;
        a[f] = 3.0 * c.x() + 2.0 * c.y() + 0.9 * (rng() / 4294967296.0 - 0.5);
      }
      const Eigen::MatrixX3d U = angleVectors(m.geometry.bases, a);
      for (double weight : { 3.0, 10.0, 30.0 })
      {
        FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
        const FrameTopology before = t;
        BranchPointOptions opt;
        opt.branchPointWeight = weight;
        opt.splitDistance = 0; // the merges alone (splits add singular points on purpose)
        optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, t, opt);
        double largest = 0.0;
        for (int v = 0; v < m.topo.numVertices; ++v)
        {
          if (!m.topo.boundaryVertex[v])
            largest = std::max(largest, std::abs(before.index[v]));
        }
        for (int v = 0; v < m.topo.numVertices; ++v)
        {
          if (m.topo.boundaryVertex[v])
            continue;
          ASSERT_FALSE(before.index[v] == 0.0 && t.index[v] != 0.0)
            << name << " seed " << seed << " weight " << weight << " point " << v << " became "
            << t.index[v];
          ASSERT_LE(std::abs(t.index[v]), largest) << name << " " << v;
        }
        EXPECT_LE(t.singularities, before.singularities);
        EXPECT_NEAR(t.index.sum(), m.topo.eulerCharacteristic(), 1e-9);
      }
    }
  }
}

namespace
{
/// A smooth field with noise: singularities of either sign at every distance.
Eigen::MatrixX3d noisyFrames(const Mesh& m)
{
  Eigen::VectorXd a(m.s.F.rows());
  std::mt19937 rng(7);
  for (Eigen::Index f = 0; f < a.size(); ++f)
  {
    const Eigen::Vector3d c = (m.s.V.row(m.s.F(f, 0)) + m.s.V.row(m.s.F(f, 1))) / 2.0;
    a[f] = 3.0 * c.x() + 2.0 * c.y() + 1.2 * (rng() / 4294967296.0 - 0.5);
  }
  return angleVectors(m.geometry.bases, a);
}
}

TEST(Matchings, CloseOppositeQuartersCancelAndNothingElseChanges)
{
  for (const char* name : { "sphere", "saddle", "roundedcube", "torus", "knot" })
  {
    const Mesh m = prepare(testSurface(name));
    // a smooth field with noise: pairs of opposite quarters at every distance
    const Eigen::MatrixX3d U = noisyFrames(m);
    const FrameTopology before = computeMatchings(m.s.F, m.topo, m.geometry, U);
    const bool handles = m.topo.components[0].genus > 0;
    std::vector<char> changed;
    FrameTopology none = before;
    EXPECT_EQ(cancelClosePairs(m.s.F, m.topo, m.geometry, U, none, 0.0, changed), 0);
    EXPECT_EQ(none.matching, before.matching);
    for (double edges : { 2.0, 4.0 })
    {
      SCOPED_TRACE(std::string(name) + " within " + std::to_string(edges) + " edges");
      FrameTopology t = before;
      const int cancelled = cancelClosePairs(
        m.s.F, m.topo, m.geometry, U, t, edges * m.geometry.referenceLength, changed);
      std::printf("[ %s ] %d singularities, %d pairs within %.0f edges cancelled\n", name,
        before.singularities, cancelled, edges);
      // on a surface with handles too, where the pairs lie within disks of it (the knot's tube
      // is narrower than 8 edges: there they stay)
      if (!handles || edges == 2.0)
      {
        EXPECT_GT(cancelled, 0);
      }
      else if (std::string(name) == "knot")
      {
        EXPECT_EQ(cancelled, 0);
      }
      EXPECT_EQ(t.singularities, before.singularities - 2 * cancelled);
      EXPECT_EQ(std::count(changed.begin(), changed.end(), 1) > 0, cancelled > 0);
      // only opposite quarters went, in pairs; no point changed its index otherwise
      double removedSum = 0.0;
      for (int v = 0; v < m.topo.numVertices; ++v)
      {
        if (t.index[v] != before.index[v])
        {
          ASSERT_EQ(t.index[v], 0.0) << v;
          ASSERT_EQ(std::abs(before.index[v]), 0.25) << v;
          removedSum += before.index[v];
        }
      }
      EXPECT_EQ(removedSum, 0.0);
      EXPECT_NEAR(t.index.sum(), m.topo.eulerCharacteristic(), 1e-9);
      EXPECT_LT(t.maxIndexError, 1e-9);
    }
    // A pair as far apart as the surface is thick cancels only where no handle's loop must
    // cross its path: within twice that around it the surface is no disk, so none does.
    const Eigen::Vector3d size = m.s.V.colwise().maxCoeff() - m.s.V.colwise().minCoeff();
    FrameTopology wide = before;
    const int far = cancelClosePairs(m.s.F, m.topo, m.geometry, U, wide, size.minCoeff(), changed);
    EXPECT_EQ(far > 0, !handles) << name;
  }
}

namespace
{
/// Per point, the length of the shortest edge path from the sources, spread below `limit`
/// (infinity beyond); with innerOnly, over inner points only.
std::vector<double> edgePathLengths(
  const Mesh& m, const std::vector<int>& sources, double limit, bool innerOnly = false)
{
  std::vector<double> d(m.topo.numVertices, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (const int a : sources)
  {
    d[a] = 0.0;
    queue.push({ 0.0, a });
  }
  while (!queue.empty())
  {
    const auto [du, u] = queue.top();
    queue.pop();
    if (du > d[u])
      continue;
    for (int i = m.topo.ringOffsets[u]; i < m.topo.ringOffsets[u + 1]; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int w = m.s.F(m.topo.ringFaces[i], k);
        const double nd = du + (m.s.V.row(w) - m.s.V.row(u)).norm();
        if (nd < limit && nd < d[w] && !(innerOnly && m.topo.boundaryVertex[w]))
        {
          d[w] = nd;
          queue.push({ nd, w });
        }
      }
    }
  }
  return d;
}

/// Pairs of inner quarters of the same index closer than `length` along edges.
int closeLikePairs(const Mesh& m, const FrameTopology& t, double length)
{
  int pairs = 0;
  for (int a = 0; a < m.topo.numVertices; ++a)
  {
    if (std::abs(t.index[a]) != 0.25 || m.topo.boundaryVertex[a])
    {
      continue;
    }
    const std::vector<double> d = edgePathLengths(m, { a }, length);
    for (int u = a + 1; u < m.topo.numVertices; ++u)
    {
      pairs += d[u] < length && t.index[u] == t.index[a];
    }
  }
  return pairs;
}
}

namespace
{
/// Quarter singularities of t closer than `length` to the inner points beside the boundary
/// along paths over inner points, as moveCloseQuartersApart measures it.
int quartersNearBoundary(const Mesh& m, const FrameTopology& t, double length)
{
  std::vector<int> beside;
  for (int e = 0; e < m.topo.numEdges(); ++e)
  {
    const int a = m.topo.edges(e, 0), b = m.topo.edges(e, 1);
    if (m.topo.boundaryVertex[a] != m.topo.boundaryVertex[b])
    {
      beside.push_back(m.topo.boundaryVertex[a] ? b : a);
    }
  }
  const std::vector<double> d = edgePathLengths(m, beside, length, true);
  int near = 0;
  for (int v = 0; v < m.topo.numVertices; ++v)
  {
    near += std::abs(std::abs(t.index[v]) - 0.25) < 1e-9 && d[v] < length;
  }
  return near;
}
}

TEST(Matchings, QuartersBesideTheBoundaryMoveInward)
{
  // A singularity must lie on a grid point and the boundary on grid lines: a quarter within a
  // grid edge of the boundary leaves the triangles between them no room (the teapot's spout
  // kept a triangle collapsed onto a grid point at most densities). The noisy field crowds
  // quarters everywhere, so that only some find a free point inside the saddle.
  const char* name = "saddle";
  {
    const Mesh m = prepare(testSurface(name));
    const Eigen::MatrixX3d U = noisyFrames(m);
    const FrameTopology before = computeMatchings(m.s.F, m.topo, m.geometry, U);
    const double length = 2.0 * m.geometry.referenceLength;
    std::vector<char> changed;
    FrameTopology t = before;
    // like quarters never closer than 1e-12: only the boundary moves them
    const int moved =
      moveCloseQuartersApart(m.s.F, m.topo, m.geometry, U, t, 1e-12, length, length, changed);
    std::printf("[ %s ] %d quarters near the boundary, %d moved, %d left\n", name,
      quartersNearBoundary(m, before, length), moved, quartersNearBoundary(m, t, length));
    ASSERT_GT(quartersNearBoundary(m, before, length), 0) << name;
    EXPECT_GT(moved, 0) << name;
    // each quarter moved was within the length of the points beside the boundary and is now at
    // least that far
    EXPECT_EQ(quartersNearBoundary(m, t, length), quartersNearBoundary(m, before, length) - moved)
      << name;
    EXPECT_EQ(t.singularities, before.singularities) << name;
    for (const double q : { -0.5, -0.25, 0.25, 0.5 })
    {
      EXPECT_EQ((t.index.array() == q).count(), (before.index.array() == q).count()) << q;
    }
    EXPECT_LT(t.maxIndexError, 1e-9);
    FrameTopology none = before;
    EXPECT_EQ(
      moveCloseQuartersApart(m.s.F, m.topo, m.geometry, U, none, 1e-12, length, 0.0, changed), 0);
    EXPECT_EQ(none.matching, before.matching);
  }
}

TEST(Matchings, CloseLikeQuartersMoveApartAndKeepTheirIndices)
{
  for (const char* name : { "sphere", "torus" })
  {
    const Mesh m = prepare(testSurface(name));
    // quarters of either sign at every distance
    const Eigen::MatrixX3d U = noisyFrames(m);
    const FrameTopology before = computeMatchings(m.s.F, m.topo, m.geometry, U);
    const double length = 2.0 * m.geometry.referenceLength;
    std::vector<char> changed;
    FrameTopology t = before;
    const int moved =
      moveCloseQuartersApart(m.s.F, m.topo, m.geometry, U, t, length, length, 0.0, changed);
    std::printf(
      "[ %s ] %d singularities, %d quarters moved apart\n", name, before.singularities, moved);
    ASSERT_GT(closeLikePairs(m, before, length), 0) << name;
    if (m.topo.components[0].genus == 0)
    {
      EXPECT_GT(moved, 0) << name;
      EXPECT_LT(closeLikePairs(m, t, length), closeLikePairs(m, before, length)) << name;
    }
    else
    {
      EXPECT_EQ(moved, 0) << "the torus is too narrow for a disk of 5 such lengths";
    }
    EXPECT_EQ(std::count(changed.begin(), changed.end(), 1) > 0, moved > 0);
    // the same singularities, some elsewhere: as many of each index, no new index
    EXPECT_EQ(t.singularities, before.singularities) << name;
    for (const double q : { -0.5, -0.25, 0.25, 0.5 })
    {
      EXPECT_EQ((t.index.array() == q).count(), (before.index.array() == q).count()) << q;
    }
    EXPECT_NEAR(t.index.sum(), m.topo.eulerCharacteristic(), 1e-9);
    EXPECT_LT(t.maxIndexError, 1e-9);
    FrameTopology none = before;
    EXPECT_EQ(
      moveCloseQuartersApart(m.s.F, m.topo, m.geometry, U, none, 0.0, length, 0.0, changed), 0);
    EXPECT_EQ(none.matching, before.matching);
  }
}

namespace
{
/// A unit sphere of nu meridians and nv - 1 parallels, closed by a fan at each pole (points 0
/// and 1): poles of valence nu, as in surfaces of revolution.
Surface latLongSphere(int nu, int nv)
{
  Surface s;
  s.V.resize(2 + nu * (nv - 1), 3);
  s.V.row(0) << 0, 0, 1;
  s.V.row(1) << 0, 0, -1;
  for (int j = 1; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const double theta = Pi * j / nv, phi = 2 * Pi * i / nu;
      s.V.row(2 + (j - 1) * nu + i) << std::sin(theta) * std::cos(phi),
        std::sin(theta) * std::sin(phi), std::cos(theta);
    }
  }
  std::vector<Eigen::Vector3i> tris;
  auto at = [&](int j, int i) { return 2 + (j - 1) * nu + (i % nu); };
  for (int i = 0; i < nu; ++i)
  {
    tris.emplace_back(0, at(1, i), at(1, i + 1));
    tris.emplace_back(1, at(nv - 1, i + 1), at(nv - 1, i));
    for (int j = 1; j + 1 < nv; ++j)
    {
      tris.emplace_back(at(j, i), at(j + 1, i), at(j + 1, i + 1));
      tris.emplace_back(at(j, i), at(j + 1, i + 1), at(j, i + 1));
    }
  }
  s.F.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (std::size_t f = 0; f < tris.size(); ++f)
  {
    s.F.row(static_cast<Eigen::Index>(f)) = tris[f].transpose();
  }
  return s;
}

/// Frames along the parallels about the axis through point `pole`: index +1 at the pole and at
/// the antipode.
Eigen::MatrixX3d parallelField(const Mesh& m, int pole)
{
  const Eigen::Vector3d axis = m.s.V.row(pole).normalized();
  Eigen::MatrixX3d U(m.s.F.rows(), 3);
  for (int f = 0; f < m.s.F.rows(); ++f)
  {
    const Eigen::Vector3d c =
      (m.s.V.row(m.s.F(f, 0)) + m.s.V.row(m.s.F(f, 1)) + m.s.V.row(m.s.F(f, 2))) / 3.0;
    U.row(f) = axis.cross(c).normalized();
  }
  return U;
}

/// Edge hops between two points.
int hops(const Mesh& m, int from, int to)
{
  std::vector<int> d(m.s.V.rows(), -1);
  std::vector<int> queue{ from };
  d[from] = 0;
  for (std::size_t i = 0; i < queue.size(); ++i)
  {
    const int u = queue[i];
    for (int j = m.topo.ringOffsets[u]; j < m.topo.ringOffsets[u + 1]; ++j)
    {
      const int f = m.topo.ringFaces[j];
      for (int k = 0; k < 3; ++k)
      {
        const int w = m.s.F(f, k);
        if (d[w] < 0)
        {
          d[w] = d[u] + 1;
          queue.push_back(w);
        }
      }
    }
  }
  return d[to];
}
}

TEST(Matchings, WholeTurnSingularitiesAreSplitIntoQuarters)
{
  // No quad grid can follow a field that turns once around a point (index 1): the split moves
  // its four quarters to separate points, at least splitDistance edges apart.
  const Mesh m = prepare(latLongSphere(32, 24));
  const Eigen::MatrixX3d U = parallelField(m, 0);
  FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  int whole = 0;
  for (int v = 0; v < m.topo.numVertices; ++v)
  {
    whole += std::abs(t.index[v] - 1.0) < 1e-9;
  }
  ASSERT_EQ(whole, 2) << "the field turns once around each pole";
  ASSERT_EQ(t.singularities, 2);
  BranchPointOptions opt;
  const BranchPointReport r = optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, t, opt);
  EXPECT_EQ(r.split, 2);
  EXPECT_EQ(r.splitFailed, 0);
  EXPECT_EQ(t.singularities, 8);
  EXPECT_EQ(t.branchPoints, 8);
  std::vector<int> quarters;
  for (int v = 0; v < m.topo.numVertices; ++v)
  {
    if (t.index[v] != 0.0)
    {
      EXPECT_NEAR(t.index[v], 0.25, 1e-9) << v;
      quarters.push_back(v);
    }
  }
  EXPECT_NEAR(t.index.sum(), 2.0, 1e-9);
  for (std::size_t i = 0; i < quarters.size(); ++i)
  {
    for (std::size_t j = i + 1; j < quarters.size(); ++j)
    {
      EXPECT_GE(hops(m, quarters[i], quarters[j]), opt.splitDistance);
    }
  }
  // splitDistance 0: left alone
  FrameTopology kept = computeMatchings(m.s.F, m.topo, m.geometry, U);
  opt.splitDistance = 0;
  EXPECT_EQ(optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, kept, opt).split, 0);
  EXPECT_EQ(kept.singularities, 2);
}

TEST(Matchings, QuartersOfASplitPoleOfSliversGoAsFarAsOnACoarseMesh)
{
  // A pole of 200 slivers (a latitude-longitude sphere of 200 x 100, as VTK's sphere source makes
  // it): 4 edges from the pole are 0.13 of the radius, less than a quad at a few thousand quads,
  // and the map between quarters so close folded. With length-scaled costs the quarters go at
  // least 4 reference lengths (the edges of a 4,000-triangle mesh) along their paths, and as far
  // from each other along the surface; counted in edges, as before, without.
  const Mesh m = prepare(latLongSphere(200, 100));
  const Eigen::MatrixX3d U = parallelField(m, 0);
  BranchPointOptions opt;
  FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  const BranchPointReport r = optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, t, opt);
  EXPECT_EQ(r.split, 2);
  EXPECT_EQ(r.splitFailed, 0);
  const double length = opt.splitDistance * m.geometry.referenceLength;
  // shortest edge path between points, by length
  auto pathLength = [&](int from, int to) {
    return edgePathLengths(m, { from }, std::numeric_limits<double>::infinity())[to];
  };
  std::vector<int> quarters;
  for (int v = 0; v < m.topo.numVertices; ++v)
  {
    if (t.index[v] != 0.0)
    {
      EXPECT_NEAR(t.index[v], 0.25, 1e-9) << v;
      quarters.push_back(v);
      // a quarter of the north pole (point 0) or of the south pole (1)
      const int pole = m.s.V(v, 2) > 0 ? 0 : 1;
      EXPECT_GE(pathLength(pole, v), 0.9 * length) << v;
    }
  }
  ASSERT_EQ(quarters.size(), 8u);
  for (std::size_t i = 0; i < quarters.size(); ++i)
  {
    for (std::size_t j = i + 1; j < quarters.size(); ++j)
    {
      EXPECT_GE(pathLength(quarters[i], quarters[j]), length);
    }
  }
  // every edge counted once: 4 edges from the pole, as the edge count asks
  opt.lengthScaledCost = false;
  FrameTopology counted = computeMatchings(m.s.F, m.topo, m.geometry, U);
  optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, counted, opt);
  for (int v = 0; v < m.topo.numVertices; ++v)
  {
    if (counted.index[v] != 0.0)
    {
      EXPECT_LT(pathLength(m.s.V(v, 2) > 0 ? 0 : 1, v), 0.5 * length) << v;
    }
  }
}

TEST(Matchings, WithoutTheOptimizationWholeTurnsAreStillSplitButNothingMerges)
{
  // The field keeps its own singularities without the branch-point optimization, but no map can
  // follow a whole turn: the stage splits it all the same (the teapot's lid with the smoothest
  // field had a +1 at its pole and half its map folded over), and merges nothing.
  const Mesh m = prepare(latLongSphere(32, 24));
  const Eigen::MatrixX3d U = parallelField(m, 0);
  MatchingOptions options;
  options.optimizeBranchPoints = false;
  const MatchingResult r = buildMatchings(
    m.s.V, m.s.F, m.topo, m.geometry, U, Eigen::MatrixX3d(), Eigen::VectorXd(), {}, options);
  EXPECT_EQ(r.branchPointsBefore, 0) << "a whole turn has no layer shift";
  EXPECT_EQ(r.report.split, 2);
  EXPECT_EQ(r.topology.singularities, 8);
  EXPECT_EQ(r.topology.branchPoints, 8);
  EXPECT_LT(r.topology.index.maxCoeff(), 0.25 + 1e-9);
  EXPECT_NEAR(r.topology.index.sum(), 2.0, 1e-9);
  EXPECT_TRUE(r.framesFitted);
  // a field without whole turns (the torus' parallels: none at all) is left exactly as it is
  const Mesh torus = prepare(makeTorus(1.0, 0.4, 48, 24));
  Eigen::MatrixX3d T(torus.s.F.rows(), 3);
  for (int f = 0; f < torus.s.F.rows(); ++f)
  {
    const Eigen::Vector3d c = (torus.s.V.row(torus.s.F(f, 0)) + torus.s.V.row(torus.s.F(f, 1)) +
                                torus.s.V.row(torus.s.F(f, 2))) /
      3.0;
    T.row(f) = Eigen::Vector3d::UnitZ().cross(c).normalized();
  }
  const MatchingResult kept = buildMatchings(torus.s.V, torus.s.F, torus.topo, torus.geometry, T,
    Eigen::MatrixX3d(), Eigen::VectorXd(), {}, options);
  EXPECT_EQ(
    kept.topology.matching, computeMatchings(torus.s.F, torus.topo, torus.geometry, T).matching);
  EXPECT_EQ(kept.report.split, 0);
  EXPECT_FALSE(kept.framesFitted);
}

TEST(Matchings, FittingLeavesAFieldItsMatchingsSayUntwistedWhateverWayTheDiagonalsLean)
{
  // A latitude-longitude sphere, each of whose quads is split along the diagonal that leans the
  // same way, and the field along its parallels (index 1 at each pole): the matchings say that
  // field, so the fit should leave it as it is, up to a common turn. With each edge weighted by
  // its triangles' areas, (A_f + A_g) / 3, the leaning diagonals turned it by 15.1 degrees between
  // latitudes (as the fit after the cone pairs turned the teapot's body by 25 degrees and sheared
  // its quads); weighted by the edge over the centres' distance, 8.0 (4.8 and 2.4 within 30
  // degrees of the equator: what is left comes from the fans around the poles).
  const Mesh m = prepare(latLongSphere(32, 24));
  const Eigen::MatrixX3d U = parallelField(m, 0);
  const FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  const Eigen::VectorXd alpha =
    fitFramesToMatchings(m.s.V, m.s.F, m.topo, m.geometry, U, t.matching, Eigen::VectorXd());
  double low = 1e9, high = -1e9;
  for (int f = 0; f < m.s.F.rows(); ++f)
  {
    const double z = (m.s.V(m.s.F(f, 0), 2) + m.s.V(m.s.F(f, 1), 2) + m.s.V(m.s.F(f, 2), 2)) / 3;
    if (std::abs(z) < 0.8) // away from the poles' fans
    {
      low = std::min(low, alpha[f]);
      high = std::max(high, alpha[f]);
    }
  }
  std::printf("turn between latitudes %.2f degrees\n", (high - low) * 180 / Pi);
  EXPECT_LT((high - low) * 180 / Pi, 10.0);
}

TEST(Matchings, FittingFramesToChangedMatchingsKeepsIndicesAndSpreadsTheTurn)
{
  // After the split the matchings along the paths disagree with the frames by about a quarter
  // turn; the fit turns the frames so that every edge agrees within a small angle, and changes
  // neither matchings nor indices.
  const Mesh m = prepare(latLongSphere(32, 24));
  const Eigen::MatrixX3d U = parallelField(m, 0);
  FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, t);
  const double before = t.deviation.cwiseAbs().maxCoeff();
  const Eigen::VectorXd alpha =
    fitFramesToMatchings(m.s.V, m.s.F, m.topo, m.geometry, U, t.matching, Eigen::VectorXd());
  Eigen::MatrixX3d fitted = U;
  Eigen::MatrixX3d V = U;
  rotateFrames(m.geometry.bases, alpha, fitted, V);
  const FrameTopology after = evaluateMatchings(m.s.F, m.topo, m.geometry, fitted, t.matching);
  EXPECT_EQ((after.index - t.index).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(computeMatchings(m.s.F, m.topo, m.geometry, fitted).matching, t.matching)
    << "the fitted field's own smallest-angle matchings are the given ones";
  std::printf(
    "largest matched angle %.3f -> %.3f rad\n", before, after.deviation.cwiseAbs().maxCoeff());
  EXPECT_GT(before, 1.0);
  // (0.28 rad with the edges weighted by their triangles' areas; weighted by their length over
  // the centres' distance, 0.43 on an edge near a pole, where the fans' short edges weigh little)
  EXPECT_LT(after.deviation.cwiseAbs().maxCoeff(), 0.5);
  EXPECT_THROW(fitFramesToMatchings(
                 m.s.V, m.s.F, m.topo, m.geometry, U.topRows(3), t.matching, Eigen::VectorXd()),
    std::invalid_argument);
}

TEST(Matchings, RejectsMatchingsThatAreNotInverse)
{
  const Mesh m = prepare(testSurface("sphere"));
  const Eigen::MatrixX3d U = randomFrames(m, 1);
  FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
  Eigen::MatrixX3i bad = t.matching;
  bad(0, 0) = (bad(0, 0) + 1) % 4;
  EXPECT_THROW(evaluateMatchings(m.s.F, m.topo, m.geometry, U, bad), std::invalid_argument);
}

TEST(Matchings, LengthScaledMergeCostDoesNotDependOnTheMeshResolution)
{
  // A +1/4, -1/4 pair 0.3 apart on a (nearly flat) square of side 2, meshed with 20 and with 80
  // quads a side: the length-scaled cost decides the same at both resolutions, the edge count
  // (the paper's) keeps the pair on the fine mesh at a weight that merges it on the coarse one.
  const Eigen::Vector2d a(-0.15, 0.05), b(0.15, 0.05);
  std::map<std::pair<int, bool>, int> after;
  std::map<std::pair<int, bool>, double> pathCost;
  for (const int n : { 20, 80 })
  {
    const Mesh m = prepare(makeSaddle(1e6, 1.0, n));
    Eigen::MatrixX3d U(m.s.F.rows(), 3);
    for (int f = 0; f < m.s.F.rows(); ++f)
    {
      const Eigen::Vector3d c =
        (m.s.V.row(m.s.F(f, 0)) + m.s.V.row(m.s.F(f, 1)) + m.s.V.row(m.s.F(f, 2))) / 3.0;
      const Eigen::Vector2d p(c.x(), c.y());
      const double theta =
        0.25 * (std::atan2((p - a).y(), (p - a).x()) - std::atan2((p - b).y(), (p - b).x()));
      const Eigen::Vector3d normal = m.geometry.bases.normal.row(f);
      Eigen::Vector3d u(std::cos(theta), std::sin(theta), 0.0);
      U.row(f) = (u - u.dot(normal) * normal).normalized();
    }
    for (const bool scaled : { true, false })
    {
      FrameTopology t = computeMatchings(m.s.F, m.topo, m.geometry, U);
      ASSERT_EQ(t.singularities, 2) << n;
      BranchPointOptions opt;
      opt.lengthScaledCost = scaled;
      // merge whatever it costs: the cost of the path is what we look at
      opt.branchPointWeight = 1000;
      const BranchPointReport r = optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, t, opt);
      ASSERT_EQ(r.singularitiesAfter, 0);
      pathCost[{ n, scaled }] = r.costAfter - r.costBefore + 2 * opt.branchPointWeight;
      std::printf("n %d, %s: the merge costs %.2f\n", n, scaled ? "length-scaled" : "edge count",
        pathCost[{ n, scaled }]);
    }
  }
  // the scaled cost changes little with a 4x finer mesh, the edge count about 4x
  const double scaledRatio =
    pathCost[std::make_pair(80, true)] / pathCost[std::make_pair(20, true)];
  const double countRatio =
    pathCost[std::make_pair(80, false)] / pathCost[std::make_pair(20, false)];
  EXPECT_NEAR(scaledRatio, 1.0, 0.3);
  EXPECT_GT(countRatio, 2.5);
}

TEST(Matchings, BranchPointOptimizationReportsProgressAndStopsWhenAsked)
{
  // A random field on the torus: hundreds of singular points to search from.
  const Mesh m = prepare(testSurface("torus"));
  const Eigen::MatrixX3d U = randomFrames(m, 3);
  const FrameTopology start = computeMatchings(m.s.F, m.topo, m.geometry, U);
  FrameTopology quiet = start;
  const BranchPointReport plain = optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, quiet);

  std::vector<double> fractions;
  FrameTopology watched = start;
  const BranchPointReport r = optimizeBranchPoints(
    m.s.F, m.topo, m.geometry, U, watched, BranchPointOptions(), Progress([&](double x) {
      fractions.push_back(x);
      return true;
    }));
  std::printf("%zu reports, %d singularities split, %d paths changed\n", fractions.size(), r.split,
    r.pathsChanged);
  ASSERT_GT(fractions.size(), 20u);
  // in order from 0 to 1, and so all within [0, 1]
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  // Reporting changes nothing.
  EXPECT_EQ(r.pathsChanged, plain.pathsChanged);
  EXPECT_EQ(r.costAfter, plain.costAfter);
  EXPECT_TRUE(watched.matching == quiet.matching);

  int calls = 0;
  FrameTopology stopped = start;
  EXPECT_THROW(optimizeBranchPoints(m.s.F, m.topo, m.geometry, U, stopped, BranchPointOptions(),
                 Progress([&](double) { return ++calls < 5; })),
    Cancelled);
  EXPECT_EQ(calls, 5);
}

TEST(Matchings, AComponentIsMeasuredOnItsOwnScale)
{
  // A small rounded cube (its flat sides leave the curvature frames noisy: many singularities to
  // merge) beside a sphere 233 times its area. Merges are priced in the grid the cube would get
  // at 2,000 quads: its share by area (8.5 quads) is below its minimum (24), so its reference
  // length is that of 24 quads on it; with that, and the same frames, it merges exactly as it
  // does alone in that unit.
  Surface cube = makeRoundedCube(0.2, 8);
  const Surface sphere = makeIcosphere(20.0, 4);
  Surface both;
  both.V.resize(sphere.V.rows() + cube.V.rows(), 3);
  both.V << sphere.V, cube.V;
  both.F.resize(sphere.F.rows() + cube.F.rows(), 3);
  both.F << sphere.F, (cube.F.array() + static_cast<int>(sphere.V.rows())).matrix();
  Mesh alone = prepare(cube);
  const Mesh joint = prepare(both);
  ASSERT_EQ(joint.topo.numComponents(), 2);
  const Eigen::Index first = sphere.F.rows(), n = cube.F.rows();

  const double cubeArea = surfaceArea(cube.V, cube.F), total = surfaceArea(both.V, both.F);
  ASSERT_LT(2000.0 * cubeArea / total, ReferenceComponentQuads);
  EXPECT_NEAR(joint.geometry.componentReferenceLength[first], std::sqrt(cubeArea / 24.0), 1e-12);
  EXPECT_NEAR(joint.geometry.componentReferenceLength[0] / joint.geometry.referenceLength, 1.0,
    0.01); // the sphere: about the whole surface's
  EXPECT_EQ(alone.geometry.componentReferenceLength,
    Eigen::VectorXd::Constant(n, alone.geometry.referenceLength));

  // the cube alone with its curvature frames, priced in the same unit: the same merges
  const Eigen::MatrixX3d a = computeCurvatureField(alone.s.V, alone.s.F, alone.topo).frameU;
  Eigen::MatrixX3d j = computeCurvatureField(joint.s.V, joint.s.F, joint.topo).frameU;
  j.middleRows(first, n) = a;
  alone.geometry.componentReferenceLength =
    joint.geometry.componentReferenceLength.segment(first, n);
  FrameTopology ta = computeMatchings(alone.s.F, alone.topo, alone.geometry, a);
  FrameTopology tj = computeMatchings(joint.s.F, joint.topo, joint.geometry, j);
  const int before = ta.singularities;
  optimizeBranchPoints(alone.s.F, alone.topo, alone.geometry, a, ta);
  optimizeBranchPoints(joint.s.F, joint.topo, joint.geometry, j, tj);
  std::printf("the cube: %.1f of 2,000 quads by area (%.0f times its area beside it); %d "
              "singularities, after the merges %d\n",
    2000.0 * cubeArea / total, total / cubeArea - 1.0, before, ta.singularities);
  ASSERT_LT(ta.singularities, before); // merges happened
  EXPECT_EQ(ta.matching, tj.matching.middleRows(first, n));
  EXPECT_EQ(ta.index, tj.index.segment(sphere.V.rows(), cube.V.rows()));
}
