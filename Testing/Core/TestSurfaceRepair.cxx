// Tests of the repair: points merged, non-manifold edges cut apart into sheets, fans split,
// orientation, flat caps flipped away, T-junctions closed.
#include "DegenerateTriangles.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "SurfaceRefinement.h"
#include "SurfaceRepair.h"
#include "TJunctions.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace quadcover;

namespace
{
constexpr double Pi = 3.14159265358979323846;
}

namespace
{
/// A closed unit box from corner (x0, y0, z0): 8 points, 12 outward triangles, appended.
void appendBox(Surface& s, double x0, double y0, double z0)
{
  const int base = static_cast<int>(s.V.rows());
  s.V.conservativeResize(base + 8, 3);
  for (int i = 0; i < 8; ++i)
  {
    s.V.row(base + i) << x0 + (i & 1), y0 + ((i >> 1) & 1), z0 + ((i >> 2) & 1);
  }
  const int quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  const int f0 = static_cast<int>(s.F.rows());
  s.F.conservativeResize(f0 + 12, 3);
  for (int q = 0; q < 6; ++q)
  {
    const int* c = quads[q];
    s.F.row(f0 + 2 * q) << base + c[0], base + c[1], base + c[2];
    s.F.row(f0 + 2 * q + 1) << base + c[0], base + c[2], base + c[3];
  }
}

/// Merges exactly coincident points (as the repair filter's clean step does).
void weld(Surface& s)
{
  std::vector<int> to(s.V.rows());
  std::vector<Eigen::RowVector3d> kept;
  for (int i = 0; i < s.V.rows(); ++i)
  {
    to[i] = static_cast<int>(kept.size());
    for (size_t j = 0; j < kept.size(); ++j)
    {
      if (kept[j] == s.V.row(i))
      {
        to[i] = static_cast<int>(j);
        break;
      }
    }
    if (to[i] == static_cast<int>(kept.size()))
    {
      kept.push_back(s.V.row(i));
    }
  }
  s.V.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t j = 0; j < kept.size(); ++j)
  {
    s.V.row(static_cast<Eigen::Index>(j)) = kept[j];
  }
  for (int f = 0; f < s.F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      s.F(f, k) = to[s.F(f, k)];
    }
  }
}

/// The signed volume the first `faces` triangles (all by default) enclose: positive for a
/// closed surface facing outwards.
double signedVolume(const Surface& s, int faces = -1)
{
  double v = 0.0;
  for (int f = 0; f < (faces < 0 ? s.F.rows() : faces); ++f)
  {
    v += s.V.row(s.F(f, 0)).dot(s.V.row(s.F(f, 1)).cross(s.V.row(s.F(f, 2)))) / 6.0;
  }
  return v;
}

/// The components' (Euler characteristic, boundary loops), sorted.
std::vector<std::pair<int, int>> shape(const Surface& s)
{
  const MeshTopology T = buildTopology(s.F, static_cast<int>(s.V.rows()));
  EXPECT_TRUE(T.isManifold()) << T.describeDefects();
  EXPECT_TRUE(T.isOriented()) << T.describeDefects();
  std::vector<std::pair<int, int>> out;
  for (const ComponentInfo& c : T.components)
  {
    out.emplace_back(c.eulerCharacteristic, c.numBoundaryLoops);
  }
  std::sort(out.begin(), out.end());
  return out;
}

using Shape = std::vector<std::pair<int, int>>;
}

TEST(MakeManifold, LeavesAManifoldSurfaceAsItIs)
{
  Surface s = testSurface("torus");
  const Eigen::MatrixX3i before = s.F;
  const ManifoldRepair r = makeManifold(s.V, s.F);
  EXPECT_EQ(r.cutEdges, 0);
  EXPECT_TRUE(r.copies.empty());
  EXPECT_TRUE(r.reversed.empty());
  EXPECT_EQ(s.F, before);
}

TEST(MakeManifold, TwoBoxesSharingAnEdgeBecomeTwoClosedBoxes)
{
  Surface s;
  appendBox(s, 0, 0, 0);
  appendBox(s, 1, 1, 0); // shares the edge x = y = 1 with the first
  weld(s);
  ASSERT_EQ(s.V.rows(), 14);
  ASSERT_FALSE(buildTopology(s.F, 14).nonManifoldEdges.empty());
  const ManifoldRepair r = makeManifold(s.V, s.F);
  EXPECT_EQ(r.cutEdges, 1);
  EXPECT_EQ(r.copies.size(), 2u); // both points of the edge
  EXPECT_TRUE(r.reversed.empty());
  EXPECT_EQ(shape(s), (Shape{ { 2, 0 }, { 2, 0 } }));
  EXPECT_NEAR(signedVolume(s), 2.0, 1e-12);
}

TEST(MakeManifold, TwoBoxesOneInsideOutStillSplitIntoBoxes)
{
  Surface s;
  appendBox(s, 0, 0, 0);
  appendBox(s, 1, 1, 0);
  for (int f = 12; f < 24; ++f)
  {
    std::swap(s.F(f, 1), s.F(f, 2)); // the second box faces inwards
  }
  weld(s);
  const ManifoldRepair r = makeManifold(s.V, s.F);
  EXPECT_EQ(r.cutEdges, 1);
  EXPECT_EQ(shape(s), (Shape{ { 2, 0 }, { 2, 0 } }));
  EXPECT_TRUE(r.reversed.empty()) << "each box keeps its own orientation";
}

