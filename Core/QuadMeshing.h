// QuadMeshing.h: the quad stage as vtkQuadExtractor runs it (extraction, repair, relaxation,
// figures), the joining of a surface cut open along its seams, and the samples of the
// Hausdorff distance between a surface and its quad mesh.
#ifndef quadcover_QuadMeshing_h
#define quadcover_QuadMeshing_h

#include "FrameSmoother.h"
#include "MeshTopology.h"
#include "Progress.h"
#include "QuadCollapse.h"
#include "QuadExtraction.h"
#include "QuadFacing.h"
#include "QuadPatching.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/// The quad stage: what it runs after the extraction.
struct QuadMeshOptions
{
  QuadExtractionOptions extraction;
  /// Relax the quads around every quad with a corner turned inside out (repairInvertedQuads) or
  /// facing against the surface, then move the corners of those left (repairFacing), and give
  /// the vertices of quads still inside out a last round with QuadRelaxOptions::unfold.
  bool repairInvertedQuads = true;
  /// Fill the holes that cells without a quad leave inside the surface with quads
  /// (patchQuadMesh), where the map could not be repaired.
  bool fillHoles = true;
  /// Move the quad vertices beside the sharp edges onto them (snapToCreases), before the
  /// relaxation, so that quad edges follow the creases the grid lines run beside (with the frames
  /// held along them, SmootherOptions::alignToFeatures; without, the grid lines cross the creases
  /// and the snapping leaves quads folded across them).
  bool snapToCreases = true;
  /// The sharp edges (sharpEdges) for snapToCreases, and featureAngle the relaxation's creases
  /// too: the same concepts as SmootherOptions::featureAngle and minimumFeatureLength, and their
  /// defaults.
  double featureAngle = SmootherOptions().featureAngle;
  int minimumFeatureLength = SmootherOptions().minimumFeatureLength;
  /// Sweeps of tangential relaxation of the whole mesh afterwards (relaxQuads, vertices whose
  /// quads span a sharp bend held); 0: none. Three sweeps take the shared meshes' median
  /// edge-length RSD at 6,500 quads from 10.6 to 10.2% and the angle RSD from 7.7 to 7.2%, and
  /// none of their Hausdorff distances grows (Documentation/Algorithms.md); more change little.
  int relaxationIterations = 3;
  /// Measure the two-sided Hausdorff distance to the surface (hausdorffSamples); the filter
  /// finds the closest points.
  bool computeHausdorffDistance = true;
};

/// The largest pieces of quads hanging by a corner off their component's quads that the quad
/// stage drops (dropPinchedFragments; the truck's disk of 512 triangles: 21 quads and one more
/// at a corner, at 1,000, 3,000 and 6,500 quads).
constexpr int PinchedFragmentQuads = 2;

/// How near the rest of its component's quads, in their median edges, a disk cut off them lies
/// when the quad stage drops it (dropPiecesAgainstRest).
constexpr double PieceAgainstRestReach = 0.25;

struct QuadMeshResult
{
  QuadMesh mesh;
  QuadQuality quality;       ///< measureQuads of the final mesh
  int invertedExtracted = 0; ///< quads with a corner turned inside out as extracted (after the
                             ///< holes are filled)
  int invertedFinal = 0;     ///< and in the final mesh
  QuadPatchResult patch;     ///< what patchQuadMesh did
  FacingRepair facing;       ///< what repairFacing did
  int turnedExtracted = 0;   ///< turnedQuads as extracted (after the holes are filled)
  int turnedQuads = 0;       ///< turnedQuads of the final mesh
  int splitVertices = 0;     ///< copies splitPinchedVertices added
  int fragmentQuads = 0;     ///< quads dropPinchedFragments and dropPiecesAgainstRest removed
  QuadCollapseResult collapse; ///< what removeTurnedQuads did
  int snappedVertices = 0;   ///< vertices snapToCreases moved onto a sharp edge, and
                             ///< straightenCreaseSteps beside one
  int liftedVertices = 0;    ///< vertices liftOffOtherComponents moved off the surface
  int emptyComponents = 0;   ///< componentsWithoutQuads of the final mesh
  int droppedCells() const
  {
    return mesh.cellsOffSurface + mesh.cellsDegenerate + mesh.cellsConflicting;
  }
};

