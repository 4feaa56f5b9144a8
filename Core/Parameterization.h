// Parameterization.h: the seamless integer-grid map of stage 4 (QuadCover Sect. 2.5, 4, 4.1):
// a Poisson solve on the surface cut open along a cut graph, with the covering's transition
// functions z' = J^r z + t across the cut, integer translations and branch points on the grid.
#ifndef quadcover_Parameterization_h
#define quadcover_Parameterization_h

#include "CutGraph.h"
#include "FrameSmoother.h"
#include "Matchings.h"
#include "MeshTopology.h"
#include "Progress.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace quadcover
{

enum class RoundingMode
{
  None,   ///< the continuous minimizer (translations and branch points not integer)
  Simple, ///< round every integer unknown of the continuous minimizer at once, then re-solve
  Greedy  ///< fix the unknown closest to an integer, update the others exactly, repeat
};

/// ParameterizationOptions::adaptiveCurvature's grid has at most this many times the cells of the
/// uniform grid (where more of the surface asks for a finer grid, the finest parts are coarser).
constexpr double AdaptiveMaximumGrowth = 4.0;

struct ParameterizationOptions
{
  /// World length of one grid unit, the quads' edge length; 0 chooses it from targetQuadCount.
  double targetEdgeLength = 0.0;
  /// About how many quads, when targetEdgeLength is 0: the edge length starts at
  /// edgeLengthForQuadCount and is corrected after the continuous solve so that the map covers
  /// this many unit cells (its (u, v) area). A field that is far from integrable is fitted by a
  /// map with shorter gradients than 1/edgeLength, which would give fewer and larger quads than
  /// the area promised. The map is linear in 1/edgeLength, so the correction costs no solve; it
  /// is bounded to a factor of 4 either way in the number of quads (folds cancel area). The
  /// edge length used is Parameterization::edgeLength.
  double targetQuadCount = 3000;
  /// Branch points on grid points (integer unknowns), so extraction gives only quads. Without
  /// it only the seam translations are integer and a branch point may lie at the middle of a
  /// grid cell or edge (Theorem 2).
  bool pureQuads = true;
  RoundingMode roundingMode = RoundingMode::Greedy;
  /// With targetQuadCount, the edge length is at most this over the surface's mean curvature
  /// (the mean of k1 + k2, by the signed dihedral angles: 2 / radius on a sphere, 1 / r on a
  /// torus of tube radius r), so that a thin tube gets at least 4 quads around it (2 pi / 1.5):
  /// with 3, flat quads cut through the tube and some face against the surface; 0: no limit.
  /// Spheres are not limited at 24 quads (0.72 radius), nor is any surface at the usual counts.
  double curvatureEdgeLength = 1.5;
  /// With targetQuadCount, the grid has at least this many cells per branch point of the field
  /// (after the pairs closer than minimumSingularitySeparation cancel, the cone pairs and moves
  /// included; the adaptive grid's trial keeps it too, a trial on a coarser grid, kept only when
  /// its map ranks better, may not): a grid too coarse
  /// for its singularities folds between them (decimated-knight at 100 quads: 90 branch points on a
  /// map of 186 cells, quads in two pieces; a gyroid at 300 quads: 209 on 322, two minutes of
  /// untangling), so such a surface gets more quads than asked; 0: no limit.
  double minimumQuadsPerSingularity = 4;
  /// Boundary edges along a frame direction (within boundaryTolerance degrees) lie on an integer
  /// grid line (constant u or v), so quads end cleanly at the border; not those on a straight run
  /// of their loop (between turns of more than 45 degrees) shorter than a grid edge, the steps of
  /// a jagged boundary, which would fold the map (unless within 1.5 grid edges of another loop:
  /// the lines keep the two apart).
  /// The same concept as SmootherOptions::alignToBoundary, and its default.
  bool alignToBoundary = SmootherOptions().alignToBoundary;
  /// The same concept as BranchPointOptions::boundaryTolerance, and its default.
  double boundaryTolerance = BranchPointOptions().boundaryTolerance;
  /// Sharp edges (sharpEdges: featureAngle, in chains of minimumFeatureLength with smooth sides, on
  /// crease networks at least four grid edges long) along a frame direction in both their triangles
  /// (within boundaryTolerance degrees) lie on an integer grid line, as boundary edges do, so that
  /// quad edges run along the creases and quad vertices sit on them (fandisk at 6,500 quads: 33% of
  /// its crease points kept, 80% with it). Off by default: on scans it puts noisy sharp edges on
  /// lines at a cost in time and evenness (cheburashka: 300 times the untangling, 0.5 -> 1.8 s).
  bool featureLines = false;
  /// The same concepts as SmootherOptions::featureAngle and minimumFeatureLength, and their
  /// defaults.
  double featureAngle = SmootherOptions().featureAngle;
  int minimumFeatureLength = SmootherOptions().minimumFeatureLength;
  /// After rounding, triangles whose (u, v) image is flipped are untangled: the real unknowns
  /// of their neighbourhood (2 rings, then 4 and 8) move to minimize a foldover-free distortion
  /// energy, in at most this many rounds per neighbourhood; 0 leaves flips as they are.
  int maximumUntangleRounds = 30;
  /// The untangling's budget, so that its time stays bounded: at most this many energy
  /// evaluations per triangle of the surface, a surface of more than 20,000 triangles counted as
  /// one of 20,000 (param::UntangleBudgetTriangles), for one repair of a map (its trials on other
  /// grids share one such budget, the one on the adaptive grid has a quarter), and twice that for
  /// all of one map's repairs together: the first, the trials on other grids and cells, a repair
  /// done again (a Newton step's Hessian counts as 12; counted as work, not time, so that every
  /// machine gives the same map). Before both bounds armadillo (86k triangles) took 50 s at 100
  /// quads, its five repairs 10,000 evaluations per triangle in all.
  /// On the shared and generated meshes at 1,000, 3,000 and 6,500 quads, both with the defaults
  /// and the smoothest field, every map that came out of its repair without a flipped triangle
  /// spent at most 1,553 (the teapot at 1,000 quads); maps that kept flips spent up to 9,575
  /// (decimated-knight, smoothest field, 1,000 quads: 1,000 triangles, 0.4 s). (With L-BFGS,
  /// a budget of 2,500 cut some short, but also the repair of small components that their trials
  /// on other grids then put right: Data/components.obj's small tori.)
  int untangleWork = 10000;
  /// Worker threads of the untangling and of the maps of a surface's components, each on its own
  /// (0: defaultThreadCount()). Results do not depend on it.
  /// The same concept as CurvatureOptions::numberOfThreads, and its default.
  int numberOfThreads = 0;
  /// Each component of the surface gets a map of its own, with at least this many quads for each
  /// of its holes and handles (2 minus its Euler characteristic, at least 1: a disk or a sphere
  /// this many, a wheel of 14 boundary loops 14 times as many): its share of targetQuadCount by
  /// area, or targetEdgeLength made shorter where that would give fewer. (A component far smaller
  /// than a grid cell would otherwise get no quad at all, and one of many holes on a few dozen
  /// quads loses them.)
  int minimumComponentQuadCount = ReferenceComponentQuads;
  /// A map that keeps flipped triangles or points wound the wrong way after its repair, or whose
  /// quads would not keep the surface's topology (pieces, Euler characteristic, boundary loops),
  /// is rounded and repaired again with up to this many other grid sizes (2, 1/2, 4, 1/4, 8 and
  /// 16 times the quads, in turn, never fewer than minimumComponentQuadCount, 8 and 16 times only
  /// up to maximumRegridQuadCount; a map whose quads keep the topology and, repaired, face the
  /// right way only 2 and 1/2) until one has neither (defects but flat triangles: slivers the map
  /// lays on a line, which no grid gives area), which replaces it, else the first better than the
  /// first map (the topology first); 0 keeps the first. Maps without defects whose quads keep the
  /// topology are never touched, nor maps of more than 10 maximumRegridQuadCount triangles whose
  /// repair spent its budget (time); the trials share one repair's budget (untangleWork). A map
  /// that trials may follow is first repaired with one trial's share; when no trial does better
  /// and that share was spent, its repair is done again from the start with what the map's budget
  /// has left, if that is more, and kept if it has no more defects (the truck: 7-9 s -> 5-6.5 s,
  /// the same maps elsewhere).
  int maximumRegrids = 6;
  /// Only maps of at most this many quads are tried on other grids: a small component's grid is
  /// coarse against its singularities, and its trials are cheap.
  double maximumRegridQuadCount = 1000;
  /// Opposite quarter singularities (+1/4 and -1/4) closer than this many grid edges along the
  /// surface cancel before the map is cut (cancelClosePairs), and a quarter closer than a third of
  /// it to one of the same index, or closer than a grid edge to the boundary, moves apart to it
  /// (moveCloseQuartersApart); the frames around the changed edges turn to agree; 0 keeps every
  /// one where it is. Both would have to lie on grid points (the boundary on grid lines): a pair
  /// closer than a grid edge folds the map or stretches the quads between them.
  double minimumSingularitySeparation = 1.5;
  /// Pairs of opposite quarter cones are added where the singularities leave the quads' size
  /// uneven, each where it lowers the variance of the modelled log scale, summed over the grid's
  /// cells, by at least this, and the field's own quarters moved where that lowers it by twice
  /// this (conePairsForEvenScale, ConePairOptions::minimumGain); 0: neither. 6 against the former
  /// 13: the shared meshes' median edge RSD at 5,000, 6,500 and 8,000 quads 10.7, 10.3, 10.6 ->
  /// 9.8, 9.7, 10.3% and angle RSD 7.6, 7.5, 7.4 -> 7.5, 7.2, 7.0%, with fewer map defects over
  /// the count sweep (Benchmarks/README.md, 2026-12-05). On a surface between two or more
  /// boundary loops a map that keeps defects with its pairs is made again without them
  /// (Parameterization::droppedConePairs).
  double conePairGain = 6.0;
  /// Before the map, triangles with an edge longer than this many grid edges (targetEdgeLength,
  /// or the edge of targetQuadCount quads) are split, longest edge first (refineLongEdges, which
  /// vtkQuadCoverSolver runs): a linear map cannot bend inside a triangle larger than a few grid
  /// cells (a CAD export's slivers across a flat face folded the map around its holes); 0: none.
  double maximumTriangleEdge = 3.0;
  /// Where a strip of the surface between two boundary lines that face each other is narrower
  /// than a grid edge (the bars of a grille, the surface between two slots), or a wall between
  /// two creases is lower than one (the rim of a thin plate), the map's grid is made finer
  /// around it, down to the strip's width but at most this many times finer
  /// (thinStripGridScale): on a uniform grid both sides of the strip round onto one grid line,
  /// which cuts it and joins the holes, and the quads fold over a wall. The same bound holds
  /// around a handle or a neck so narrow that a loop around it within two grid edges of one of
  /// the field's singular points is shorter than about four (shortLoopGridScale: about three
  /// grid edges around it), where a uniform grid closes the tunnel or cuts the neck. 1: a
  /// uniform grid everywhere.
  double maximumThinStripRefinement = 8.0;
  /// Adaptive density: where the surface curves sharply against the grid (a thin ear, finger or
  /// horn, a small bump), the grid edge is about this many times the radius of curvature, seen
  /// at the grid's scale (curvatureGridScale; at most 8 times finer, growing back over a few grid
  /// edges), so that thin parts keep their shape: 0.5 puts about 12 quads around a thin tube.
  /// The quads there count as they are, so the surface has about targetQuadCount quads in all,
  /// larger elsewhere (with targetEdgeLength they come on top: at most AdaptiveMaximumGrowth
  /// times the uniform grid's). 0: a uniform grid (thin strips and defects aside).
  double adaptiveCurvature = 0.0;
  /// Where the repaired map keeps defects (flipped triangles, points wound the wrong way: a thin
  /// ear or finger a grid cell around, cones packed closer than a cell), the grid is made this
  /// many times finer around them, growing back over a few grid edges, and the map is rounded and
  /// repaired again (the same factorization, a new right-hand side); the new map is kept when it
  /// has fewer defects. The same where the quads of a surface with two or more boundary loops
  /// would join two of them (a strip between two holes less than a grid edge or two wide cut):
  /// the grid this many times finer between them (then its square, at most 8), the new map kept
  /// when its quads keep the surface's topology. 1: no second map.
  double defectGridRefinement = 2.0;
  /// Where the repaired map keeps defects, first the adaptive grid (as adaptiveCurvature with
  /// this value, its quads counted the same way) is tried: the map made again on it (the same
  /// factorization, a quarter of the untangling budget), kept when it has fewer defects; then
  /// the grid defectGridRefinement times finer around those left. A thin finger or claw a grid
  /// cell around keeps its shape (armadillo at 1,000 quads: Hausdorff distance 11.2 -> 8.1%,
  /// at 3,000 quads 3.9 -> 1.4%). 0 (or adaptiveCurvature set): not tried.
  double defectAdaptiveCurvature = 1.5;
  /// A map (per component) that keeps defects (flipped triangles, wrong windings) after all the
  /// local repairs and trials above, and whose quads would not keep the surface's Euler
  /// characteristic and boundary loops, is made again on a uniformly finer grid, sqrt(2) times
  /// finer each time (than the map's grid and the grid asked), at most this many times; the first
  /// whose quads keep them is kept (the truck's body at 1,000 quads, whose 33 loops the local
  /// refinements could not keep apart, at a grid sqrt(2) times finer). With pureQuads only.
  /// 0: never.
  int maximumFinerGridRetries = 2;
};

/**
 * The map and what it took. Complex notation: z = u + i v, J = multiplication by i (a quarter
 * turn). Across edge k of face f, on the cut, the neighbour g's values at the two shared points
 * are z_g = i^r z_f + t with r = combedMatching(f,k) and t in Z^2 once rounded (RoundingMode::None
 * leaves t real); off the cut z_g = z_f.
 */
struct Parameterization
{
  Eigen::MatrixXd cornerUV;        ///< #F x 6: u, v at corners 0, 1, 2
  Eigen::MatrixX3i seam;           ///< #F x 3: 1 where edge k is on the cut graph
  Eigen::VectorXi comb;            ///< #F: quarter turns added to the frame (u follows X_comb)
  Eigen::MatrixX3i combedMatching; ///< #F x 3 matchings after combing: 0 off the cut, -1 boundary
  CutGraph cut;
  /// The surface cut open: one point per sector (corners of a point between cut or boundary
  /// edges), sectorPoint its original point, sectorUV its (u, v), cornerSector per corner 3f+k.
  std::vector<int> sectorPoint;
  Eigen::MatrixX2d sectorUV;
  std::vector<int> cornerSector;
  /// #V: the layer shift and index of every point in the field the map follows: the given
  /// matchings', but 0 at the points of the pairs it cancelled (cancelledPairs), and the quarters
  /// it moved apart (movedSingularities) where they went
  Eigen::VectorXi layerShift;
  Eigen::VectorXd singularityIndex;

  // ---- figures ----
  /// the edge length used (world length of one grid unit): options.targetEdgeLength, or the one
  /// targetQuadCount gave
  double edgeLength = 0.0;
  /// pairs of opposite singularities cancelled (options.minimumSingularitySeparation)
  int cancelledPairs = 0;
  /// quarter singularities moved away from one of the same index closer than a third of
  /// minimumSingularitySeparation grid edges (moveCloseQuartersApart), and moved where the quads'
  /// size would vary less (conePairsForEvenScale, with the cone pairs), before the map is solved
  /// (not separatedBranchPoints: branch points of one triangle the rounding put apart)
  int movedSingularities = 0;
  /// pairs of opposite quarter cones added for quads of even size (conePairGain)
  int addedConePairs = 0;
  /// pairs the map of a surface between two or more boundary loops was first made with and then
  /// made again without, because it kept more defects (flipped triangles and wrong windings) with
  /// them; addedConePairs is then 0
  int droppedConePairs = 0;
  /// the uniformly finer grid whose map was kept because the first map's quads would not keep the
  /// surface's topology (maximumFinerGridRetries): i for a grid sqrt(2)^i times finer than the
  /// first map's (and the one asked), 0 when the first map was kept; per component, summed
  int finerGridRetries = 0;
  /// triangles where the grid is finer than edgeLength (maximumThinStripRefinement: thin strips,
  /// walls, short loops around handles and necks; adaptiveCurvature; defectGridRefinement where
  /// it was kept)
  int finerGridTriangles = 0;
  /// the grid was made finer than targetQuadCount asks, for the field's branch points
  /// (minimumQuadsPerSingularity; on a surface of several components, on one of them at least)
  bool finerForSingularities = false;
  int branchPoints = 0;         ///< inner points with a non-zero layer shift
  int branchPointsOnGrid = 0;   ///< of those, mapped to integer (u, v) within 1e-6
  int seamEdges = 0;            ///< cut edges
  int alignedBoundaryEdges = 0; ///< boundary edges put on grid lines
  int alignedFeatureEdges = 0;  ///< sharp edges put on grid lines
  int unknowns = 0;             ///< real unknowns of the solve
  int integerUnknowns = 0;      ///< of which integer
  int constraints = 0;          ///< real linear constraints eliminated
  /// constraints whose elimination could not keep integers integer (0 unless the cut graph
  /// is unusual); the map may then miss the grid there (see maxSeamError)
  int nonUnitPivots = 0;
  /// branch points rounded to the next nearest grid point because the nearest was taken by a
  /// branch point of the same triangle
  int separatedBranchPoints = 0;
  /// boundary (and feature) lines rounded away from the nearest integer because it closed the thin
  /// hole or cut the thin strip between them and a line facing them
  int separatedBoundaryLines = 0;
  /// Energy sum A_f |grad phi - K|^2 / (area * |K|^2) (0 for a perfect fit): the continuous
  /// minimizer, the rounded map before untangling, and the final map.
  double energyContinuous = 0.0;
  double energyRounded = 0.0;
  double energyFinal = 0.0;
  int flippedContinuous = 0; ///< triangles with a non-positive (u, v) area
  int flippedRounded = 0;
  int flipped = 0; ///< in the final map
  /// inner points whose (u, v) angles do not add up to 2 pi (1 - index) in the final map
  int wrongWindings = 0;
  int untangleRegions = 0;          ///< neighbourhoods untangled (each growing the last)
  /// the untangling stopped at its budget (its share of untangleWork, or what the map had left)
  bool untangleBudgetSpent = false;
  /// the untangling's work: triangle energy evaluations, every repair and regrid trial summed
  long long untangleEvaluations = 0;
  /// other grid sizes tried because the repaired map kept defects (maximumRegrids)
  int regrids = 0;
  double untangleSeconds = 0.0;
  double maxSeamError = 0.0; ///< largest distance of a seam translation from Z^2, in grid units
  std::vector<double> solveSeconds; ///< factorization + solve, one entry per sparse solve
  std::string solver;               ///< sparse solver used
};

/**
 * Computes the integer-grid map of a frame field with given matchings.
 *
 * The surface is cut into disks through every singular point (computeCutGraph), the frames
 * are combed (turned by quarter turns) so that matchings vanish off the cut, and the map is
 * unknown per sector. The cut's transition functions z_B = i^r z_A + t_e (one t_e per cut edge)
 * and the boundary lines are linear constraints with integer coefficients; they are eliminated
 * so that every remaining integer unknown (translations, branch points, boundary lines) keeps
 * every dependent one integer. The energy sum_f A_f |grad phi - K_f|^2 with K_f the combed
 * frame (X_c, X_{c+1}) / edgeLength is minimized (one sparse Cholesky), the integer unknowns are
 * rounded (roundingMode), the rest is solved again with the integers fixed, and flipped triangles
 * are untangled locally (maximumUntangleRounds).
 *
 * @param[in] geometry computeFrameGeometry(V, F, topo)
 * @param[in] frameU   #F x 3 tangent frame directions (four-fold symmetric)
 * @param[in] matching #F x 3 in the convention of FrameTopology (vtkMatchingBuilder's Matching)
 * @param[in] progress told after each step, and as the rounding and the untangling go on
 * @throws Cancelled when progress's callback asks to stop
 * @throws std::invalid_argument on sizes that do not match, a non-manifold or misoriented
 *         surface, matchings that are not inverse across an edge, a negative target edge
 *         length, or a target edge length of 0 without a positive target quad count
 * @throws std::runtime_error when the sparse factorization fails
 */
Parameterization computeParameterization(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3i& matching, const ParameterizationOptions& options = {},
  const Progress& progress = Progress());

/// The edge length that gives about `quads` quads: sqrt(total area / quads).
double edgeLengthForQuadCount(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, double quads);

}

#endif