TEST(MakeManifold, AFinIsCutOffTheBox)
{
  Surface s;
  appendBox(s, 0, 0, 0);
  // a fin of two triangles standing on the top edge from (0,0,1) to (1,0,1), leaning outwards
  const int base = static_cast<int>(s.V.rows());
  s.V.conservativeResize(base + 4, 3);
  s.V.row(base) << 0, 0, 1;
  s.V.row(base + 1) << 1, 0, 1;
  s.V.row(base + 2) << 1, -1, 2;
  s.V.row(base + 3) << 0, -1, 2;
  s.F.conservativeResize(14, 3);
  s.F.row(12) << base, base + 1, base + 2;
  s.F.row(13) << base, base + 2, base + 3;
  weld(s);
  const ManifoldRepair r = makeManifold(s.V, s.F);
  EXPECT_EQ(r.cutEdges, 1);
  EXPECT_EQ(shape(s), (Shape{ { 1, 1 }, { 2, 0 } })); // the fin a disk, the box closed
  EXPECT_NEAR(signedVolume(s, 12), 1.0, 1e-12) << "the box still faces outwards";
}

TEST(MakeManifold, AFinLeaningIntoTheBoxIsCutOffToo)
{
  // A fin of two triangles standing on a box edge and reaching into the box: around the edge
  // it lies between the box's two faces on the solid's side, next to both. Standing on the top
  // edge from (0,0,1) to (1,0,1) (two faces at a right angle), and on the top face's diagonal
  // from (0,0,1) to (1,1,1) (two faces in one plane); each way round.
  const double fins[2][4][3] = {
    { { 0, 0, 1 }, { 1, 0, 1 }, { 1, 0.5, 0.5 }, { 0, 0.5, 0.5 } }, // into the box from its edge
    { { 0, 0, 1 }, { 1, 1, 1 }, { 1, 1, 0.25 }, { 0, 0, 0.25 } },   // hanging from the diagonal
  };
  for (int placement = 0; placement < 2; ++placement)
  {
    for (const bool turned : { false, true })
    {
      Surface s;
      appendBox(s, 0, 0, 0);
      const int base = static_cast<int>(s.V.rows());
      s.V.conservativeResize(base + 4, 3);
      for (int i = 0; i < 4; ++i)
      {
        s.V.row(base + i) << fins[placement][i][0], fins[placement][i][1], fins[placement][i][2];
      }
      s.F.conservativeResize(14, 3);
      s.F.row(12) << base, base + 1, base + 2;
      s.F.row(13) << base, base + 2, base + 3;
      if (turned)
      {
        std::swap(s.F(12, 1), s.F(12, 2));
        std::swap(s.F(13, 1), s.F(13, 2));
      }
      weld(s);
      ASSERT_EQ(s.V.rows(), 10);
      SCOPED_TRACE(std::string(placement == 0 ? "on the top edge" : "on the diagonal") +
        (turned ? ", turned" : ""));
      ManifoldRepair r;
      ASSERT_NO_THROW(r = makeManifold(s.V, s.F));
      EXPECT_EQ(r.cutEdges, 1);
      EXPECT_EQ(r.copies.size(), 2u) << "the fin's own copies of the edge's two points";
      EXPECT_EQ(shape(s), (Shape{ { 1, 1 }, { 2, 0 } })); // the fin a disk, the box closed
      EXPECT_NEAR(signedVolume(s, 12), 1.0, 1e-12) << "the box closed, facing outwards";
    }
  }
}

TEST(MakeManifold, AZeroAreaSliverOnAnEdgeDoesNotStealItsPair)
{
  // a collinear triangle on the box's edge (0,0,1)-(1,0,1), listed before the box
  Surface box;
  appendBox(box, 0, 0, 0);
  Surface s;
  s.V.resize(3, 3);
  s.V << 0, 0, 1, 1, 0, 1, 2, 0, 1;
  s.F.resize(1, 3);
  s.F << 0, 1, 2;
  const int base = 3;
  s.V.conservativeResize(base + 8, 3);
  s.V.bottomRows(8) = box.V;
  s.F.conservativeResize(13, 3);
  s.F.bottomRows(12) = box.F.array() + base;
  weld(s);
  const ManifoldRepair r = makeManifold(s.V, s.F);
  EXPECT_EQ(r.cutEdges, 1);
  const MeshTopology T = buildTopology(s.F, static_cast<int>(s.V.rows()));
  EXPECT_TRUE(T.nonManifoldEdges.empty());
  EXPECT_NEAR(signedVolume(s), 1.0, 1e-12) << "the box closed and facing outwards";
}

