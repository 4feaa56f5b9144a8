// QuadFacing.h: which way a quad faces against the surface it remeshes, and the repair that turns
// the quads facing against it (or turned inside out) back by moving their corners on the surface.
#ifndef quadcover_QuadFacing_h
#define quadcover_QuadFacing_h

#include "MeshTopology.h"
#include "QuadMesh.h"
#include "SurfaceLocator.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/**
 * How quad i faces the surface: the cosine between its normal (the sum of its corners' cross
 * products about its centre) and the normal of the surface triangle closest to its centre, over
 * the whole surface (the smallest over the triangles within a thousandth of the quad's mean edge
 * of the closest distance, so that a tie above a crease or where components cross is not left to
 * chance). In [-1, 1]; -1 for a quad of zero area. Where those triangles face back at the quad
 * (a cosine of -0.5 or less), lie on other components than its corners' triangles
 * (mesh.vertexTriangle; the locator's triangles labelled, SurfaceLocator::setComponents), while the
 * quad faces as its corners' triangles do, its centre lies below them and, lifted onto its own
 * sheet, faces the surface closest to it there, the quad is measured against its corners' triangles
 * instead: two sheets closer than the quad bulges (the walls of a hollow part, 1% of its size
 * apart, at 1,000 quads), which no move of its corners on the surface mends; liftOffOtherComponents
 * does. Components that cross (a teapot's spout in its body) are measured as closest.
 */
double quadFacing(const SurfaceLocator& surface, const QuadMesh& mesh, int i);

/// What liftOffOtherComponents did.
struct SheetLift
{
  int liftedVertices = 0; ///< quad vertices moved off the surface
  int remaining = 0;      ///< quads it would still lift (they face against the closest surface)
};

/// The quads quadFacing measures against their corners' triangles (its exception), in index
/// order: those liftOffOtherComponents lifts; each faces against the triangle closest to its
/// centre over the whole surface.
std::vector<int> quadsToLift(const SurfaceLocator& surface, const QuadMesh& mesh);

/**
 * The corners of quadsToLift lifted off their own triangles along those triangles' normals, each
 * by the most its quads' centres lie below their own sheet (half their depth below their corners'
 * tangent planes), so that the centres come onto it. The vertices leave the surface by about a
 * quad's bulge over it (its sagitta; their vertexTriangle kept, vertexPoint -1); elsewhere
 * nothing moves.
 */
SheetLift liftOffOtherComponents(const SurfaceLocator& surface, QuadMesh& mesh);

/// The smaller of quadFacing and quadScaledJacobian: at most 0 for a quad facing against the
/// surface or with a corner inside out (what repairFacing repairs).
double quadWorstOf(const SurfaceLocator& surface, const QuadMesh& mesh, int i);

/// The quads that face against the surface (quadFacing <= 0), in index order: the figure
/// TurnedQuads.
std::vector<int> turnedQuads(const SurfaceLocator& surface, const QuadMesh& mesh);

/// turnedQuads of the quads q on the surface (V, F).
std::vector<int> turnedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const QuadMesh& q);

/**
 * quadFacing of a quad mesh's quads, kept from one call to the next: a quad is measured again
 * only where its corners are not exactly where they were when it was last measured, so that
 * each call gives what quadFacing gives. For the passes over every quad of a mesh whose repairs
 * move a few of its vertices between them (cheburashka at 6,500 quads: 60,000 closest-point
 * searches over nine passes, 9% of the run).
 */
class QuadFacingMemo
{
public:
  /// threads: for the quads turned() measures (0: defaultThreadCount()).
  explicit QuadFacingMemo(const SurfaceLocator& surface, int threads = 0)
    : surface_(surface)
    , threads_(threads)
  {}

  /// quadFacing(surface, mesh, i)
  double facing(const QuadMesh& mesh, int i);

  /// quadWorstOf(surface, mesh, i)
  double worst(const QuadMesh& mesh, int i);

  /// turnedQuads(surface, mesh); the quads to measure again measured on the threads asked.
  std::vector<int> turned(const QuadMesh& mesh);

private:
  static Eigen::Matrix<double, 4, 3> cornersOf(const QuadMesh& mesh, int i);
  /// Is quad i to be measured (again)? Sizes the memo to the mesh first.
  bool stale(const QuadMesh& mesh, int i);

  const SurfaceLocator& surface_;
  int threads_ = 0;
  std::vector<Eigen::Matrix<double, 4, 3>> corners_; ///< per quad, where it was measured
  std::vector<double> facing_;                       ///< and what it measured (NaN: never)
};

/// What repairFacing did.
struct FacingRepair
{
  int before = 0;        ///< quads facing against the surface or turned inside out, before
  int after = 0;         ///< and after
  int movedVertices = 0; ///< quad vertices moved (each counted once)
  long long measurements = 0; ///< quads measured (the work, bounded by 40 a quad plus 100,000)
};

/**
 * Quads that face against the surface (turnedQuads) or have a corner turned inside out
 * (quadScaledJacobian <= 0) are left where the map is compressed or folds across a sharp crease or
 * a thin part: a quad straddling a crease mostly on one side, or wrapped around a rim thinner than
 * itself. This moves their corners, and then those of the quads around them (up to three rings),
 * one at a time to the point of the surface nearby (within about an edge length, on the triangles
 * connected to the vertex's own, crease points included) that makes the worst of its quads best,
 * the worst measured as the smaller of quadFacing and quadScaledJacobian; a vertex whose quads are
 * all fine stays. The connectivity stays (the mesh keeps all quads, manifold, its Euler
 * characteristic). A vertex on both the quad mesh's boundary and the surface's slides along the
 * surface's boundary instead (points at up to 3/4 of its longest quad edge each way, and the
 * surface points passed), never past a corner where the boundary turns by more than 30 degrees,
 * nor onto one; other vertices on either boundary stay (the teapot's spout at 1,000 quads: two
 * quads inside out at its rim, whose corners could not move, now none). The work is
 * bounded (FacingRepair::measurements), so that where it cannot succeed it stops in about the time
 * the extraction took. When the moves leave more such quads than they found, the mesh is put
 * back.
 * @param[in]     V, F, topo the surface the quads lie on
 * @param[in]     surface    SurfaceLocator(V, F)
 * @param[in,out] mesh       the quad mesh: V, vertexTriangle, vertexPoint
 * @param[in,out] facings    if given, a QuadFacingMemo on `surface` that has measured this mesh's
 *                           quads before (they are not measured again where they did not move)
 */
FacingRepair repairFacing(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const SurfaceLocator& surface, QuadMesh& mesh,
  QuadFacingMemo* facings = nullptr);
}

#endif
