// Parameterization.cxx: computeParameterization, the integer-grid map as its list of steps (the
// steps are in CutSurface.cxx, SeamlessSystem.cxx, IntegerRounding.cxx, MapRepair.cxx,
// MapRegrid.cxx and MapRefinement.cxx), and
// the figures of how well the map meets the grid.
#include "Parameterization.h"

#include "ConePairs.h"
#include "CurvatureSizing.h"
#include "FrameField.h"
#include "ParameterizationSteps.h"
#include "ThinStrips.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace quadcover
{
using namespace param; // the steps, internal to Core

namespace
{

/// @throws std::invalid_argument (see computeParameterization)
void checkArguments(const Inputs& in)
{
  const int nF = in.numFaces();
  const int nV = in.numVertices();
  if (in.topo.numFaces != nF || in.topo.numVertices != nV || in.frameU.rows() != nF ||
    in.matching.rows() != nF || in.geometry.bases.b1.rows() != nF)
  {
    throw std::invalid_argument("computeParameterization: sizes do not match");
  }
  const std::string matching = checkMatching(in.topo, in.matching);
  if (!matching.empty())
  {
    throw std::invalid_argument(matching); // a user's array: its own words, no function name
  }
  const ParameterizationOptions& options = in.options;
  const bool fromQuadCount = options.targetEdgeLength == 0.0;
  if (!(options.targetEdgeLength >= 0) || !std::isfinite(options.targetEdgeLength) ||
    (fromQuadCount && !(options.targetQuadCount > 0 && std::isfinite(options.targetQuadCount))))
  {
    throw std::invalid_argument("computeParameterization: the target edge length must be positive "
                                "or 0 with a positive target quad count");
  }
  if (!in.topo.isManifold() || !in.topo.isOriented())
  {
    throw std::invalid_argument("computeParameterization: " + in.topo.describeDefects());
  }
}

/// The map's figures known before any step: the edge length to start from, the solver.
Parameterization startMap(const Inputs& in)
{
  Parameterization out;
  out.edgeLength = in.options.targetEdgeLength == 0.0
    ? edgeLengthForQuadCount(in.V, in.F, in.options.targetQuadCount)
    : in.options.targetEdgeLength;
#ifdef QUADCOVER_HAVE_CHOLMOD
  out.solver = "CHOLMOD supernodal LLT";
#else
  out.solver = "Eigen SimplicialLDLT";
#endif
  return out;
}

/// |sum over inner edges of the signed dihedral angle times the edge's length| / area: the
/// surface's mean of k1 + k2 (2 / radius on a sphere, 1 / r on a torus of tube radius r; noise
/// cancels in the sum).
double meanCurvature(const Inputs& in)
{
  const Eigen::MatrixX3d& normal = in.geometry.bases.normal;
  double sum = 0.0;
  for (int f = 0; f < in.numFaces(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = in.topo.faceNeighbors(f, k);
      if (g > f)
      {
        const Eigen::Vector3d e = in.V.row(in.F(f, (k + 1) % 3)) - in.V.row(in.F(f, k));
        const Eigen::Vector3d nf = normal.row(f).transpose();
        const Eigen::Vector3d ng = normal.row(g).transpose();
        sum += std::atan2(e.normalized().dot(nf.cross(ng)), nf.dot(ng)) * e.norm();
      }
    }
  }
  const double area = surfaceArea(in.V, in.F);
  return area > 0 ? std::abs(sum) / area : 0.0;
}

/// Raises the smallest scales of `scale` (#F grid edge over h) to a common floor so that the
/// grid has at most `growth` times the cells of the uniform one (sum A / scale^2 <= growth sum A).
void boundGridGrowth(const Eigen::VectorXd& area, double growth, Eigen::VectorXd& scale)
{
  const auto cells = [&](double floor) {
    double sum = 0.0;
    for (Eigen::Index f = 0; f < scale.size(); ++f)
    {
      const double s = std::max(scale[f], floor);
      sum += area[f] / (s * s);
    }
    return sum;
  };
  const double limit = growth * area.sum();
  if (!(cells(0.0) > limit))
  {
    return;
  }
  double low = scale.minCoeff(), high = 1.0; // cells(low) > limit >= cells(high)
  for (int i = 0; i < 40; ++i)
  {
    const double middle = 0.5 * (low + high);
    (cells(middle) > limit ? low : high) = middle;
  }
  scale = scale.cwiseMax(high);
}

/// The creases (sharpEdges) where a step reads them: the cone pairs (conePairGain), the grid
/// around thin walls (maximumThinStripRefinement) and adaptiveCurvature; else none.
std::vector<char> creasesForTheSteps(const Inputs& in)
{
  const ParameterizationOptions& o = in.options;
  return o.conePairGain > 0 || o.maximumThinStripRefinement > 1 || o.adaptiveCurvature > 0 ||
      o.defectAdaptiveCurvature > 0
    ? sharpEdges(in.topo, in.geometry.bases, o.featureAngle, o.minimumFeatureLength)
    : std::vector<char>();
}

/// sys.cellScale and countedCell: finer around thin strips and walls (thinStripGridScale),
/// around short loops near the field's singular points (out.singularityIndex;
/// shortLoopGridScale) and, with adaptiveCurvature, where the surface curves sharply
/// (curvatureGridScale, at most AdaptiveMaximumGrowth times the uniform grid's cells in all); the
/// finer wins. creases: creasesForTheSteps.
void setGridScale(
  const Inputs& in, const std::vector<char>& creases, SeamlessSystem& sys, Parameterization& out)
{
  sys.cellScale = thinStripGridScale(
    in.V, in.F, in.topo, out.edgeLength, in.options.maximumThinStripRefinement, creases);
  std::vector<int> singular; // inner ones: around a boundary point every ball reaches the boundary
  for (Eigen::Index p = 0; p < out.singularityIndex.size(); ++p)
  {
    if (out.singularityIndex[p] != 0 && !in.topo.boundaryVertex[p])
    {
      singular.push_back(static_cast<int>(p));
    }
  }
  const Eigen::VectorXd loops = shortLoopGridScale(in.V, in.F, in.topo, in.geometry.edgeLength,
    singular, out.edgeLength, in.options.maximumThinStripRefinement);
  if (loops.size() > 0)
  {
    sys.cellScale =
      sys.cellScale.size() > 0 ? Eigen::VectorXd(sys.cellScale.cwiseMin(loops)) : loops;
  }
  const Eigen::VectorXd curved =
    adaptiveGridScale(in, creases, out.edgeLength, in.options.adaptiveCurvature);
  if (curved.size() > 0)
  {
    const Eigen::VectorXd strips =
      sys.cellScale.size() > 0 ? sys.cellScale : Eigen::VectorXd::Ones(in.numFaces());
    sys.cellScale = strips.cwiseMin(curved);
    sys.countedCell = sys.cellScale.cwiseQuotient(curved);
  }
  out.finerGridTriangles = static_cast<int>((sys.cellScale.array() < 1.0).count());
}

/// For ParameterizationOptions::curvatureEdgeLength: the edge length made shorter (the map
/// scaled, as correctEdgeLength does) where it is longer than that over the mean curvature.
void limitEdgeLengthByCurvature(
  const Inputs& in, SeamlessSystem& sys, Eigen::VectorXd& x, Parameterization& out)
{
  const double curvature = meanCurvature(in);
  const double longest = in.options.curvatureEdgeLength / curvature;
  if (in.options.targetEdgeLength != 0.0 || !(curvature > 0) || !(out.edgeLength > longest))
  {
    return;
  }
  refineGrid(out.edgeLength / longest, sys, x, out);
}

/// out.sectorUV and cornerUV from the columns' values x.
void storeMap(const SeamlessSystem& sys, const Eigen::VectorXd& x, Parameterization& out)
{
  out.sectorUV = sys.uv(x);
  out.cornerUV = cornerUVOf(out.sectorUV, out.cornerSector);
}

/// out.maxSeamError: how far the translations across the cut are from Z^2.
void measureSeams(const Inputs& in, Parameterization& out)
{
  const MeshTopology& topo = in.topo;
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (!out.cut.onCut[e])
    {
      continue;
    }
    const int c0 = topo.edgeCorners(e, 0);
    const int f = c0 / 3;
    const int g = topo.edgeCorners(e, 1) / 3;
    const int r = out.combedMatching(f, c0 % 3);
    for (int end = 0; end < 2; ++end)
    {
      const int p = topo.edges(e, end);
      const Eigen::Vector2d a = out.sectorUV.row(sectorOf(in.F, out, f, p)).transpose();
      const Eigen::Vector2d b = out.sectorUV.row(sectorOf(in.F, out, g, p)).transpose();
      Eigen::Vector2d rotated = a;
      for (int q = 0; q < r; ++q)
      {
        rotated = Eigen::Vector2d(-rotated.y(), rotated.x());
      }
      const Eigen::Vector2d t = b - rotated;
      out.maxSeamError =
        std::max(out.maxSeamError, (t - t.array().round().matrix()).cwiseAbs().maxCoeff());
    }
  }
}

/// The frames of in turned to agree with `newMatching` (fitFramesToMatchings), those `held`
/// staying: frameU and matching set.
void fitFrames(const Inputs& in, const Eigen::MatrixX3i& newMatching, const std::vector<char>& held,
  Eigen::MatrixX3d& frameU, Eigen::MatrixX3i& matching)
{
  const Eigen::VectorXd alpha = fitFramesToMatchings(in.V, in.F, in.topo, in.geometry, in.frameU,
    newMatching, Eigen::VectorXd(), MatchingOptions().fitSmoothingWeight, held);
  frameU = in.frameU;
  Eigen::MatrixX3d frameV(frameU.rows(), 3); // turned along, not used
  for (int f = 0; f < in.numFaces(); ++f)
  {
    frameV.row(f) = in.geometry.bases.normal.row(f).cross(frameU.row(f));
  }
  rotateFrames(in.geometry.bases, alpha, frameU, frameV);
  matching = newMatching;
}

/// Pairs of opposite quarter cones where the field's singularities leave the quads' size uneven,
/// and moves of its own quarters (conePairsForEvenScale, options.conePairGain), made along paths
/// (addConePairs); all frames then turn to agree but those along the boundary and sharp edges.
/// Returns the pairs added and `moved` the quarters moved; frameU and matching are set when
/// either is above 0. sharp: creasesForTheSteps.
int addConePairsForEvenScale(const Inputs& in, const std::vector<char>& sharp,
  const FrameTopology& given, double edgeLength, Eigen::MatrixX3d& frameU,
  Eigen::MatrixX3i& matching, int& moved)
{
  moved = 0;
  if (!(in.options.conePairGain > 0))
  {
    return 0;
  }
  ConePairOptions options;
  options.minimumGain = in.options.conePairGain;
  options.numberOfThreads = in.options.numberOfThreads;
  const ConePairs chosen = conePairsForEvenScale(
    in.V, in.F, in.topo, in.geometry.defect, given.index, edgeLength, sharp, options);
  if (chosen.pairs.empty())
  {
    return 0;
  }
  FrameTopology topology = given;
  std::vector<char> changed;
  const int added =
    addConePairs(in.F, in.topo, in.geometry, in.frameU, topology, chosen, changed, moved);
  if (added + moved == 0)
  {
    return 0;
  }
  // all free but along the boundary and sharp edges: held within a few grid edges of the pairs,
  // the frames kept the pairs' turning close to them (median edge RSD of the shared meshes
  // 10.1 -> 10.5%)
  std::vector<char> held(in.F.rows(), 0);
  for (int f = 0; f < in.numFaces(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      held[f] |= in.topo.faceNeighbors(f, k) < 0 || sharp[in.topo.faceEdges(f, k)];
    }
  }
  fitFrames(in, topology.matching, held, frameU, matching);
  return added;
}

/// Opposite quarter singularities closer than options.minimumSingularitySeparation grid edges
/// cancelled (cancelClosePairs): no grid can put both on grid points without stretching the
/// quads between them (armadillo's smoothest field at 1,000 quads: 180 singularities, dozens of
/// pairs within a grid edge, and a map that folds). Then quarters closer than a third of the
/// separation to one of the same index, or closer than a grid edge to the boundary, move apart,
/// to the separation (moveCloseQuartersApart), their number in `moved`. The frames within a few
/// grid edges of the changed edges turn to agree with the new matchings (fitFramesToMatchings), the
/// rest held. `given` is the field of in's matchings (evaluateField). Returns the pairs cancelled;
/// frameU and matching are set when any changed.
int settleSingularitiesCloserThanGrid(const Inputs& in, const FrameTopology& given,
  double edgeLength, Eigen::MatrixX3d& frameU, Eigen::MatrixX3i& matching, int& moved)
{
  moved = 0;
  const double separation = in.options.minimumSingularitySeparation * edgeLength;
  if (!(separation > 0))
  {
    return 0;
  }
  FrameTopology topology = given;
  std::vector<char> changed;
  const int cancelled =
    cancelClosePairs(in.F, in.topo, in.geometry, in.frameU, topology, separation, changed);
  std::vector<char> movedFaces;
  moved = moveCloseQuartersApart(in.F, in.topo, in.geometry, in.frameU, topology, separation / 3.0,
    separation, edgeLength, movedFaces);
  if (cancelled == 0 && moved == 0)
  {
    return 0;
  }
  for (int f = 0; f < in.numFaces(); ++f)
  {
    changed[f] = changed[f] || movedFaces[f];
  }
  // free: the faces within 2 separations (in rings of the reference length) of a changed edge
  const int rings = 2 +
    static_cast<int>(std::ceil(2.0 * separation / std::max(in.geometry.referenceLength, 1e-300)));
  std::vector<char> held(in.F.rows(), 1);
  std::vector<int> front;
  for (int f = 0; f < in.numFaces(); ++f)
  {
    if (changed[f])
    {
      held[f] = 0;
      front.push_back(f);
    }
  }
  for (int ring = 0; ring < rings && !front.empty(); ++ring)
  {
    std::vector<int> next;
    for (const int f : front)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int g = in.topo.faceNeighbors(f, k);
        if (g >= 0 && held[g])
        {
          held[g] = 0;
          next.push_back(g);
        }
      }
    }
    front.swap(next);
  }
  fitFrames(in, topology.matching, held, frameU, matching);
  return cancelled;
}

