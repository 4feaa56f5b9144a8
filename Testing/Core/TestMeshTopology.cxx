// Connectivity invariants on generated surfaces and on hand-made defects.
#include "MeshTopology.h"
#include "SurfaceDisks.h"
#include "SurfaceRepair.h"
#include "Surfaces.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

using namespace quadcover;

namespace
{
struct Expect
{
  const char* name;
  int chi;
  int genus;
  int loops;
};
}

TEST(MeshTopology, EulerGenusAndBoundaryOfGeneratedSurfaces)
{
  const Expect expect[] = { { "torus", 0, 1, 0 }, { "sphere", 2, 0, 0 }, { "knot", 0, 1, 0 },
    { "cylinder", 0, 0, 2 }, { "saddle", 1, 0, 1 }, { "roundedcube", 2, 0, 0 } };
  for (const Expect& e : expect)
  {
    const Surface s = testSurface(e.name);
    const MeshTopology T = buildTopology(s.F, static_cast<int>(s.V.rows()));
    SCOPED_TRACE(e.name);
    EXPECT_TRUE(T.isManifold()) << T.describeDefects();
    EXPECT_TRUE(T.isOriented());
    ASSERT_EQ(T.numComponents(), 1);
    EXPECT_EQ(T.eulerCharacteristic(), e.chi);
    EXPECT_EQ(T.components[0].genus, e.genus);
    EXPECT_EQ(static_cast<int>(T.boundaryLoops.size()), e.loops);
    EXPECT_TRUE(T.unreferencedVertices.empty());
    // Every face-edge incidence is consistent with the edge list.
    for (int f = 0; f < T.numFaces; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int e = T.faceEdges(f, k);
        ASSERT_GE(e, 0);
        const std::set<int> a = { s.F(f, k), s.F(f, (k + 1) % 3) };
        const std::set<int> b = { T.edges(e, 0), T.edges(e, 1) };
        EXPECT_EQ(a, b);
        // The edge knows its slot in this face.
        ASSERT_TRUE(T.edgeCorners(e, 0) == 3 * f + k || T.edgeCorners(e, 1) == 3 * f + k);
        const int g = T.faceNeighbors(f, k);
        if (g >= 0)
        {
          // Symmetric adjacency.
          bool back = false;
          for (int kk = 0; kk < 3; ++kk)
          {
            back = back || T.faceNeighbors(g, kk) == f;
          }
          EXPECT_TRUE(back);
        }
      }
    }
  }
}

TEST(MeshTopology, OneRingsAreOrderedCounterclockwise)
{
  for (const char* name : { "sphere", "cylinder", "knot" })
  {
    const Surface s = testSurface(name);
    const MeshTopology T = buildTopology(s.F, static_cast<int>(s.V.rows()));
    for (int v = 0; v < T.numVertices; ++v)
    {
      const int b = T.ringOffsets[v], n = T.valence(v);
      ASSERT_GT(n, 0);
      ASSERT_TRUE(T.ringOrdered[v]);
      // Each incident face exactly once.
      std::set<int> faces(T.ringFaces.begin() + b, T.ringFaces.begin() + b + n);
      EXPECT_EQ(static_cast<int>(faces.size()), n);
      // Consecutive faces share the edge from v to the previous face's last corner.
      for (int i = 0; i + 1 < n; ++i)
      {
        const int f = T.ringFaces[b + i], g = T.ringFaces[b + i + 1];
        const int k = MeshTopology::cornerOf(s.F, f, v);
        EXPECT_EQ(T.faceNeighbors(f, (k + 2) % 3), g) << name << " vertex " << v;
      }
      if (!T.boundaryVertex[v])
      {
        const int f = T.ringFaces[b + n - 1];
        const int k = MeshTopology::cornerOf(s.F, f, v);
        EXPECT_EQ(T.faceNeighbors(f, (k + 2) % 3), T.ringFaces[b]);
      }
      else
      {
        const int f = T.ringFaces[b];
        EXPECT_EQ(T.faceNeighbors(f, MeshTopology::cornerOf(s.F, f, v)), -1);
        const int g = T.ringFaces[b + n - 1];
        EXPECT_EQ(T.faceNeighbors(g, (MeshTopology::cornerOf(s.F, g, v) + 2) % 3), -1);
      }
    }
  }
}