namespace
{
int countFlat(const Surface& s, double ratio)
{
  int n = 0;
  for (int f = 0; f < s.F.rows(); ++f)
  {
    n += isDegenerateTriangle(s.V.row(s.F(f, 0)), s.V.row(s.F(f, 1)), s.V.row(s.F(f, 2)), ratio);
  }
  return n;
}

double totalArea(const Surface& s)
{
  double area = 0.0;
  for (int f = 0; f < s.F.rows(); ++f)
  {
    const Eigen::Vector3d a = s.V.row(s.F(f, 0)), b = s.V.row(s.F(f, 1)), c = s.V.row(s.F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}
}

TEST(FlipDegenerateTriangles, RowsOfCapsOnEdgesBecomeProperTriangles)
{
  for (const double lift : { 0.0, 1e-9, -1e-9 })
  {
    SCOPED_TRACE("caps lifted " + std::to_string(lift) + " of their edge");
    Surface s = makeIcosphere(1.0, 2);
    int caps = 0;
    for (const int f : { 0, 50, 100, 150, 200, 250 })
    {
      caps += fanCapsOnEdge(s, f, 5, lift);
    }
    ASSERT_EQ(countFlat(s, FlatTriangleRatio), caps);
    const Eigen::MatrixX3i before = s.F;
    const double area = totalArea(s);
    const DegenerateFlips flips = flipDegenerateTriangles(s.V, s.F);
    EXPECT_EQ(flips.flippedEdges, caps);
    EXPECT_EQ(countFlat(s, FlatTriangleRatio), 0);
    EXPECT_EQ(s.F.rows(), before.rows());
    EXPECT_EQ(shape(s), (Shape{ { 2, 0 } })) << "still a closed, oriented sphere";
    EXPECT_NEAR(totalArea(s), area, 1e-9 * area);
    EXPECT_NEAR(signedVolume(s), signedVolume(Surface{ "", s.V, before, {}, {} }), 1e-9);
    for (int f = 0; f < s.F.rows(); ++f)
    {
      const Eigen::Vector3d a = s.V.row(s.F(f, 0)), b = s.V.row(s.F(f, 1)), c = s.V.row(s.F(f, 2));
      EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0) << "triangle " << f << " turned over";
      const int from = flips.triangleSource[f];
      EXPECT_EQ(countFlat(Surface{ "", s.V, before.row(from), {}, {} }, FlatTriangleRatio), 0)
        << "triangle " << f << " takes the data of a cap";
    }
  }
}

TEST(FlipDegenerateTriangles, LeavesCapsOnTheBoundaryAndProperTrianglesAsTheyAre)
{
  // a square of two triangles whose bottom edge a-b carries a point m: (a, m, c), (m, b, c) and
  // the cap (a, b, m), whose longest edge is the boundary: no neighbour to flip with
  Surface s;
  s.V.resize(5, 3);
  s.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0, 0;
  s.F.resize(4, 3);
  s.F << 0, 4, 3, 4, 1, 3, 0, 1, 4, 1, 2, 3;
  const Eigen::MatrixX3i before = s.F;
  DegenerateFlips flips = flipDegenerateTriangles(s.V, s.F);
  EXPECT_EQ(flips.flippedEdges, 0);
  EXPECT_EQ(s.F, before);
  Surface sphere = makeIcosphere(1.0, 2);
  const Eigen::MatrixX3i whole = sphere.F;
  flips = flipDegenerateTriangles(sphere.V, sphere.F);
  EXPECT_EQ(flips.flippedEdges, 0);
  EXPECT_EQ(sphere.F, whole);
}

namespace
{
/// The surface of these points and triangles, its equal points merged.
Surface welded(
  const std::vector<Eigen::RowVector3d>& points, const std::vector<Eigen::RowVector3i>& triangles)
{
  Surface s;
  s.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    s.V.row(static_cast<Eigen::Index>(i)) = points[i];
  }
  s.F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    s.F.row(static_cast<Eigen::Index>(i)) = triangles[i];
  }
  weld(s);
  return s;
}

/// A unit box whose six faces are gridded one by one, n[i] x n[i] squares of two triangles each,
/// every face facing out; `gap` moves the points of the last face's sides inside its plane,
/// off the other faces' edges. Coincident points merged.
Surface boxMeshedFaceByFace(const std::array<int, 6>& n, double gap = 0.0)
{
  const double sides[6][3][3] = { { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 } },
    { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 } },
    { { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } }, { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 } },
    { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  std::vector<Eigen::RowVector3d> points;
  std::vector<Eigen::RowVector3i> triangles;
  for (int side = 0; side < 6; ++side)
  {
    const Eigen::RowVector3d o(sides[side][0][0], sides[side][0][1], sides[side][0][2]);
    const Eigen::RowVector3d u(sides[side][1][0], sides[side][1][1], sides[side][1][2]);
    const Eigen::RowVector3d v(sides[side][2][0], sides[side][2][1], sides[side][2][2]);
    const int m = n[side], base = static_cast<int>(points.size());
    for (int j = 0; j <= m; ++j)
    {
      for (int i = 0; i <= m; ++i)
      {
        const bool inner = i > 0 && i < m && j > 0 && j < m;
        const double pull = side == 5 && !inner ? gap : 0.0; // towards the face's middle
        points.push_back(o + u * (i / double(m)) + v * (j / double(m)) +
          pull * ((u + v) * 0.5 - u * (i / double(m)) - v * (j / double(m))));
      }
    }
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        const int a = base + j * (m + 1) + i, b = a + 1, c = a + m + 1, d = c + 1;
        triangles.emplace_back(a, b, d);
        triangles.emplace_back(a, d, c);
      }
    }
  }
  return welded(points, triangles);
}
}

TEST(CloseTJunctions, ABoxMeshedFaceByFaceBecomesOneClosedSurface)
{
  Surface s = boxMeshedFaceByFace({ 4, 6, 5, 3, 8, 7 });
  {
    Surface apart = s;
    makeManifold(apart.V, apart.F);
    EXPECT_EQ(shape(apart).size(), 6u) << "without the T-junctions closed: six squares";
  }
  const Eigen::MatrixX3i before = s.F;
  const double area = totalArea(s);
  const TJunctionSplits splits = closeTJunctions(s.V, s.F, 1e-9);
  // on each of the box's 12 edges, the inner points of each side that the other lacks: n1 - 1
  // and n2 - 1, less twice the gcd(n1, n2) - 1 they share
  EXPECT_EQ(splits.closed, 96);
  EXPECT_EQ(s.F.rows(), before.rows() + splits.closed);
  EXPECT_NEAR(totalArea(s), area, 1e-12);
  EXPECT_EQ(countFlat(s, FlatTriangleRatio), 0);
  ASSERT_EQ(splits.triangleSource.size(), static_cast<std::size_t>(s.F.rows()));
  for (int f = 0; f < s.F.rows(); ++f)
  {
    const auto normal = [](const Surface& m, const Eigen::RowVector3i& t) {
      return Eigen::Vector3d((m.V.row(t[1]) - m.V.row(t[0])).cross(m.V.row(t[2]) - m.V.row(t[0])))
        .normalized();
    };
    EXPECT_NEAR(
      normal(s, s.F.row(f)).dot(normal(s, before.row(splits.triangleSource[f]))), 1.0, 1e-12)
      << "triangle " << f << " is a part of its source";
  }
  makeManifold(s.V, s.F);
  EXPECT_EQ(shape(s), (Shape{ { 2, 0 } })) << "one closed box";
  EXPECT_NEAR(signedVolume(s), 1.0, 1e-12);
}

