// Matchings.h: the topology of a frame field (stage 3): per-edge matchings, layer shifts,
// singularity indices, and the branch-point optimization of QuadCover Sect. 4.2.
#ifndef quadcover_Matchings_h
#define quadcover_Matchings_h

#include "FrameField.h"
#include "MeshTopology.h"
#include "Progress.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace quadcover
{

/**
 * Matchings and what they imply.
 *
 * Convention (the paper's, Def. 5): matching(f,k) = r for face f and the neighbour g across its
 * edge k means X_{g,m} = X_{f,(m - r) mod 4}: g's first frame vector, carried into f's plane,
 * is f's frame vector number -r (mod 4), where f's vectors are X_0 = U, X_1 = n x U, X_2 = -U,
 * X_3 = -n x U (quarter turns counterclockwise about f's normal). So matching(g,k') =
 * -matching(f,k) mod 4, and -1 marks an edge with no neighbour (boundary or non-manifold).
 *
 * layerShift(v) = sum of the matchings from each triangle to the next, counterclockwise around v
 * (Def. 4), mod 4; 0 on the boundary. index(v) is the frame field's true index at v: (angle
 * defect + the frame's turning relative to parallel transport around v) / 2 pi, a multiple of
 * 1/4 inside with layerShift = 4 index mod 4. On the boundary the index is that of the surface
 * doubled across its boundary, halved; with frames aligned to the boundary it is a multiple of
 * 1/4 too, and in all cases
 *   sum of all indices (inner and boundary vertices) = Euler characteristic   (Poincare-Hopf).
 */
struct FrameTopology
{
  Eigen::MatrixX3i matching;  ///< #F x 3, in {0,1,2,3}, -1 without a neighbour
  Eigen::VectorXi layerShift; ///< #V in {0,1,2,3}
  Eigen::VectorXd index;      ///< #V true index
  Eigen::MatrixX3d deviation; ///< #F x 3 angle between matched vectors across edge k (C_ij)
  int singularities = 0;      ///< inner vertices with a non-zero index
  int branchPoints = 0;       ///< inner vertices with a non-zero layer shift
  double matchingCost = 0.0;  ///< sum over inner edges of the deviation (sum C_ij)
  double maxIndexError = 0.0; ///< largest distance of an inner index from a multiple of 1/4
};

/// The geometry matchings are measured in; computed once per mesh.
struct FrameGeometry
{
  FaceBases bases;
  Eigen::MatrixX3d transport;  ///< computeTransport
  Eigen::MatrixX3d edgeAngle;  ///< #F x 3 angle of edge k (corner k to k+1) in f's basis
  Eigen::VectorXd defect;      ///< angleDefects
  Eigen::MatrixX3d edgeLength; ///< #F x 3 length of edge k
  /// sqrt(total area / 2000): about the edge length of a 4,000-triangle mesh of the same area
  double referenceLength = 0.0;
  /// #F per triangle, the edge of the grid its component would get if the surface were meshed
  /// with 2,000 quads: its share of them by area, but at least ReferenceComponentQuads for each
  /// of its holes and handles (2 - chi, at least 1), as the map gives each component its minimum
  /// (ParameterizationOptions::minimumComponentQuadCount). On one component, referenceLength.
  /// The costs of merges and splits on a component are measured in it: with the whole surface's,
  /// a part whose grid is far finer than its share (a wheel of 14 holes beside a car's body) had
  /// its singularities merged as if paths on it were ten times cheaper, and its map folded.
  Eigen::VectorXd componentReferenceLength;
};

/// The quads per hole and handle of a component in FrameGeometry::componentReferenceLength
/// (ParameterizationOptions::minimumComponentQuadCount's default).
constexpr int ReferenceComponentQuads = 24;

/// The reference length of face f's component; the whole surface's where the component has none
/// (no area) or the geometry was not computed per component.
inline double referenceLengthAt(const FrameGeometry& geometry, int f)
{
  const double own =
    f < geometry.componentReferenceLength.size() ? geometry.componentReferenceLength[f] : 0.0;
  return own > 0.0 ? own : geometry.referenceLength;
}

FrameGeometry computeFrameGeometry(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo);

/// Smallest-angle matchings of the frame field (angle of FrameU, four-fold) and their topology.
FrameTopology computeMatchings(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU);

/// Layer shifts, indices and costs of the frame field with the given matchings.
/// @throws std::invalid_argument when matching(f,k) and its twin are not inverse
FrameTopology evaluateMatchings(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, const Eigen::MatrixX3i& matching);

struct BranchPointOptions
{
  /// lambda of the cost lambda * (number of singular inner points) + sum of matching deviations
  /// (radians); a path is changed only when it lowers that cost.
  double branchPointWeight = 4.0;
  /// Each edge's deviation counts in proportion to its length over its component's reference
  /// length (FrameGeometry::componentReferenceLength), so that the cost of a path is about the same
  /// however finely the surface is meshed (merging two singularities bends the field over their
  /// distance, not over a number of edges). Off: every edge counts once, as in the paper, and a
  /// finer mesh keeps more singularities.
  bool lengthScaledCost = true;
  /// Frames within this many degrees of a boundary edge follow it (as the solver's
  /// boundaryTolerance puts such edges on grid lines): used to undo merges that would leave a
  /// tube's loops on different frame families.
  double boundaryTolerance = 10.0;
  /// Vertices a search may visit from one branch point (a guard on very large meshes).
  int maximumSearchSize = 20000;
  int maximumPasses = 10;
  /// Inner singularities of index >= 1/2 are split first into quarters placed at least this
  /// many edges apart (and from other singularities), with lengthScaledCost also this many
  /// reference lengths of their component along the surface (a fan of slivers is many edges in a
  /// short distance);
  /// 0 leaves them alone.
  int splitDistance = 4;
  /// Singularities of index at least this many quarters are split (2: +1/2 and more).
  int splitQuarters = 2;
};

struct BranchPointReport
{
  int before = 0; ///< branch points before
  int after = 0;  ///< after
  int singularitiesBefore = 0;
  int singularitiesAfter = 0;
  double costBefore = 0; ///< lambda * singularities + scaledMatchingCost
  double costAfter = 0;
  int pathsChanged = 0;
  int split = 0;       ///< singularities of index >= 1/2 split into quarters
  int splitFailed = 0; ///< quarters that found no place (left where they were)
  /// merges undone because they left a singularity-free component between boundary loops with
  /// its frames following different frame families along different loops
  int twistsAvoided = 0;
};

/// The matching cost the branch-point optimization weighs: the sum of deviations C_ij over
/// inner edges, each times its length over its component's reference length when lengthScaled
/// (BranchPointOptions), else FrameTopology::matchingCost.
double scaledMatchingCost(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const FrameTopology& topology, bool lengthScaled);

/**
 * Greedy branch-point optimization (Sect. 4.2): from each singular point of index +-1/4 or
 * +-1/2, search edge paths (Dijkstra on the added matching deviation) to other singular points,
 * and change the matchings along the best path when that lowers lambda * C_b + sum C_ij, C_b
 * counting singular inner points. Changing the matchings along a path by delta quarter turns
 * adds delta/4 to the start's index and takes it from the end's, leaving the points in between
 * alone, so Poincare-Hopf keeps holding. A path must clear its start and make its end's index
 * strictly smaller: pairs whose layer shifts cancel disappear together (the paper's merge), and
 * no two singularities combine into one of higher order (+1/4 and +1/4 into +1/2, which would
 * make a valence-2 quad vertex). Updates `topology` in place.
 */
BranchPointReport optimizeBranchPoints(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  const BranchPointOptions& options = BranchPointOptions(), const Progress& progress = Progress());

/**
 * Cancels pairs of opposite inner quarter singularities (+1/4 with -1/4) that lie closer than
 * maxLength along an edge path over regular inner points: the matchings along the shortest such
 * path change by a quarter turn, which clears both ends and leaves the points between alone.
 * The closest pairs go first; a cancellation that would leave a tube twisted (see
 * optimizeBranchPoints) is undone. On a component with handles only where the triangles within
 * 2 maxLength of the first point form a disk: a path there changes the field's turning only
 * along loops around its ends, which the indices account for, as on a component without
 * handles; a path that a handle's loop must cross also turns the field along that loop, and a
 * flat torus has no such turning (the smoothest field's small tori of Data/components.obj kept
 * folds on every grid). A grid cannot keep two singularities closer than about one
 * of its edges apart: both must lie on grid points. Updates `topology` in place.
 * @param[out] changedFaces #F, 1 for the faces on both sides of a changed edge
 * @return the number of pairs cancelled
 */
int cancelClosePairs(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  double maxLength, std::vector<char>& changedFaces);

/**
 * Moves inner quarter singularities that lie closer than `closerThan` (along edge paths) to one
 * of the same index, or closer than `boundaryCloserThan` to the inner points beside the boundary
 * (joined to it by an edge; 0: never), apart: each such quarter goes along the cheapest path over
 * regular points to one at least minLength from every other singularity and from the inner
 * points beside the boundary (whatever boundaryCloserThan), at most 4 minLength away (no grid can
 * put two singularities much less than one of its edges apart on grid points; three +1/4 within
 * half a grid edge of each other on cheburashka at 3,000 quads left triangles flipped, while the
 * corners of a plate thinner than a grid edge, 0.8 of one apart, stay best where they are; a
 * -1/4 one triangle from the teapot's spout opening, with the boundary on grid lines through its
 * grid point, left a triangle collapsed onto that point at most densities).
 * Changes on a component with handles only inside a disk around the quarter (5 minLength; for a
 * quarter beside the boundary, whose short loop may lie in that ball, 1.25 times its path); the
 * tube check of cancelClosePairs cannot object (the moved quarter stays a singularity of its
 * component). Updates `topology` in place.
 * @param[out] changedFaces #F, 1 for the faces on both sides of a changed edge
 * @return the number of quarters moved
 */
int moveCloseQuartersApart(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU, FrameTopology& topology,
  double closerThan, double minLength, double boundaryCloserThan, std::vector<char>& changedFaces);

/**
 * Turns the frames so that they agree with given matchings: the angles alpha minimizing
 *   8 lambda sum_{inner edges fg} c |e_fg| / |c_f - c_g| (delta_fg + alpha_g - alpha_f)^2
 *     + (1 - lambda) sum_f A_f w_f alpha_f^2
 * (the smoothing energy of smoothFrames, expanded to second order about the current frames,
 * with each edge weighted by its length over the distance between its triangles' centres, c
 * such that the weights sum to the areas (A_f + A_g)/3 of smoothFrames' links: weighted by the
 * areas, a triangulation whose diagonals lean one way turns the fitted field, 15 degrees from
 * one latitude to another on a latitude-longitude sphere, 8 so),
 * where delta_fg is the angle left between the matched frames across the edge. lambda is
 * close to 1 by default (0.97): with a balance of 0.5 the curvature alignment keeps
 * the turning near the changed edges, and the map must fold there (on the six shared meshes at
 * 3,000 quads, 7-196 triangles per mesh flipped after rounding and a 10-35% higher map energy;
 * at 0.97, 2-102). The matchings,
 * layer shifts and indices stay as they are (the alphas cancel around every point), while the
 * turning that a changed matching (optimizeBranchPoints) leaves on one edge spreads smoothly
 * over the surface: the field then has the singularities its matchings say, and the
 * parameterization need not fold to follow it. One sparse solve.
 * @param[in] weight #F alignment weights (FrameWeight), or empty for none (pure smoothing)
 * @param[in] held   #F, 1 for frames that stay as they are (held along boundaries and sharp
 *                   edges by smoothFrames, or away from a few changed edges), or empty; only
 *                   the others are unknowns
 * @return #F the angles alpha to turn each frame by (rotateFrames)
 * @throws std::invalid_argument on sizes that do not match or lambda outside (0, 1]
 */
Eigen::VectorXd fitFramesToMatchings(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3i& matching, const Eigen::VectorXd& weight, double lambda = 0.97,
  const std::vector<char>& held = {});

/**
 * "" when every matching is 0, 1, 2 or 3 on an edge with a neighbour and -1 on one without
 * (FrameTopology's convention), else one line naming the first triangle and edge that is not.
 */
std::string checkMatching(const MeshTopology& topo, const Eigen::MatrixX3i& matching);

/// The whole matching stage (vtkMatchingBuilder): what it runs and with which weights.
struct MatchingOptions
{
  /// Run optimizeBranchPoints after the smallest-angle matchings. Without it, inner points of
  /// index 3/4 or more are still split into quarters (branchPoints.splitDistance > 0): no map can
  /// follow a whole turn, and a valence-1 quad vertex is a quad folded onto itself (a +1/2 stays:
  /// a valence-2 quad vertex, but a valid mesh). Off by default: merges buy few singularities with
  /// stretch (median edge-length RSD over the shared meshes at 6,500 quads: 20.1% with them and
  /// no cone pairs, 10.3% with the present defaults; Documentation/Algorithms.md).
  bool optimizeBranchPoints = false;
  BranchPointOptions branchPoints;
  /// After the optimization changed matchings, turn the frames so that they agree with them
  /// (fitFramesToMatchings), frames held along the boundary staying as they are.
  bool fitFramesToMatchings = true;
  /// lambda of that fit: close to 1 (see fitFramesToMatchings).
  double fitSmoothingWeight = 0.97;
};

struct MatchingResult
{
  FrameTopology topology;     ///< of the final matchings and frames
  Eigen::MatrixX3d frameU;    ///< #F x 3 the frames: fitted when framesFitted, else as given
  Eigen::MatrixX3d frameV;    ///< #F x 3 (normal x frameU where none was given)
  bool framesFitted = false;  ///< the frames were turned to agree with changed matchings
  int branchPointsBefore = 0; ///< of the smallest-angle matchings
  double matchingCostBefore = 0.0;
  /// what the optimization lowers (BranchPointReport::costBefore/After), before and after
  double objectiveBefore = 0.0;
  double objectiveAfter = 0.0;
  BranchPointReport report; ///< all 0 without the optimization
};

/**
 * The matching stage as vtkMatchingBuilder runs it: computeMatchings, then (optionally)
 * optimizeBranchPoints, then, when that changed matchings, fitFramesToMatchings (frames that
 * `constrained` holds on a triangle with a boundary edge stay: the boundary must stay on grid
 * lines), the frames turned and the matchings evaluated again.
 * @param[in] frameV      #F x 3 or empty (normal x frameU)
 * @param[in] weight      #F alignment weights (FrameWeight) or empty; non-finite ones count 0
 * @param[in] constrained #F, 1 where smoothFrames held the frame, or empty
 */
MatchingResult buildMatchings(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3d& frameV, const Eigen::VectorXd& weight,
  const std::vector<char>& constrained, const MatchingOptions& options = MatchingOptions(),
  const Progress& progress = Progress());

}

#endif
