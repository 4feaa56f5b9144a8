// QuadMeshAdjacency.h: what the quad stage's repairs ask of a quad mesh's connectivity: the quads
// of each vertex, the vertices on its boundary or on the surface's, those near some quads; and
// its mean edge, their unit of length.
#ifndef quadcover_QuadMeshAdjacency_h
#define quadcover_QuadMeshAdjacency_h

#include "MeshTopology.h"
#include "QuadMesh.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/// The quads of each vertex, one vertex after the other: vertex v's are
/// quads[offsets[v] .. offsets[v + 1]), in index order.
struct VertexQuads
{
  std::vector<int> offsets; ///< #V + 1
  std::vector<int> quads;   ///< 4 #Q
};

VertexQuads vertexQuads(const QuadMesh& mesh);

/// The quads' connectivity as a triangle mesh's: each quad four triangles around a point of its
/// own (numbered after the quads' points), so that the points, edges, Euler characteristic,
/// boundary loops, pieces and non-manifold edges and points are the quads'. (Two triangles a quad
/// would share a diagonal between two quads that touch at opposite corners: an edge of four
/// triangles in a manifold quad mesh. Armadillo with holes at 3,000 quads read as non-manifold
/// and of Euler characteristic -6, its quads manifold and of -8, and the map that kept two of its
/// holes apart was refused.)
MeshTopology quadTopology(const QuadMesh& mesh);

/// The mean length of the quads' edges, each quad's four counted (an edge of two quads twice);
/// 0 without quads.
double meanQuadEdge(const QuadMesh& mesh);

/// #V, 1 for a vertex on an edge that does not have exactly two quads (the quad mesh's boundary,
/// or a non-manifold edge).
std::vector<char> quadMeshBoundary(const QuadMesh& mesh);

/// Whether quad vertex v lies on a boundary edge of the surface (V, F): its input point is a
/// boundary point, or it is within 1e-7 of an edge length of a boundary edge of its triangle.
bool onSurfaceBoundary(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const QuadMesh& mesh, int v);

/// #V, 1 for the vertices of the listed quads and of the quads within `rings` quad rings of them.
std::vector<char> verticesNear(const QuadMesh& mesh, const std::vector<int>& quads, int rings);

/**
 * Gives every vertex whose quads fall into several fans (joined through the vertex alone: two
 * pieces of the mesh, or two of its boundary loops, touching at a point) one copy per fan, so
 * that the mesh is manifold at its vertices as at its edges. The fan of the vertex's lowest quad
 * keeps it; the copies are appended (V, vertexTriangle and vertexPoint copied). Returns the
 * copies added.
 */
int splitPinchedVertices(QuadMesh& mesh);

/// Removes the vertices no quad uses, numbering the others in the order the quads first use
/// them; vertexTriangle and vertexPoint follow when they have an entry per vertex (otherwise
/// they are cleared).
void removeUnusedVertices(QuadMesh& mesh);

/**
 * Removes the fragments of a component's quads: pieces of the mesh (quads joined through edges)
 * of at most `largest` quads that touch, at points only (directly, or through other such
 * pieces), a piece at least four times their size on the same component of the surface (the
 * component of each quad's triangle, quadTriangle). Such a fragment is a quad or two hanging by a
 * corner off the rest (where a component's grid meets its boundary at a point); the pinch split
 * would leave it a piece of its own, which the surface's component does not have. Pieces that
 * touch nothing, or only pieces of other components or not much larger, are kept (two pieces
 * larger than `largest` touching do not join their groups). The vertices no quad uses any more
 * are removed.
 * @param faceComponent per surface triangle its component (MeshTopology::faceComponent)
 * @return the quads removed
 */
int dropPinchedFragments(QuadMesh& mesh, const Eigen::VectorXi& faceComponent, int largest);

/**
 * Removes the pieces of a component's quads (quads joined through edges) that are disks lying
 * against the rest: a piece other than the largest on its component of the surface (by
 * quadTriangle), of Euler characteristic 1, whose every corner lies within `reach` times the
 * largest piece's median edge of that piece's quads. Such a piece is a tongue of the surface
 * narrower than the grid, lying on or beside the rest, that the map cut off at its neck: a
 * strip 0.001 wide in a CAD part's seam, where the quads are 0.033 (the truck's body). Without
 * it the component's quads keep the surface's topology (a disk cut off at a neck takes none of
 * it along), and the surface lost lies within the reach of the quads. A disk that sticks out, or
 * a larger piece, is kept. The vertices no quad uses any more are removed.
 * @return the quads removed
 */
int dropPiecesAgainstRest(QuadMesh& mesh, const Eigen::VectorXi& faceComponent, double reach);
}

#endif
