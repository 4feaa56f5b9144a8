// MapRepair.cxx: the integer-grid map's flipped triangles untangled and its fans wound the wrong
// way laid out again (the winding check and up to three untangling attempts).
#include "ParameterizationSteps.h"

#include "Untangler.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadcover
{
namespace param
{
namespace
{
/// The angle of the surface at corner k of face f.
double cornerAngle(const Inputs& in, int f, int k)
{
  const Eigen::Vector3d a = in.V.row(in.F(f, (k + 1) % 3)) - in.V.row(in.F(f, k));
  const Eigen::Vector3d b = in.V.row(in.F(f, (k + 2) % 3)) - in.V.row(in.F(f, k));
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

Eigen::VectorXd areaRoots(const Eigen::VectorXd& faceArea)
{
  Eigen::VectorXd sqrtArea = Eigen::VectorXd::Zero(faceArea.size());
  for (Eigen::Index f = 0; f < faceArea.size(); ++f)
  {
    sqrtArea[f] = std::sqrt(std::max(0.0, faceArea[f]));
  }
  return sqrtArea;
}

/**
 * The repair of one map. A least-squares map puts the extra quarter turn of a negative cone into
 * one triangle, which flips; untangled the wrong way, the fan closes up into 90 degrees (index
 * +3/4) next to a point wound twice. Such fans are laid out again before they are untangled.
 */
class MapRepair
{
public:
  MapRepair(const Inputs& in, const Field& field, const SeamlessSystem& sys,
    const Parameterization& out, long long budget, const Progress& progress)
    : in_(in)
    , field_(field)
    , sys_(sys)
    , out_(out)
    , Dr_(sys.D)
    , sqrtArea_(areaRoots(sys.faceArea))
    , given_(budget)
    , work_(given_)
    , untangler_{ Dr_, sys.D, sqrtArea_, out.edgeLength, sys.cellScale, sys.numReal, &work_,
      Untangler::DefaultTheta, in.options.numberOfThreads }
    , progress_(progress)
    , rankedByQuads_(rankedByQuads(in, sys, out.edgeLength))
  {}

  /// Up to three attempts: the fans wound the wrong way are laid out again (cones first, then
  /// in later attempts every point listed) and held while their surroundings untangle; then
  /// everything untangles, those fans free again. Each attempt goes on from the map the one
  /// before left; the best attempt is kept, a later one on a tie (score). A large map (one
  /// not ranked by its quads) gets the first attempt only: on the shared surfaces at 1,000,
  /// 3,000 and 6,500 quads the later ones of a large map left as many defects give or take two
  /// (armadillo 24, 24, 22 at 3,000 quads; 16, 16, 18 at 6,500), for two thirds of its
  /// untangling time (1.1 of 1.6 s). Adds the neighbourhoods untangled to regions.
  void attempts(Eigen::VectorXd& x, Defects& defects, int& regions)
  {
    Eigen::VectorXd xs = sys_.P * x;
    Eigen::VectorXd bestX;
    Defects best;
    std::pair<int, std::size_t> bestScore;
    const int maxAttempts = rankedByQuads_ ? 3 : 1;
    for (int attempt = 0; attempt < maxAttempts && defects.count() > 0 && !untangler_.spent();
         ++attempt)
    {
      // cones first: a point wound twice is usually the neighbour of a cone closed up into
      // 90 degrees, and comes right with it
      std::stable_sort(defects.wrong.begin(), defects.wrong.end(),
        [&](int a, int b) { return isCone(a) > isCone(b); });
      std::vector<char> frozen(xs.size(), 0);
      for (const int p : defects.wrong)
      {
        if (isCone(p) || attempt > 0)
        {
          layOut(p, xs, frozen);
        }
      }
      x.head(sys_.numReal) = xs.head(sys_.numReal);
      // the new fans held first, so that their winding stays, then everything
      if (!defects.wrong.empty())
      {
        defects.flipped = flippedIn(x);
        untangleRings(xs, x, defects.flipped, frozen);
      }
      regions += untangleRings(xs, x, defects.flipped, {});
      defects.wrong = wrongIn(x);
      const std::pair<int, std::size_t> attemptScore = score(x, defects);
      if (attempt > 0 && attemptScore > bestScore)
      {
        continue;
      }
      bestX = x;
      best = defects;
      bestScore = attemptScore;
    }
    if (bestX.size() > 0)
    {
      x = bestX;
      defects = best;
    }
  }

  bool spent() const { return untangler_.spent(); }
  /// The triangle energy evaluations spent so far.
  long long used() const { return given_ - work_; }
  /// How good the map x is, lower better: its defects, and before them, on a rounded map small
  /// enough to cut its quads out, its rank (mapRank: whether its quads keep the surface's
  /// topology, then whether it has defects but flat triangles). Fewer
  /// defects can still give worse quads: on a piece of the truck of genus 3 (16 cones) the
  /// repair took a map of 23 defects whose quads keep the handles to one of 8 that loses them.
  std::pair<int, std::size_t> score(const Eigen::VectorXd& x, const Defects& d) const
  {
    const int r = rankedByQuads_ ? mapRank(in_, d, sys_.uv(x), out_.cornerSector) : 0;
    return { r, d.count() };
  }

private:
  /// The widest neighbourhood untangled, in rings (2, 4, then 8). A fourth free pass at 16 rings
  /// lowered the flips in 7 of its 419 runs over the robustness corpus (59 surfaces and the
  /// shared meshes refined, at 1,000, 3,000 and 6,500 quads) and cost an eighth of all the
  /// untangling's seconds; without it the same 27 of the 33 runs that changed are valid
  /// (Benchmarks/README.md "2026-12-07 (8)").
  static constexpr int MaximumRings = 8;

  bool isCone(int p) const { return field_.topology.layerShift[p] != 0; }
  std::vector<int> flippedIn(const Eigen::VectorXd& x) const
  {
    return flippedFaces(sys_.uv(x), out_.cornerSector, sys_.faceArea);
  }
  std::vector<int> wrongIn(const Eigen::VectorXd& x) const
  {
    return wrongWindings(in_, field_, out_, sys_.uv(x), sys_.faceArea);
  }

  /// Untangles neighbourhoods of 2, 4, ... MaximumRings rings around the flipped triangles while
  /// any are left, the frozen unknowns held; xs (symbols) and x (columns) move together.
  /// Returns the number of neighbourhoods untangled.
  int untangleRings(Eigen::VectorXd& xs, Eigen::VectorXd& x, std::vector<int>& flipped,
    const std::vector<char>& frozen)
  {
    int regions = 0;
    for (int rings = 2; rings <= MaximumRings && !flipped.empty() && !untangler_.spent();
         rings *= 2)
    {
      untangler_.run(in_.topo, in_.F, flipped, rings, in_.options.maximumUntangleRounds, xs, frozen,
        halving(progress_, runs_++));
      ++regions;
      x.head(sys_.numReal) = xs.head(sys_.numReal);
      flipped = flippedIn(x);
    }
    return regions;
  }

  /// Lays the fan of p out again: ring points at their distance in grid units, the corner
  /// angles at p the triangle's own scaled to add up to 2 pi (1 - index), turning with the
  /// charts across cut edges. A ring point moves when its (u, v) are two real unknowns (a 2 x 2
  /// system).
  void layOut(int p, Eigen::VectorXd& xs, std::vector<char>& frozen) const
  {
    const MeshTopology& topo = in_.topo;
    const int begin = topo.ringOffsets[p];
    const int n = topo.ringOffsets[p + 1] - begin;
    double total = 0.0;
    for (int i = 0; i < n; ++i)
    {
      const int f = topo.ringFaces[begin + i];
      total += cornerAngle(in_, f, MeshTopology::cornerOf(in_.F, f, p));
    }
    const double stretch = 2 * Pi * (1 - field_.topology.index[p]) / total;
    if (!(stretch > 0))
    {
      return; // index 1 or more: no fan can close up around it
    }
    // the first face's edge from p to its next corner keeps its direction
    int f = topo.ringFaces[begin];
    int k = MeshTopology::cornerOf(in_.F, f, p);
    const int s0 = out_.cornerSector[3 * f + k];
    const int s1 = out_.cornerSector[3 * f + (k + 1) % 3];
    double direction = std::atan2(sys_.sectorValue(xs, s1, 1) - sys_.sectorValue(xs, s0, 1),
      sys_.sectorValue(xs, s1, 0) - sys_.sectorValue(xs, s0, 0));
    for (int i = 0; i < n; ++i)
    {
      f = topo.ringFaces[begin + i];
      k = MeshTopology::cornerOf(in_.F, f, p);
      const int cone = out_.cornerSector[3 * f + k];
      direction += stretch * cornerAngle(in_, f, k);
      // place the face's other ring point (corner k + 2) in this face's chart
      const Eigen::Vector3d b = in_.V.row(in_.F(f, (k + 2) % 3)) - in_.V.row(in_.F(f, k));
      const double cell = sys_.cell(f);
      const double radius = b.norm() / (out_.edgeLength * cell); // in the local grid's units
      const Eigen::Vector2d target(sys_.sectorValue(xs, cone, 0) + radius * std::cos(direction),
        sys_.sectorValue(xs, cone, 1) + radius * std::sin(direction));
      place(out_.cornerSector[3 * f + (k + 2) % 3], target, xs, frozen);
      // into the next face's chart: the edge p -> ring turns with the chart across the edge
      const int g = topo.faceNeighbors(f, (k + 2) % 3);
      if (g >= 0)
      {
        direction += out_.combedMatching(f, (k + 2) % 3) * Pi / 2;
      }
    }
  }

  /// Moves sector `ring` to `target` where its (u, v) are two real symbols (or one, on a
  /// boundary line: along it), and freezes them.
  void place(
    int ring, const Eigen::Vector2d& target, Eigen::VectorXd& xs, std::vector<char>& frozen) const
  {
    int sym[2] = { -1, -1 };
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    Eigen::Vector2d rest = target;
    bool movable = true;
    for (int c = 0; c < 2; ++c)
    {
      for (const auto& t : sys_.sectorExpr[2 * ring + c])
      {
        if (t.first >= sys_.numReal)
        {
          rest[c] -= t.second * xs[t.first];
          continue;
        }
        int slot = sym[0] == t.first ? 0 : (sym[1] == t.first ? 1 : (sym[0] < 0 ? 0 : 1));
        if (sym[slot] >= 0 && sym[slot] != t.first)
        {
          movable = false;
        }
        sym[slot] = t.first;
        M(c, slot) += t.second;
      }
    }
    if (movable && sym[0] >= 0 && sym[1] >= 0 && std::abs(M.determinant()) > 1e-9)
    {
      const Eigen::Vector2d solved = M.inverse() * rest;
      xs[sym[0]] = solved[0];
      xs[sym[1]] = solved[1];
      frozen[sym[0]] = frozen[sym[1]] = 1;
    }
    else if (movable && sym[0] >= 0 && sym[1] < 0 && M.col(0).squaredNorm() > 1e-18)
    {
      // one coordinate on a boundary line: move along it
      xs[sym[0]] = M.col(0).dot(rest) / M.col(0).squaredNorm();
      frozen[sym[0]] = 1;
    }
  }

  const Inputs& in_;
  const Field& field_;
  const SeamlessSystem& sys_;
  const Parameterization& out_;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Dr_;
  const Eigen::VectorXd sqrtArea_;
  const long long given_;     // the untangling's budget
  long long work_;            // what the untangling may still spend, in triangle energy evaluations
  const Untangler untangler_; // in symbols: only the real ones move, and they are the real columns
  /// How many untangling runs there will be is not known beforehand: run k of the repair gets
  /// the part halving(progress_, k).
  const Progress progress_;
  const bool rankedByQuads_; // attempts ranked by their quads' topology first
  int runs_ = 0;
};
}

std::vector<int> wrongWindings(const Inputs& in, const Field& field, const Parameterization& out,
  const Eigen::MatrixX2d& uv, const Eigen::VectorXd& faceArea)
{
  const std::vector<int>& sector = out.cornerSector;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(in.numVertices());
  std::vector<char> unknown(in.numVertices(), 0); // at a corner of a triangle left out
  for (int f = 0; f < in.numFaces(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      unknown[in.F(f, k)] |= !(faceArea[f] > 0.0);
      const Eigen::Vector2d z = uv.row(sector[3 * f + k]).transpose();
      const Eigen::Vector2d a = uv.row(sector[3 * f + (k + 1) % 3]).transpose() - z;
      const Eigen::Vector2d b = uv.row(sector[3 * f + (k + 2) % 3]).transpose() - z;
      sum[in.F(f, k)] += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  }
  std::vector<int> wrong;
  for (int p = 0; p < in.numVertices(); ++p)
  {
    if (!in.topo.boundaryVertex[p] && in.topo.ringOrdered[p] && !unknown[p] &&
      std::abs(sum[p] - 2 * Pi * (1 - field.topology.index[p])) > 1e-3)
    {
      wrong.push_back(p);
    }
  }
  return wrong;
}

long long untangleBudget(const Inputs& in)
{
  return static_cast<long long>(std::max(0, in.options.untangleWork)) *
    std::min<long long>(in.numFaces(), UntangleBudgetTriangles);
}

long long repairBudget(const Inputs& in, const Parameterization& out, double share)
{
  const double budget = static_cast<double>(untangleBudget(in));
  const double left = UntangleBudgetShares * budget - static_cast<double>(out.untangleEvaluations);
  return static_cast<long long>(std::max(0.0, std::min(share * budget, left)));
}

void repairMap(const Inputs& in, const Field& field, const SeamlessSystem& sys, Eigen::VectorXd& x,
  Defects& defects, long long budget, Parameterization& out, const Progress& progress)
{
  if (defects.count() == 0 || in.options.maximumUntangleRounds <= 0)
  {
    return;
  }
  if (budget <= 0)
  {
    out.untangleBudgetSpent = true; // nothing left to spend
    out.untangleSeconds = 0.0;
    return;
  }
  const auto started = std::chrono::steady_clock::now();
  MapRepair repair(in, field, sys, out, budget, progress);
  // kept in case the repair leaves a map that scores worse than the one it was given
  const Eigen::VectorXd before = x;
  const Defects found = defects;
  repair.attempts(x, defects, out.untangleRegions);
  if (repair.score(before, found) < repair.score(x, defects))
  {
    x = before;
    defects = found;
  }
  out.untangleSeconds = seconds(started);
  out.untangleBudgetSpent = repair.spent();
  out.untangleEvaluations += repair.used();
  progress.report(1.0);
}
}
}
