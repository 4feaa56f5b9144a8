// QuadMeshAdjacency.cxx: vertexQuads, quadTopology, quadMeshBoundary, onSurfaceBoundary,
// verticesNear, splitPinchedVertices, removeUnusedVertices, dropPinchedFragments,
// dropPiecesAgainstRest.
#include "QuadMeshAdjacency.h"

#include "SurfaceLocator.h"
#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
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

double meanQuadEdge(const QuadMesh& mesh)
{
  double sum = 0.0;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      sum += (mesh.V.row(mesh.Q(i, k)) - mesh.V.row(mesh.Q(i, (k + 1) % 4))).norm();
    }
  }
  return mesh.Q.rows() > 0 ? sum / (4.0 * mesh.Q.rows()) : 0.0;
}

std::vector<char> quadMeshBoundary(const QuadMesh& mesh)
{
  std::vector<char> boundary(mesh.V.rows(), 0);
  // the quads' edges sorted, so that each edge's copies are side by side
  std::vector<std::pair<int, int>> edges;
  edges.reserve(4 * static_cast<std::size_t>(mesh.Q.rows()));
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = mesh.Q(i, k), b = mesh.Q(i, (k + 1) % 4);
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j)
  {
    while (j < edges.size() && edges[j] == edges[i])
    {
      ++j;
    }
    if (j - i != 2)
    {
      boundary[edges[i].first] = boundary[edges[i].second] = 1;
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

MeshTopology quadTopology(const QuadMesh& mesh)
{
  const Eigen::Index nV = mesh.V.rows(), nQ = mesh.Q.rows();
  Eigen::MatrixX3i T(4 * nQ, 3);
  for (Eigen::Index q = 0; q < nQ; ++q)
  {
    const int centre = static_cast<int>(nV + q);
    for (int k = 0; k < 4; ++k)
    {
      T.row(4 * q + k) << mesh.Q(q, k), mesh.Q(q, (k + 1) % 4), centre;
    }
  }
  return buildTopology(T, static_cast<int>(nV + nQ));
}

int splitPinchedVertices(QuadMesh& mesh)
{
  const VertexQuads around = vertexQuads(mesh);
  const int nV = static_cast<int>(mesh.V.rows());
  std::vector<int> source; // the vertex each copy copies
  for (int v = 0; v < nV; ++v)
  {
    // its quads (a degenerate one lists v twice), joined where they share an edge at v
    std::vector<int> quads(
      around.quads.begin() + around.offsets[v], around.quads.begin() + around.offsets[v + 1]);
    quads.erase(std::unique(quads.begin(), quads.end()), quads.end());
    if (quads.size() < 2)
    {
      continue;
    }
    std::vector<int> fan(quads.size());
    std::iota(fan.begin(), fan.end(), 0);
    std::map<int, int> across; // the other end of an edge at v -> the first of its quads met
    for (int i = 0; i < static_cast<int>(quads.size()); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        if (mesh.Q(quads[i], k) != v)
        {
          continue;
        }
        for (const int w : { mesh.Q(quads[i], (k + 1) % 4), mesh.Q(quads[i], (k + 3) % 4) })
        {
          const auto [at, first] = across.emplace(w, i);
          if (w != v && !first)
          {
            unite(fan, i, at->second);
          }
        }
      }
    }
    // the fan of the lowest quad keeps v; each other fan gets a copy
    std::map<int, int> copyOf; // a fan's root -> its vertex
    copyOf[findRoot(fan, 0)] = v;
    for (int i = 0; i < static_cast<int>(quads.size()); ++i)
    {
      const auto [at, added] =
        copyOf.emplace(findRoot(fan, i), nV + static_cast<int>(source.size()));
      if (added)
      {
        source.push_back(v);
      }
      for (int k = 0; k < 4; ++k)
      {
        if (mesh.Q(quads[i], k) == v)
        {
          mesh.Q(quads[i], k) = at->second;
        }
      }
    }
  }
  const int copies = static_cast<int>(source.size());
  mesh.V.conservativeResize(nV + copies, 3);
  for (int c = 0; c < copies; ++c)
  {
    mesh.V.row(nV + c) = mesh.V.row(source[c]);
    if (mesh.vertexTriangle.size() == static_cast<std::size_t>(nV) + c)
    {
      mesh.vertexTriangle.push_back(mesh.vertexTriangle[source[c]]);
    }
    if (mesh.vertexPoint.size() == static_cast<std::size_t>(nV) + c)
    {
      mesh.vertexPoint.push_back(mesh.vertexPoint[source[c]]);
    }
  }
  return copies;
}
void removeUnusedVertices(QuadMesh& mesh)
{
  const bool perVertexTriangle =
    mesh.vertexTriangle.size() == static_cast<std::size_t>(mesh.V.rows());
  const bool perVertexPoint = mesh.vertexPoint.size() == static_cast<std::size_t>(mesh.V.rows());
  std::vector<int> newIndex(mesh.V.rows(), -1);
  int used = 0;
  for (Eigen::Index i = 0; i < mesh.Q.rows(); ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      int& index = newIndex[mesh.Q(i, k)];
      index = index < 0 ? used++ : index;
      mesh.Q(i, k) = index;
    }
  }
  Eigen::MatrixX3d V(used, 3);
  std::vector<int> vertexTriangle(perVertexTriangle ? used : 0, -1);
  std::vector<int> vertexPoint(perVertexPoint ? used : 0, -1);
  for (int v = 0; v < static_cast<int>(newIndex.size()); ++v)
  {
    const int n = newIndex[v];
    if (n < 0)
    {
      continue;
    }
    V.row(n) = mesh.V.row(v);
    if (perVertexTriangle)
    {
      vertexTriangle[n] = mesh.vertexTriangle[v];
    }
    if (perVertexPoint)
    {
      vertexPoint[n] = mesh.vertexPoint[v];
    }
  }
  mesh.V.swap(V);
  mesh.vertexTriangle.swap(vertexTriangle);
  mesh.vertexPoint.swap(vertexPoint);
}

