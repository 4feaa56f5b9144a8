// Strips of the surface narrower than a grid edge between two boundary lines, and walls between two
// creases: the local grid size asked around them (thinStripGridScale), and the map that keeps them,
// so that the quads keep the holes apart and do not fold over a thin plate's rim.
#include "FrameField.h"
#include "QuadExtraction.h"
#include "QuadFacing.h"
#include "QuadMeshing.h"
#include "QuadQuality.h"
#include "TestChain.h"
#include "ThinStrips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using namespace quadcover;

namespace
{
/// The unit square in n x n cells of two triangles each, without the cells of the given rows in
/// columns [c0, c1): a flat plate with slots one cell wide.
Surface makeSlottedPlate(int n, const std::vector<int>& rows, int c0, int c1)
{
  Surface s;
  s.name = "slotted plate";
  s.V.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      s.V.row(j * (n + 1) + i) << static_cast<double>(i) / n, static_cast<double>(j) / n, 0.0;
    }
  }
  std::vector<Eigen::Vector3i> F;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      if (std::count(rows.begin(), rows.end(), j) > 0 && i >= c0 && i < c1)
      {
        continue;
      }
      const int a = j * (n + 1) + i;
      F.emplace_back(a, a + 1, a + n + 2);
      F.emplace_back(a, a + n + 2, a + n + 1);
    }
  }
  s.F.resize(static_cast<Eigen::Index>(F.size()), 3);
  for (std::size_t f = 0; f < F.size(); ++f)
  {
    s.F.row(static_cast<Eigen::Index>(f)) = F[f].transpose();
  }
  return s;
}
}

TEST(ThinStrips, TheRoundingKeepsAThinStripAtLeastACellWide)
{
  // The strip between the slots is 0.4 grid cells wide, its sides 6 and 6.4 cells from the
  // plate's edge: rounded each to its nearest integer, both went to one grid line and the map
  // flattened the strip onto it (on the truck's body, the strips between the slots of a grille:
  // their quads ran the slots into one hole). The rounding keeps facing boundary lines apart: the
  // strip is at least a cell wide. (The grid is kept uniform, to test the rounding alone.)
  ParameterizationOptions options;
  options.targetEdgeLength = 1.0 / 16; // 40 mesh cells: 2.5 per grid cell
  options.maximumThinStripRefinement = 1.0;
  const int n = 40, row = 15, c0 = 10, c1 = 30;
  const Chain c = runChain(makeSlottedPlate(n, { row - 1, row + 1 }, c0, c1), 0, options);
  ASSERT_EQ(c.topo.boundaryLoops.size(), 3u);
  EXPECT_GT(c.map.separatedBoundaryLines, 0) << "the strip's sides should have met on one line";
  double stripCells = 0.0; // the (u, v) area of the strip's triangles
  for (int f = 0; f < c.s.F.rows(); ++f)
  {
    const Eigen::Vector3d centre =
      (c.s.V.row(c.s.F(f, 0)) + c.s.V.row(c.s.F(f, 1)) + c.s.V.row(c.s.F(f, 2))) / 3.0;
    if (centre.y() > static_cast<double>(row) / n && centre.y() < (row + 1.0) / n &&
      centre.x() > static_cast<double>(c0) / n && centre.x() < static_cast<double>(c1) / n)
    {
      const auto t = c.map.cornerUV.row(f);
      stripCells += 0.5 * ((t[2] - t[0]) * (t[5] - t[1]) - (t[3] - t[1]) * (t[4] - t[0]));
    }
  }
  const double stripLength = (c1 - c0) / (n * options.targetEdgeLength); // in grid cells
  EXPECT_GT(stripCells, 0.9 * stripLength) << "at least one cell wide along its length";
  const QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
  const QuadQuality m = measureQuads(q.V, q.Q);
  EXPECT_EQ(m.quads, m.faces);
  EXPECT_EQ(m.nonManifoldEdges, 0);
  EXPECT_EQ(m.boundaryLoops, 3) << "two slots, two holes";
  EXPECT_EQ(m.eulerCharacteristic, -1);
}

namespace
{
/// The triangles' centres.
Eigen::MatrixX3d centres(const Surface& s)
{
  Eigen::MatrixX3d c(s.F.rows(), 3);
  for (int f = 0; f < s.F.rows(); ++f)
  {
    c.row(f) = (s.V.row(s.F(f, 0)) + s.V.row(s.F(f, 1)) + s.V.row(s.F(f, 2))) / 3.0;
  }
  return c;
}
}

