// The frame smoother: descent, lambda = 0, singularities of smoothed curvature fields, recovery
// of a known field from noise, constraints along features and boundaries, which edges are creases.
#include "CurvatureFrames.h"
#include "FrameField.h"
#include "FrameSmoother.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "Surfaces.h"
#include "TestSurfaces.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace quadcover;

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Deg = 180.0 / Pi;

struct Case
{
  Surface s;
  MeshTopology topo;
  FrameGeometry geometry;
  CurvatureField curvature;
};

Case prepare(Surface s)
{
  MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  FrameGeometry g = computeFrameGeometry(s.V, s.F, topo);
  CurvatureField c = computeCurvatureField(s.V, s.F, topo);
  return { std::move(s), std::move(topo), std::move(g), std::move(c) };
}

SmootherResult smooth(const Case& c, SmootherOptions opt = SmootherOptions())
{
  return smoothFrames(c.s.V, c.s.F, c.topo, c.geometry, c.curvature.frameU, c.curvature.frameV,
    c.curvature.weight, opt);
}

FrameTopology topology(const Case& c, const Eigen::MatrixX3d& U)
{
  return computeMatchings(c.s.F, c.topo, c.geometry, U);
}

/// Angle between two crosses (degrees, in [0, 45]).
double crossAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& n)
{
  return std::abs(wrapQuarter(std::atan2(n.dot(a.cross(b)), a.dot(b)))) * Deg;
}
}

TEST(FrameSmoother, EnergyNeverIncreases)
{
  for (const char* name : { "knot", "sphere", "roundedcube", "cylinder" })
  {
    const Case c = prepare(testSurface(name));
    for (double lambda : { 0.2, 0.5, 0.9, 1.0 })
    {
      SmootherOptions opt;
      opt.smoothingWeight = lambda;
      const SmootherResult r = smooth(c, opt);
      for (size_t i = 1; i < r.energyHistory.size(); ++i)
      {
        ASSERT_LE(r.energyHistory[i], r.energyHistory[i - 1]) << name << " lambda " << lambda;
      }
      // No run met a step that raised the energy beyond rounding (the descent stops at such a
      // step instead of recording it, so only this count can show a bound that does not hold).
      EXPECT_EQ(r.rejectedSteps, 0) << name << " lambda " << lambda;
      EXPECT_EQ(r.energyHistory.size(), static_cast<size_t>(r.iterations) + 1);
      EXPECT_EQ(r.energyAfter, r.energyHistory.back());
      // Unit tangent frames, V turned with U.
      for (int f = 0; f < c.topo.numFaces; ++f)
      {
        const Eigen::Vector3d n = c.geometry.bases.normal.row(f), u = r.frameU.row(f);
        ASSERT_NEAR(u.norm(), 1.0, 1e-9);
        ASSERT_NEAR(u.dot(n), 0.0, 1e-9);
        ASSERT_NEAR((Eigen::Vector3d(r.frameV.row(f)) - n.cross(u)).norm(), 0.0, 1e-9);
      }
    }
  }
}