TEST(CloseTJunctions, LeavesPointsOffTheEdgesAndSurfacesWithoutBoundary)
{
  // the last face's sides pulled 1e-6 inwards: a crack, not a T-junction at 1e-9
  Surface s = boxMeshedFaceByFace({ 4, 6, 5, 3, 8, 7 }, 1e-6);
  const Eigen::MatrixX3i before = s.F;
  TJunctionSplits splits = closeTJunctions(s.V, s.F, 1e-9);
  // the face x = 1 (7 x 7) meets the faces of 4, 6, 5 and 3 squares: those four seams' 6 + 6 +
  // 6 + 6 + 3 + 5 + 4 + 2 T-junctions stay open, the other eight seams' are closed
  EXPECT_EQ(splits.closed, 96 - (4 * 6 + 3 + 5 + 4 + 2)) << "only the other faces' seams";
  Surface sphere = makeIcosphere(1.0, 2);
  const Eigen::MatrixX3i whole = sphere.F;
  splits = closeTJunctions(sphere.V, sphere.F, 1e-3);
  EXPECT_EQ(splits.closed, 0);
  EXPECT_EQ(sphere.F, whole);
  EXPECT_THROW(closeTJunctions(sphere.V, sphere.F, -1.0), std::invalid_argument);
}

namespace
{
/// A unit sphere from two hemispheres meshed apart: `upper` and `lower` points on the equator
/// (lower a multiple of upper: the ends of each upper chord are shared), `rings` rings each.
Surface hemispheresMeshedApart(int upper, int lower, int rings = 8)
{
  std::vector<Eigen::RowVector3d> points;
  std::vector<Eigen::RowVector3i> triangles;
  for (const int side : { 1, -1 })
  {
    const int n = side > 0 ? upper : lower;
    const int base = static_cast<int>(points.size());
    for (int k = 0; k < rings; ++k)
    {
      const double latitude = side * 0.5 * Pi * k / rings;
      for (int i = 0; i < n; ++i)
      {
        const double around = 2.0 * Pi * i / n;
        points.emplace_back(std::cos(latitude) * std::cos(around),
          std::cos(latitude) * std::sin(around), std::sin(latitude));
      }
    }
    points.emplace_back(0.0, 0.0, side);
    const int pole = static_cast<int>(points.size()) - 1;
    const auto add = [&](int a, int b, int c) {
      triangles.push_back(side > 0 ? Eigen::RowVector3i(a, b, c) : Eigen::RowVector3i(a, c, b));
    };
    for (int k = 0; k < rings; ++k)
    {
      for (int i = 0; i < n; ++i)
      {
        const int a = base + k * n + i, b = base + k * n + (i + 1) % n;
        if (k + 1 == rings)
        {
          add(a, b, pole);
          continue;
        }
        add(a, b, b + n);
        add(a, b + n, a + n);
      }
    }
  }
  return welded(points, triangles);
}
}

TEST(CloseTJunctions, ACurvedSeamCutAtTwiceThePointsIsZipped)
{
  // 32 chords above, 64 below: each upper chord has a lower point 0.5% of the diagonal off it
  for (const int factor : { 2, 4 })
  {
    SCOPED_TRACE(std::to_string(factor) + " lower chords per upper one");
    Surface s = hemispheresMeshedApart(32, 32 * factor);
    {
      Surface apart = s;
      makeManifold(apart.V, apart.F);
      EXPECT_EQ(shape(apart), (Shape{ { 1, 1 }, { 1, 1 } })) << "two hemispheres before";
    }
    const TJunctionSplits splits = closeTJunctions(s.V, s.F, 1e-9);
    EXPECT_EQ(splits.closed, 32 * (factor - 1));
    EXPECT_EQ(splits.crackPoints, splits.closed);
    makeManifold(s.V, s.F);
    EXPECT_EQ(shape(s), (Shape{ { 2, 0 } })) << "one closed sphere";
    EXPECT_GT(signedVolume(s), 4.0);
  }
  // a seam whose sides are cut at 6 and 4 chords a quarter (the ends of only every other
  // chord shared) is not a crack along any one edge: left open
  Surface mutual = hemispheresMeshedApart(16, 24);
  EXPECT_EQ(closeTJunctions(mutual.V, mutual.F, 1e-9).closed, 0);
}

