// MapRegrid.cxx: a map that keeps flipped triangles or wrong windings after its repair is rounded
// and repaired again at other grid sizes (finer, coarser) until one has no defects, which is
// kept. The continuous map is linear in 1 / edgeLength, so each grid size costs a rounding, one
// back-substitution and a repair: no new factorization.
#include "ParameterizationSteps.h"

#include "NearbyPoints.h"
#include "QuadExtraction.h"
#include "QuadMeshAdjacency.h"
#include "QuadMeshing.h"
#include "QuadPatching.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <utility>

namespace quadcover
{
namespace param
{
namespace
{
/// The factors (in the number of quads) tried in turn, finer first: a map that cannot follow
/// its field between singularities that are close against a grid cell (a small torus of the
/// smoothest field: 16 branch points on 24 quads) needs more quads; one that folds where the
/// grid is fine against the triangles, fewer. The last two, only while the trial has at most
/// maximumRegridQuadCount quads, are for a small component whose holes or strips are narrow against
/// its share of the quads (pieces of the truck with 24 quads: a tube whose boundary loops are 4.6
/// quads long, a strip whose fans wound the wrong way until the grid was 8 times finer).
constexpr double QuadFactors[] = { 2.0, 0.5, 4.0, 0.25, 8.0, 16.0 };

/// How many of QuadFactors are tried at most.
int maximumTries(const Inputs& in)
{
  return std::max(0, std::min(in.options.maximumRegrids, static_cast<int>(std::size(QuadFactors))));
}

/// The defects of map uv that are not flat triangles: a flipped triangle whose (u, v) area is at
/// most QuadExtractionOptions::flatTolerance times its longest (u, v) edge squared is a sliver
/// that the map lays on a line (between a boundary's grid line and a branch point on it, say),
/// keeps no area on any grid, and the quads cross it. Other grids are tried for the other
/// defects only.
std::size_t defectsBeyondFlat(
  const Defects& defects, const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector)
{
  const double flatArea = QuadExtractionOptions().flatTolerance; // as the extraction sees it
  std::size_t count = defects.wrong.size();
  for (const int f : defects.flipped)
  {
    double longest = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      longest = std::max(longest,
        (uv.row(cornerSector[3 * f + (k + 1) % 3]) - uv.row(cornerSector[3 * f + k]))
          .squaredNorm());
    }
    count += !(std::abs(twiceUVArea(uv, cornerSector, f)) <= flatArea * longest);
  }
  return count;
}

/// A repair that spent its untangling budget is tried on other grids only on a surface of at
/// most this many triangles per quad of maximumRegridQuadCount: there the trials (which share one
/// more budget) cost seconds; on a large surface (armadillo) minutes, for nothing.
constexpr double SpentTrianglesPerQuad = 10.0;

/// The quads that map uv gives, with the connectivity the quad stage leaves them: cut out, their
/// holes inside the surface filled, pieces of a quad or two hanging by a corner and disks cut
/// off lying against the rest dropped, and
/// points where quads touch in several fans split (what the quad stage does besides moving
/// vertices).
QuadMesh patchedQuads(
  const Inputs& in, const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector)
{
  QuadMesh quads =
    extractQuads(in.V, in.F, in.topo, cornerUVOf(uv, cornerSector), QuadExtractionOptions());
  patchQuadMesh(in.V, in.F, in.topo, quads);
  dropPinchedFragments(quads, in.topo.faceComponent, PinchedFragmentQuads);
  dropPiecesAgainstRest(quads, in.topo.faceComponent, PieceAgainstRestReach);
  splitPinchedVertices(quads);
  return quads;
}

/// Whether the quads' topology has the surface's pieces, Euler characteristic and boundary loops.
bool sameTopology(const MeshTopology& quads, const MeshTopology& surface)
{
  return quads.numComponents() == surface.numComponents() &&
    quads.eulerCharacteristic() == surface.eulerCharacteristic() &&
    quads.boundaryLoops.size() == surface.boundaryLoops.size();
}

/// Per point of `from`, the index of its nearest point in `to` within `reach`, else -1.
std::vector<int> nearestWithin(
  const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to, double reach)
{
  std::vector<Eigen::Vector3d> all = from;
  all.insert(all.end(), to.begin(), to.end());
  const int n = static_cast<int>(from.size());
  // nearbyPoints gives each point the later ones: those of `to` for every point of `from`
  const std::vector<std::vector<int>> near = nearbyPoints(all, reach);
  std::vector<int> nearest(from.size(), -1);
  for (int i = 0; i < n; ++i)
  {
    double best = reach;
    for (const int j : near[i])
    {
      if (j < n)
      {
        continue;
      }
      const double d = (all[j] - from[i]).norm();
      if (d < best)
      {
        best = d;
        nearest[i] = j - n;
      }
    }
  }
  return nearest;
}

/// Per boundary loop of the surface, the boundary loop of `quads` (whose topology quadTopo is)
/// that most of its points lie nearest to (within `reach`), or -1.
std::vector<int> quadLoopOfEachLoop(
  const Inputs& in, const QuadMesh& quads, const MeshTopology& quadTopo, double reach)
{
  std::vector<Eigen::Vector3d> quadPoints, loopPoints;
  std::vector<int> quadLoop, loopOf;
  for (std::size_t l = 0; l < quadTopo.boundaryLoops.size(); ++l)
  {
    for (const int v : quadTopo.boundaryLoops[l])
    {
      quadPoints.push_back(quads.V.row(v).transpose());
      quadLoop.push_back(static_cast<int>(l));
    }
  }
  for (std::size_t l = 0; l < in.topo.boundaryLoops.size(); ++l)
  {
    for (const int p : in.topo.boundaryLoops[l])
    {
      loopPoints.push_back(in.V.row(p).transpose());
      loopOf.push_back(static_cast<int>(l));
    }
  }
  const std::vector<int> nearest = nearestWithin(loopPoints, quadPoints, reach);
  std::vector<std::map<int, int>> votes(in.topo.boundaryLoops.size());
  for (std::size_t i = 0; i < nearest.size(); ++i)
  {
    if (nearest[i] >= 0)
    {
      ++votes[loopOf[i]][quadLoop[nearest[i]]];
    }
  }
  std::vector<int> chosen(votes.size(), -1);
  for (std::size_t l = 0; l < votes.size(); ++l)
  {
    int most = 0;
    for (const auto& [loop, count] : votes[l])
    {
      if (count > most)
      {
        most = count;
        chosen[l] = loop;
      }
    }
  }
  return chosen;
}

/// Do the quads that map uv gives, after the quad stage's repairs (buildQuadMesh with its
/// default options, whatever the quad stage is given), neither turn a corner inside out nor face
/// against the surface?
bool quadsFaceRight(
  const Inputs& in, const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector)
{
  const QuadMeshResult quads = buildQuadMesh(in.V, in.F, in.topo, cornerUVOf(uv, cornerSector));
  return quads.invertedFinal == 0 && quads.turnedQuads == 0;
}
}

// (Without PureQuads the branch points are off the grid and the cells around them give no quads:
// only the defects count.)
int mapRank(const Inputs& in, const Defects& defects, const Eigen::MatrixX2d& uv,
  const std::vector<int>& cornerSector)
{
  const bool clean = defectsBeyondFlat(defects, uv, cornerSector) == 0;
  const bool whole = !in.options.pureQuads || keepsTopology(in, uv, cornerSector);
  return whole ? (clean ? 0 : 1) : (clean ? 2 : 3);
}

bool rankedByQuads(const Inputs& in, const SeamlessSystem& sys, double edgeLength)
{
  return in.options.roundingMode != RoundingMode::None && sys.numInteger > 0 &&
    sys.faceArea.sum() / (edgeLength * edgeLength) <= in.options.maximumRegridQuadCount;
}

int regridTrials(const Inputs& in, const SeamlessSystem& sys, double edgeLength)
{
  const bool trialsFollow = rankedByQuads(in, sys, edgeLength) &&
    in.numFaces() <= SpentTrianglesPerQuad * in.options.maximumRegridQuadCount;
  return trialsFollow ? maximumTries(in) : 0;
}

bool keepsTopology(
  const Inputs& in, const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector)
{
  const QuadMesh quads = patchedQuads(in, uv, cornerSector);
  const MeshTopology topo = quadTopology(quads);
  return topo.isManifold() && sameTopology(topo, in.topo);
}

namespace
{
/// Two points of one loop are across a neck when the loop between them is more than this many
/// times the reach long, either way round (pointsBetweenJoinedLoops).
constexpr double NeckLength = 2.0;

/// The pairs of the surface's boundary points (index pairs into in.topo's loops, flattened) that
/// pointsBetweenJoinedLoops may refine between, whatever the map: within `reach`, of two loops or
/// across a neck of one. loopOf: per flattened point, its loop.
std::vector<std::pair<int, int>> pairsAcrossLoops(
  const Inputs& in, double reach, std::vector<int>& loopOf)
{
  std::vector<Eigen::Vector3d> points;
  std::vector<double> along;
  std::vector<double> loopLength(in.topo.boundaryLoops.size(), 0.0);
  loopOf.clear();
  for (std::size_t l = 0; l < in.topo.boundaryLoops.size(); ++l)
  {
    const std::vector<int>& loop = in.topo.boundaryLoops[l];
    for (std::size_t k = 0; k < loop.size(); ++k)
    {
      points.push_back(in.V.row(loop[k]).transpose());
      loopOf.push_back(static_cast<int>(l));
      along.push_back(loopLength[l]);
      loopLength[l] += (in.V.row(loop[(k + 1) % loop.size()]) - in.V.row(loop[k])).norm();
    }
  }
  std::vector<std::pair<int, int>> pairs; // each once: nearbyPoints gives only the later points
  const std::vector<std::vector<int>> near = nearbyPoints(points, reach);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    for (const int j : near[i])
    {
      const double apart = std::abs(along[i] - along[j]);
      const bool acrossNeck = loopOf[i] == loopOf[j] &&
        std::min(apart, loopLength[loopOf[i]] - apart) > NeckLength * reach;
      if ((loopOf[i] != loopOf[j] || acrossNeck) && (points[i] - points[j]).norm() < reach)
      {
        pairs.emplace_back(static_cast<int>(i), j);
      }
    }
  }
  return pairs;
}
}