/**
 * The map repaired, and where it keeps defects tried on other grids (regridDefectiveMap). A map
 * that other grids are tried for is first repaired with the budget of one trial: where its grid
 * cannot be repaired cheaply another one mostly can (the truck's pieces of a few hundred
 * triangles spent their whole budget, 0.25 to 0.4 s each, and kept 2 to 10 defects). When no
 * other grid does better and that budget was spent, its repair is done again from the start with
 * what the map has left (repairBudget), if that is more, and kept if it has no more defects.
 */
void repairFirstThenRegrid(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, const Eigen::VectorXd& continuous, bool greedy, bool round,
  Eigen::VectorXd& x, Defects& defects, Parameterization& out, const Progress& progress)
{
  const int trials = round ? regridTrials(in, sys, out.edgeLength) : 0;
  const Eigen::VectorXd given = x;
  const Defects found = defects;
  const long long firstBudget = repairBudget(in, out, trials > 0 ? 1.0 / trials : 1.0);
  repairMap(in, field, sys, x, defects, firstBudget, out, progress.part(0.0, 0.4));
  const bool spent = out.untangleBudgetSpent;
  const bool replaced = round &&
    regridDefectiveMap(
      in, field, sys, factor, continuous, greedy, x, defects, out, progress.part(0.4, 0.7));
  // what is left after the trials (with maximumRegrids 1 or 2 no more than the first had)
  const long long again = repairBudget(in, out, 1.0);
  if (trials > 0 && !replaced && spent && defects.count() > 0 && again > firstBudget)
  {
    const double firstSeconds = out.untangleSeconds;
    Eigen::VectorXd first = std::move(x);
    Defects firstDefects = std::move(defects);
    x = given;
    defects = found;
    repairMap(in, field, sys, x, defects, again, out, progress.part(0.7, 1.0));
    out.untangleSeconds += firstSeconds;
    if (defects.count() > firstDefects.count())
    {
      x = std::move(first);
      defects = std::move(firstDefects);
      out.untangleBudgetSpent = true;
    }
  }
  progress.report(1.0);
}