TEST(CloseTJunctions, ALensWiderThanACrackStaysOpen)
{
  // a triangle whose edge a-b (length 1) faces a fan bowed away from it through three points,
  // `bow` of the edge's length off it at the middle: a crack at 0.02, a slot at 0.06 (whose path
  // is still less than 2% longer than the edge)
  for (const double bow : { 0.02, 0.06 })
  {
    SCOPED_TRACE("bowed " + std::to_string(bow));
    Surface s;
    s.V.resize(6, 3);
    s.V << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.25, -0.75 * bow, 0, 0.5, -bow, 0, 0.75, -0.75 * bow, 0;
    s.V.conservativeResize(7, 3);
    s.V.row(6) << 0.5, -1, 0;
    s.F.resize(5, 3);
    s.F << 0, 1, 2, 3, 0, 6, 4, 3, 6, 5, 4, 6, 1, 5, 6;
    const TJunctionSplits splits = closeTJunctions(s.V, s.F, 1e-9);
    EXPECT_EQ(splits.closed, bow < CrackWidth ? 3 : 0);
    makeManifold(s.V, s.F); // where the lens stays open its ends are bowties: split
    const Shape expected = bow < CrackWidth ? Shape{ { 1, 1 } } : Shape{ { 1, 1 }, { 1, 1 } };
    EXPECT_EQ(shape(s), expected);
  }
}

TEST(CloseTJunctions, EachTriangleIsSplitAlongItsOwnEdgesOnceAndKeepsFacing)
{
  // a thin triangular hole a, b, p (1.2% of its length wide), each side an edge of a triangle
  // of its own: p is a crack's point along a-b and b one along a-p, and the parts of a-b's
  // triangle have a-p's points' edges (splitting along every edge found split again forever)
  Surface hole;
  hole.V.resize(6, 3);
  hole.V << 0, 0, 0, 1, -0.006, 0, 1, 0.006, 0, 0.5, -1, 0, 2, 0, 0, 0.5, 1, 0;
  hole.F.resize(3, 3);
  hole.F << 0, 1, 3, 1, 2, 4, 2, 0, 5;
  // a needle x, y, z (1e-8 high) and a point p a 4e-9 off both x-y and y-z, the corner of a
  // triangle of its own: it goes into one of the two edges, never a part (y, p, p)
  Surface needle;
  needle.V.resize(6, 3);
  needle.V << 0, 0, 0, 1, 0, 0, 0, 1e-8, 0, 0.5, 4e-9, 0, 0.5, -1, 0, 0.6, -1, 0;
  needle.F.resize(2, 3);
  needle.F << 0, 1, 2, 3, 4, 5;
  for (Surface* s : { &hole, &needle })
  {
    const Eigen::MatrixX3i before = s->F;
    const TJunctionSplits splits = closeTJunctions(s->V, s->F, s == &hole ? 1e-9 : 1e-8);
    EXPECT_EQ(splits.closed, s == &hole ? 2 : 1) << "p into a-b and b into a-p; p into one edge";
    EXPECT_EQ(s->F.rows(), before.rows() + splits.closed);
    for (int f = 0; f < s->F.rows(); ++f)
    {
      const Eigen::RowVector3i t = s->F.row(f);
      EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) << "triangle " << f;
      const Eigen::RowVector3i from = before.row(splits.triangleSource[f]);
      const auto normal = [&](const Eigen::RowVector3i& r) {
        return Eigen::Vector3d(
          (s->V.row(r[1]) - s->V.row(r[0])).cross(s->V.row(r[2]) - s->V.row(r[0])));
      };
      EXPECT_GT(normal(t).dot(normal(from)), 0.0) << "triangle " << f << " turned over";
    }
  }
}

TEST(MakeManifold, ThreePagesOfABookBecomeASheetAndAPage)
{
  Surface s;
  s.V.resize(5, 3);
  s.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, -1;
  s.F.resize(3, 3);
  s.F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  const ManifoldRepair r = makeManifold(s.V, s.F);
  EXPECT_EQ(r.cutEdges, 1);
  EXPECT_EQ(shape(s), (Shape{ { 1, 1 }, { 1, 1 } }));
}

TEST(MakeManifold, OrientsEachComponentTheWayMostOfItFaces)
{
  Surface s = testSurface("sphere");
  const double volume = signedVolume(s);
  for (int f = 0; f < 10; ++f)
  {
    std::swap(s.F(f, 1), s.F(f, 2));
  }
  const ManifoldRepair r = makeManifold(s.V, s.F);
  EXPECT_EQ(r.reversed.size(), 10u) << "the ten, not the rest";
  EXPECT_NEAR(signedVolume(s), volume, 1e-9);
}

TEST(MakeManifold, RefusesAMoebiusStripNamingIt)
{
  // a closed strip of 12 quads with a half turn, next to a good sphere
  Surface s = testSurface("sphere");
  const int base = static_cast<int>(s.V.rows()), n = 12;
  s.V.conservativeResize(base + 2 * n, 3);
  for (int i = 0; i < n; ++i)
  {
    const double t = 2 * 3.14159265358979323846 * i / n, half = t / 2;
    for (int j = 0; j < 2; ++j)
    {
      const double w = j == 0 ? -0.3 : 0.3;
      s.V.row(base + 2 * i + j) << (3 + w * std::cos(half)) * std::cos(t),
        (3 + w * std::cos(half)) * std::sin(t), w * std::sin(half);
    }
  }
  const int f0 = static_cast<int>(s.F.rows());
  s.F.conservativeResize(f0 + 2 * n, 3);
  for (int i = 0; i < n; ++i)
  {
    const int a = base + 2 * i, b = a + 1;
    // the last quad closes the strip onto its start the other way round
    const int c = i + 1 < n ? a + 2 : base + 1, d = i + 1 < n ? b + 2 : base;
    s.F.row(f0 + 2 * i) << a, c, b;
    s.F.row(f0 + 2 * i + 1) << b, c, d;
  }
  try
  {
    makeManifold(s.V, s.F);
    FAIL() << "a Moebius strip was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("component 2 of 2 is not orientable"), std::string::npos)
      << e.what();
  }
}

