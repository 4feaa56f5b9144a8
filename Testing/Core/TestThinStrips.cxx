// Strips of the surface narrower than a grid edge between two boundary lines: the local grid size
// asked around them (thinStripGridScale), and the map that keeps them, so that the quads keep the
// holes apart.
#include "QuadExtraction.h"
#include "QuadQuality.h"
#include "TestChain.h"
#include "ThinStrips.h"

#include <gtest/gtest.h>

#include <algorithm>
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
