// Curvature against analytic values: torus, cylinder, sphere, saddle, the noisy knot tube.
#include "CurvatureFrames.h"
#include "MeshTopology.h"
#include "Surfaces.h"
#include "TestSurfaces.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace quadcover;

namespace
{
constexpr double Deg = 180.0 / 3.14159265358979323846;

struct Sample
{
  Surface s;
  MeshTopology topo;
  CurvatureField field;
};

Sample run(Surface s, double radius = 2.0, int threads = 0)
{
  MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  CurvatureOptions opt;
  opt.neighborhoodRadius = radius;
  opt.numberOfThreads = threads;
  CurvatureField field = computeCurvatureField(s.V, s.F, topo, opt);
  return { std::move(s), std::move(topo), std::move(field) };
}

/// Analytic direction1 at a face: vertex directions (sign-aligned) averaged, in the face's plane.
Eigen::Vector3d analyticDirection1(const Sample& r, int f)
{
  Eigen::Vector3d d = r.s.direction1.row(r.s.F(f, 0));
  for (int k = 1; k < 3; ++k)
  {
    Eigen::Vector3d e = r.s.direction1.row(r.s.F(f, k));
    d += e.dot(d) < 0 ? -e : e;
  }
  const Eigen::Vector3d n = r.field.normals.row(f);
  return (d - d.dot(n) * n).normalized();
}

/// Angle between two lines (degrees, in [0, 90]).
double lineAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * Deg;
}

double analyticKappa(const Sample& r, int f, int which)
{
  return (r.s.kappa(r.s.F(f, 0), which) + r.s.kappa(r.s.F(f, 1), which) +
           r.s.kappa(r.s.F(f, 2), which)) /
    3.0;
}

struct Errors
{
  double meanAngle = 0, maxAngle = 0, medianAngle = 0, p90Angle = 0;
  double meanK1 = 0, meanK2 = 0; // mean absolute error relative to max |kappa1|
};

Errors errors(const Sample& r)
{
  std::vector<double> angles;
  double k1 = 0, k2 = 0, scale = r.s.kappa.col(0).cwiseAbs().maxCoeff();
  const int nf = static_cast<int>(r.s.F.rows());
  for (int f = 0; f < nf; ++f)
  {
    angles.push_back(lineAngle(r.field.direction1.row(f), analyticDirection1(r, f)));
    k1 += std::abs(r.field.curvatures(f, 0) - analyticKappa(r, f, 0));
    k2 += std::abs(r.field.curvatures(f, 1) - analyticKappa(r, f, 1));
  }
  Errors e;
  for (double a : angles)
  {
    e.meanAngle += a / nf;
  }
  std::sort(angles.begin(), angles.end());
  e.maxAngle = angles.back();
  e.medianAngle = angles[nf / 2];
  e.p90Angle = angles[nf * 9 / 10];
  e.meanK1 = k1 / nf / scale;
  e.meanK2 = k2 / nf / scale;
  return e;
}
}

TEST(CurvatureFrames, FramesAreOrthonormalTangentAndSorted)
{
  for (const char* name : { "torus", "sphere", "cylinder", "saddle", "knot", "roundedcube" })
  {
    const Sample r = run(testSurface(name));
    for (int f = 0; f < r.topo.numFaces; ++f)
    {
      const Eigen::Vector3d n = r.field.normals.row(f), u = r.field.frameU.row(f),
                            v = r.field.frameV.row(f), d1 = r.field.direction1.row(f),
                            d2 = r.field.direction2.row(f);
      ASSERT_NEAR(u.norm(), 1.0, 1e-12) << name;
      ASSERT_NEAR(u.dot(n), 0.0, 1e-12) << name;
      ASSERT_NEAR((v - n.cross(u)).norm(), 0.0, 1e-12) << name;
      ASSERT_NEAR(d1.dot(d2), 0.0, 1e-12) << name;
      ASSERT_NEAR((u - d2).norm(), 0.0, 1e-12) << name; // FrameU along kappa2
      ASSERT_GE(r.field.curvatures(f, 0), r.field.curvatures(f, 1)) << name;
      const double w = r.field.weight[f];
      ASSERT_TRUE(w >= 0.0 && w <= std::sqrt(2.0) + 1e-12) << name;
    }
  }
}

TEST(CurvatureFrames, CylinderIsExact)
{
  const double radius = 0.5;
  const Sample r = run(makeCylinder(radius, 2.0, 64, 40));
  const int nf = r.topo.numFaces;
  double maxAngle = 0, maxK1 = 0, maxK2 = 0;
  for (int f = 0; f < nf; ++f)
  {
    maxAngle = std::max(maxAngle, lineAngle(r.field.direction1.row(f), analyticDirection1(r, f)));
    // Away from the rims the neighbourhood is complete.
    const double z = r.s.V.row(r.s.F(f, 0)).z();
    if (std::abs(z) < 1.0 - 3.0 * r.field.curvatureRadius)
    {
      maxK1 = std::max(maxK1, std::abs(r.field.curvatures(f, 0) * radius - 1.0));
      maxK2 = std::max(maxK2, std::abs(r.field.curvatures(f, 1) * radius));
    }
  }
  EXPECT_LT(maxAngle, 1e-6);
  EXPECT_LT(maxK1, 2e-3); // pi / (n sin(pi/n)) - 1 = 4e-4 for n = 64
  EXPECT_LT(maxK2, 1e-9);
}