/// out.branchPointsOnGrid: the branch points mapped to integer (u, v).
void countBranchPointsOnGrid(const Field& field, Parameterization& out)
{
  std::vector<char> branch = field.branch;
  for (int s = 0; s < static_cast<int>(out.sectorPoint.size()); ++s)
  {
    const int p = out.sectorPoint[s];
    if (branch[p])
    {
      const Eigen::RowVector2d uv = out.sectorUV.row(s);
      if ((uv - uv.array().round().matrix()).cwiseAbs().maxCoeff() < 1e-6)
      {
        branch[p] = 0; // count each point once
        ++out.branchPointsOnGrid;
      }
    }
  }
}
}

namespace param
{
void limitEdgeLengthBySingularities(
  const Inputs& in, SeamlessSystem& sys, Eigen::VectorXd& x, Parameterization& out)
{
  const double wanted = in.options.minimumQuadsPerSingularity * out.branchPoints;
  if (in.options.targetEdgeLength != 0.0 || !(wanted > 0) || sys.numColumns() == 0)
  {
    return;
  }
  const double cells = countedCells(in, sys, x, out);
  if (cells > 0 && cells < wanted)
  {
    refineGrid(std::sqrt(wanted / cells), sys, x, out);
    out.finerForSingularities = true;
  }
}

Eigen::VectorXd adaptiveGridScale(
  const Inputs& in, const std::vector<char>& creases, double edgeLength, double edgeOverRadius)
{
  constexpr double AdaptiveMaximumRefinement = 8.0;
  Eigen::VectorXd curved = curvatureGridScale(
    in.V, in.F, in.topo, edgeLength, edgeOverRadius, AdaptiveMaximumRefinement, creases);
  if (curved.size() > 0)
  {
    Eigen::VectorXd area(in.numFaces());
    for (int f = 0; f < in.numFaces(); ++f)
    {
      area[f] = triangleArea(in.V, in.F, f);
    }
    boundGridGrowth(area, AdaptiveMaximumGrowth, curved);
  }
  return curved;
}
}