TEST(RedundantTriangles, RepeatsAndComponentsWithoutAreaGo)
{
  Surface s = testSurface("sphere");
  const int nf = static_cast<int>(s.F.rows()), nv = static_cast<int>(s.V.rows());
  s.F.conservativeResize(nf + 3, 3);
  s.F.row(nf) = s.F.row(5);                           // a repeat
  s.F.row(nf + 1) << s.F(7, 0), s.F(7, 2), s.F(7, 1); // a repeat the other way round
  s.V.conservativeResize(nv + 3, 3);
  s.V.row(nv) << 5, 0, 0;
  s.V.row(nv + 1) << 6, 0, 0;
  s.V.row(nv + 2) << 7, 0, 0;
  s.F.row(nf + 2) << nv, nv + 1, nv + 2; // a collinear triangle on its own
  const std::vector<char> remove = redundantTriangles(s.V, s.F);
  std::vector<int> removed;
  for (int f = 0; f < static_cast<int>(remove.size()); ++f)
  {
    if (remove[f])
    {
      removed.push_back(f);
    }
  }
  EXPECT_EQ(removed, (std::vector<int>{ nf, nf + 1, nf + 2 }));
}

namespace
{
/// mergeCoincidentPoints' rule by brute force: corners in order, each new point merged into the
/// first merged point within the tolerance.
MergedPoints mergeByBruteForce(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, double tol)
{
  MergedPoints m;
  m.pointOf.assign(V.rows(), -1);
  for (Eigen::Index c = 0; c < F.size(); ++c)
  {
    const int p = F(c / 3, c % 3);
    if (m.pointOf[p] >= 0)
    {
      continue;
    }
    for (int q = 0; q < static_cast<int>(m.source.size()) && m.pointOf[p] < 0; ++q)
    {
      if ((V.row(m.source[q]) - V.row(p)).squaredNorm() <= tol * tol)
      {
        m.pointOf[p] = q;
      }
    }
    if (m.pointOf[p] < 0)
    {
      m.pointOf[p] = static_cast<int>(m.source.size());
      m.source.push_back(p);
    }
  }
  return m;
}
}

TEST(MergeCoincidentPoints, MergesWithinTheToleranceAsTheRuleSaysAcrossCellSides)
{
  // A sphere as a soup (each triangle its own three points), moved far from the origin, every
  // copy but the first displaced by 0.3, 0.9, 1.1 or 3 tolerances, some along an axis through
  // the side of a hash cell (1024 tolerances wide), plus points no triangle uses.
  const Surface sphere = testSurface("sphere");
  const double tol = 1e-9;
  const int nf = static_cast<int>(sphere.F.rows());
  Eigen::MatrixX3d V(3 * nf + 2, 3);
  Eigen::MatrixX3i F(nf, 3);
  std::vector<int> copies(sphere.V.rows(), 0);
  const double steps[] = { 0.0, 0.3, 0.9, 1.1, 3.0 };
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int p = sphere.F(f, k);
      const int n = copies[p]++;
      Eigen::RowVector3d x = sphere.V.row(p) + Eigen::RowVector3d(1e3, -2e3, 0.5);
      // every 7th point on a cell side: its copies straddle it
      if (p % 7 == 0)
      {
        x[0] = std::floor(x[0] / (1024 * tol)) * 1024 * tol;
      }
      x[n % 3] += steps[n % 5] * tol;
      V.row(3 * f + k) = x;
      F(f, k) = 3 * f + k;
    }
  }
  V.row(3 * nf) << 0, 0, 0;
  V.row(3 * nf + 1) = V.row(0);
  const MergedPoints fast = mergeCoincidentPoints(V, F, tol);
  const MergedPoints slow = mergeByBruteForce(V, F, tol);
  EXPECT_EQ(fast.pointOf, slow.pointOf);
  EXPECT_EQ(fast.source, slow.source);
  EXPECT_EQ(fast.pointOf[3 * nf], -1);
  EXPECT_EQ(fast.pointOf[3 * nf + 1], -1);
  // merged: fewer than the corners, more than the sphere's points (copies 3 and 4 stay apart)
  EXPECT_GT(static_cast<int>(fast.source.size()), sphere.V.rows());
  EXPECT_LT(static_cast<int>(fast.source.size()), 3 * nf);
  // tolerance 0: equal points only
  Eigen::MatrixX3d W(4, 3);
  W << 0, 0, 0, 1, 0, 0, 0, 0, 0, 1e-100, 0, 0;
  Eigen::MatrixX3i G(2, 3);
  G << 0, 1, 2, 3, 1, 0;
  const MergedPoints exact = mergeCoincidentPoints(W, G, 0.0);
  EXPECT_EQ(exact.pointOf, (std::vector<int>{ 0, 1, 0, 2 }));
  EXPECT_EQ(exact.source, (std::vector<int>{ 0, 1, 3 }));
  EXPECT_THROW(mergeCoincidentPoints(W, G, -1.0), std::invalid_argument);
  G(1, 0) = 4;
  EXPECT_THROW(mergeCoincidentPoints(W, G, 0.0), std::invalid_argument);
}