TEST(CurvatureFrames, TorusDirectionsAndCurvaturesConvergeUnderRefinement)
{
  Errors prev;
  int level = 0;
  for (int nu : { 48, 96, 192 })
  {
    const Errors e = errors(run(makeTorus(1.0, 0.4, nu, nu / 2)));
    std::printf("[ torus %3d x %3d ] direction error mean %.3f deg, max %.3f deg; "
                "|dk1|/k1 %.4f, |dk2|/k1 %.4f\n",
      nu, nu / 2, e.meanAngle, e.maxAngle, e.meanK1, e.meanK2);
    EXPECT_LT(e.maxAngle, 3.0);
    EXPECT_LT(e.meanK1, 0.05);
    if (level++ > 0)
    {
      EXPECT_LT(e.meanK1, prev.meanK1);
      EXPECT_LT(e.meanK2, prev.meanK2);
      EXPECT_LE(e.meanAngle, prev.meanAngle + 1e-9);
    }
    prev = e;
  }
  EXPECT_LT(prev.meanAngle, 1.0);
}

TEST(CurvatureFrames, SphereIsUmbilicAndConvex)
{
  const Sample r = run(makeIcosphere(2.0, 4));
  double maxW = 0, meanW = 0;
  for (int f = 0; f < r.topo.numFaces; ++f)
  {
    maxW = std::max(maxW, r.field.weight[f]);
    meanW += r.field.weight[f] / r.topo.numFaces;
    // Outward normals: both curvatures positive, near 1/R.
    EXPECT_NEAR(r.field.curvatures(f, 0), 0.5, 0.05);
    EXPECT_NEAR(r.field.curvatures(f, 1), 0.5, 0.05);
  }
  std::printf("[ sphere ] omega mean %.4f max %.4f\n", meanW, maxW);
  EXPECT_LT(meanW, 0.05);
  EXPECT_LT(maxW, 0.15);
}

TEST(CurvatureFrames, SaddleAtTheOrigin)
{
  const Sample r = run(makeSaddle(1.0, 0.5, 60));
  int count = 0;
  for (int f = 0; f < r.topo.numFaces; ++f)
  {
    const Eigen::Vector3d c =
      (r.s.V.row(r.s.F(f, 0)) + r.s.V.row(r.s.F(f, 1)) + r.s.V.row(r.s.F(f, 2))) / 3.0;
    if (c.head<2>().norm() > 0.08)
    {
      continue;
    }
    ++count;
    EXPECT_NEAR(r.field.curvatures(f, 0), 1.0, 0.05);
    EXPECT_NEAR(r.field.curvatures(f, 1), -1.0, 0.05);
    // kappa1 = +1 bends away from the upward normal: along y (within the tilted tangent plane).
    EXPECT_LT(lineAngle(r.field.direction1.row(f), analyticDirection1(r, f)), 0.5);
    EXPECT_LT(lineAngle(r.field.direction1.row(f), Eigen::Vector3d::UnitY()), 5.0);
    EXPECT_NEAR(r.field.weight[f], std::sqrt(2.0), 0.01);
  }
  EXPECT_GT(count, 10);
}

TEST(CurvatureFrames, NoisyIrregularKnotTubeFollowsPrincipalDirections)
{
  // The paper's Fig. 2 case: jittered, randomly split grid with noise of 3% of the tube radius.
  const Sample r = run(testSurface("knot"), 3.0);
  const Errors e = errors(r);
  std::printf("[ noisy knot ] direction error median %.2f deg, 90%% %.2f deg, mean %.2f deg\n",
    e.medianAngle, e.p90Angle, e.meanAngle);
  EXPECT_LT(e.medianAngle, 4.0);
  EXPECT_LT(e.p90Angle, 10.0);
  // kappa1 = 1 / tube.
  EXPECT_LT(e.meanK1, 0.1);
}

TEST(CurvatureFrames, LargerRadiusSmoothsNoise)
{
  const Errors small = errors(run(testSurface("knot"), 0.0));
  const Errors large = errors(run(testSurface("knot"), 3.0));
  EXPECT_LT(large.meanAngle, small.meanAngle);
}

TEST(CurvatureFrames, ResultDoesNotDependOnThreadCount)
{
  const Sample a = run(testSurface("knot"), 2.0, 1);
  const Sample b = run(testSurface("knot"), 2.0, 2);
  EXPECT_EQ(a.field.curvatures, b.field.curvatures);
  EXPECT_EQ(a.field.frameU, b.field.frameU);
}