std::vector<int> pointsBetweenJoinedLoops(
  const Inputs& in, const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector, double reach)
{
  std::vector<int> loopOf;
  const std::vector<std::pair<int, int>> pairs = pairsAcrossLoops(in, reach, loopOf);
  if (pairs.empty())
  {
    return {}; // no loop comes near another or itself: nothing to refine between
  }
  // (two loops that the quads pinch together at a point are two: the quad stage splits it)
  const QuadMesh quads = patchedQuads(in, uv, cornerSector);
  const MeshTopology quadTopo = quadTopology(quads);
  if (sameTopology(quadTopo, in.topo))
  {
    return {}; // the quads keep the loops (however the nearest points fall)
  }
  std::vector<int> quadLoop = quadLoopOfEachLoop(in, quads, quadTopo, reach);
  // quads in more pieces than the surface: strips between loops, or necks between two stretches
  // of one loop, were cut through, and the loops may each still have one of their own: every
  // loop counts as joined, to the others and to itself
  const bool cut = quadTopo.numComponents() > in.topo.numComponents();
  if (cut)
  {
    quadLoop.assign(in.topo.boundaryLoops.size(), 0);
  }
  std::vector<int> sharing(quadTopo.boundaryLoops.size() + 2, 0);
  for (const int q : quadLoop)
  {
    ++sharing[q + 1]; // (-1: none)
  }
  auto joined = [&](int l) { return cut || (quadLoop[l] >= 0 && sharing[quadLoop[l] + 1] > 1); };
  std::vector<char> between(loopOf.size(), 0);
  for (const auto& [i, j] : pairs)
  {
    if (joined(loopOf[i]) && joined(loopOf[j]) && quadLoop[loopOf[i]] == quadLoop[loopOf[j]])
    {
      between[i] = between[j] = 1;
    }
  }
  std::vector<int> result;
  for (std::size_t l = 0, i = 0; l < in.topo.boundaryLoops.size(); ++l)
  {
    for (const int p : in.topo.boundaryLoops[l])
    {
      if (between[i++])
      {
        result.push_back(p);
      }
    }
  }
  return result;
}