TEST(RefineCoarseComponents, SplitsOnlyTheCoarseComponentsKeepingTheSurface)
{
  // a 12-triangle box beside a sphere of 5,120 triangles
  Surface s = testSurface("sphere");
  const int sphereFaces = static_cast<int>(s.F.rows());
  appendBox(s, 3.0, 0.0, 0.0);
  const Surface before = s;
  const MeshTopology topoBefore = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const Refinement r = refineCoarseComponents(s.V, s.F, 256);
  EXPECT_EQ(r.refinedTriangles, 12);
  EXPECT_EQ(s.F.rows(), sphereFaces + 12 * 64) << "the box split three times: 768 >= 256";
  ASSERT_EQ(static_cast<Eigen::Index>(r.parent.size()), s.F.rows());
  EXPECT_EQ(s.V.topRows(before.V.rows()), before.V) << "the points stay where they were";
  ASSERT_EQ(static_cast<Eigen::Index>(r.midpoints.size()), s.V.rows() - before.V.rows());
  for (std::size_t i = 0; i < r.midpoints.size(); ++i)
  {
    const Eigen::Index p = before.V.rows() + static_cast<Eigen::Index>(i);
    EXPECT_EQ(s.V.row(p), 0.5 * (s.V.row(r.midpoints[i][0]) + s.V.row(r.midpoints[i][1])));
  }
  // each input triangle's parts cover it exactly, facing the same way
  std::vector<Eigen::Vector3d> area(before.F.rows(), Eigen::Vector3d::Zero());
  for (Eigen::Index t = 0; t < s.F.rows(); ++t)
  {
    const Eigen::Vector3d a = s.V.row(s.F(t, 0)), b = s.V.row(s.F(t, 1)), c = s.V.row(s.F(t, 2));
    area[r.parent[t]] += 0.5 * (b - a).cross(c - a);
  }
  for (Eigen::Index t = 0; t < before.F.rows(); ++t)
  {
    const Eigen::Vector3d a = before.V.row(before.F(t, 0)), b = before.V.row(before.F(t, 1)),
                          c = before.V.row(before.F(t, 2));
    EXPECT_LT((area[t] - 0.5 * (b - a).cross(c - a)).norm(), 1e-12) << "triangle " << t;
  }
  // the sphere's triangles are the same ones, in order
  EXPECT_EQ(s.F.topRows(sphereFaces), before.F.topRows(sphereFaces));
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  EXPECT_TRUE(topo.isManifold());
  EXPECT_TRUE(topo.isOriented());
  EXPECT_EQ(topo.numComponents(), 2);
  EXPECT_EQ(topo.eulerCharacteristic(), topoBefore.eulerCharacteristic());
  EXPECT_TRUE(topo.boundaryLoops.empty());
}

TEST(RefineCoarseComponents, LeavesASurfaceWithEnoughTrianglesAsItIs)
{
  Surface s = testSurface("sphere");
  const Surface before = s;
  for (const int minimum : { 0, 256, static_cast<int>(s.F.rows()) })
  {
    const Refinement r = refineCoarseComponents(s.V, s.F, minimum);
    EXPECT_EQ(r.refinedTriangles, 0);
    EXPECT_TRUE(r.midpoints.empty());
    EXPECT_EQ(s.V, before.V);
    EXPECT_EQ(s.F, before.F);
  }
}

namespace
{
/// A flat regular n-gon of radius 1 as a fan from its first corner: n - 2 triangles, most of them
/// long slivers (a CAD export's flat face).
Surface slivers(int n)
{
  Surface s;
  s.V.resize(n, 3);
  for (int i = 0; i < n; ++i)
  {
    s.V.row(i) << std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0.0;
  }
  s.F.resize(n - 2, 3);
  for (int i = 0; i < n - 2; ++i)
  {
    s.F.row(i) << 0, i + 1, i + 2;
  }
  return s;
}

double smallestAngle(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  double smallest = M_PI;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d a = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      const Eigen::Vector3d b = V.row(F(f, (k + 2) % 3)) - V.row(F(f, k));
      smallest = std::min(smallest, std::atan2(a.cross(b).norm(), a.dot(b)));
    }
  }
  return smallest;
}

double longestEdge(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  double longest = 0.0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      longest = std::max(longest, (V.row(F(f, k)) - V.row(F(f, (k + 1) % 3))).norm());
    }
  }
  return longest;
}
}