TEST(FrameSmoother, LambdaZeroReturnsTheInputFrames)
{
  const Case c = prepare(testSurface("knot"));
  SmootherOptions opt;
  opt.smoothingWeight = 0.0;
  opt.alignToFeatures = false;
  opt.alignToBoundary = false;
  const SmootherResult r = smooth(c, opt);
  EXPECT_LT((r.frameU - c.curvature.frameU).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(r.energyAfter, 0.0);
}

TEST(FrameSmoother, TorusKeepsNoSingularities)
{
  const Case c = prepare(testSurface("torus"));
  // With the alignment everywhere (no coherence weighting) it stays along the curvature
  // directions (omega is large everywhere on a torus): within 2 degrees at an even balance,
  // within 8 at the default lambda (mostly smoothness).
  for (const auto& [lambda, bound] : { std::pair<double, double>{ 0.5, 2.0 }, { 0.95, 8.0 } })
  {
    SmootherOptions opt;
    opt.smoothingWeight = lambda;
    opt.coherenceRadius = 0.0;
    const SmootherResult r = smooth(c, opt);
    EXPECT_EQ(topology(c, r.frameU).singularities, 0) << "lambda " << lambda;
    double worst = 0.0;
    for (int f = 0; f < c.topo.numFaces; ++f)
    {
      worst = std::max(worst,
        crossAngle(r.frameU.row(f), c.curvature.frameU.row(f), c.geometry.bases.normal.row(f)));
    }
    EXPECT_LT(worst, bound) << "lambda " << lambda;
  }
  // With the defaults the curvature lines, which turn along the parallels, count less
  // (coherence 0.5-0.65): still no singularity.
  EXPECT_EQ(topology(c, smooth(c).frameU).singularities, 0) << "defaults";
}

TEST(FrameSmoother, CoherenceIsOneOnParallelDirectionsAndFallsWhereTheyScatterOrTurn)
{
  const auto meanCoherence = [](const Case& c, const Eigen::MatrixX3d& U, double radius) {
    SmootherOptions opt;
    opt.coherenceRadius = radius;
    const auto [u, v] = tangentFrames(c.geometry.bases, U, Eigen::MatrixX3d());
    const SmootherResult r =
      smoothFrames(c.s.V, c.s.F, c.topo, c.geometry, u, v, c.curvature.weight, opt);
    EXPECT_EQ(r.coherence.size(), c.s.F.rows());
    EXPECT_GE(r.coherence.minCoeff(), 0.0);
    EXPECT_LE(r.coherence.maxCoeff(), 1.0);
    return r.coherence.mean();
  };
  // A cylinder's curvature directions are parallel: 1 everywhere.
  const Case cylinder = prepare(testSurface("cylinder"));
  EXPECT_GT(meanCoherence(cylinder, cylinder.curvature.frameU, 0.1), 0.999);
  // The torus' turn along the parallels (geodesic curvature): in between.
  const Case torus = prepare(testSurface("torus"));
  const double turning = meanCoherence(torus, torus.curvature.frameU, 0.1);
  EXPECT_GT(turning, 0.4);
  EXPECT_LT(turning, 0.8);
  // The cylinder's directions turned at random (noise): near 0, and no radius: 1.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-Pi, Pi);
  Eigen::MatrixX3d noisy = cylinder.curvature.frameU;
  for (Eigen::Index f = 0; f < noisy.rows(); ++f)
  {
    const Eigen::Vector3d n = cylinder.geometry.bases.normal.row(f);
    noisy.row(f) = Eigen::AngleAxisd(angle(random), n) * Eigen::Vector3d(noisy.row(f));
  }
  EXPECT_LT(meanCoherence(cylinder, noisy, 0.1), 0.15);
  EXPECT_EQ(meanCoherence(cylinder, noisy, 0.0), 1.0);
}

TEST(FrameSmoother, SphereEndsWithEightQuarterSingularities)
{
  const Case c = prepare(testSurface("sphere"));
  const SmootherResult r = smooth(c);
  const FrameTopology t = topology(c, r.frameU);
  std::printf("[ sphere ] %d singularities, energy %.4g -> %.4g, %d iterations, %s start\n",
    t.singularities, r.energyBefore, r.energyAfter, r.iterations,
    r.fromGlobalStart ? "global" : "input");
  EXPECT_EQ(t.singularities, 8);
  for (int v = 0; v < c.topo.numVertices; ++v)
  {
    EXPECT_TRUE(t.index[v] == 0.0 || t.index[v] == 0.25) << v << " " << t.index[v];
  }
  EXPECT_LT(r.energyAfter, r.energyBefore);
}

TEST(FrameSmoother, RecoversAKnownFieldFromNoise)
{
  // A cylinder whose frames point along the axis, disturbed by up to 25 degrees of noise; with
  // the noisy frames as alignment target (weight 1) and lambda = 0.9 the field comes back.
  Case c = prepare(makeCylinder(0.5, 2.0, 64, 40));
  std::mt19937 rng(11);
  const int nf = c.topo.numFaces;
  Eigen::MatrixX3d truth(nf, 3), noisy(nf, 3), noisyV(nf, 3);
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d n = c.geometry.bases.normal.row(f);
    const Eigen::Vector3d axis = (Eigen::Vector3d::UnitZ() - n.z() * n).normalized();
    truth.row(f) = axis.transpose();
    const double a = (25.0 / Deg) * (2.0 * (rng() / 4294967296.0) - 1.0);
    const Eigen::Vector3d u = std::cos(a) * axis + std::sin(a) * n.cross(axis);
    noisy.row(f) = u.transpose();
    noisyV.row(f) = n.cross(u).transpose();
  }
  SmootherOptions opt;
  opt.smoothingWeight = 0.9;
  opt.alignToBoundary = false;
  const SmootherResult r =
    smoothFrames(c.s.V, c.s.F, c.topo, c.geometry, noisy, noisyV, Eigen::VectorXd::Ones(nf), opt);
  double mean = 0.0, worst = 0.0, before = 0.0;
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d n = c.geometry.bases.normal.row(f);
    const double e = crossAngle(r.frameU.row(f), truth.row(f), n);
    mean += e / nf;
    worst = std::max(worst, e);
    before += crossAngle(noisy.row(f), truth.row(f), n) / nf;
  }
  std::printf(
    "[ noisy cylinder ] mean error %.2f deg before, %.2f after, max %.2f\n", before, mean, worst);
  EXPECT_LT(mean, 2.0);
  EXPECT_LT(worst, 6.0);
}