double edgeLengthForQuadCount(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, double quads)
{
  if (!(quads > 0))
  {
    throw std::invalid_argument("the quad count must be positive");
  }
  return std::sqrt(surfaceArea(V, F) / quads);
}

namespace
{

/// The map of one component: its singularities settled, cone pairs added, cut, solved, rounded
/// and repaired.
Parameterization mapComponent(const Inputs& given, const Progress& progress)
{
  const Eigen::MatrixX3d& V = given.V;
  const Eigen::MatrixX3i& F = given.F;
  const MeshTopology& topo = given.topo;
  const FrameGeometry& geometry = given.geometry;
  const ParameterizationOptions& options = given.options;
  Parameterization out = startMap(given);
  Field field = evaluateField(given);
  Eigen::MatrixX3d ownFrames;
  Eigen::MatrixX3i ownMatching;
  out.cancelledPairs = settleSingularitiesCloserThanGrid(
    given, field.topology, out.edgeLength, ownFrames, ownMatching, out.movedSingularities);
  const bool changed = out.cancelledPairs > 0 || out.movedSingularities > 0;
  const Inputs settled =
    changed ? Inputs{ V, F, topo, geometry, ownFrames, ownMatching, options } : given;
  if (changed)
  {
    field = evaluateField(settled);
  }
  Eigen::MatrixX3d pairedFrames;
  Eigen::MatrixX3i pairedMatching;
  int movedByScale = 0;
  // the creases, the same for every frame field on this surface
  const std::vector<char> creases = creasesForTheSteps(given);
  out.addedConePairs = addConePairsForEvenScale(
    settled, creases, field.topology, out.edgeLength, pairedFrames, pairedMatching, movedByScale);
  out.movedSingularities += movedByScale;
  const bool paired = out.addedConePairs + movedByScale > 0;
  const Inputs in =
    paired ? Inputs{ V, F, topo, geometry, pairedFrames, pairedMatching, options } : settled;
  if (paired)
  {
    field = evaluateField(in);
  }
  out.layerShift = field.topology.layerShift;
  out.singularityIndex = field.topology.index;

  // ---- the surface cut open through the singular points, the frames combed off the cut ----
  cutThroughSingularities(in, field, out);
  progress.report(0.03);
  combFrames(in, out);
  cutIntoSectors(in, out);
  progress.report(0.04);

  // ---- the seamless system: unknowns, constraints eliminated, the energy ----
  Eliminator elim = constrainUnknowns(in, field, out, progress.part(0.04, 0.07));
  SeamlessSystem sys = numberUnknowns(elim, out);
  setGridScale(in, creases, sys, out);
  progress.report(0.08);
  assembleEnergy(in, field, out, sys, progress.part(0.08, 0.22));

  // ---- the continuous minimizer, and the edge length corrected by the map's area ----
  const bool round = options.roundingMode != RoundingMode::None && sys.numInteger > 0;
  const bool greedy = round && options.roundingMode == RoundingMode::Greedy;
  HessianFactor factor;
  Eigen::VectorXd x = solveContinuous(sys, greedy, factor, out, progress.part(0.22, 0.5));
  correctEdgeLength(in, sys, x, out);
  // the adaptive grid already follows the curvature, at most curvatureEdgeLength times the radius
  // (limiting the whole grid again doubled the quads of the fifty components)
  const bool adaptiveCovers = in.options.adaptiveCurvature > 0 &&
    in.options.adaptiveCurvature <= in.options.curvatureEdgeLength;
  if (in.options.curvatureEdgeLength > 0 && !adaptiveCovers)
  {
    limitEdgeLengthByCurvature(in, sys, x, out);
  }
  limitEdgeLengthBySingularities(in, sys, x, out);
  const Eigen::VectorXd continuous = x;
  out.energyContinuous = sys.energy(x);
  out.flippedContinuous =
    static_cast<int>(flippedFaces(sys.uv(x), out.cornerSector, sys.faceArea).size());

  // ---- the integer unknowns rounded, the real ones solved again with them fixed ----
  if (round)
  {
    const Eigen::VectorXd integers =
      roundIntegers(in, field, sys, x, factor, greedy, out, progress.part(0.5, 0.57));
    solveWithIntegersFixed(sys, factor, integers, greedy, x, out);
  }
  progress.report(0.6);
  out.energyRounded = sys.energy(x);
  Defects defects;
  defects.flipped = flippedFaces(sys.uv(x), out.cornerSector, sys.faceArea);
  out.flippedRounded = static_cast<int>(defects.flipped.size());

  // ---- flipped triangles untangled, fans wound the wrong way laid out again ----
  defects.wrong = wrongWindings(in, field, out, sys.uv(x), sys.faceArea);
  repairFirstThenRegrid(
    in, field, sys, factor, continuous, greedy, round, x, defects, out, progress.part(0.6, 0.9));
  if (round)
  {
    adaptAroundThinParts(
      in, creases, field, sys, factor, greedy, x, defects, out, progress.part(0.9, 0.94));
    refineAroundDefects(in, field, sys, factor, greedy, x, defects, out, progress.part(0.94, 0.96));
    refineBetweenJoinedLoops(
      in, field, sys, factor, greedy, x, defects, out, progress.part(0.96, 0.98));
  }
  out.wrongWindings = static_cast<int>(defects.wrong.size());
  out.flipped = static_cast<int>(defects.flipped.size());
  out.energyFinal = sys.energy(x);

  // ---- the map per corner, and how well it meets the grid ----
  storeMap(sys, x, out);
  measureSeams(in, out);
  countBranchPointsOnGrid(field, out);
  progress.report(1.0);
  return out;
}

/// How much finer each grid a map whose quads do not keep the surface's topology is made again
/// on is than the one before (ParameterizationOptions::maximumFinerGridRetries).
constexpr double FinerGridStep = 1.4142135623730951;

/// Defects a repaired map keeps: triangles flipped, points wound the wrong way.
int defectsOf(const Parameterization& map)
{
  return map.flipped + map.wrongWindings;
}

}