namespace
{
/// Per quad its piece (quads joined through shared edges): the lowest quad's index.
std::vector<int> piecesThroughEdges(const QuadMesh& mesh)
{
  const int nQ = static_cast<int>(mesh.Q.rows());
  std::vector<std::array<int, 3>> edges; // (lower end, upper end, quad)
  edges.reserve(4 * static_cast<std::size_t>(nQ));
  for (int i = 0; i < nQ; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = mesh.Q(i, k), b = mesh.Q(i, (k + 1) % 4);
      edges.push_back({ std::min(a, b), std::max(a, b), i });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<int> piece(nQ);
  std::iota(piece.begin(), piece.end(), 0);
  for (std::size_t e = 1; e < edges.size(); ++e)
  {
    if (edges[e][0] == edges[e - 1][0] && edges[e][1] == edges[e - 1][1])
    {
      unite(piece, edges[e][2], edges[e - 1][2]);
    }
  }
  for (int i = 0; i < nQ; ++i)
  {
    piece[i] = findRoot(piece, i);
  }
  return piece;
}

/// The mesh without the quads marked (and without the vertices no quad uses any more).
void removeQuads(QuadMesh& mesh, const std::vector<char>& remove)
{
  const bool perQuad = mesh.quadTriangle.size() == static_cast<std::size_t>(mesh.Q.rows());
  int kept = 0;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    if (!remove[i])
    {
      mesh.Q.row(kept) = mesh.Q.row(i);
      if (perQuad)
      {
        mesh.quadTriangle[kept] = mesh.quadTriangle[i];
      }
      ++kept;
    }
  }
  mesh.Q.conservativeResize(kept, 4);
  mesh.quadTriangle.resize(perQuad ? kept : 0);
  removeUnusedVertices(mesh);
}

/// The mesh without the pieces marked (marked: per piece root, piecesThroughEdges'); returns the
/// quads removed.
int removePieces(QuadMesh& mesh, const std::vector<int>& piece, const std::vector<char>& marked)
{
  std::vector<char> remove(piece.size(), 0);
  int removed = 0;
  for (std::size_t i = 0; i < piece.size(); ++i)
  {
    remove[i] = marked[piece[i]];
    removed += remove[i];
  }
  if (removed > 0)
  {
    removeQuads(mesh, remove);
  }
  return removed;
}
}