TEST(ThinStrips, TheGridIsAsFineAsTheStripIsWide)
{
  // two slots in rows 39 and 41 of an 80 x 80 plate: the strip between them (row 40) is 1/80
  // wide, a fifth of a grid edge of 1/16
  const int n = 80;
  const Surface s = makeSlottedPlate(n, { 39, 41 }, 20, 60);
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const double h = 1.0 / 16;
  const Eigen::VectorXd scale = thinStripGridScale(s.V, s.F, topo, h, 8.0);
  ASSERT_EQ(scale.size(), s.F.rows());
  const Eigen::MatrixX3d c = centres(s);
  for (int f = 0; f < s.F.rows(); ++f)
  {
    ASSERT_GE(scale[f], 1.0 / 8 - 1e-12);
    ASSERT_LE(scale[f], 1.0 + 1e-12);
    const bool inStrip = c(f, 1) > 40.0 / n && c(f, 1) < 41.0 / n && c(f, 0) > 0.3 && c(f, 0) < 0.7;
    if (inStrip)
    {
      EXPECT_NEAR(scale[f], (1.0 / n) / h, 1e-9) << "the strip's own width";
    }
    // the size grows by a quarter of the distance walked: 0.1 to 0.1125 past the strip's end
    // (x = 0.75), along its row, (1/80 + (0.1 ... 0.1125) / 4) / h
    if (c(f, 1) > 40.0 / n && c(f, 1) < 41.0 / n && c(f, 0) > 0.85 && c(f, 0) < 0.8625)
    {
      EXPECT_GT(scale[f], 0.59);
      EXPECT_LT(scale[f], 0.66);
    }
    if (c(f, 1) < 0.1 || c(f, 1) > 0.9)
    {
      EXPECT_EQ(scale[f], 1.0) << "far from the strip the grid is uniform";
    }
  }
  // at most 4 times finer: the strip asks for a quarter of h
  const Eigen::VectorXd capped = thinStripGridScale(s.V, s.F, topo, h, 4.0);
  EXPECT_NEAR(capped.minCoeff(), 0.25, 1e-9);
  EXPECT_EQ(thinStripGridScale(s.V, s.F, topo, h, 1.0).size(), 0) << "1: uniform";
  EXPECT_EQ(thinStripGridScale(s.V, s.F, topo, 0.5 / n, 8.0).size(), 0)
    << "a strip wider than the grid edge needs nothing";
}

TEST(ThinStrips, ASlotIsNoStrip)
{
  // one slot a fifth of a grid edge wide (the plate's edge 8 grid edges from it across and 4
  // along): the slot's sides face each other across the hole, not across the surface
  const int n = 80;
  const Surface s = makeSlottedPlate(n, { 40 }, 20, 60);
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  EXPECT_EQ(thinStripGridScale(s.V, s.F, topo, 1.0 / 16, 8.0).size(), 0);
  // the plate's corners: boundary edges at right angles are no strip either
  const Surface plain = makeSlottedPlate(n, {}, 0, 0);
  const MeshTopology plainTopo = buildTopology(plain.F, static_cast<int>(plain.V.rows()));
  EXPECT_EQ(thinStripGridScale(plain.V, plain.F, plainTopo, 1.0 / 16, 8.0).size(), 0);
}

TEST(ThinStrips, ANeckThinnerThanTheGridAsksForThreeGridEdgesAroundIt)
{
  // A dumbbell of bulbs of radius 0.5 joined by a neck of radius 0.03 (girth 0.19), on a grid of
  // edge 0.2: the triangles within 2 grid edges of a point on the neck wrap around it, and the
  // point asks for a grid edge of about a third of its girth. A point at a pole, where every
  // ball that near is a disk, asks for nothing.
  const int nAround = 32, nAlong = 100;
  const double neck = 0.03, h = 0.2;
  const Surface s = makeDumbbell(1.0, 0.5, neck, nAround, nAlong);
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const Eigen::MatrixX3d length = computeFrameGeometry(s.V, s.F, topo).edgeLength; // as the map
  const int pole = (nAlong - 1) * nAround;           // the south pole (after the rings)
  const int onNeck = (nAlong / 2 - 1) * nAround + 5; // a point of the middle ring
  ASSERT_NEAR(s.V(onNeck, 2), 0.0, 1e-12);
  EXPECT_EQ(shortLoopGridScale(s.V, s.F, topo, length, { pole }, h, 8.0).size(), 0);
  const Eigen::VectorXd scale = shortLoopGridScale(s.V, s.F, topo, length, { onNeck }, h, 8.0);
  ASSERT_EQ(scale.size(), s.F.rows());
  const double girth = 2 * 3.14159265358979 * neck;
  const double finest = scale.minCoeff() * h;
  std::printf("finest grid edge %.3f of the neck's girth\n", finest / girth);
  EXPECT_GT(finest, 0.25 * girth) << "about three grid edges around the neck";
  EXPECT_LT(finest, 0.45 * girth);
  EXPECT_GE(scale.minCoeff(), 1.0 / 8.0 - 1e-12);
  for (int f = 0; f < s.F.rows(); ++f)
  {
    if (std::abs(s.V(s.F(f, 0), 2)) > 0.9)
    {
      EXPECT_DOUBLE_EQ(scale[f], 1.0) << "near the poles the grid stays uniform";
    }
  }
  EXPECT_EQ(shortLoopGridScale(s.V, s.F, topo, length, { onNeck }, h, 1.0).size(), 0)
    << "no refinement allowed";
}

