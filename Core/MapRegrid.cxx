// MapRegrid.cxx: a map that keeps flipped triangles or wrong windings after its repair is rounded
// and repaired again at other grid sizes (finer, coarser) until one has no defects, which is
// kept. The continuous map is linear in 1 / edgeLength, so each grid size costs a rounding, one
// back-substitution and a repair: no new factorization.
#include "ParameterizationSteps.h"

#include <algorithm>
#include <cmath>
#include <iterator>
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
/// grid is fine against the triangles, fewer.
constexpr double QuadFactors[] = { 2.0, 0.5, 4.0, 0.25 };
}

void regridDefectiveMap(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, const Eigen::VectorXd& continuous, bool greedy, Eigen::VectorXd& x,
  Defects& defects, Parameterization& out, const Progress& progress)
{
  const int tries = std::min(in.options.maximumRegrids, static_cast<int>(std::size(QuadFactors)));
  if (defects.count() == 0 || tries <= 0 || sys.numInteger == 0 || out.untangleBudgetSpent)
  {
    return;
  }
  // the trials share one repair's untangling budget: a map that no grid can repair (the
  // teapot's sliver cone) costs at most twice the time, not five times; and a repair that spent
  // its budget is not tried again (armadillo: minutes more for nothing)
  ParameterizationOptions trialOptions = in.options;
  trialOptions.untangleWork = std::max(1, in.options.untangleWork / tries);
  const Inputs trialIn{ in.V, in.F, in.topo, in.geometry, in.frameU, in.matching, trialOptions };
  const Eigen::VectorXd rhs = sys.rhs;
  const double energyNorm = sys.energyNorm;
  const double edgeLength = out.edgeLength;
  // the scale (in 1 / edgeLength) of the best map so far; 1: the first
  double bestScale = 1.0;
  const double cells = sys.faceArea.sum() / (edgeLength * edgeLength);
  if (cells > in.options.maximumRegridQuadCount)
  {
    // a large map keeps its grid: its defects are local, each trial costs a repair of the whole
    // map, and a grid twice as fine (rocker-arm, smoothest field) changed a valid mesh of 6,500
    // quads into one of 13,000 with a quad against the surface
    return;
  }
  for (int i = 0; i < tries && defects.count() > 0; ++i)
  {
    const double q = QuadFactors[i];
    if (q < 1.0 && cells * q < in.options.minimumComponentQuadCount)
    {
      continue; // never fewer quads than a component must have
    }
    const double scale = std::sqrt(q);
    sys.rhs = rhs * scale;
    sys.energyNorm = energyNorm * scale * scale;
    Parameterization trial = out;
    trial.edgeLength = edgeLength / scale;
    trial.untangleRegions = 0;
    trial.separatedBranchPoints = 0;
    trial.untangleEvaluations = 0;
    const Progress part = halving(progress, i);
    Eigen::VectorXd xt = continuous * scale;
    const Eigen::VectorXd integers =
      roundIntegers(trialIn, field, sys, xt, factor, greedy, trial, part.part(0.0, 0.1));
    solveWithIntegersFixed(sys, factor, integers, greedy, xt, trial);
    Defects found;
    found.flipped = flippedFaces(sys.uv(xt), trial.cornerSector);
    trial.flippedRounded = static_cast<int>(found.flipped.size());
    trial.energyRounded = sys.energy(xt);
    found.wrong = wrongWindings(trialIn, field, trial, sys.uv(xt));
    repairMap(trialIn, field, sys, xt, found, trial, part.part(0.1, 1.0));
    ++out.regrids;
    out.untangleEvaluations += trial.untangleEvaluations;
    // only a map without defects replaces the first: one with fewer can still give worse quads
    // (the teapot's spout, smoothest field: 9 defects and valid quads; 1 defect at 4 times the
    // quads, a -1/4 cone closed up, and a quad against the surface)
    if (found.count() == 0)
    {
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
}
}
}