TEST(CurvatureFrames, RejectsBadInput)
{
  Surface s = testSurface("sphere");
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  CurvatureOptions bad;
  bad.neighborhoodRadius = -1.0;
  EXPECT_THROW(computeCurvatureField(s.V, s.F, topo, bad), std::invalid_argument);
  s.V(3, 1) = std::nan("");
  EXPECT_THROW(computeCurvatureField(s.V, s.F, topo), std::invalid_argument);
}

TEST(CurvatureFrames, ZeroAreaTriangleGetsNeighbourhoodNormal)
{
  Surface s = testSurface("sphere");
  // Collapse triangle 0 onto a line: its third vertex moves to the middle of the first edge.
  // (This distorts the neighbours too, but all that matters is a finite, tangent frame.)
  const int a = s.F(0, 0), b = s.F(0, 1), c = s.F(0, 2);
  s.V.row(c) = 0.5 * (s.V.row(a) + s.V.row(b));
  const Sample r = run(s);
  EXPECT_EQ(r.field.degenerateFaces, 1);
  EXPECT_EQ(r.field.zeroFrames, 0);
  EXPECT_TRUE(r.field.curvatures.allFinite());
  EXPECT_NEAR(r.field.normals.row(0).norm(), 1.0, 1e-12);
  // Every frame, the degenerate triangle's included, is a unit tangent vector.
  for (int f = 0; f < r.topo.numFaces; ++f)
  {
    ASSERT_NEAR(r.field.frameU.row(f).norm(), 1.0, 1e-12) << f;
    ASSERT_NEAR(r.field.frameU.row(f).dot(r.field.normals.row(f)), 0.0, 1e-12) << f;
  }
}

TEST(CurvatureFrames, DegeneracyIsJudgedPerTriangleNotAgainstTheLargest)
{
  // A sphere of radius 1e-3 beside one triangle of size 1e5: the small triangles are fine.
  Surface s = makeIcosphere(1e-3, 3);
  const Eigen::Index nv = s.V.rows(), nf = s.F.rows();
  s.V.conservativeResize(nv + 3, 3);
  s.V.bottomRows(3) << 1e5, 0, 0, 2e5, 0, 0, 1e5, 1e5, 0;
  s.F.conservativeResize(nf + 1, 3);
  s.F.row(nf) << static_cast<int>(nv), static_cast<int>(nv + 1), static_cast<int>(nv + 2);
  const Sample r = run(s);
  EXPECT_EQ(r.field.degenerateFaces, 0);
  EXPECT_EQ(r.field.zeroFrames, 0);
  for (Eigen::Index f = 0; f < nf; ++f)
  {
    ASSERT_NEAR(r.field.curvatures(f, 0) * 1e-3, 1.0, 0.05) << f;
  }
}

TEST(CurvatureFrames, NeighbourhoodIsCapped)
{
  Surface s = testSurface("torus");
  MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  CurvatureOptions opt;
  opt.neighborhoodRadius = 20.0;
  opt.maximumNeighborhood = 50;
  const CurvatureField field = computeCurvatureField(s.V, s.F, topo, opt);
  EXPECT_EQ(field.truncatedNeighborhoods, topo.numFaces);
  opt.maximumNeighborhood = 0; // no limit
  EXPECT_EQ(computeCurvatureField(s.V, s.F, topo, opt).truncatedNeighborhoods, 0);
}

TEST(CurvatureFrames, InputFramesAreProjectedAndCompleted)
{
  Sample r = run(testSurface("torus"));
  const int nf = r.topo.numFaces;
  Eigen::MatrixX3d user(nf, 3);
  for (int f = 0; f < nf; ++f)
  {
    user.row(f) = Eigen::RowVector3d(0.0, 0.0, 1.0) + 0.5 * r.field.normals.row(f);
  }
  user.row(0).setZero();                      // no direction: the curvature frame stays
  user.row(1) = 3.0 * r.field.normals.row(1); // normal: the curvature frame stays
  const Eigen::MatrixX3d curvatureU = r.field.frameU;
  EXPECT_EQ(applyInputFrames(r.field, user),
    static_cast<int>((r.field.normals.col(2).array().abs() > 1.0 - 1e-12).count()) + 2);
  EXPECT_EQ(r.field.frameU.row(0), curvatureU.row(0));
  for (int f = 2; f < nf; ++f)
  {
    const Eigen::Vector3d n = r.field.normals.row(f), u = r.field.frameU.row(f);
    Eigen::Vector3d expect = Eigen::Vector3d::UnitZ() - n.z() * n;
    if (expect.norm() < 1e-9)
      continue;
    EXPECT_LT((u - expect.normalized()).norm(), 1e-9);
    EXPECT_LT((Eigen::Vector3d(r.field.frameV.row(f)) - n.cross(u)).norm(), 1e-12);
  }
}
