// MeshTopology.h: connectivity of a triangle mesh, the combinatorial base of every stage.
#ifndef quadcover_MeshTopology_h
#define quadcover_MeshTopology_h

#include <Eigen/Core>

#include <algorithm>

#include <string>
#include <vector>

namespace quadcover
{

/// Topological figures of one connected component (vertices joined by triangle edges).
struct ComponentInfo
{
  int numVertices = 0;
  int numEdges = 0;
  int numFaces = 0;
  int numBoundaryLoops = 0;
  int eulerCharacteristic = 0; ///< V - E + F
  bool manifold = true;        ///< no non-manifold edge or vertex
  bool oriented = true;        ///< every interior edge is traversed once in each direction
  /// (2 - chi - b) / 2 for a manifold, consistently oriented component; -1 otherwise.
  int genus = -1;
};

/// 2 - chi = 2 genus + boundary loops of a component of Euler characteristic chi, at least 1 (a
/// disk or a sphere: 1): how many times a component's minimum of quads it needs so that no hole
/// or handle is left only a few cells.
inline int holesAndHandles(int eulerCharacteristic)
{
  return std::max(1, 2 - eulerCharacteristic);
}

/**
 * Edges, adjacency, ordered one-rings, boundary loops and components of a triangle mesh.
 *
 * Conventions (used by every later stage):
 * - edge k of face f joins F(f,k) and F(f,(k+1)%3);
 * - edges(e,0) < edges(e,1);
 * - a one-ring lists the faces around a vertex counterclockwise (seen from the side the
 *   triangles' orientation points to); for a boundary vertex it starts at the face whose edge
 *   from v to the face's next corner is a boundary edge, and ends at the other boundary face.
 */
struct MeshTopology
{
  int numVertices = 0;
  int numFaces = 0;

  Eigen::MatrixX2i edges;         ///< #E x 2 vertex indices, sorted
  Eigen::MatrixX3i faceEdges;     ///< #F x 3 edge index of edge k
  Eigen::MatrixX3i faceNeighbors; ///< #F x 3 face across edge k; -1 on boundary/non-manifold
  Eigen::MatrixX2i edgeFaces;     ///< #E x 2 the first two faces on the edge (-1 if absent)
  /// #E x 2 the edge's slot in those faces, as corner 3f+k (the edge is edge k of face f, running
  /// F(f,k) -> F(f,k+1)); -1 if absent. edgeCorners(e,i) / 3 == edgeFaces(e,i).
  Eigen::MatrixX2i edgeCorners;
  Eigen::VectorXi edgeFaceCount; ///< #E number of faces on the edge

  std::vector<int> ringOffsets; ///< #V+1, CSR offsets into ringFaces
  /// Non-degenerate faces around each vertex: counterclockwise where ringOrdered, else (at
  /// non-manifold vertices, or where neighbours disagree in orientation) in index order.
  std::vector<int> ringFaces;
  std::vector<char> ringOrdered;    ///< #V, 1 where ringFaces is the counterclockwise fan
  std::vector<char> boundaryVertex; ///< #V, 1 on an edge with one triangle

  std::vector<std::vector<int>> boundaryLoops; ///< vertex loops, in the faces' direction
  Eigen::VectorXi vertexComponent;             ///< #V component index, -1 for unreferenced vertices
  Eigen::VectorXi faceComponent;               ///< #F component index
  std::vector<ComponentInfo> components;

  /// faces that repeat a vertex index: they have no edges, no neighbours and are in no ring
  std::vector<int> degenerateFaces;
  std::vector<int> nonManifoldEdges; ///< edges with more than two faces
  /// vertices whose triangles form several fans joined only at the vertex (orientation aside)
  std::vector<int> nonManifoldVertices;
  std::vector<int> misorientedEdges; ///< interior edges traversed twice in the same direction
  std::vector<int> unreferencedVertices;

  int numEdges() const { return static_cast<int>(edges.rows()); }
  int numComponents() const { return static_cast<int>(components.size()); }
  bool isManifold() const
  {
    return degenerateFaces.empty() && nonManifoldEdges.empty() && nonManifoldVertices.empty();
  }
  bool isOriented() const { return misorientedEdges.empty(); }
  bool isClosed() const { return boundaryLoops.empty(); }
  /// Euler characteristic of the whole mesh (unreferenced vertices not counted).
  int eulerCharacteristic() const;
  /// Number of (non-degenerate) faces around v.
  int valence(int v) const { return ringOffsets[v + 1] - ringOffsets[v]; }
  /// Position (0..2) of vertex v in face f, -1 if absent.
  static int cornerOf(const Eigen::MatrixX3i& F, int f, int v)
  {
    return F(f, 0) == v ? 0 : (F(f, 1) == v ? 1 : (F(f, 2) == v ? 2 : -1));
  }
  /// One line that names what is wrong (non-manifold, misoriented, degenerate), "" if nothing.
  std::string describeDefects() const;
};

/// Calls visit(f, k, g) for each edge k of each face f that has a neighbour g across it
/// (faceNeighbors(f, k) >= 0), faces in index order and edges 0, 1, 2 within each: every inner
/// edge twice, once from each side.
template<typename Visit>
void forEachNeighbor(const MeshTopology& topo, Visit&& visit)
{
  const int nf = static_cast<int>(topo.faceNeighbors.rows());
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g >= 0)
      {
        visit(f, k, g);
      }
    }
  }
}

/// Builds the connectivity of a triangle mesh.
/// @param[in] F           #F x 3 vertex indices
/// @param[in] numVertices number of vertices (indices must lie in [0, numVertices))
/// @throws std::invalid_argument if an index is out of range
MeshTopology buildTopology(const Eigen::MatrixX3i& F, int numVertices);

}

#endif
