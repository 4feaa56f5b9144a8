// QuadExtraction.h: the quad mesh of an integer-grid map (stage 5) and its quality figures.
#ifndef quadcover_QuadExtraction_h
#define quadcover_QuadExtraction_h

#include "MeshTopology.h"
#include "Progress.h"

#include <Eigen/Core>

#include <array>

#include <utility>
#include <vector>

namespace quadcover
{

struct QuadExtractionOptions
{
  /// Barycentric tolerance for a grid point on a triangle's edge or corner.
  double tolerance = 1e-7;
  /// Triangles a walk from a cell's centre to one of its corners may cross.
  int maximumWalk = 10000;
};

struct QuadMesh
{
  Eigen::MatrixX3d V;              ///< quad vertices, on the input surface
  Eigen::MatrixX4i Q;              ///< quads, counterclockwise seen from the surface's orientation
  std::vector<int> vertexTriangle; ///< the input triangle each vertex lies in
  std::vector<int> vertexPoint;    ///< the input point a vertex sits on, or -1
  std::vector<int> quadTriangle;   ///< the input triangle holding each quad's centre
  // what could not become a quad (all 0 on a seamless, flip-free map)
  int cellsOffSurface = 0;       ///< a corner beyond the boundary, or a walk that failed
  int cellsDegenerate = 0;       ///< two corners at one grid point
  int cellsConflicting = 0;      ///< removed: they overlapped others (folded maps)
  int nonIntegerTransitions = 0; ///< inner edges whose translation is not integer
  /// corners that could not be reached along the straight segment from their cell's centre (a
  /// flipped triangle or the boundary on it) and were searched for by stepping towards them
  int walkFallbacks = 0;
};

/**
 * What overlapping cells of a folded map leave behind: repeated quads (the same corners in the
 * same cyclic order: a centre on an edge or point is held by every triangle there) are merged,
 * and every quad that shares a directed edge with another, or lies on an edge of more than two
 * quads, is removed, so that what is left is manifold. `owner` (one entry per quad) follows.
 * @return the quads removed (merged repeats not counted)
 * @throws std::invalid_argument when owner and quads differ in size
 */
int removeOverlappingQuads(std::vector<std::array<int, 4>>& quads, std::vector<int>& owner);

/**
 * Cuts the quads out of an integer-grid map: every unit cell [a, a+1] x [b, b+1] of the grid
 * becomes one quad, found through its centre (a + 1/2, b + 1/2) in the triangle that holds it
 * (a centre on an edge or point is found from each triangle there, and the copies merged). Its four
 * corners are found by walking in the (u, v) plane from the centre, across edges and seams (through
 * the transition functions read off the map), to the triangle that holds each corner; a corner on a
 * point, on an edge or inside a triangle gets one identity wherever it is reached from, so that
 * quads share vertices across seams and a branch point of index k/4 becomes a vertex of valence 4 -
 * k. Triangles with a flipped (u, v) image hold no quad centre and stop walks; quads that still
 * overlap (the same corner reached twice along one edge direction) are removed and counted, so
 * the output stays manifold.
 * @param[in] cornerUV #F x 6 (u, v at corners 0, 1, 2), as computeParameterization gives
 * @throws std::invalid_argument on sizes that do not match or a non-manifold surface
 */
QuadMesh extractQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixXd& cornerUV,
  const QuadExtractionOptions& options = QuadExtractionOptions(),
  const Progress& progress = Progress());

struct QuadRelaxOptions
{
  /// Sweeps over the vertices; 0 leaves the mesh as extracted.
  int relaxationIterations = 0;
  /// Share of the way each vertex moves towards its target per sweep, in (0, 1].
  double step = 0.5;
  /// Input edges with a dihedral angle above this (degrees) are creases: vertices on them stay,
  /// and no vertex is moved across one.
  double featureAngle = 60.0;
  /// #V of the quad mesh, 1 for the vertices that may move; empty: all of them.
  std::vector<char> movable;
};

struct QuadRelaxReport
{
  int fixedVertices = 0; ///< on the boundary or on a crease: not moved
  int rejectedMoves = 0; ///< moves that would have folded a quad
  double maxMove = 0.0;  ///< longest single move, in units of the mean edge length
};

/**
 * Tangential relaxation: each free quad vertex moves towards the area-weighted mean of the
 * centres of its quads, within the plane of the input triangle it lies in, and is put back on
 * the input surface (the closest point, found by walking from its triangle across edges that
 * are neither boundary nor crease). The connectivity stays; vertices on the quad mesh's boundary
 * or on input creases (featureAngle) stay where they are; a move that would turn a quad corner
 * inside out (against the input's normal) is not made. It evens out uneven spacing, at the
 * price of the grid lines' exact alignment with the frame field; it cannot move quads from one
 * region to another, so the distortion of a map far from the field's metric mostly stays. Updates
 * mesh.V and mesh.vertexTriangle (vertexPoint becomes -1 where a vertex leaves its input point).
 * @throws std::invalid_argument on sizes that do not match or step outside (0, 1]
 */
QuadRelaxReport relaxQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh, const QuadRelaxOptions& options,
  const Progress& progress = Progress());

/**
 * Repairs quads with a corner turned inside out (scaled Jacobian <= 0, as measureQuads measures
 * it), which the map leaves at some branch points on coarse or strongly curved parts: relaxQuads
 * on their vertices and those within `rings` quad rings, in rounds of `iterations` sweeps, until
 * none is left or a round repairs nothing (at most `rounds`; a round that leaves more is undone).
 * Far from them nothing moves.
 * @return the inverted quads before and after
 */
/// Quads with a corner turned inside out: scaled Jacobian <= 0, as measureQuads measures it.
int countInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q);

std::pair<int, int> repairInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh, int rings = 2, int iterations = 10, int rounds = 3);

/// The paper's Table 1 figures and more, for a quad (or polygon) mesh.
struct QuadQuality
{
  int vertices = 0;
  int faces = 0;
  int quads = 0;             ///< faces with four distinct corners
  int irregularInner = 0;    ///< inner vertices of valence other than 4
  int irregularBoundary = 0; ///< boundary vertices of valence other than 2 (corner) or 3
  double edgeLengthRSD = 0;  ///< relative standard deviation of edge lengths
  double angleRSD = 0;       ///< of corner angles (about pi/2)
  double minScaledJacobian = 0;
  double meanScaledJacobian = 0;
  int nonManifoldEdges = 0; ///< edges of more than two faces, or twice in one direction
  int boundaryEdges = 0;
  int boundaryLoops = 0;
  int eulerCharacteristic = 0;
  int components = 0;
  Eigen::VectorXi valence;        ///< per vertex
  Eigen::VectorXd scaledJacobian; ///< per face: the smallest over its corners
};

/// Figures of a quad mesh (vertices V, faces Q as 4 vertex ids).
QuadQuality measureQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q);

}

#endif