TEST(MeshTopology, BoundaryLoopsFollowTheOrientation)
{
  const Surface s = testSurface("cylinder");
  const MeshTopology T = buildTopology(s.F, static_cast<int>(s.V.rows()));
  ASSERT_EQ(T.boundaryLoops.size(), 2u);
  for (const auto& loop : T.boundaryLoops)
  {
    EXPECT_EQ(loop.size(), 48u); // nAround of the test cylinder
    // All vertices of a loop lie at one height.
    for (int v : loop)
    {
      EXPECT_NEAR(s.V(v, 2), s.V(loop[0], 2), 1e-12);
      EXPECT_TRUE(T.boundaryVertex[v]);
    }
  }
}

TEST(MeshTopology, SeveralComponents)
{
  const Surface a = testSurface("sphere");
  const Surface b = testSurface("torus");
  Eigen::MatrixX3i F(a.F.rows() + b.F.rows(), 3);
  F << a.F, (b.F.array() + static_cast<int>(a.V.rows())).matrix();
  const MeshTopology T = buildTopology(F, static_cast<int>(a.V.rows() + b.V.rows()));
  ASSERT_EQ(T.numComponents(), 2);
  EXPECT_EQ(T.eulerCharacteristic(), 2);
  EXPECT_EQ(T.components[0].genus, 0);
  EXPECT_EQ(T.components[1].genus, 1);
  EXPECT_EQ(T.faceComponent[0], 0);
  EXPECT_EQ(T.faceComponent[F.rows() - 1], 1);
}

TEST(MeshTopology, ManyComponentsWithShuffledVertexIndices)
{
  // Seven spheres and tori whose vertex numbers are interleaved at random: the component
  // labelling must not depend on the numbering.
  std::vector<Surface> parts;
  for (int i = 0; i < 7; ++i)
  {
    parts.push_back(i % 2 ? makeTorus(1.0, 0.3, 12, 8) : makeIcosphere(1.0, 1));
  }
  int nv = 0, nf = 0;
  for (const Surface& s : parts)
  {
    nv += static_cast<int>(s.V.rows());
    nf += static_cast<int>(s.F.rows());
  }
  std::vector<int> perm(nv);
  std::iota(perm.begin(), perm.end(), 0);
  std::mt19937 rng(3);
  std::shuffle(perm.begin(), perm.end(), rng);
  Eigen::MatrixX3i F(nf, 3);
  int vo = 0, fo = 0;
  for (const Surface& s : parts)
  {
    for (Eigen::Index f = 0; f < s.F.rows(); ++f, ++fo)
    {
      for (int k = 0; k < 3; ++k)
      {
        F(fo, k) = perm[vo + s.F(f, k)];
      }
    }
    vo += static_cast<int>(s.V.rows());
  }
  const MeshTopology T = buildTopology(F, nv);
  ASSERT_EQ(T.numComponents(), 7);
  EXPECT_EQ(T.eulerCharacteristic(), 4 * 2 + 3 * 0);
  int tori = 0;
  for (const ComponentInfo& c : T.components)
  {
    EXPECT_TRUE(c.genus == 0 || c.genus == 1);
    tori += c.genus;
  }
  EXPECT_EQ(tori, 3);
}

TEST(MeshTopology, DetectsNonManifoldEdge)
{
  // Three triangles on one edge (0,1).
  Eigen::MatrixX3i F(3, 3);
  F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  const MeshTopology T = buildTopology(F, 5);
  EXPECT_FALSE(T.isManifold());
  EXPECT_EQ(T.nonManifoldEdges.size(), 1u);
  EXPECT_NE(T.describeDefects().find("non-manifold edges"), std::string::npos);
}

TEST(MeshTopology, DetectsBowtieVertex)
{
  // Two triangles touching only at vertex 0.
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 3, 4;
  const MeshTopology T = buildTopology(F, 5);
  EXPECT_EQ(T.nonManifoldVertices, std::vector<int>{ 0 });
  EXPECT_EQ(T.numComponents(), 1);
}

TEST(MeshTopology, DetectsMisorientedAndDegenerateTriangles)
{
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 1, 3; // both traverse 0 -> 1
  EXPECT_EQ(buildTopology(F, 4).misorientedEdges.size(), 1u);
  Eigen::MatrixX3i G(1, 3);
  G << 0, 0, 1;
  const MeshTopology T = buildTopology(G, 2);
  EXPECT_EQ(T.degenerateFaces.size(), 1u);
  EXPECT_FALSE(T.isManifold());
}

TEST(MeshTopology, RejectsOutOfRangeIndices)
{
  Eigen::MatrixX3i F(1, 3);
  F << 0, 1, 7;
  EXPECT_THROW(buildTopology(F, 3), std::invalid_argument);
}

TEST(MeshTopology, EmptyMesh)
{
  const MeshTopology T = buildTopology(Eigen::MatrixX3i(0, 3), 0);
  EXPECT_EQ(T.numComponents(), 0);
  EXPECT_EQ(T.eulerCharacteristic(), 0);
}

