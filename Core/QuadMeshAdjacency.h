// QuadMeshAdjacency.h: what the quad stage's repairs ask of a quad mesh's connectivity: the quads
// of each vertex, the vertices on its boundary or on the surface's, those near some quads.
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
}

#endif