/**
 * extractQuads, then patchQuadMesh, repairInvertedQuads (or only countInvertedQuads), repairQuads
 * of the quads facing against the surface, repairFacing, a last repairQuads round with
 * QuadRelaxOptions::unfold for the quads still inside out (kept when fewer stay so and none more
 * faces against the surface), relaxQuads with options.relaxationIterations sweeps
 * (QuadRelaxOptions::holdAcrossBends; the corners of a quad it made face against the surface or
 * turn inside out are put back), dropPinchedFragments (of at most 2 quads) and
 * dropPiecesAgainstRest, removeTurnedQuads
 * (with options.repairInvertedQuads) of the quads still facing against the surface or inside out,
 * liftOffOtherComponents, splitPinchedVertices, then measureQuads. The quads' facing is measured
 * by quadFacing with the surface's triangles labelled by their components.
 * @throws std::invalid_argument as extractQuads does
 */
QuadMeshResult buildQuadMesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixXd& cornerUV,
  const QuadMeshOptions& options = QuadMeshOptions(), const Progress& progress = Progress());

/// The components of the surface on which no quad of `mesh` lies (by the triangle holding each
/// quad's centre, else its first corner's): 0 on a valid remesh.
int componentsWithoutQuads(const MeshTopology& topo, const QuadMesh& mesh);

/**
 * Joins a surface cut open along its seams (vtkQuadCoverSolver's SplitSeams output) back
 * together: point p of the cut surface is point pointId[p] of the whole one.
 * @param[in]     V       #P x 3 points of the cut surface
 * @param[in,out] F       #F x 3 triangles, renumbered into the joined points
 * @param[in]     pointId #P, each in [0, #P)
 * @return the joined surface's points (max(pointId) + 1 rows; an id no point has stays at 0)
 * @throws std::invalid_argument on sizes that do not match or ids out of range
 */
Eigen::MatrixX3d joinSplitPoints(
  const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, const std::vector<int>& pointId);

/// True when the points that share an id lie at one position, as the points of a surface cut
/// open along its seams do (and an unrelated array of ids most likely does not).
/// @param[in] V #P x 3 @param[in] pointId #P, each in [0, #P)
bool splitPointsCoincide(const Eigen::MatrixX3d& V, const std::vector<int>& pointId);

/// What the two-sided Hausdorff distance between a surface and its quad mesh is measured on.
struct HausdorffSamples
{
  /// the surface's points that its triangles use, measured against quadTriangles
  Eigen::MatrixX3d surfacePoints;
  /// the quads' corners, edge midpoints and centres, measured against the surface
  Eigen::MatrixX3d quadPoints;
  /// 2 #Q x 3: each quad (a, b, c, d) as the triangles (a, b, c) and (a, c, d)
  Eigen::MatrixX3i quadTriangles;
  /// of the bounding box of surfacePoints: the distances are reported as a share of it
  double diagonal = 0.0;
};

/// Each quad (a, b, c, d) as the triangles (a, b, c) and (a, c, d): 2 #Q x 3.
Eigen::MatrixX3i quadTriangles(const Eigen::MatrixX4i& Q);

/// @param[in] V, F the surface; @param[in] quadV, Q the quad mesh
HausdorffSamples hausdorffSamples(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const Eigen::MatrixX3d& quadV, const Eigen::MatrixX4i& Q);

/// The largest distance from the points to the triangles (V, F) (0 without points, infinity
/// without a triangle of positive area), on `threads` threads (0: defaultThreadCount()); the
/// same on any number of them.
double largestDistance(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& V,
  const Eigen::MatrixX3i& F, int threads = 0);

}

#endif