TEST(ThinStrips, TheMapWidensAStripNarrowerThanACell)
{
  // The strip between two slots is a fifth of a grid edge wide. On a uniform grid the continuous
  // map keeps it a fifth of a cell wide, and the rounding alone has to stretch it to a cell (on
  // the truck's body, the bars between the slots of its vents: the map folded there and their
  // quads joined the slots). With the grid made finer around it, the map itself gives the strip
  // about a cell.
  const int n = 80, row = 40, c0 = 20, c1 = 60;
  const Surface plate = makeSlottedPlate(n, { row - 1, row + 1 }, c0, c1);
  std::map<double, double> width; // refinement -> the strip's mean (u, v) width, in cells
  for (const double refinement : { 8.0, 1.0 })
  {
    ParameterizationOptions options;
    options.targetEdgeLength = 1.0 / 16;
    options.maximumThinStripRefinement = refinement;
    options.roundingMode = RoundingMode::None; // the continuous map
    const Chain c = runChain(plate, 0, options);
    EXPECT_EQ(c.map.finerGridTriangles > 0, refinement > 1);
    const Eigen::MatrixX3d centre = centres(c.s);
    double cells = 0.0;
    for (int f = 0; f < c.s.F.rows(); ++f)
    {
      if (centre(f, 1) > static_cast<double>(row) / n && centre(f, 1) < (row + 1.0) / n &&
        centre(f, 0) > static_cast<double>(c0) / n && centre(f, 0) < static_cast<double>(c1) / n)
      {
        const auto t = c.map.cornerUV.row(f);
        cells += 0.5 * std::abs((t[2] - t[0]) * (t[5] - t[1]) - (t[3] - t[1]) * (t[4] - t[0]));
      }
    }
    // the strip's length in cells: on the finer grid the strip's cells are a fifth as long
    const double stripScale = refinement > 1 ? (1.0 / n) / options.targetEdgeLength : 1.0;
    width[refinement] = cells / ((c1 - c0) / (n * options.targetEdgeLength) / stripScale);
  }
  EXPECT_LT(width[1.0], 0.3) << "a uniform grid: about the strip's own fifth of a cell";
  EXPECT_GT(width[8.0], 0.7) << "a finer grid around the strip: about a cell";
}

namespace
{
/// A profile in the (x, z) plane, each of its segments cut into pieces of about `edge`, swept
/// along y over [0, 1] in steps of `edge`: an open sheet of two triangles per cell.
Surface sweptProfile(const std::vector<Eigen::Vector2d>& profile, double edge)
{
  std::vector<Eigen::Vector2d> points{ profile.front() };
  for (std::size_t i = 1; i < profile.size(); ++i)
  {
    const Eigen::Vector2d d = profile[i] - profile[i - 1];
    const int steps = std::max(1, static_cast<int>(std::lround(d.norm() / edge)));
    for (int k = 1; k <= steps; ++k)
    {
      points.push_back(profile[i - 1] + d * static_cast<double>(k) / steps);
    }
  }
  const int m = static_cast<int>(points.size());
  const int n = std::max(1, static_cast<int>(std::lround(1.0 / edge)));
  Surface s;
  s.name = "swept profile";
  s.V.resize(m * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i < m; ++i)
    {
      s.V.row(j * m + i) << points[i].x(), static_cast<double>(j) / n, points[i].y();
    }
  }
  s.F.resize(2 * (m - 1) * n, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i + 1 < m; ++i)
    {
      const int a = j * m + i;
      s.F.row(f++) << a, a + 1, a + m + 1;
      s.F.row(f++) << a, a + m + 1, a + m;
    }
  }
  return s;
}

std::vector<char> creasesOf(const Surface& s, const MeshTopology& topo)
{
  return sharpEdges(topo, computeFaceBases(s.V, s.F, topo), 60.0, 3);
}
}