TEST(FrameSmoother, HeldFramesFollowTheirEdgesAndStayPut)
{
  for (const char* name : { "cylinder", "roundedcube" })
  {
    Case c =
      prepare(std::string(name) == "roundedcube" ? makeRoundedCube(0.0, 8) : testSurface(name));
    const SmootherResult r = smooth(c);
    ASSERT_GT(r.numConstrained, 0) << name;
    SmootherOptions loose;
    loose.maximumNumberOfIterations = 1;
    const SmootherResult early = smooth(c, loose);
    for (int f = 0; f < c.topo.numFaces; ++f)
    {
      if (!r.constrained[f])
        continue;
      // The cross contains one of the triangle's held edges' directions.
      double best = 90.0;
      for (int k = 0; k < 3; ++k)
      {
        const int g = c.topo.faceNeighbors(f, k);
        const bool held = g < 0 ||
          c.geometry.bases.normal.row(f).dot(c.geometry.bases.normal.row(g)) < std::cos(30.0 / Deg);
        if (held)
        {
          const Eigen::Vector3d e = c.s.V.row(c.s.F(f, (k + 1) % 3)) - c.s.V.row(c.s.F(f, k));
          best = std::min(best, crossAngle(r.frameU.row(f), e, c.geometry.bases.normal.row(f)));
        }
      }
      ASSERT_LT(best, 1e-9) << name << " " << f;
      // Held frames do not move while the free ones are optimized.
      ASSERT_LT((r.frameU.row(f) - early.frameU.row(f)).norm(), 1e-12);
    }
  }
}

TEST(FrameSmoother, SharpCubeGetsItsEightCornerBranchPoints)
{
  // Curvature frames on the sharp cube, features held: the paper's Fig. 4.
  const Case c = prepare(makeRoundedCube(0.0, 8));
  const SmootherResult r = smooth(c);
  const FrameTopology t = topology(c, r.frameU);
  EXPECT_EQ(r.featureEdges, 12 * 8);
  EXPECT_EQ(t.branchPoints, 8);
  for (int v = 0; v < c.topo.numVertices; ++v)
  {
    const bool corner = c.s.V.row(v).cwiseAbs().minCoeff() > 1.0 - 1e-12;
    EXPECT_EQ(t.layerShift[v], corner ? 1 : 0) << v;
  }
}

namespace
{
/// A closed prism over a regular n-gon (radius 1, height 2, rings + 1 rings of points), its caps
/// fans around their centres: a faceted cylinder, the rims its only creases.
Surface cappedPrism(int n, int rings)
{
  Surface s;
  s.V.resize(n * (rings + 1) + 2, 3);
  for (int j = 0; j <= rings; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double a = 2.0 * Pi * i / n;
      s.V.row(j * n + i) << std::cos(a), std::sin(a), 2.0 * j / rings;
    }
  }
  const int bottom = n * (rings + 1), top = bottom + 1;
  s.V.row(bottom) << 0.0, 0.0, 0.0;
  s.V.row(top) << 0.0, 0.0, 2.0;
  std::vector<Eigen::Vector3i> faces;
  for (int j = 0; j < rings; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = j * n + i, b = j * n + (i + 1) % n;
      faces.emplace_back(a, b, b + n);
      faces.emplace_back(a, b + n, a + n);
    }
  }
  for (int i = 0; i < n; ++i)
  {
    faces.emplace_back(bottom, (i + 1) % n, i);
    faces.emplace_back(top, rings * n + i, rings * n + (i + 1) % n);
  }
  s.F.resize(static_cast<int>(faces.size()), 3);
  for (int f = 0; f < s.F.rows(); ++f)
  {
    s.F.row(f) = faces[f].transpose();
  }
  return s;
}

int countSharp(const Surface& s, double smoothSideFraction)
{
  const MeshTopology topo = buildTopology(s.F, static_cast<int>(s.V.rows()));
  const FrameGeometry g = computeFrameGeometry(s.V, s.F, topo);
  const std::vector<char> sharp = sharpEdges(topo, g.bases, SmootherOptions().featureAngle,
    SmootherOptions().minimumFeatureLength, smoothSideFraction);
  return static_cast<int>(std::count(sharp.begin(), sharp.end(), 1));
}
}