TEST(MeshTopology, SplitsBowtieVerticesIntoManifoldFans)
{
  // Two triangles touching at vertex 0.
  Eigen::MatrixX3d V = Eigen::MatrixX3d::Random(5, 3);
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 3, 4;
  EXPECT_EQ(makeManifold(V, F).copies, std::vector<int>{ 0 });
  ASSERT_EQ(V.rows(), 6);
  EXPECT_EQ(V.row(5), V.row(0));
  const MeshTopology T = buildTopology(F, 6);
  EXPECT_TRUE(T.isManifold()) << T.describeDefects();
  EXPECT_EQ(T.numComponents(), 2);

  Surface s = testSurface("sphere");
  const Eigen::MatrixX3i before = s.F;
  EXPECT_TRUE(makeManifold(s.V, s.F).copies.empty());
  EXPECT_EQ(s.F, before);
}

TEST(MeshTopology, MisorientedFanIsNotNonManifoldAndHasNoOrderedRing)
{
  // An open fan around vertex 0 with its third triangle flipped.
  Eigen::MatrixX3i F(4, 3);
  F << 0, 1, 2, 0, 2, 3, 0, 4, 3, 0, 4, 5;
  const MeshTopology T = buildTopology(F, 6);
  EXPECT_FALSE(T.isOriented());
  EXPECT_TRUE(T.nonManifoldVertices.empty()) << "misorientation is not non-manifoldness";
  EXPECT_FALSE(T.ringOrdered[0]);
  std::set<int> ring(
    T.ringFaces.begin() + T.ringOffsets[0], T.ringFaces.begin() + T.ringOffsets[1]);
  EXPECT_EQ(ring, (std::set<int>{ 0, 1, 2, 3 }));
}

TEST(MeshTopology, MobiusStripIsManifoldButNotOrientable)
{
  // A strip of 6 quads whose ends are glued with a half twist.
  const int n = 6;
  Eigen::MatrixX3i F(2 * n, 3);
  for (int i = 0; i < n; ++i)
  {
    int a = i, b = i + 1, c = n + 1 + i + 1, d = n + 1 + i; // bottom row 0..n, top row n+1..2n+1
    if (i == n - 1)
    {
      b = n + 1; // glue with the twist: bottom end meets the top start
      c = 0;
    }
    F.row(2 * i) << a, b, c;
    F.row(2 * i + 1) << a, c, d;
  }
  const MeshTopology T = buildTopology(F, 2 * n + 2);
  EXPECT_FALSE(T.isOriented());
  EXPECT_TRUE(T.nonManifoldVertices.empty()) << T.describeDefects();
  EXPECT_TRUE(T.nonManifoldEdges.empty());
  ASSERT_EQ(T.numComponents(), 1);
  EXPECT_EQ(T.components[0].genus, -1);
  EXPECT_EQ(T.boundaryLoops.size(), 1u); // a Moebius strip has one boundary curve
}

TEST(MeshTopology, DegenerateTriangleLeavesItsNeighboursAlone)
{
  // Triangle 2 repeats vertex 1 and lies on edge (0,1) shared by triangles 0 and 1.
  Eigen::MatrixX3i F(3, 3);
  F << 0, 1, 2, 0, 3, 1, 0, 1, 1;
  const MeshTopology T = buildTopology(F, 4);
  EXPECT_EQ(T.degenerateFaces, std::vector<int>{ 2 });
  EXPECT_TRUE(T.nonManifoldEdges.empty());
  EXPECT_EQ(T.faceNeighbors(0, 0), 1);
  EXPECT_EQ(T.faceNeighbors(2, 0), -1);
  EXPECT_EQ(T.faceEdges(2, 0), -1);
  for (int v = 0; v < 4; ++v)
  {
    for (int i = T.ringOffsets[v]; i < T.ringOffsets[v + 1]; ++i)
    {
      EXPECT_NE(T.ringFaces[i], 2);
    }
  }
}

TEST(MeshTopology, BowtieHasTwoBoundaryLoops)
{
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 3, 4;
  const MeshTopology T = buildTopology(F, 5);
  ASSERT_EQ(T.boundaryLoops.size(), 2u);
  EXPECT_EQ(T.boundaryLoops[0].size(), 3u);
  EXPECT_EQ(T.boundaryLoops[1].size(), 3u);
}

