// QuadMeshAdjacency.cxx: vertexQuads, quadMeshBoundary, onSurfaceBoundary, verticesNear.
#include "QuadMeshAdjacency.h"

#include "SurfaceLocator.h"

#include <algorithm>
#include <map>
#include <utility>

namespace quadcover
{

VertexQuads vertexQuads(const QuadMesh& mesh)
{
  const int nV = static_cast<int>(mesh.V.rows());
  const int nQ = static_cast<int>(mesh.Q.rows());
  VertexQuads r;
  r.offsets.assign(nV + 1, 0);
  r.quads.resize(4 * static_cast<std::size_t>(nQ));
  for (int i = 0; i < nQ; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      ++r.offsets[mesh.Q(i, k) + 1];
    }
  }
  for (int v = 0; v < nV; ++v)
  {
    r.offsets[v + 1] += r.offsets[v];
  }
  std::vector<int> fill(r.offsets.begin(), r.offsets.end() - 1);
  for (int i = 0; i < nQ; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      r.quads[fill[mesh.Q(i, k)]++] = i;
    }
  }
  return r;
}

std::vector<char> quadMeshBoundary(const QuadMesh& mesh)
{
  std::vector<char> boundary(mesh.V.rows(), 0);
  std::map<std::pair<int, int>, int> edgeCount;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = mesh.Q(i, k), b = mesh.Q(i, (k + 1) % 4);
      ++edgeCount[{ std::min(a, b), std::max(a, b) }];
    }
  }
  for (const auto& [edge, count] : edgeCount)
  {
    if (count != 2)
    {
      boundary[edge.first] = boundary[edge.second] = 1;
    }
  }
  return boundary;
}

bool onSurfaceBoundary(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const QuadMesh& mesh, int v)
{
  if (mesh.vertexPoint[v] >= 0)
  {
    return topo.boundaryVertex[mesh.vertexPoint[v]] != 0; // on a point of the surface
  }
  const int t = mesh.vertexTriangle[v];
  if (t < 0)
  {
    return false;
  }
  const Eigen::Vector3d p = mesh.V.row(v);
  for (int k = 0; k < 3; ++k)
  {
    if (topo.faceNeighbors(t, k) < 0)
    {
      const Eigen::Vector3d a = V.row(F(t, k)), b = V.row(F(t, (k + 1) % 3));
      if ((closestOnSegment(p, a, b) - p).norm() <= 1e-7 * (b - a).norm())
      {
        return true;
      }
    }
  }
  return false;
}

std::vector<char> verticesNear(const QuadMesh& mesh, const std::vector<int>& quads, int rings)
{
  std::vector<char> near(mesh.V.rows(), 0);
  for (const int i : quads)
  {
    for (int k = 0; k < 4; ++k)
    {
      near[mesh.Q(i, k)] = 1;
    }
  }
  // grow by quad rings: every vertex of a quad with a vertex already in
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<char> grown = near;
    for (int i = 0; i < mesh.Q.rows(); ++i)
    {
      const bool touches =
        near[mesh.Q(i, 0)] || near[mesh.Q(i, 1)] || near[mesh.Q(i, 2)] || near[mesh.Q(i, 3)];
      for (int k = 0; k < 4 && touches; ++k)
      {
        grown[mesh.Q(i, k)] = 1;
      }
    }
    near.swap(grown);
  }
  return near;
}

}