TEST(RefineLongEdges, SplitsSliversIntoShorterBetterShapedTrianglesKeepingTheSurface)
{
  Surface s = slivers(40);
  appendBox(s, 3.0, 0.0, 0.0);
  const MeshTopology topoBefore = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const double before = smallestAngle(s.V, s.F);
  const EdgeRefinement r = refineLongEdges(s.V, s.F, 0.3, 1000000);
  EXPECT_EQ(r.refinedTriangles, static_cast<int>(s.F.rows())) << "every triangle has a long edge";
  EXPECT_LE(longestEdge(r.V, r.F), 0.3);
  // longest-edge bisection: angles stay bounded (Rivara: at least half the smallest given one)
  EXPECT_GE(smallestAngle(r.V, r.F), 0.5 * before - 1e-12);
  EXPECT_EQ(r.V.topRows(s.V.rows()), s.V) << "the points stay where they were";
  ASSERT_EQ(static_cast<Eigen::Index>(r.midpoints.size()), r.V.rows() - s.V.rows());
  for (std::size_t i = 0; i < r.midpoints.size(); ++i)
  {
    const Eigen::Index p = s.V.rows() + static_cast<Eigen::Index>(i);
    EXPECT_EQ(r.V.row(p), 0.5 * (r.V.row(r.midpoints[i][0]) + r.V.row(r.midpoints[i][1])));
  }
  // each input triangle's parts cover it exactly, facing the same way, and each part's edge
  // said to lie along its parent's edge e does
  ASSERT_EQ(static_cast<Eigen::Index>(r.parent.size()), r.F.rows());
  std::vector<Eigen::Vector3d> area(s.F.rows(), Eigen::Vector3d::Zero());
  for (Eigen::Index t = 0; t < r.F.rows(); ++t)
  {
    const int p = r.parent[t];
    const Eigen::Vector3d a = r.V.row(r.F(t, 0)), b = r.V.row(r.F(t, 1)), c = r.V.row(r.F(t, 2));
    area[p] += 0.5 * (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k)
    {
      const int e = r.parentEdge(t, k);
      if (e < 0)
        continue;
      const Eigen::Vector3d p0 = s.V.row(s.F(p, e)), p1 = s.V.row(s.F(p, (e + 1) % 3));
      const Eigen::Vector3d q0 = r.V.row(r.F(t, k)), q1 = r.V.row(r.F(t, (k + 1) % 3));
      EXPECT_LT((q0 - p0).cross(p1 - p0).norm(), 1e-12) << "part " << t << " edge " << k;
      EXPECT_LT((q1 - p0).cross(p1 - p0).norm(), 1e-12) << "part " << t << " edge " << k;
      EXPECT_GT((q1 - q0).dot(p1 - p0), 0.0) << "the same direction";
    }
  }
  for (Eigen::Index t = 0; t < s.F.rows(); ++t)
  {
    const Eigen::Vector3d a = s.V.row(s.F(t, 0)), b = s.V.row(s.F(t, 1)), c = s.V.row(s.F(t, 2));
    EXPECT_LT((area[t] - 0.5 * (b - a).cross(c - a)).norm(), 1e-12) << "triangle " << t;
  }
  const MeshTopology topo = buildTopology(r.F, static_cast<int>(r.V.rows()));
  EXPECT_TRUE(topo.isManifold()) << "conforming: no T-junctions";
  EXPECT_TRUE(topo.isOriented());
  EXPECT_EQ(topo.numComponents(), 2);
  EXPECT_EQ(topo.eulerCharacteristic(), topoBefore.eulerCharacteristic());
  EXPECT_EQ(topo.boundaryLoops.size(), topoBefore.boundaryLoops.size());
}

TEST(RefineLongEdges, LeavesShortEdgesAndStopsBeforeTheTriangleLimit)
{
  const Surface s = testSurface("sphere");
  const double longest = longestEdge(s.V, s.F);
  for (const double most : { 0.0, -1.0, longest, 2 * longest })
  {
    const EdgeRefinement r = refineLongEdges(s.V, s.F, most, 1000000);
    EXPECT_EQ(r.refinedTriangles, 0) << most;
    EXPECT_EQ(r.V, s.V);
    EXPECT_EQ(r.F, s.F);
    for (Eigen::Index t = 0; t < r.parentEdge.rows(); ++t)
    {
      ASSERT_EQ(r.parentEdge.row(t), Eigen::RowVector3i(0, 1, 2));
    }
  }
  const int limit = 3 * static_cast<int>(s.F.rows());
  const EdgeRefinement r = refineLongEdges(s.V, s.F, 1e-6 * longest, limit);
  EXPECT_LE(r.F.rows(), limit) << "a round that could pass the limit is not started";
  EXPECT_EQ(r.F.rows(), s.F.rows()) << "every round may quadruple: none fits under 3 times";
}

TEST(RefineLongEdges, CarriedMatchingsKeepEverySingularityAndAddNone)
{
  const Surface s = testSurface("sphere");
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const FrameGeometry geometry = computeFrameGeometry(s.V, s.F, topo);
  // a field with singularities: the direction of z projected onto each triangle (and x where
  // that vanishes)
  Eigen::MatrixX3d frameU(s.F.rows(), 3);
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
  {
    const Eigen::Vector3d n = geometry.bases.normal.row(f);
    Eigen::Vector3d d = Eigen::Vector3d::UnitZ() - n.dot(Eigen::Vector3d::UnitZ()) * n;
    if (d.norm() < 1e-3)
      d = Eigen::Vector3d::UnitX() - n.dot(Eigen::Vector3d::UnitX()) * n;
    frameU.row(f) = d.normalized();
  }
  const FrameTopology given = computeMatchings(s.F, topo, geometry, frameU);
  ASSERT_GT(given.singularities, 0);
  const EdgeRefinement r = refineLongEdges(s.V, s.F, 0.5 * longestEdge(s.V, s.F), 1000000);
  ASSERT_GT(r.refinedTriangles, 0);
  Eigen::MatrixX3d carried(r.F.rows(), 3);
  for (Eigen::Index t = 0; t < r.F.rows(); ++t)
  {
    carried.row(t) = frameU.row(r.parent[t]);
  }
  const MeshTopology refinedTopo = buildTopology(r.F, static_cast<int>(r.V.rows()));
  const Eigen::MatrixX3i matching = refinedMatching(r, given.matching);
  EXPECT_EQ(checkMatching(refinedTopo, matching), "");
  const FrameTopology refined = evaluateMatchings(
    r.F, refinedTopo, computeFrameGeometry(r.V, r.F, refinedTopo), carried, matching);
  EXPECT_EQ(refined.singularities, given.singularities);
  for (Eigen::Index v = 0; v < r.V.rows(); ++v)
  {
    const int shift = v < s.V.rows() ? given.layerShift[v] : 0;
    EXPECT_EQ(refined.layerShift[v], shift) << "point " << v;
    const double index = v < s.V.rows() ? given.index[v] : 0.0;
    EXPECT_NEAR(refined.index[v], index, 1e-9) << "point " << v;
  }
}