TEST(MeshTopology, SplitIsLinearInTheValence)
{
  // A fan of 100000 triangles around vertex 0 plus one triangle touching it only at 0: the
  // split must give one copy (and would take minutes if it were quadratic).
  const int n = 100000;
  Eigen::MatrixX3i F(n + 1, 3);
  for (int i = 0; i < n; ++i)
  {
    F.row(i) << 0, i + 1, i + 2;
  }
  F.row(n) << 0, n + 2, n + 3;
  F(n, 1) = n + 3;
  F(n, 2) = n + 4;
  Eigen::MatrixX3d V = Eigen::MatrixX3d::Random(n + 5, 3);
  EXPECT_EQ(makeManifold(V, F).copies, std::vector<int>{ 0 });
  EXPECT_EQ(F(n, 0), n + 5);
}

namespace
{
Eigen::MatrixX3d edgeLengths(const Surface& s)
{
  Eigen::MatrixX3d length(s.F.rows(), 3);
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      length(f, k) = (s.V.row(s.F(f, (k + 1) % 3)) - s.V.row(s.F(f, k))).norm();
    }
  }
  return length;
}
}

TEST(MeshTopology, BallsAreDisksUntilTheyWrapAroundAHandle)
{
  // A torus of tube radius 0.25 about a circle of radius 1: a ball narrower than the tube's
  // girth (1.57) is a disk; one wider wraps around the tube (an annulus, chi 0).
  const Surface torus = makeTorus(1.0, 0.25, 64, 16);
  const MeshTopology topo = buildTopology(torus.F, static_cast<int>(torus.V.rows()));
  const Eigen::MatrixX3d length = edgeLengths(torus);
  DiskTest disks(torus.F, topo, length);
  for (const int a : { 0, 17, 500 })
  {
    EXPECT_TRUE(disks.ballIsDisk(a, 0.3)) << a;
    EXPECT_FALSE(disks.ballIsDisk(a, 1.2)) << a;
    EXPECT_TRUE(disks.ballIsDisk(a, 0.5)) << a << ": the same test again, after a wider one";
  }
  EXPECT_FALSE(disks.ballIsDisk(0, 100.0)) << "the whole torus";
  // On a sphere every ball short of the whole is a disk; past half of it the search stops.
  const Surface sphere = makeIcosphere(1.0, 3);
  const MeshTopology sphereTopo = buildTopology(sphere.F, static_cast<int>(sphere.V.rows()));
  const Eigen::MatrixX3d sphereLength = edgeLengths(sphere);
  DiskTest sphereDisks(sphere.F, sphereTopo, sphereLength);
  EXPECT_TRUE(sphereDisks.ballIsDisk(3, 0.5));
  EXPECT_TRUE(sphereDisks.ballIsDisk(3, 1.2));
  EXPECT_FALSE(sphereDisks.ballIsDisk(3, 10.0)) << "more than half of it";
  EXPECT_TRUE(sphereDisks.ballIsDisk(3, 0.0)) << "the triangles around the point alone";
}

TEST(MeshTopology, BallsThatReachTheBoundaryAreBeyondWhenAsked)
{
  // An open tube of radius 0.1 (girth 0.63) and length 2, a point halfway: a ball of radius 0.2
  // is a disk, one of 0.5 wraps around the tube (no disk) and stays 0.5 from its ends. Around a
  // point 0.31 from an end, one of 0.5 reaches that end: an annulus that holds its loop.
  using Ball = DiskTest::Ball;
  const int nAround = 32, nAlong = 64;
  const Surface tube = makeCylinder(0.1, 2.0, nAround, nAlong);
  const MeshTopology topo = buildTopology(tube.F, static_cast<int>(tube.V.rows()));
  const Eigen::MatrixX3d length = edgeLengths(tube);
  DiskTest disks(tube.F, topo, length);
  const int middle = nAlong / 2; // vertex i * (nAlong + 1) + j: around i, along j
  for (const bool boundaryBeyond : { false, true })
  {
    EXPECT_EQ(disks.ball(middle, 0.2, boundaryBeyond), Ball::Disk);
    EXPECT_EQ(disks.ball(middle, 0.5, boundaryBeyond), Ball::NotDisk);
    EXPECT_EQ(disks.ball(middle, 100.0, boundaryBeyond), Ball::Beyond) << "more than half";
  }
  const int nearEnd = 10;
  EXPECT_EQ(disks.ball(nearEnd, 0.5, false), Ball::NotDisk);
  EXPECT_EQ(disks.ball(nearEnd, 0.5, true), Ball::Beyond);
  EXPECT_EQ(disks.ball(0, 0.2, false), Ball::Disk) << "a half disk at an end";
  EXPECT_EQ(disks.ball(0, 0.2, true), Ball::Beyond);
}
