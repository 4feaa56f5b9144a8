// QuadRelaxation.h: tangential relaxation of an extracted quad mesh on its input surface, and the
// repair of inverted quads with it.
#ifndef quadcover_QuadRelaxation_h
#define quadcover_QuadRelaxation_h

#include "MeshTopology.h"
#include "Progress.h"
#include "QuadMesh.h"

#include <Eigen/Core>

#include <functional>

#include <utility>
#include <vector>

namespace quadcover
{

struct QuadRelaxOptions
{
  /// Sweeps over the vertices; 0 leaves the mesh as extracted.
  int relaxationIterations = 0;
  /// Share of the way each vertex moves towards its target per sweep, in (0, 1].
  double step = 0.5;
  /// Input edges with a dihedral angle above this (degrees) are creases: vertices on them stay,
  /// and no vertex is moved across one.
  double featureAngle = 60.0;
  /// Vertices whose quads span a bend of the input sharper than featureAngle (the input's normal
  /// at a corner of their quads against its normal at the vertex) stay: moved along the surface
  /// they would pull their quads' chords across the bend and cut it off (the rim of a thin ear,
  /// a ridge no quad edge follows). For the relaxation that evens out the quads; the repairs of
  /// inverted quads move them.
  bool holdAcrossBends = false;
  /// #V of the quad mesh, 1 for the vertices that may move; empty: all of them.
  std::vector<char> movable;
  /// Where a vertex's quads have a corner inside out and its step was not made or did not turn
  /// fewer of them back, try short steps in eight directions of its triangle's plane (0.05, 0.15
  /// and 0.3 of the mean quad edge) and take the best: the fewest corners inside out, then the
  /// best worst corner.
  bool unfold = false;
};

struct QuadRelaxReport
{
  int fixedVertices = 0; ///< on the boundary or on a crease: not moved
  int heldMoves = 0;     ///< moves not made because the vertex's quads span a bend
  int rejectedMoves = 0; ///< moves that would have folded a quad
  double maxMove = 0.0;  ///< longest single move, in units of the mean edge length
};

/**
 * Tangential relaxation: each free quad vertex moves towards the area-weighted mean of the
 * centres of its quads, within the plane of the input triangle it lies in, and is put back on
 * the input surface (the closest point, found by walking from its triangle across edges that
 * are neither boundary nor crease). The connectivity stays; vertices on the quad mesh's boundary
 * or on input creases (featureAngle) stay where they are, with options.holdAcrossBends also
 * those whose quads span a bend that sharp; a move that would turn a quad corner
 * inside out (against the input's normal) is not made; with options.unfold a vertex whose
 * quads keep a corner inside out also tries short steps around it. It evens out uneven
 * spacing, at the price of the grid lines' exact alignment with the frame field; it cannot move
 * quads from one region to another, so the distortion of a map far from the field's metric
 * mostly stays. Updates
 * mesh.V and mesh.vertexTriangle (vertexPoint becomes -1 where a vertex leaves its input point).
 * @throws std::invalid_argument on sizes that do not match or step outside (0, 1]
 * @throws Cancelled when progress's callback says stop (mesh is then partly relaxed)
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
 * @throws Cancelled when progress's callback says stop (mesh is then partly repaired)
 */
std::pair<int, int> repairInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh, int rings = 2, int iterations = 10, int rounds = 3,
  const Progress& progress = Progress());

/// repairInvertedQuads for the quads findBad lists (a mesh's quads that are wrong in some way;
/// a round that makes the list longer is undone); `unfold` as QuadRelaxOptions::unfold.
std::pair<int, int> repairQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh,
  const std::function<std::vector<int>(const QuadMesh&)>& findBad, int rings, int iterations,
  int rounds, const Progress& progress = Progress(), bool unfold = false);
}

#endif