Parameterization computeParameterization(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3i& matching, const ParameterizationOptions& options,
  const Progress& progress)
{
  progress.report(0.0);
  const Inputs given{ V, F, topo, geometry, frameU, matching, options };
  checkArguments(given);
  if (topo.numComponents() > 1)
  {
    return mapEachComponent(given, progress);
  }
  Parameterization out = mapComponent(given, progress);
  const bool betweenLoops = topo.numComponents() == 1 && topo.components[0].numBoundaryLoops >= 2;
  const bool withoutPairs = betweenLoops && out.addedConePairs > 0;
  const bool finerGrids = options.pureQuads && options.maximumFinerGridRetries > 0;
  if (defectsOf(out) == 0 || !(withoutPairs || finerGrids))
  {
    return out;
  }
  const auto whole = [&](const Parameterization& map) {
    return !options.pureQuads || keepsTopology(given, map.sectorUV, map.cornerSector);
  };
  bool outWhole = whole(out);
  ParameterizationOptions kept = options;
  // on a surface between two or more boundary loops, a map that keeps defects with cone pairs
  // added is made again without them (nor the moves), and that one kept when it is better: its
  // quads keep the surface's topology where the first map's do not, or neither or both do and it
  // keeps fewer defects (the topology first, as mapRank ranks maps). A pair can turn the frames
  // between the loops (Documentation/Algorithms.md). Elsewhere a second map would only cost time
  // (armadillo, which keeps a few defects either way: 3.0 -> 4.5 s).
  if (withoutPairs)
  {
    ParameterizationOptions plainOptions = options;
    plainOptions.conePairGain = 0.0;
    const Inputs plainInputs{ V, F, topo, geometry, frameU, matching, plainOptions };
    Parameterization plain = mapComponent(plainInputs, progress.part(1.0, 1.0));
    const bool plainWhole = whole(plain);
    if (plainWhole != outWhole ? plainWhole : defectsOf(plain) < defectsOf(out))
    {
      plain.droppedConePairs = out.addedConePairs;
      out = std::move(plain);
      outWhole = plainWhole;
      kept = plainOptions;
    }
  }
  // quads that do not keep the surface's topology: the map made again on uniformly finer grids,
  // the first whose quads keep it kept (the truck's body at 1,000 quads, whose 33 loops the
  // grid's local refinements could not keep apart). Finer than the map's grid and than the grid
  // asked: a trial on a coarser grid may have replaced the first map (MapRegrid.cxx).
  const double edgeLength = std::min(out.edgeLength, startMap(given).edgeLength);
  for (int i = 1; !outWhole && i <= options.maximumFinerGridRetries; ++i)
  {
    ParameterizationOptions finerOptions = kept;
    finerOptions.targetEdgeLength = edgeLength / std::pow(FinerGridStep, i);
    const Inputs finerInputs{ V, F, topo, geometry, frameU, matching, finerOptions };
    Parameterization finer = mapComponent(finerInputs, progress.part(1.0, 1.0));
    if (whole(finer))
    {
      finer.droppedConePairs = out.droppedConePairs;
      finer.finerForSingularities = out.finerForSingularities; // the grid asked was made finer
      finer.finerGridRetries = i;
      out = std::move(finer);
      outWhole = true;
    }
  }
  return out;
}
}