int dropPinchedFragments(QuadMesh& mesh, const Eigen::VectorXi& faceComponent, int largest)
{
  const int nQ = static_cast<int>(mesh.Q.rows());
  if (nQ == 0 || largest <= 0)
  {
    return 0;
  }
  const std::vector<int> piece = piecesThroughEdges(mesh);
  std::vector<int> size(nQ, 0), component(nQ, -1);
  for (int i = 0; i < nQ; ++i)
  {
    ++size[piece[i]];
    const int t = i < static_cast<int>(mesh.quadTriangle.size()) ? mesh.quadTriangle[i] : -1;
    if (component[piece[i]] < 0 && t >= 0 && t < faceComponent.size())
    {
      component[piece[i]] = faceComponent[t];
    }
  }
  // pieces joined through points into groups, each join through a piece of at most `largest`
  // quads (two large pieces touching stay apart); in each group, per component, the largest piece
  std::vector<int> group(nQ);
  std::iota(group.begin(), group.end(), 0);
  const VertexQuads around = vertexQuads(mesh);
  for (int v = 0; v + 1 < static_cast<int>(around.offsets.size()); ++v)
  {
    for (int j = around.offsets[v]; j < around.offsets[v + 1]; ++j)
    {
      for (int l = around.offsets[v]; l < j; ++l)
      {
        const int a = piece[around.quads[j]], b = piece[around.quads[l]];
        if (a != b && (size[a] <= largest || size[b] <= largest))
        {
          unite(group, a, b);
        }
      }
    }
  }
  std::map<std::pair<int, int>, int> most; // (group, component) -> its largest piece's size
  for (int i = 0; i < nQ; ++i)
  {
    if (piece[i] == i && component[i] >= 0)
    {
      int& m = most[{ findRoot(group, i), component[i] }];
      m = std::max(m, size[i]);
    }
  }
  // a small piece with a piece of its component at least four times its size in its group
  std::vector<char> fragment(nQ, 0);
  for (int i = 0; i < nQ; ++i)
  {
    if (piece[i] == i && component[i] >= 0 && size[i] <= largest)
    {
      fragment[i] = most[{ findRoot(group, i), component[i] }] >= 4 * size[i];
    }
  }
  return removePieces(mesh, piece, fragment);
}

