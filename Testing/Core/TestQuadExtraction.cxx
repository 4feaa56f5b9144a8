// The quad mesh of an integer-grid map: closed inputs give closed, manifold, oriented quad
// meshes with the input's Euler characteristic; irregular vertices are exactly the branch points
// with the valence their index predicts; boundaries keep their loops; a folded map still gives a
// valid mesh.
#include "GridMapChecks.h"
#include "QuadExtraction.h"
#include "TestChain.h"
#include "TestSurfaces.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace quadcover;

namespace
{
/// Every inner branch point must be a quad vertex of valence 4 - 4 * index; every other inner
/// quad vertex has valence 4. Returns the branch points found among the quad vertices.
int expectValencesFromIndices(const Chain& c, const QuadMesh& q, const QuadQuality& m)
{
  int found = 0;
  for (int v = 0; v < q.V.rows(); ++v)
  {
    const int p = q.vertexPoint[v];
    if (p >= 0 && !c.topo.boundaryVertex[p] && c.field.layerShift[p] != 0)
    {
      ++found;
      EXPECT_EQ(m.valence[v], static_cast<int>(std::lround(4 - 4 * c.field.index[p]))) << p;
    }
  }
  return found;
}

void expectClosedQuadMesh(const Chain& c, const QuadMesh& q, const std::string& name)
{
  SCOPED_TRACE(name);
  const QuadQuality m = measureQuads(q.V, q.Q);
  EXPECT_GT(m.faces, 0);
  EXPECT_EQ(m.quads, m.faces) << "all quads";
  EXPECT_EQ(m.nonManifoldEdges, 0);
  EXPECT_EQ(m.boundaryEdges, 0) << "closed";
  EXPECT_EQ(m.eulerCharacteristic, c.topo.eulerCharacteristic());
  EXPECT_EQ(m.components, c.topo.numComponents());
  EXPECT_EQ(q.cellsOffSurface + q.cellsDegenerate + q.cellsConflicting, 0);
  EXPECT_EQ(expectValencesFromIndices(c, q, m), c.map.branchPoints);
  EXPECT_EQ(m.irregularInner, c.map.branchPoints) << "irregular vertices are the branch points";
  EXPECT_GT(m.minScaledJacobian, 0.0) << "no inverted quad";
  std::printf("[ %s ] %d quads, %d vertices, %d irregular, edge RSD %.1f%%, angle RSD %.1f%%, "
              "scaled Jacobian min %.2f mean %.2f\n",
    name.c_str(), m.faces, m.vertices, m.irregularInner, 100 * m.edgeLengthRSD, 100 * m.angleRSD,
    m.minScaledJacobian, m.meanScaledJacobian);
}
}

TEST(QuadExtraction, ClosedSurfacesGiveClosedManifoldQuadMeshes)
{
  for (const char* name : { "sphere", "torus", "knot", "roundedcube" })
  {
    const Chain c = runChain(testSurface(name), 1500);
    ASSERT_EQ(c.map.flipped, 0) << name;
    const QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
    expectClosedQuadMesh(c, q, name);
    // about as many quads as asked (the map's area in cells)
    EXPECT_NEAR(q.Q.rows() / 1500.0, 1.0, 0.2) << name;
  }
}

TEST(QuadExtraction, CellCentresOnEdgesAndPointsGiveOneQuad)
{
  // On these regular meshes at 6,500 quads many cell centres and grid points fall exactly on
  // mesh edges and points (to rounding): each cell must still give exactly one quad.
  for (const char* name : { "torus", "sphere" })
  {
    const Chain c = runChain(testSurface(name), 6500);
    const QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
    expectClosedQuadMesh(c, q, name);
  }
}

