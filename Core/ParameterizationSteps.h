// ParameterizationSteps.h: internal to Core: the steps of computeParameterization and the state
// they share (the surface cut open, the seamless system, rounding, the repair of the map).
#ifndef quadcover_ParameterizationSteps_h
#define quadcover_ParameterizationSteps_h

#include "Eliminator.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "Parameterization.h"
#include "Progress.h"
#include "SparseSolver.h"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

namespace quadcover
{
namespace param
{
constexpr double Pi = 3.14159265358979323846;

using SparseMatrix = Eigen::SparseMatrix<double>;

inline double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// Reports i / n done about every 1% of a loop over n items (cheap on every iteration).
inline void reportEvery(const Progress& progress, int i, int n)
{
  if (i % std::max(1, n / 100) == 0)
  {
    progress.report(static_cast<double>(i) / n);
  }
}

/// The part of `progress` for step i = 0, 1, ... of a sequence that may stop at any step: half
/// of what is left.
inline Progress halving(const Progress& progress, int i)
{
  return progress.part(1.0 - std::ldexp(1.0, -i), 1.0 - std::ldexp(1.0, -i - 1));
}

/// What computeParameterization was given.
struct Inputs
{
  const Eigen::MatrixX3d& V;
  const Eigen::MatrixX3i& F;
  const MeshTopology& topo;
  const FrameGeometry& geometry;
  const Eigen::MatrixX3d& frameU;
  const Eigen::MatrixX3i& matching;
  const ParameterizationOptions& options;

  int numFaces() const { return static_cast<int>(F.rows()); }
  int numVertices() const { return static_cast<int>(V.rows()); }
};

/// The frame field as the steps read it.
struct Field
{
  FrameTopology topology;   ///< evaluateMatchings: index and layer shift per point
  std::vector<char> branch; ///< #V: 1 for an inner point with a non-zero layer shift
  Eigen::VectorXd theta;    ///< #F: the frame's angle in the face basis, before combing
};

/// The map of a surface of several components: computeParameterization on each, with its own
/// edge length (ParameterizationOptions::minimumComponentQuadCount per hole and handle), put
/// together (ComponentMaps.cxx). Parameterization::edgeLength is the largest component's.
Parameterization mapEachComponent(const Inputs& in, const Progress& progress);

// ---- the surface cut open (CutSurface.cxx) ----

/// The field's layer shifts, indices and angles.
Field evaluateField(const Inputs& in);

/// The cut graph through every singular point: out.cut, seamEdges, branchPoints.
void cutThroughSingularities(const Inputs& in, const Field& field, Parameterization& out);

/// Quarter turns so that matchings vanish across every edge off the cut: out.comb,
/// combedMatching, seam.
/// @throws std::logic_error when a matching off the cut remains (a singular point off the cut)
void combFrames(const Inputs& in, Parameterization& out);

/// The corners of a point between cut (or boundary) edges: out.cornerSector, sectorPoint.
void cutIntoSectors(const Inputs& in, Parameterization& out);

/// The sector of point p in face f.
inline int sectorOf(const Eigen::MatrixX3i& F, const Parameterization& out, int f, int p)
{
  return out.cornerSector[3 * f + MeshTopology::cornerOf(F, f, p)];
}

// ---- the seamless system (SeamlessSystem.cxx) ----

/**
 * The map's unknowns after elimination and its energy. Columns are the unknowns left: the real
 * ones (0 .. numReal - 1), then the integer ones. Symbols are what the sectors are written in:
 * the real unknowns (the same as the real columns), then every integer unknown a sector refers
 * to, eliminated or not; P maps symbols to columns (an eliminated integer unknown may be a long
 * sum: a seam's translation sums the branch points beyond it).
 */
struct SeamlessSystem
{
  int numReal = 0;
  int numInteger = 0;
  std::vector<Expr> sectorExpr;    ///< 2 #S: u (2s) and v (2s + 1) of sector s, in symbols
  std::vector<Expr> symbolColumns; ///< integer symbol numReal + k in columns, per k
  SparseMatrix P;                  ///< #symbols x #columns
  /// 4 #F x #symbols: sqrt(A) (grad u . x, grad u . y, grad v . x, grad v . y) per triangle
  SparseMatrix D;
  SparseMatrix H; ///< #columns x #columns: P^T D^T D P, its lower triangle only
  /// 4 #F: sqrt(A) times the combed frame (U', V') / (edgeLength cellScale)
  Eigen::VectorXd rhs;
  Eigen::VectorXd faceArea; ///< #F: 0 for a degenerate triangle (DegenerateAreaRatio; left out)
  /// #F: the grid edge wanted in each triangle over the map's edge length (thinStripGridScale,
  /// curvatureGridScale); empty: 1 everywhere
  Eigen::VectorXd cellScale;
  /// #F: how a cell of each triangle counts against targetQuadCount (correctEdgeLength), in
  /// cells of the uniform grid: cellScale where a thin strip's grid is finer (its few extra
  /// quads come on top), 1 where adaptiveCurvature's is (they count); empty: cellScale
  Eigen::VectorXd countedCell;
  double energyNorm = 0.0; ///< 2 sum A / cellScale^2 / edgeLength^2: the energy's scale