TEST(FrameSmoother, CreasesNeedSmoothSides)
{
  // A faceted cylinder of 8 and of 12 sides: its two rims (90 degrees) are creases, though the
  // faces beside them meet at 45 or 30 degrees along them (a bend about an axis across the rim,
  // which the sides' test does not see); the edges between sides bend less than the feature angle.
  for (const int n : { 8, 12 })
  {
    EXPECT_EQ(countSharp(cappedPrism(n, 3), SmoothSideFraction), 2 * n) << n;
  }
  // Spheres of a few hundred triangles, their points moved in and out at random: coarse smooth
  // surfaces. Their edges bent past the feature angle form networks long enough to pass as
  // creases by their bend alone, but the surface beside them bends about as much: few networks
  // have smooth sides where most of their edges do.
  int byBend = 0, creases = 0;
  for (const unsigned seed : { 1u, 2u, 3u, 4u, 5u })
  {
    Surface bumpy = makeIcosphere(1.0, 2);
    std::mt19937 random(seed); // its raw output is the same with every standard library
    for (int v = 0; v < bumpy.V.rows(); ++v)
    {
      bumpy.V.row(v) *= 0.75 + 0.5 * (random() / 4294967296.0);
    }
    byBend += countSharp(bumpy, 1e9);
    creases += countSharp(bumpy, SmoothSideFraction);
  }
  std::printf("bumpy spheres: %d sharp edges by their bend, %d creases\n", byBend, creases);
  EXPECT_GE(byBend, 200);
  EXPECT_LE(10 * creases, byBend);
}

TEST(FrameSmoother, ReportsProgressAndStopsWhenAsked)
{
  // The knot runs the descent from the aligned global start too; the sphere's weak curvature
  // adds the inverse iteration for the smoothest field.
  for (const char* name : { "knot", "sphere" })
  {
    SCOPED_TRACE(name);
    const Case c = prepare(testSurface(name));
    const SmootherResult plain = smooth(c);
    std::vector<double> fractions;
    const SmootherResult r = smoothFrames(c.s.V, c.s.F, c.topo, c.geometry, c.curvature.frameU,
      c.curvature.frameV, c.curvature.weight, SmootherOptions(), Progress([&](double x) {
        fractions.push_back(x);
        return true;
      }));
    std::printf(
      "%s: %zu reports, %d iterations in the chosen run\n", name, fractions.size(), r.iterations);
    ASSERT_GT(fractions.size(), 10u);
    // in order from 0 to 1, and so all within [0, 1]
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_EQ(fractions.back(), 1.0);
    // Reporting changes nothing.
    EXPECT_EQ(r.energyHistory, plain.energyHistory);
    EXPECT_TRUE(r.frameU == plain.frameU);
    EXPECT_EQ(r.fromGlobalStart, plain.fromGlobalStart);

    int calls = 0;
    EXPECT_THROW(
      smoothFrames(c.s.V, c.s.F, c.topo, c.geometry, c.curvature.frameU, c.curvature.frameV,
        c.curvature.weight, SmootherOptions(), Progress([&](double) { return ++calls < 5; })),
      Cancelled);
    EXPECT_EQ(calls, 5);
  }
}

TEST(FrameSmoother, TheRunFromTheInputBesideTheGlobalRunsEndsAsAfterThem)
{
  // On two threads the run from the input runs beside the global starts' runs and learns their
  // end late; the result must be the one thread's, bit for bit, whichever run wins. A cancel
  // while it runs stops both.
  int inputWins = 0, inputLoses = 0;
  for (const double lambda : { 0.95, 1.0 })
  {
    for (const char* name : { "knot", "sphere", "torus" })
    {
      SCOPED_TRACE(std::string(name) + " lambda " + std::to_string(lambda));
      const Case c = prepare(testSurface(name));
      SmootherOptions one, two;
      one.smoothingWeight = two.smoothingWeight = lambda;
      one.numberOfThreads = 1;
      two.numberOfThreads = 2;
      const SmootherResult a = smooth(c, one), b = smooth(c, two);
      EXPECT_EQ(a.energyHistory, b.energyHistory);
      EXPECT_EQ(a.iterations, b.iterations);
      EXPECT_EQ(a.rejectedSteps, b.rejectedSteps);
      EXPECT_EQ(a.fromGlobalStart, b.fromGlobalStart);
      EXPECT_EQ(a.energyBefore, b.energyBefore);
      EXPECT_TRUE(a.rotation == b.rotation);
      (a.fromGlobalStart ? inputLoses : inputWins) += 1;
      for (const SmootherOptions& options : { one, two })
      {
        // reports of 0.6 and on are the run from the input's (or the end)
        EXPECT_THROW(
          smoothFrames(c.s.V, c.s.F, c.topo, c.geometry, c.curvature.frameU, c.curvature.frameV,
            c.curvature.weight, options, Progress([](double x) { return x < 0.6; })),
          Cancelled);
      }
    }
  }
  // both outcomes were compared
  EXPECT_GT(inputWins, 0);
  EXPECT_GT(inputLoses, 0);
}