TEST(QuadExtraction, QuadVerticesLieOnTheSurfaceAndFacesAreConsistentlyOriented)
{
  const Chain c = runChain(testSurface("sphere"), 800);
  const QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
  for (int v = 0; v < q.V.rows(); ++v)
  {
    EXPECT_NEAR(q.V.row(v).norm(), 1.0, 0.01) << "on the (inscribed) unit sphere";
  }
  // outward: the quad normal (diagonal cross product) points away from the centre
  for (int i = 0; i < q.Q.rows(); ++i)
  {
    const Eigen::Vector3d a = q.V.row(q.Q(i, 0)), b = q.V.row(q.Q(i, 1)), cc = q.V.row(q.Q(i, 2)),
                          d = q.V.row(q.Q(i, 3));
    EXPECT_GT((cc - a).cross(d - b).dot(a + b + cc + d), 0.0) << i;
  }
}

TEST(QuadExtraction, BoundariesKeepTheirLoops)
{
  const Chain c = runChain(testSurface("cylinder"), 600);
  const QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
  const QuadQuality m = measureQuads(q.V, q.Q);
  EXPECT_EQ(m.quads, m.faces);
  EXPECT_EQ(m.nonManifoldEdges, 0);
  EXPECT_EQ(m.boundaryLoops, 2);
  EXPECT_EQ(m.eulerCharacteristic, 0);
  EXPECT_EQ(m.irregularInner, 0);
  EXPECT_EQ(m.irregularBoundary, 0);
  EXPECT_EQ(q.cellsOffSurface, 0) << "the boundaries lie on grid lines: no cell sticks out";
}

TEST(QuadExtraction, AFoldedMapStillGivesAValidMesh)
{
  Chain c = runChain(testSurface("sphere"), 800);
  // fold the map: push a few points' (u, v) across their neighbours
  int moved = 0;
  for (int f = 0; f < c.s.F.rows() && moved < 6; f += 97)
  {
    c.map.cornerUV(f, 0) += 1.7;
    c.map.cornerUV(f, 1) -= 0.9;
    ++moved;
  }
  ASSERT_GT(checks::flippedTriangles(c.map.cornerUV), 0);
  const QuadMesh q = extractQuads(c.s.V, c.s.F, c.topo, c.map.cornerUV);
  const QuadQuality m = measureQuads(q.V, q.Q);
  EXPECT_GT(m.faces, 500);
  EXPECT_EQ(m.nonManifoldEdges, 0);
  EXPECT_EQ(m.quads, m.faces);
  std::printf("folded: %d quads, %d cells off, %d degenerate, %d conflicting, %d transitions "
              "not integer\n",
    m.faces, q.cellsOffSurface, q.cellsDegenerate, q.cellsConflicting, q.nonIntegerTransitions);
}

TEST(QuadExtraction, MeasuresAKnownQuadMesh)
{
  // a 3 x 2 grid of unit squares in the plane
  Eigen::MatrixX3d V(12, 3);
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      V.row(4 * j + i) << i, j, 0;
    }
  }
  Eigen::MatrixX4i Q(6, 4);
  int f = 0;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      Q.row(f++) << 4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i;
    }
  }
  const QuadQuality m = measureQuads(V, Q);
  EXPECT_EQ(m.vertices, 12);
  EXPECT_EQ(m.faces, 6);
  EXPECT_EQ(m.quads, 6);
  EXPECT_EQ(m.eulerCharacteristic, 1);
  EXPECT_EQ(m.boundaryLoops, 1);
  EXPECT_EQ(m.boundaryEdges, 10);
  EXPECT_EQ(m.irregularInner, 0);
  EXPECT_EQ(m.irregularBoundary, 0) << "corners valence 2, sides 3";
  EXPECT_NEAR(m.edgeLengthRSD, 0.0, 1e-12);
  EXPECT_NEAR(m.angleRSD, 0.0, 1e-12);
  EXPECT_NEAR(m.minScaledJacobian, 1.0, 1e-12);
  // stretch one column: edge lengths 1 and 2
  for (int j = 0; j < 3; ++j)
  {
    V(4 * j + 3, 0) = 4.0;
  }
  EXPECT_GT(measureQuads(V, Q).edgeLengthRSD, 0.2);
  // a face listed twice in the same direction is non-manifold
  Eigen::MatrixX4i twice(2, 4);
  twice << 0, 1, 5, 4, 0, 1, 5, 4;
  EXPECT_EQ(measureQuads(V, twice).nonManifoldEdges, 4);
}