  int numColumns() const { return numReal + numInteger; }
  /// cellScale of face f (1 when cellScale is empty)
  double cell(int f) const { return cellScale.size() > 0 ? cellScale[f] : 1.0; }

  /// Coordinate c (0: u, 1: v) of a sector, from the symbols' values.
  double sectorValue(const Eigen::VectorXd& symbols, int sector, int c) const
  {
    double value = 0.0;
    for (const auto& t : sectorExpr[2 * sector + c])
    {
      value += t.second * symbols[t.first];
    }
    return value;
  }

  /// #S x 2: the (u, v) of every sector, from the columns' values.
  Eigen::MatrixX2d uv(const Eigen::VectorXd& columns) const;

  /// sum A_f |grad phi - K|^2 / (area |K|^2) of the map given by the columns' values.
  double energy(const Eigen::VectorXd& columns) const
  {
    return (D * (P * columns) - rhs).squaredNorm() / energyNorm;
  }
};

/// The unknowns (u, v per sector, a translation per cut edge, boundary and feature lines) and the
/// linear constraints among them, eliminated: the cut's transition functions, boundary and sharp
/// edges on grid lines, one pinned point per component. Sets out.alignedBoundaryEdges,
/// alignedFeatureEdges, constraints and nonUnitPivots.
Eliminator constrainUnknowns(
  const Inputs& in, const Field& field, Parameterization& out, const Progress& progress);

/// The columns and symbols of the unknowns left (numReal, numInteger, sectorExpr,
/// symbolColumns, P); sets out.unknowns and integerUnknowns.
SeamlessSystem numberUnknowns(Eliminator& elim, Parameterization& out);

/// The energy sum_f A_f |grad phi - K_f|^2 with K_f the combed frame / edgeLength: sys.D, H,
/// rhs, faceArea, energyNorm.
void assembleEnergy(const Inputs& in, const Field& field, const Parameterization& out,
  SeamlessSystem& sys, const Progress& progress);

/// Twice the signed (u, v) area of face f.
inline double twiceUVArea(const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector, int f)
{
  const Eigen::Vector2d a = uv.row(cornerSector[3 * f]).transpose();
  const Eigen::Vector2d b = uv.row(cornerSector[3 * f + 1]).transpose();
  const Eigen::Vector2d c = uv.row(cornerSector[3 * f + 2]).transpose();
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

/// The faces whose (u, v) area is not positive, but those left out of the energy (faceArea 0:
/// degenerate, their image only what their corners' other triangles make it).
std::vector<int> flippedFaces(const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector,
  const Eigen::VectorXd& faceArea);

/// The map per corner (#F x 6: u, v at corners 0, 1, 2) from the map per sector.
inline Eigen::MatrixXd cornerUVOf(const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector)
{
  const Eigen::Index nf = static_cast<Eigen::Index>(cornerSector.size() / 3);
  Eigen::MatrixXd cornerUV(nf, 6);
  for (Eigen::Index f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      cornerUV.block<1, 2>(f, 2 * k) = uv.row(cornerSector[3 * f + k]);
    }
  }
  return cornerUV;
}

// ---- solving and rounding (IntegerRounding.cxx) ----

/// H factored once: the continuous solve, and the greedy rounding's conditioning and re-solve.
struct HessianFactor
{
  SpdSolver<double> solver;
  Eigen::MatrixXd S; ///< numInteger x numInteger: the integer block of H^-1 (greedy only)
};

/// The continuous minimizer (#columns), with H factored into `factor` (and S for greedy).
/// @throws std::runtime_error when the factorization fails
Eigen::VectorXd solveContinuous(const SeamlessSystem& sys, bool greedy, HessianFactor& factor,
  Parameterization& out, const Progress& progress);

/// The unit cells the map x covers, a cell of a finer grid (a thin strip's, the adaptive grid's)
/// counted as the cells of the uniform grid it replaces (SeamlessSystem::countedCell): about as
/// many as the quads it gives.
double countedCells(const Inputs& in, const SeamlessSystem& sys, const Eigen::VectorXd& x,
  const Parameterization& out);

/// The grid made `factor` times finer: the map x scaled by it (it is linear in 1 / edgeLength),
/// with the right-hand side and energy scale, out.edgeLength divided by it.
void refineGrid(double factor, SeamlessSystem& sys, Eigen::VectorXd& x, Parameterization& out);

/// For ParameterizationOptions::targetQuadCount: scales the continuous minimizer (refineGrid)
/// so that the map covers about that many unit cells (countedCells).
void correctEdgeLength(
  const Inputs& in, SeamlessSystem& sys, Eigen::VectorXd& x, Parameterization& out);

/// The integer unknowns' values (numInteger), rounded from the continuous minimizer x, greedy
/// (with exact conditioning through factor.S) or simple, never putting two branch points of one
/// triangle (with packedCones: of the faces around one point, in one chart) on one grid point
/// nor two boundary lines that face each other across a thin hole or strip on one line; sets
/// out.separatedBranchPoints and separatedBoundaryLines.
Eigen::VectorXd roundIntegers(const Inputs& in, const Field& field, const SeamlessSystem& sys,
  const Eigen::VectorXd& x, const HessianFactor& factor, bool greedy, Parameterization& out,
  const Progress& progress, bool packedCones = false);

/// The minimizer x (#columns) with the integer unknowns fixed to `integers`.
void solveWithIntegersFixed(const SeamlessSystem& sys, const HessianFactor& factor,
  const Eigen::VectorXd& integers, bool greedy, Eigen::VectorXd& x, Parameterization& out);

// ---- flipped triangles and windings (MapRepair.cxx) ----

/// What is wrong with a map: flipped triangles, inner points wound the wrong way.
struct Defects
{
  std::vector<int> flipped;
  std::vector<int> wrong;

