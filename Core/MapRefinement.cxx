// MapRefinement.cxx: a repaired map that keeps defects, or whose quads join two boundary loops,
// made again on finer cells: around its defects, between the joined loops, on the adaptive grid
// (each trial kept only when it is better).
#include "ParameterizationSteps.h"

#include "ThinStrips.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadcover
{
namespace param
{
namespace
{
/// What a trial on other cells changes of sys, to put back when the trial is not kept.
struct SavedCells
{
  explicit SavedCells(const SeamlessSystem& sys)
    : rhs(sys.rhs)
    , energyNorm(sys.energyNorm)
    , cellScale(sys.cellScale)
    , countedCell(sys.countedCell)
  {}
  void restore(SeamlessSystem& sys) const
  {
    sys.rhs = rhs;
    sys.energyNorm = energyNorm;
    sys.cellScale = cellScale;
    sys.countedCell = countedCell;
  }
  const Eigen::VectorXd rhs;
  const double energyNorm;
  const Eigen::VectorXd cellScale, countedCell;
};

/// sys's cells scaled to `scale` (#F, grid edge over h): the right-hand side and the energy's
/// norm follow them; the energy's matrix, and so the factorization, does not change.
void setCellScale(const Eigen::VectorXd& scale, double h, SeamlessSystem& sys)
{
  const Eigen::Index nF = scale.size();
  const Eigen::VectorXd old = sys.cellScale.size() > 0 ? sys.cellScale : Eigen::VectorXd::Ones(nF);
  for (Eigen::Index f = 0; f < nF; ++f)
  {
    sys.rhs.segment<4>(4 * f) *= old[f] / scale[f];
    sys.energyNorm +=
      2.0 / (h * h) * sys.faceArea[f] * (1.0 / (scale[f] * scale[f]) - 1.0 / (old[f] * old[f]));
  }
  sys.cellScale = scale;
}

/// The map made again on sys's cells as they are now: the continuous map solved with the same
/// factor (its edge length corrected for the quad count when `correctLength`), rounded and
/// repaired with `budget`. Returns the new map (its untangling counted afresh) with x and its
/// defects.
Parameterization remapOnCells(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, bool greedy, bool correctLength, long long budget,
  const Parameterization& out, Eigen::VectorXd& x, Defects& found, const Progress& progress)
{
  x = factor.solver.solve(Eigen::VectorXd(sys.P.transpose() * (sys.D.transpose() * sys.rhs)));
  Parameterization trial = out;
  trial.untangleRegions = 0;
  trial.untangleEvaluations = 0;
  trial.untangleSeconds = 0.0;
  trial.untangleBudgetSpent = false;
  trial.separatedBranchPoints = 0;
  trial.separatedBoundaryLines = 0;
  if (correctLength)
  {
    correctEdgeLength(in, sys, x, trial);
    limitEdgeLengthBySingularities(in, sys, x, trial); // which the correction may undo
  }
  const Eigen::VectorXd integers =
    roundIntegers(in, field, sys, x, factor, greedy, trial, progress.part(0.0, 0.1));
  solveWithIntegersFixed(sys, factor, integers, greedy, x, trial);
  found.flipped = flippedFaces(sys.uv(x), trial.cornerSector, sys.faceArea);
  trial.flippedRounded = static_cast<int>(found.flipped.size());
  trial.energyRounded = sys.energy(x);
  found.wrong = wrongWindings(in, field, trial, sys.uv(x), sys.faceArea);
  repairMap(in, field, sys, x, found, budget, trial, progress.part(0.1, 1.0));
  return trial;
}

/// The trial map (made on sys's cells as they are now) kept in place of out when `better` (the
/// work and time of both maps count, whichever is kept); else sys's cells put back.
void keepTrialIf(bool better, Parameterization&& trial, Eigen::VectorXd&& xt, Defects&& found,
  const SavedCells& saved, SeamlessSystem& sys, Eigen::VectorXd& x, Defects& defects,
  Parameterization& out)
{
  out.untangleEvaluations += trial.untangleEvaluations;
  out.untangleSeconds += trial.untangleSeconds;
  if (better)
  {
    trial.untangleEvaluations = out.untangleEvaluations;
    trial.untangleSeconds = out.untangleSeconds;
    trial.untangleRegions += out.untangleRegions;
    trial.finerGridTriangles = static_cast<int>((sys.cellScale.array() < 1.0).count());
    out = std::move(trial);
    x = std::move(xt);
    defects = std::move(found);
    return;
  }
  saved.restore(sys);
}

/// The trial map kept in place of out when it has fewer defects (keepTrialIf).
void keepFewerDefects(Parameterization&& trial, Eigen::VectorXd&& xt, Defects&& found,
  const SavedCells& saved, SeamlessSystem& sys, Eigen::VectorXd& x, Defects& defects,
  Parameterization& out)
{
  const bool fewer = found.count() < defects.count();
  keepTrialIf(
    fewer, std::move(trial), std::move(xt), std::move(found), saved, sys, x, defects, out);
}

/// sys's cell scale with the grid edge at each of `points` sizeAt(point, the scale of the grid
/// there already is, its smallest over the point's triangles), growing back by a quarter of the
/// distance walked, as around thin strips; never coarser than before.
template<typename SizeAt>
Eigen::VectorXd finerAt(const Inputs& in, const SeamlessSystem& sys, double h,
  const std::vector<int>& points, SizeAt sizeAt)
{
  const int nF = in.numFaces();
  const Eigen::VectorXd oldScale =
    sys.cellScale.size() > 0 ? sys.cellScale : Eigen::VectorXd::Ones(nF);
  std::vector<double> local(static_cast<std::size_t>(in.numVertices()), 1.0);
  for (int f = 0; f < nF; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      local[in.F(f, k)] = std::min(local[in.F(f, k)], oldScale[f]);
    }
  }
  std::vector<double> size(static_cast<std::size_t>(in.numVertices()), h);
  for (const int p : points)
  {
    size[p] = sizeAt(p, local[p]);
  }
  spreadGridSizes(in.V, in.topo, 0.25, size);
  Eigen::VectorXd newScale = oldScale;
  for (int f = 0; f < nF; ++f)
  {
    const double s = (size[in.F(f, 0)] + size[in.F(f, 1)] + size[in.F(f, 2)]) / (3 * h);
    newScale[f] = std::min(oldScale[f], s);
  }
  return newScale;
}

/// sys's cell scale made `finer` times finer around `points` (each asks for its own grid, finer
/// already around a thin strip, over finer; finerAt).
Eigen::VectorXd finerAround(const Inputs& in, const SeamlessSystem& sys, double h, double finer,
  const std::vector<int>& points)
{
  return finerAt(in, sys, h, points, [&](int, double local) { return h * local / finer; });
}

/// sys's cell scale with a grid edge at each of near.points no longer than its gap to the nearest
/// point of another boundary loop over `cellsPerGap`, at most `maximumFiner` times finer than
/// the grid there already is (finerAt).
Eigen::VectorXd finerAtGaps(const Inputs& in, const SeamlessSystem& sys, double h,
  const LoopGaps& near, double cellsPerGap, double maximumFiner)
{
  return finerAt(in, sys, h, near.points, [&](int p, double local) {
    return std::min(h * local, std::max(near.gap[p] / cellsPerGap, h * local / maximumFiner));
  });
}

/// The map made again on sys's cells scaled to `scale` (remapOnCells, with `budget`), kept in
/// place of out when better(trial, its x, its defects) (keepTrialIf). Returns whether it was kept.
template<typename Better>
bool remapOnScale(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, bool greedy, long long budget, const Eigen::VectorXd& scale,
  Eigen::VectorXd& x, Defects& defects, Parameterization& out, const Progress& progress,
  Better better)
{
  const double h = out.edgeLength;
  const SavedCells saved(sys);
  setCellScale(scale, h, sys);
  Eigen::VectorXd xt;
  Defects found;
  Parameterization trial =
    remapOnCells(in, field, sys, factor, greedy, false, budget, out, xt, found, progress);
  const bool keep = better(trial, xt, found);
  keepTrialIf(keep, std::move(trial), std::move(xt), std::move(found), saved, sys, x, defects, out);
  return keep;
}

/// remapOnScale on a grid `finer` times finer around `points` (finerAround).
template<typename Better>
bool remapFinerAround(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, bool greedy, long long budget, double finer,
  const std::vector<int>& points, Eigen::VectorXd& x, Defects& defects, Parameterization& out,
  const Progress& progress, Better better)
{
  return remapOnScale(in, field, sys, factor, greedy, budget,
    finerAround(in, sys, out.edgeLength, finer, points), x, defects, out, progress, better);
}

/// In grid edges, how near to another loop joined to the same quads' loop the points of a
/// boundary loop are refined around (refineBetweenJoinedLoops).
constexpr double JoinedLoopReach = 3.0;

/// How many grids refineBetweenJoinedLoops tries: defectGridRefinement times finer, then its
/// square (at most JoinedLoopMaximumRefinement).
constexpr int JoinedLoopTries = 2;

/// The finest grid between joined loops, over the grid edge (as around a thin strip by default).
constexpr double JoinedLoopMaximumRefinement = 8.0;

/// How many grid cells the grid between every two loops puts across the gap between them, at
/// most (refineBetweenJoinedLoops): with 2 the truck's body at 6,500 quads still joined two pairs
/// of its loops, with 3 and 4 none (20,114 and 21,457 quads).
constexpr double JoinedLoopCellsPerGap = 3.0;

/// A map that keeps more defects than this is beyond what a finer grid between two loops mends:
/// over the robustness corpus at 1,000, 3,000 and 6,500 quads the maps whose quads this refinement
/// kept had at most 16 defects, and the trials on maps of 300 and more (the noise isosurface at
/// 1,000 and 3,000 quads) cost 16 and 24 s, never kept (Benchmarks/README.md "2026-12-07 (5)").
constexpr std::size_t JoinedLoopMaximumDefects = 64;

}

void refineAroundDefects(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, bool greedy, Eigen::VectorXd& x, Defects& defects,
  Parameterization& out, const Progress& progress)
{
  const double finer = in.options.defectGridRefinement;
  // as for the adaptive grid: a map whose repair spent its whole budget is beyond a local repair
  // (the tube narrowing to a point at 500 quads: the second map cost 12 s and kept 3,134
  // defects against 474)
  const long long budget = repairBudget(in, out, 1.0);
  if (defects.count() == 0 || !(finer > 1) || out.untangleBudgetSpent || budget <= 0)
  {
    return;
  }
  std::vector<int> points = defects.wrong;
  for (const int f : defects.flipped)
  {
    for (int k = 0; k < 3; ++k)
    {
      points.push_back(in.F(f, k));
    }
  }
  remapFinerAround(in, field, sys, factor, greedy, budget, finer, points, x, defects, out, progress,
    [&](const Parameterization&, const Eigen::VectorXd&, const Defects& found) {
      return found.count() < defects.count();
    });
}

void refineBetweenJoinedLoops(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, bool greedy, Eigen::VectorXd& x, Defects& defects,
  Parameterization& out, const Progress& progress)
{
  const double finer = in.options.defectGridRefinement;
  if (in.topo.boundaryLoops.empty() || !in.options.pureQuads || !(finer > 1) ||
    defects.count() > JoinedLoopMaximumDefects || repairBudget(in, out, 1.0) <= 0)
  {
    return;
  }
  const double reach = JoinedLoopReach * out.edgeLength;
  const std::vector<int> points = pointsBetweenJoinedLoops(in, sys.uv(x), out.cornerSector, reach);
  if (points.empty())
  {
    return;
  }
  auto whole = [&](const Parameterization& trial, const Eigen::VectorXd& xt, const Defects&) {
    return keepsTopology(in, sys.uv(xt), trial.cornerSector);
  };
  // then finer again: two holes less than half a grid edge apart (a scan's, cut at random) need
  // a grid four times finer between them
  for (int i = 0; i < JoinedLoopTries; ++i)
  {
    const double refinement = std::min(std::pow(finer, i + 1), JoinedLoopMaximumRefinement);
    const long long budget = repairBudget(in, out, 1.0);
    if (budget <= 0 || (i > 0 && refinement <= finer) ||
      remapFinerAround(in, field, sys, factor, greedy, budget, refinement, points, x, defects, out,
        halving(progress, i), whole))
    {
      return;
    }
  }
  const LoopGaps near = pointsNearOtherLoops(in, reach);
  if (near.points.size() <= points.size())
  {
    return;
  }
  // first a grid that puts JoinedLoopCellsPerGap cells across each gap between two loops, then
  // one defectGridRefinement times finer around them all
  long long budget = repairBudget(in, out, 1.0);
  if (budget <= 0 ||
    remapOnScale(in, field, sys, factor, greedy, budget,
      finerAtGaps(
        in, sys, out.edgeLength, near, JoinedLoopCellsPerGap, JoinedLoopMaximumRefinement),
      x, defects, out, halving(progress, JoinedLoopTries), whole))
  {
    return;
  }
  budget = repairBudget(in, out, 1.0);
  if (budget > 0)
  {
    remapFinerAround(in, field, sys, factor, greedy, budget, finer, near.points, x, defects, out,
      halving(progress, JoinedLoopTries + 1), whole);
  }
}

void adaptAroundThinParts(const Inputs& in, const std::vector<char>& creases, const Field& field,
  SeamlessSystem& sys, const HessianFactor& factor, bool greedy, Eigen::VectorXd& x,
  Defects& defects, Parameterization& out, const Progress& progress)
{
  // a quarter of the untangling budget: on a map that no grid repairs (a tube narrowing to a
  // point) the trial would cost as much as the first map's repair again
  constexpr double AdaptiveTrialBudgetShare = 0.25;
  const double edgeOverRadius = in.options.defectAdaptiveCurvature;
  const long long budget = repairBudget(in, out, AdaptiveTrialBudgetShare);
  // a map whose repair spent its whole budget is beyond a local repair: the trial would only
  // add time (a tube narrowing to a point at 500 quads: 41 -> 49 s for a map of 5,520 defects
  // against 474)
  if (defects.count() == 0 || !(edgeOverRadius > 0) || in.options.adaptiveCurvature > 0 ||
    out.untangleBudgetSpent || budget <= 0)
  {
    return;
  }
  const double h = out.edgeLength;
  const Eigen::VectorXd curved = adaptiveGridScale(in, creases, h, edgeOverRadius);
  if (curved.size() == 0)
  {
    return;
  }
  const Eigen::VectorXd given =
    sys.cellScale.size() > 0 ? sys.cellScale : Eigen::VectorXd::Ones(in.numFaces());
  const SavedCells saved(sys);
  setCellScale(given.cwiseMin(curved), h, sys);
  sys.countedCell = sys.cellScale.cwiseQuotient(curved);
  Eigen::VectorXd xt;
  Defects found;
  Parameterization trial =
    remapOnCells(in, field, sys, factor, greedy, true, budget, out, xt, found, progress);
  keepFewerDefects(std::move(trial), std::move(xt), std::move(found), saved, sys, x, defects, out);
}

}
}