namespace
{
/// Per piece (piecesThroughEdges' roots) its Euler characteristic: points - edges + quads.
std::vector<int> pieceEulerCharacteristics(const QuadMesh& mesh, const std::vector<int>& piece)
{
  const int nQ = static_cast<int>(mesh.Q.rows());
  std::vector<int> chi(nQ, 0);
  std::vector<std::pair<int, int>> points; // (point, piece)
  std::vector<std::array<int, 3>> edges;   // (lower end, upper end, piece)
  for (int i = 0; i < nQ; ++i)
  {
    ++chi[piece[i]];
    for (int k = 0; k < 4; ++k)
    {
      const int a = mesh.Q(i, k), b = mesh.Q(i, (k + 1) % 4);
      points.emplace_back(a, piece[i]);
      edges.push_back({ std::min(a, b), std::max(a, b), piece[i] });
    }
  }
  std::sort(points.begin(), points.end());
  std::sort(edges.begin(), edges.end());
  for (std::size_t j = 0; j < points.size(); ++j)
  {
    chi[points[j].second] += (j == 0 || points[j] != points[j - 1]);
  }
  for (std::size_t j = 0; j < edges.size(); ++j)
  {
    chi[edges[j][2]] -= (j == 0 || edges[j] != edges[j - 1]);
  }
  return chi;
}

/// The median length of the edges of the quads of `piece` (each quad's four).
double medianEdgeOf(const QuadMesh& mesh, const std::vector<int>& piece, int which)
{
  std::vector<double> lengths;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    for (int k = 0; piece[i] == which && k < 4; ++k)
    {
      lengths.push_back((mesh.V.row(mesh.Q(i, k)) - mesh.V.row(mesh.Q(i, (k + 1) % 4))).norm());
    }
  }
  if (lengths.empty())
  {
    return 0.0;
  }
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

/// The quads of piece `which`, each as two triangles.
Eigen::MatrixX3i trianglesOfPiece(const QuadMesh& mesh, const std::vector<int>& piece, int which)
{
  const int nQ = static_cast<int>(mesh.Q.rows());
  Eigen::MatrixX3i F(2 * std::count(piece.begin(), piece.end(), which), 3);
  for (int i = 0, t = 0; i < nQ; ++i)
  {
    if (piece[i] == which)
    {
      F.row(t++) << mesh.Q(i, 0), mesh.Q(i, 1), mesh.Q(i, 2);
      F.row(t++) << mesh.Q(i, 0), mesh.Q(i, 2), mesh.Q(i, 3);
    }
  }
  return F;
}

/// Whether every corner of the quads of piece `which` lies within `reach` of `rest`.
bool pieceWithin(const QuadMesh& mesh, const std::vector<int>& piece, int which,
  const SurfaceLocator& rest, double reach)
{
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    for (int k = 0; piece[i] == which && k < 4; ++k)
    {
      if (!(rest.closest(mesh.V.row(mesh.Q(i, k)).transpose()).distance <= reach))
      {
        return false;
      }
    }
  }
  return true;
}
}

int dropPiecesAgainstRest(QuadMesh& mesh, const Eigen::VectorXi& faceComponent, double reach)
{
  const int nQ = static_cast<int>(mesh.Q.rows());
  if (nQ == 0 || !(reach > 0) || mesh.quadTriangle.size() != static_cast<std::size_t>(nQ))
  {
    return 0;
  }
  const std::vector<int> piece = piecesThroughEdges(mesh);
  std::vector<int> size(nQ, 0);
  std::map<int, std::vector<int>> pieces; // component -> its pieces (roots), in index order
  for (int i = 0; i < nQ; ++i)
  {
    ++size[piece[i]];
    const int t = mesh.quadTriangle[i];
    if (piece[i] == i && t >= 0 && t < faceComponent.size())
    {
      pieces[faceComponent[t]].push_back(i);
    }
  }
  std::vector<int> chi;
  std::vector<char> remove(nQ, 0);
  for (const auto& [component, roots] : pieces)
  {
    if (roots.size() < 2)
    {
      continue;
    }
    if (chi.empty())
    {
      chi = pieceEulerCharacteristics(mesh, piece);
    }
    // the largest piece (the first of equal size), and its unit of length
    const int rest = *std::max_element(
      roots.begin(), roots.end(), [&](int a, int b) { return size[a] < size[b]; });
    if (std::none_of(roots.begin(), roots.end(), [&](int p) { return p != rest && chi[p] == 1; }))
    {
      continue;
    }
    const double within = reach * medianEdgeOf(mesh, piece, rest);
    const Eigen::MatrixX3i restTriangles = trianglesOfPiece(mesh, piece, rest);
    const SurfaceLocator restLocator(mesh.V, restTriangles);
    for (const int p : roots)
    {
      if (p != rest && chi[p] == 1 && pieceWithin(mesh, piece, p, restLocator, within))
      {
        remove[p] = 1;
      }
    }
  }
  return removePieces(mesh, piece, remove);
}
}