  std::size_t count() const { return flipped.size() + wrong.size(); }
};

/// The inner points around which the map's angles do not add up to 2 pi (1 - index), but the
/// corners of triangles left out of the energy (faceArea 0), whose angles say nothing.
std::vector<int> wrongWindings(const Inputs& in, const Field& field, const Parameterization& out,
  const Eigen::MatrixX2d& uv, const Eigen::VectorXd& faceArea);

/// The untangling's budget of one map, in triangle energy evaluations:
/// ParameterizationOptions::untangleWork per triangle of the surface, a surface of more than
/// UntangleBudgetTriangles triangles counted as one of that many.
long long untangleBudget(const Inputs& in);

/// What one repair of a map may spend (repairMap's `budget`): `share` of untangleBudget, at most
/// what the map has left, UntangleBudgetShares of it less out.untangleEvaluations (what its
/// repairs so far spent: the first, the trials on other grids and cells). 0 when nothing is left.
long long repairBudget(const Inputs& in, const Parameterization& out, double share);

/// All the repairs of one map together (the first, its trials on other grids and cells, a repair
/// done again) spend at most this many times untangleBudget.
constexpr double UntangleBudgetShares = 2.0;

/// A surface of more triangles has the untangling budget of one of this many: the untangling's
/// time of one map stays bounded whatever the surface's size (a repair's share about 4 s on a
/// 2-core machine, all of a map's repairs about 8 s: armadillo at 100 quads; each component has
/// a map of its own). Its flips lie around the
/// singularities and the grid's folds, whose number does not grow with the triangles.
constexpr long long UntangleBudgetTriangles = 20000;

/// Untangles the flipped triangles of x and lays out again the fans wound the wrong way (up to
/// three attempts on a map ranked by its quads, else one), keeping the best map: the one with
/// the fewest defects, or on a rounded map small enough to cut its quads out (rankedByQuads) the
/// best by mapRank first. Ties go to the later attempt, then to the repaired map over x as it was
/// given. Spends at most `budget` triangle energy evaluations (repairBudget). Updates `defects`
/// and out.untangleRegions, untangleSeconds, untangleEvaluations, untangleBudgetSpent.
void repairMap(const Inputs& in, const Field& field, const SeamlessSystem& sys, Eigen::VectorXd& x,
  Defects& defects, long long budget, Parameterization& out, const Progress& progress);

// ---- maps that keep defects (MapRegrid.cxx) ----

/// How good the map uv is, best first: 0 without defects (but flat triangles, a sliver laid on a
/// line) and with quads (cut out and patched as the quad stage does) of the surface's topology;
/// 1 with that topology; 2 without defects; 3 neither. Without PureQuads the topology is not
/// checked.
int mapRank(const Inputs& in, const Defects& defects, const Eigen::MatrixX2d& uv,
  const std::vector<int>& cornerSector);

/// Is the map rounded (integer unknowns, a RoundingMode) and small enough (at most
/// maximumRegridQuadCount grid cells) that its quads are cut out to rank it (mapRank) and that
/// other grids are tried for it?
bool rankedByQuads(const Inputs& in, const SeamlessSystem& sys, double edgeLength);

/// How many other grids regridDefectiveMap tries for the map (of edge length edgeLength) if its
/// repair leaves it defective, whatever that repair spent: 0 for a large map or a surface of more
/// than 10 maximumRegridQuadCount triangles (there a spent budget stops the trials).
int regridTrials(const Inputs& in, const SeamlessSystem& sys, double edgeLength);

/// Do the quads that map uv gives (cut out, their holes inside the surface filled, as the quad
/// stage does) have the surface's topology: as many pieces, its Euler characteristic and its
/// boundary loops, manifold? A map can be free of defects and still lose a hole (a small hole
/// whose boundary lines meet the surface's outer one: a piece of the truck of 48 quads), join two
/// (pointsBetweenJoinedLoops), or leave a band around a handle (a piece of genus 3).
bool keepsTopology(
  const Inputs& in, const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector);

/// Where the quads that map uv gives (cut out and patched) join two boundary loops of the surface
/// into one (the strip between two holes cut): the surface points of those loops within `reach`
/// of a point of another loop joined to the same. Each loop belongs to the quads' loop nearest to
/// the most of its points (within reach); where the quads fall into more pieces than the
/// surface (strips between loops, or the neck of a tongue between two stretches of one loop, cut
/// through), every loop counts as joined, to the others and to itself: then two points of one
/// loop count too when the loop between them is more than twice the reach long either way round.
/// Empty when no loops were joined.
std::vector<int> pointsBetweenJoinedLoops(
  const Inputs& in, const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector, double reach);

/// The surface's boundary points near another loop or across a neck of their own, whatever the
/// map (the pairs pointsBetweenJoinedLoops chooses among), and the gaps between loops.
struct LoopGaps
{
  std::vector<int> points; ///< in the loops' order
  /// #V: each boundary point's distance to the nearest point of another loop within the reach;
  /// infinity for the others
  std::vector<double> gap;
};
LoopGaps pointsNearOtherLoops(const Inputs& in, double reach);

/// When the repaired map x still has defects, or its quads (cut out and patched as the quad stage
/// does) would not have the surface's topology: rounds the continuous minimizer `continuous` at
/// other grid sizes (ParameterizationOptions::maximumRegrids of 2, 1/2, 4, 1/4, 8, 16 times the
/// quads, never fewer than minimumComponentQuadCount, 8 and 16 only up to maximumRegridQuadCount
/// quads; only 2 and 1/2 when its quads keep the topology and, repaired, face the right way),
/// repairs each, and keeps the first with neither (defects but flat triangles, a sliver laid on a
/// line, which no grid gives area), else the first better than the map it has (the topology first,
/// then no defects): x, defects and out (its figures and edgeLength) follow it, and sys is left
/// scaled for it. Not when the first repair spent its untangling budget on a surface of more than
/// 10 maximumRegridQuadCount triangles, nor for maps of more than maximumRegridQuadCount quads.
/// Counts the grids tried in out.regrids.
/// @return whether another grid's map replaced the first
bool regridDefectiveMap(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, const Eigen::VectorXd& continuous, bool greedy, Eigen::VectorXd& x,
  Defects& defects, Parameterization& out, const Progress& progress);

/// For ParameterizationOptions::minimumQuadsPerSingularity: the grid made finer (refineGrid)
/// where the map would cover fewer unit cells (countedCells) than that many per branch point of
/// its cut surface (out.branchPoints: the cone pairs' and the moved ones included). (Folds of the
/// continuous map cancel area: the grid can come out finer than it must.)
void limitEdgeLengthBySingularities(
  const Inputs& in, SeamlessSystem& sys, Eigen::VectorXd& x, Parameterization& out);

/// The adaptive grid's scale (curvatureGridScale: the grid edge about edgeOverRadius times the
/// radius of curvature, at most 8 times finer, creases left out), bounded to at most
/// AdaptiveMaximumGrowth times the uniform grid's cells; empty where the grid stays uniform.
Eigen::VectorXd adaptiveGridScale(
  const Inputs& in, const std::vector<char>& creases, double edgeLength, double edgeOverRadius);

/// Where the repaired map keeps defects, the adaptive grid (curvatureGridScale with
/// ParameterizationOptions::defectAdaptiveCurvature, creases left out, finer still where the grid
/// already was): the map made again on it, its edge length corrected so that the quads count as
/// with adaptiveCurvature, kept when it has fewer defects.
void adaptAroundThinParts(const Inputs& in, const std::vector<char>& creases, const Field& field,
  SeamlessSystem& sys, const HessianFactor& factor, bool greedy, Eigen::VectorXd& x,
  Defects& defects, Parameterization& out, const Progress& progress);

/// Where the repaired map x keeps defects, the grid ParameterizationOptions::defectGridRefinement
/// times finer around them (growing back by a quarter of the distance walked, as around thin
/// strips): the continuous map solved again with the same factor (only the right-hand side
/// changes), rounded and repaired; kept when it has fewer defects (flipped triangles and points
/// wound the wrong way), and then counted in out.finerGridTriangles.
void refineAroundDefects(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, bool greedy, Eigen::VectorXd& x, Defects& defects,
  Parameterization& out, const Progress& progress);

/// Where the map's quads join two boundary loops into one (the strip between two holes less than
/// a grid edge or two wide, cut), or cut off a tongue between two stretches of one loop
/// (pointsBetweenJoinedLoops), the grid defectGridRefinement times finer between them, then its
/// square: the map made again (as refineAroundDefects does) and kept when its quads keep the
/// surface's topology (whatever its defects: the topology first, as mapRank ranks maps). When
/// neither is kept, two grids between every two loops within the reach, joined or not: first one
/// whose edge at each of their points is at most a third of its gap to the other loop (at most
/// JoinedLoopMaximumRefinement times finer than the grid there), then one defectGridRefinement
/// times finer around them all. A map made on such a grid is more than a local change, and the
/// joins of the next map are not always where the first map's were (the truck's body alone, at
/// grid edges near that of the truck at 6,500 quads, kept three pairs of loops joined on both
/// finer grids around them; each of the two grids kept them apart at some of five grid edges, and
/// one of them at all five). Not on a map of more than JoinedLoopMaximumDefects defects.
void refineBetweenJoinedLoops(const Inputs& in, const Field& field, SeamlessSystem& sys,
  const HessianFactor& factor, bool greedy, Eigen::VectorXd& x, Defects& defects,
  Parameterization& out, const Progress& progress);
}
}

#endif