LoopGaps pointsNearOtherLoops(const Inputs& in, double reach)
{
  std::vector<int> loopOf;
  const std::vector<std::pair<int, int>> pairs = pairsAcrossLoops(in, reach, loopOf);
  std::vector<int> point; // per flattened boundary point, its surface point
  for (const std::vector<int>& loop : in.topo.boundaryLoops)
  {
    point.insert(point.end(), loop.begin(), loop.end());
  }
  LoopGaps r;
  r.gap.assign(static_cast<std::size_t>(in.numVertices()), std::numeric_limits<double>::infinity());
  std::vector<char> near(point.size(), 0);
  for (const auto& [i, j] : pairs)
  {
    near[i] = near[j] = 1;
    if (loopOf[i] != loopOf[j])
    {
      const Eigen::Vector3d a = in.V.row(point[i]).transpose(), b = in.V.row(point[j]).transpose();
      const double d = (a - b).norm();
      r.gap[point[i]] = std::min(r.gap[point[i]], d);
      r.gap[point[j]] = std::min(r.gap[point[j]], d);
    }
  }
  for (std::size_t i = 0; i < point.size(); ++i)
  {
    if (near[i])
    {
      r.points.push_back(point[i]);
    }
  }
  return r;
}

bool regridDefectiveMap(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, const Eigen::VectorXd& continuous, bool greedy, Eigen::VectorXd& x,
  Defects& defects, Parameterization& out, const Progress& progress)
{
  const int tries = maximumTries(in);
  const double edgeLength = out.edgeLength;
  const double cells = sys.faceArea.sum() / (edgeLength * edgeLength);
  // a large map keeps its grid: its defects are local, each trial costs a repair of the whole
  // map, and a grid twice as fine (rocker-arm, smoothest field) changed a valid mesh of 6,500
  // quads into one of 13,000 with a quad against the surface
  if (tries <= 0 || !rankedByQuads(in, sys, edgeLength))
  {
    return false;
  }
  int bestRank = mapRank(in, defects, sys.uv(x), out.cornerSector);
  if (bestRank == 0 ||
    (out.untangleBudgetSpent &&
      in.numFaces() > SpentTrianglesPerQuad * in.options.maximumRegridQuadCount))
  {
    return false;
  }
  // the trials share one repair's untangling budget: a map that no grid can repair (the
  // teapot's sliver cone) costs at most twice the time, not seven times
  const double trialShare = 1.0 / tries;
  const Eigen::VectorXd rhs = sys.rhs;
  const double energyNorm = sys.energyNorm;
  // the scale (in 1 / edgeLength) of the best map so far; 1: the first
  double bestScale = 1.0;
  // a map whose quads keep the topology and face the right way (its defects only make some
  // quads irregular) changes its grid by at most a factor 2: the teapot's spout, 4 points wound
  // the wrong way at its share of 6,500 quads, was clean only at 4 times the quads, whose edges
  // half as long as the body's took the whole teapot's edge RSD from 15.8% to 30.5% (a coarse
  // cone's quads, turned inside out at 500 quads, still try every grid)
  const bool topologyKept =
    in.options.pureQuads && bestRank == 1 && quadsFaceRight(in, sys.uv(x), out.cornerSector);
  for (int i = 0; i < tries && bestRank > 0; ++i)
  {
    const double q = QuadFactors[i];
    if (topologyKept && (q > 2.0 || q < 0.5))
    {
      continue;
    }
    // (a coarser grid may have fewer cells than the field's singularities ask, and is kept only
    // when its map ranks better: bunny-lowres at 100 quads is valid on a quarter of the grid
    // those ask, and folds against the surface on theirs)
    if (q < 1.0 && cells * q < in.options.minimumComponentQuadCount)
    {
      continue; // never fewer quads than a component must have
    }
    if (q > 4.0 && cells * q > in.options.maximumRegridQuadCount)
    {
      continue; // the finest grids only while the trial stays small
    }
    const double scale = std::sqrt(q);
    sys.rhs = rhs * scale;
    sys.energyNorm = energyNorm * scale * scale;
    Parameterization trial = out;
    trial.edgeLength = edgeLength / scale;
    trial.untangleRegions = 0;
    trial.separatedBranchPoints = 0;
    trial.separatedBoundaryLines = 0;
    trial.untangleEvaluations = 0;
    const Progress part = halving(progress, i);
    Eigen::VectorXd xt = continuous * scale;
    // a trial also keeps apart the branch points around one point, not only those of one
    // triangle: cones packed closer than a cell, two on one grid point, close one of them up (a
    // piece of the truck of genus 3: 16 cones, 11 points wound the wrong way on every grid). On
    // every map it changed valid meshes into invalid ones (cheburashka and decimated-knight,
    // smoothest field, 1,000 quads).
    const Eigen::VectorXd integers =
      roundIntegers(in, field, sys, xt, factor, greedy, trial, part.part(0.0, 0.1), true);
    solveWithIntegersFixed(sys, factor, integers, greedy, xt, trial);
    Defects found;
    found.flipped = flippedFaces(sys.uv(xt), trial.cornerSector, sys.faceArea);
    trial.flippedRounded = static_cast<int>(found.flipped.size());
    trial.energyRounded = sys.energy(xt);
    found.wrong = wrongWindings(in, field, trial, sys.uv(xt), sys.faceArea);
    repairMap(
      in, field, sys, xt, found, repairBudget(in, out, trialShare), trial, part.part(0.1, 1.0));
    ++out.regrids;
    out.untangleEvaluations += trial.untangleEvaluations;
    // a better map replaces the first (an earlier trial wins a tie): one with fewer defects can
    // still give worse quads (the teapot's spout, smoothest field: 9 defects and valid quads; 1
    // defect at 4 times the quads, a -1/4 cone closed up, and a quad against the surface), so
    // only one without defects (but flat triangles) or one whose quads keep the topology does
    const int trialRank = mapRank(in, found, sys.uv(xt), trial.cornerSector);
    if (trialRank < bestRank)
    {
      bestRank = trialRank;
      trial.regrids = out.regrids;
      trial.untangleEvaluations = out.untangleEvaluations;
      out = std::move(trial);
      x = std::move(xt);
      defects = std::move(found);
      bestScale = scale;
    }
  }
  // the system as the kept map's scale has it (its energy is measured with it)
  sys.rhs = rhs * bestScale;
  sys.energyNorm = energyNorm * bestScale * bestScale;
  progress.report(1.0);
  return bestScale != 1.0;
}
}
}