TEST(ThinStrips, AWallBetweenTwoCreasesIsAStripAndAStepIsNot)
{
  // A sheet folded back on itself: a wall 0.02 high between two right-angle creases, a fifth of
  // a grid edge of 0.1, its two sheets facing apart (the rim of a thin plate). Across a step of
  // the same height between two sheets facing the same way the quads can pass: no strip.
  const double t = 0.02, h = 0.1;
  const Surface fold = sweptProfile({ { 1, 0 }, { 0, 0 }, { 0, t }, { 1, t } }, t);
  const MeshTopology foldTopo = buildTopology(fold.F, static_cast<int>(fold.V.rows()));
  const std::vector<char> foldCreases = creasesOf(fold, foldTopo);
  ASSERT_EQ(std::count(foldCreases.begin(), foldCreases.end(), 1), 2 * 50) << "two creases";
  const Eigen::VectorXd scale = thinStripGridScale(fold.V, fold.F, foldTopo, h, 8.0, foldCreases);
  ASSERT_EQ(scale.size(), fold.F.rows());
  const Eigen::MatrixX3d c = centres(fold);
  for (int f = 0; f < fold.F.rows(); ++f)
  {
    if (std::abs(c(f, 0)) < 1e-12)
    {
      EXPECT_NEAR(scale[f], t / h, 1e-9) << "the wall's own height";
    }
    if (c(f, 0) > 0.5)
    {
      EXPECT_EQ(scale[f], 1.0) << "far from the wall the grid is uniform";
    }
  }
  EXPECT_EQ(thinStripGridScale(fold.V, fold.F, foldTopo, h, 8.0).size(), 0)
    << "without the creases no strip";
  EXPECT_EQ(thinStripGridScale(fold.V, fold.F, foldTopo, t / 2, 8.0, foldCreases).size(), 0)
    << "a wall higher than a grid edge needs nothing";
  const Surface step = sweptProfile({ { -1, 0 }, { 0, 0 }, { 0, t }, { 1, t } }, t);
  const MeshTopology stepTopo = buildTopology(step.F, static_cast<int>(step.V.rows()));
  const std::vector<char> stepCreases = creasesOf(step, stepTopo);
  ASSERT_EQ(std::count(stepCreases.begin(), stepCreases.end(), 1), 2 * 50) << "two creases";
  EXPECT_EQ(thinStripGridScale(step.V, step.F, stepTopo, h, 8.0, stepCreases).size(), 0);
}

TEST(ThinStrips, AThinPlateKeepsItsRimAndCorners)
{
  // A plate 1 x 1 x 0.02 at a grid edge of 1/12: its rim is a quarter of a grid edge high. On a
  // uniform grid the rim's quads fold over it, and the corners are cut off; with the grid finer
  // around the rim the quads keep it, and no quad faces against the plate.
  const Surface plate = makeThinPlate(1.0, 1.0, 0.02, 0.02);
  std::map<double, double> corner; // refinement -> the farthest plate corner from the quads
  std::map<double, int> turned;
  for (const double refinement : { 8.0, 1.0 })
  {
    ParameterizationOptions options;
    options.targetEdgeLength = 1.0 / 12;
    options.maximumThinStripRefinement = refinement;
    const Chain c = runChain(plate, 0, options);
    EXPECT_EQ(c.map.finerGridTriangles > 0, refinement > 1);
    const QuadMeshResult r = buildQuadMesh(c.s.V, c.s.F, c.topo, c.map.cornerUV);
    turned[refinement] = static_cast<int>(turnedQuads(c.s.V, c.s.F, r.mesh).size());
    Eigen::MatrixX3d corners(8, 3);
    for (int i = 0; i < 8; ++i)
    {
      corners.row(i) << (i & 1), (i >> 1) & 1, 0.02 * ((i >> 2) & 1);
    }
    corner[refinement] = largestDistance(corners, r.mesh.V, quadTriangles(r.mesh.Q));
    std::printf("[ refinement %g ] %lld quads, %d turned, farthest corner %.4f\n", refinement,
      static_cast<long long>(r.mesh.Q.rows()), turned[refinement], corner[refinement]);
  }
  EXPECT_GT(turned[1.0], 0) << "on a uniform grid the rim's quads fold over it";
  EXPECT_EQ(turned[8.0], 0);
  EXPECT_LT(corner[8.0], 0.25 / 12) << "the corners kept, within a quarter of a grid edge";
  EXPECT_GT(corner[1.0], 3 * corner[8.0]) << "a uniform grid cuts them";
}
