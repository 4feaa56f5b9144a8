// QuadRelaxation.cxx: relaxQuads (tangential relaxation on the input surface) and
// repairInvertedQuads.
#include "QuadRelaxation.h"

#include "QuadMeshAdjacency.h"
#include "ScaledJacobian.h"
#include "SurfaceLocator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
/// The sizes and the step; checked before anything else.
void checkSizes(const Eigen::MatrixX3i& F, const MeshTopology& topo, const QuadMesh& mesh,
  const QuadRelaxOptions& options)
{
  const int nV = static_cast<int>(mesh.V.rows());
  if (topo.numFaces != static_cast<int>(F.rows()) ||
    static_cast<int>(mesh.vertexTriangle.size()) != nV ||
    static_cast<int>(mesh.vertexPoint.size()) != nV ||
    (!options.movable.empty() && static_cast<int>(options.movable.size()) != nV))
  {
    throw std::invalid_argument("relaxQuads: sizes do not match");
  }
  if (!(options.step > 0 && options.step <= 1))
  {
    throw std::invalid_argument("relaxQuads: the step must be in (0, 1]");
  }
}

/// The quads' vertices and the vertices' triangles; checked only when there is work to do.
void checkReferences(const Eigen::MatrixX3i& F, const QuadMesh& mesh)
{
  const int nV = static_cast<int>(mesh.V.rows());
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (mesh.Q(i, k) < 0 || mesh.Q(i, k) >= nV)
      {
        throw std::invalid_argument("relaxQuads: a quad refers to a vertex that does not exist");
      }
    }
  }
  for (const int t : mesh.vertexTriangle)
  {
    if (t < 0 || t >= static_cast<int>(F.rows()))
    {
      throw std::invalid_argument("relaxQuads: a vertex lies in no input triangle");
    }
  }
}

/// The corners of a vertex's quads: how many are not positive, and the worst.
struct Corners
{
  int inverted = 0;
  double worst = 1.0;
};

/// What the sweeps of relaxQuads share: the input's normals, the input edges no vertex crosses,
/// the vertices that stay, and the quads around each vertex.
class Relaxation
{
public:
  Relaxation(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
    QuadMesh& mesh, const QuadRelaxOptions& options)
    : V(V)
    , F(F)
    , topo(topo)
    , mesh(mesh)
    , options(options)
    , creaseCos(std::cos(options.featureAngle * 3.14159265358979323846 / 180.0))
  {
    computeNormals();
    findCreases();
    fixVertices();
    collectVertexQuads();
    meanEdge = meanQuadEdge(mesh);
  }

  int fixedVertices() const
  {
    int count = 0;
    for (const char f : fixed)
    {
      count += f;
    }
    return count;
  }

  /// One sweep over the vertices, in order (each move sees the ones before it).
  void sweep(QuadRelaxReport& report, const Progress& progress)
  {
    const int nV = static_cast<int>(mesh.V.rows());
    const int chunk = std::max(1024, nV / 16);
    for (int v = 0; v < nV; ++v)
    {
      if (v % chunk == 0)
      {
        progress.report(static_cast<double>(v) / nV);
      }
      if (!fixed[v] && offsets[v] != offsets[v + 1] &&
        (options.movable.empty() || options.movable[v]))
      {
        relaxVertex(v, report);
      }
    }
  }

private:
  void computeNormals()
  {
    const int nF = static_cast<int>(F.rows());
    normal.resize(nF, 3);
    centre.resize(nF, 3);
    radius.resize(nF);
    for (int f = 0; f < nF; ++f)
    {
      const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
      const Eigen::Vector3d n = (b - a).cross(c - a);
      normal.row(f) = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
      const Eigen::Vector3d m = (a + b + c) / 3.0;
      centre.row(f) = m.transpose();
      radius[f] = std::max({ (a - m).norm(), (b - m).norm(), (c - m).norm() });
    }
  }

  /// What a blocked edge is to the points on it: Blocked for all, and InnerCrease for a sharp edge
  /// between two triangles (not a boundary or non-manifold edge).
  static constexpr char Blocked = 1, InnerCrease = 2;

  /// The edges no vertex crosses (boundary, crease, non-manifold) and the points on them.
  void findCreases()
  {
    blocked.assign(topo.numEdges(), 1);
    pointOnCrease.assign(V.rows(), 0);
    for (int e = 0; e < topo.numEdges(); ++e)
    {
      if (topo.edgeFaceCount[e] == 2)
      {
        const Eigen::Vector3d n0 = normal.row(topo.edgeFaces(e, 0));
        const Eigen::Vector3d n1 = normal.row(topo.edgeFaces(e, 1));
        blocked[e] = n0.dot(n1) < creaseCos;
      }
      if (blocked[e])
      {
        const char kind = edgeKind(e);
        pointOnCrease[topo.edges(e, 0)] |= kind;
        pointOnCrease[topo.edges(e, 1)] |= kind;
      }
    }
  }

  char edgeKind(int e) const
  {
    return topo.edgeFaceCount[e] == 2 ? Blocked | InnerCrease : Blocked;
  }

  /// Fixed vertices: on the quad mesh's boundary, or on an input crease or boundary.
  void fixVertices()
  {
    fixed = quadMeshBoundary(mesh);
    creaseVertex.assign(mesh.V.rows(), 0);
    for (int v = 0; v < static_cast<int>(mesh.V.rows()); ++v)
    {
      const char kind = onCrease(v);
      creaseVertex[v] = (kind & InnerCrease) != 0;
      fixed[v] |= kind != 0;
    }
  }

  /// Is quad vertex v on a blocked input edge: its point on one, or on an edge of its triangle
  /// (relative distance to the edge's line)? 0, or the edges' kinds (Blocked, InnerCrease).
  char onCrease(int v) const
  {
    if (mesh.vertexPoint[v] >= 0)
    {
      return pointOnCrease[mesh.vertexPoint[v]];
    }
    const int f = mesh.vertexTriangle[v];
    const Eigen::Vector3d p = mesh.V.row(v);
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d a = V.row(F(f, k)), b = V.row(F(f, (k + 1) % 3));
      const double length = (b - a).norm();
      if (blocked[topo.faceEdges(f, k)] && length > 0 &&
        (p - a).cross(b - a).norm() <= 1e-6 * length * length)
      {
        return edgeKind(topo.faceEdges(f, k));
      }
    }
    return 0;
  }

  /// The quads of each vertex (CSR: offsets, quadsOf).
  void collectVertexQuads()
  {
    VertexQuads adjacency = vertexQuads(mesh);
    offsets = std::move(adjacency.offsets);
    quadsOf = std::move(adjacency.quads);
  }

  /// The area-weighted mean of the centres of v's quads; false when their area is 0.
  bool centreOfQuads(int v, Eigen::Vector3d& centre) const
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double weight = 0.0;
    for (int j = offsets[v]; j < offsets[v + 1]; ++j)
    {
      const int i = quadsOf[j];
      const Eigen::Vector3d p0 = mesh.V.row(mesh.Q(i, 0)), p1 = mesh.V.row(mesh.Q(i, 1));
      const Eigen::Vector3d p2 = mesh.V.row(mesh.Q(i, 2)), p3 = mesh.V.row(mesh.Q(i, 3));
      const double area = 0.5 * (p2 - p0).cross(p3 - p1).norm();
      sum += area * 0.25 * (p0 + p1 + p2 + p3);
      weight += area;
    }
    if (!(weight > 0))
    {
      return false;
    }
    centre = sum / weight;
    return true;
  }

  /// Do v's quads span a bend sharper than the feature angle: the input's normal at one of
  /// their corners against its normal at v? (Where they do, the surface bends that much within
  /// a quad or two, on a ridge or a tube only a few quads round: the centre of the quads lies
  /// off the surface there, and the move would drag the quads' chords across the bend.) A
  /// triangle of zero area has no normal and takes no part, nor does a corner on an inner input
  /// crease (not a boundary): its triangle may lie on either side, and a quad that reaches across
  /// the crease has a corner off it on the far side (quads along a crease that a quad edge
  /// follows move).
  bool spansBend(int v) const
  {
    const Eigen::Vector3d n = normal.row(mesh.vertexTriangle[v]);
    if (!(n.squaredNorm() > 0))
    {
      return false;
    }
    for (int j = offsets[v]; j < offsets[v + 1]; ++j)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int corner = mesh.Q(quadsOf[j], k);
        if (creaseVertex[corner])
        {
          continue;
        }
        const Eigen::Vector3d m = normal.row(mesh.vertexTriangle[corner]);
        if (m.squaredNorm() > 0 && n.dot(m) < creaseCos)
        {
          return true;
        }
      }
    }
    return false;
  }

  /// Moves v part of the way to the centre of its quads, in the plane of its triangle and back
  /// onto the surface, unless that folds a corner of its quads.
  void relaxVertex(int v, QuadRelaxReport& report)
  {
    if (options.holdAcrossBends && spansBend(v))
    {
      ++report.heldMoves;
      return;
    }
    Eigen::Vector3d centre;
    if (!centreOfQuads(v, centre))
    {
      return;
    }
    const Eigen::Vector3d old = mesh.V.row(v);
    const int oldTriangle = mesh.vertexTriangle[v];
    const Eigen::Vector3d n = normal.row(oldTriangle);
    Eigen::Vector3d move = options.step * (centre - old);
    move -= move.dot(n) * n;
    const Corners before = cornersOf(v);
    int f = oldTriangle;
    const Eigen::Vector3d moved = project(f, old + move);
    mesh.V.row(v) = moved;
    mesh.vertexTriangle[v] = f;
    const Corners after = cornersOf(v);
    // no corner turns inside out, and none already inside out gets worse
    if (after.inverted > before.inverted || (after.worst <= 0 && after.worst < before.worst))
    {
      mesh.V.row(v) = old;
      mesh.vertexTriangle[v] = oldTriangle;
      ++report.rejectedMoves;
      if (options.unfold && before.inverted > 0)
      {
        searchUnfold(v, before);
      }
    }
    else if (options.unfold && after.inverted > 0 && after.inverted >= before.inverted)
    {
      searchUnfold(v, after);
    }
    const Eigen::Vector3d now = mesh.V.row(v);
    if ((now - old).squaredNorm() > 0)
    {
      mesh.vertexPoint[v] = -1;
    }
    report.maxMove = std::max(report.maxMove, (now - old).norm() / meanEdge);
  }

  /// Where moving towards the centre leaves a corner of v's quads inside out: short steps in
  /// eight directions of the plane of v's triangle (0.05, 0.15 and 0.3 of the mean edge), each
  /// put back onto the surface; the one with the fewest corners inside out and then the best
  /// worst corner is taken, if it is better than `best` (where v is).
  void searchUnfold(int v, Corners best)
  {
    const Eigen::Vector3d start = mesh.V.row(v);
    const int startTriangle = mesh.vertexTriangle[v];
    const Eigen::Vector3d n = normal.row(startTriangle);
    const Eigen::Vector3d edge = V.row(F(startTriangle, 1)) - V.row(F(startTriangle, 0));
    if (!(n.squaredNorm() > 0) || !(edge.squaredNorm() > 0))
    {
      return;
    }
    const Eigen::Vector3d t1 = (edge - edge.dot(n) * n).normalized();
    const Eigen::Vector3d t2 = n.cross(t1);
    Eigen::Vector3d bestPoint = start;
    int bestTriangle = startTriangle;
    for (const double length : { 0.05, 0.15, 0.3 })
    {
      for (int k = 0; k < 8; ++k)
      {
        const double angle = k * 3.14159265358979323846 / 4.0;
        const Eigen::Vector3d step =
          length * meanEdge * (std::cos(angle) * t1 + std::sin(angle) * t2);
        int f = startTriangle;
        mesh.V.row(v) = project(f, start + step);
        mesh.vertexTriangle[v] = f;
        const Corners c = cornersOf(v);
        if (c.inverted < best.inverted || (c.inverted == best.inverted && c.worst > best.worst))
        {
          best = c;
          bestPoint = mesh.V.row(v);
          bestTriangle = f;
        }
      }
    }
    mesh.V.row(v) = bestPoint;
    mesh.vertexTriangle[v] = bestTriangle;
  }

  Eigen::Vector3d closestIn(int f, const Eigen::Vector3d& p) const
  {
    return closestOnTriangle(p, V.row(F(f, 0)), V.row(F(f, 1)), V.row(F(f, 2)));
  }

  /// Candidate triangles next to f: across its free edges, and around its corners up to a
  /// blocked edge.
  void gatherCandidates(int f)
  {
    candidates.clear();
    for (int k = 0; k < 3; ++k)
    {
      const int corner = F(f, k);
      for (const int side : { k, (k + 2) % 3 }) // the two edges of f at this corner
      {
        int g = f, edgeIndex = side;
        for (int guard = 0; guard < 64; ++guard)
        {
          if (blocked[topo.faceEdges(g, edgeIndex)])
          {
            break;
          }
          const int h = topo.faceNeighbors(g, edgeIndex);
          if (h < 0 || h == f)
          {
            break;
          }
          candidates.push_back(h);
          // continue around the corner: h's other edge at `corner`
          const int c = MeshTopology::cornerOf(F, h, corner);
          if (c < 0)
          {
            break;
          }
          const int shared = topo.faceEdges(g, edgeIndex);
          edgeIndex = topo.faceEdges(h, c) == shared ? (c + 2) % 3 : c;
          g = h;
        }
      }
    }
  }

  /// The closest point to p on the surface, walking from triangle f (updated to the triangle it
  /// lies in) to whichever candidate is closer until none is.
  Eigen::Vector3d project(int& f, const Eigen::Vector3d& p)
  {
    Eigen::Vector3d best = closestIn(f, p);
    double distance = (best - p).squaredNorm();
    double reach = std::sqrt(distance);
    for (int step = 0; step < 64; ++step)
    {
      gatherCandidates(f);
      int next = -1;
      for (std::size_t i = 0; i < candidates.size(); ++i)
      {
        // a candidate whose bounding sphere lies farther than the closest point so far (with
        // room for rounding far above it) cannot gain, nor can one met before in this step (the
        // fans around f's corners are walked both ways): the same walk, a tenth of the
        // triangles measured (cheburashka at 6,500 quads: 54,000 of 590,000 listed)
        const int g = candidates[i];
        const double bound = reach + radius[g] * (1.0 + 1e-9);
        if ((p - centre.row(g).transpose()).squaredNorm() > bound * bound * (1.0 + 1e-12) ||
          std::find(candidates.begin(), candidates.begin() + i, g) != candidates.begin() + i)
        {
          continue;
        }
        const Eigen::Vector3d q = closestIn(g, p);
        const double d = (q - p).squaredNorm();
        if (d < distance * (1.0 - 1e-12) - 1e-300)
        {
          distance = d;
          reach = std::sqrt(distance);
          best = q;
          next = g;
        }
      }
      if (next < 0)
      {
        break;
      }
      f = next;
    }
    return best;
  }

  /// The corners of v's quads, each measured against the input's normal at the corner and
  /// against the quad's own normal (its diagonals' cross product, as measureQuads does).
  Corners cornersOf(int v) const
  {
    Corners r;
    for (int j = offsets[v]; j < offsets[v + 1]; ++j)
    {
      const int i = quadsOf[j];
      const Eigen::Vector3d own = quadNormal(mesh.V, mesh.Q, i);
      for (int k = 0; k < 4; ++k)
      {
        const int c = mesh.Q(i, k);
        const Eigen::Vector3d next = mesh.V.row(mesh.Q(i, (k + 1) % 4)) - mesh.V.row(c);
        const Eigen::Vector3d prev = mesh.V.row(mesh.Q(i, (k + 3) % 4)) - mesh.V.row(c);
        const Eigen::Vector3d n = normal.row(mesh.vertexTriangle[c]);
        for (const Eigen::Vector3d& reference : { n, own })
        {
          const double sj = cornerScaledJacobian(next, prev, reference, -1.0);
          r.inverted += sj <= 0;
          r.worst = std::min(r.worst, sj);
        }
      }
    }
    return r;
  }

  const Eigen::MatrixX3d& V;
  const Eigen::MatrixX3i& F;
  const MeshTopology& topo;
  QuadMesh& mesh;
  const QuadRelaxOptions& options;
  const double creaseCos;          ///< cosine of options.featureAngle
  Eigen::MatrixX3d normal;         ///< #F x 3: the input's unit normals (0 where degenerate)
  Eigen::MatrixX3d centre;         ///< #F x 3: the input triangles' centroids
  Eigen::VectorXd radius;          ///< #F: their bounding spheres' radii about the centroids
  std::vector<char> blocked;       ///< per input edge: boundary, crease or non-manifold
  std::vector<char> pointOnCrease; ///< per input point: the kinds of blocked edges it is on
  std::vector<char> fixed;         ///< per quad vertex: stays where it is
  std::vector<char> creaseVertex;  ///< per quad vertex: on an inner input crease
  std::vector<int> offsets;        ///< #V + 1: where each vertex's quads start in quadsOf
  std::vector<int> quadsOf;        ///< the quads of each vertex, one after the other
  double meanEdge = 0.0;           ///< of the quad mesh, the unit of QuadRelaxReport::maxMove
  std::vector<int> candidates;     ///< gatherCandidates' result (its memory reused)
};

}

QuadRelaxReport relaxQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh, const QuadRelaxOptions& options,
  const Progress& progress)
{
  progress.report(0.0);
  checkSizes(F, topo, mesh, options);
  QuadRelaxReport report;
  if (options.relaxationIterations <= 0 || mesh.Q.rows() == 0)
  {
    return report;
  }
  checkReferences(F, mesh);
  Relaxation relaxation(V, F, topo, mesh, options);
  report.fixedVertices = relaxation.fixedVertices();
  // the setup counts as a sweep (it takes about half as long as one)
  const double share = 1.0 / (options.relaxationIterations + 1);
  for (int iteration = 0; iteration < options.relaxationIterations; ++iteration)
  {
    relaxation.sweep(report, progress.part((iteration + 1) * share, (iteration + 2) * share));
  }
  progress.report(1.0);
  return report;
}

std::pair<int, int> repairInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh, int rings, int iterations, int rounds,
  const Progress& progress)
{
  return repairQuads(
    V, F, topo, mesh, [](const QuadMesh& m) { return invertedQuads(m.V, m.Q); }, rings, iterations,
    rounds, progress);
}

std::pair<int, int> repairQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh,
  const std::function<std::vector<int>(const QuadMesh&)>& findBad, int rings, int iterations,
  int rounds, const Progress& progress, bool unfold)
{
  progress.report(0.0);
  std::vector<int> bad = findBad(mesh);
  const int before = static_cast<int>(bad.size());
  for (int round = 0; round < rounds && !bad.empty(); ++round)
  {
    QuadRelaxOptions options;
    options.relaxationIterations = iterations;
    options.unfold = unfold;
    options.movable = verticesNear(mesh, bad, rings);
    const Eigen::MatrixX3d keptV = mesh.V;
    const std::vector<int> keptTriangle = mesh.vertexTriangle, keptPoint = mesh.vertexPoint;
    relaxQuads(V, F, topo, mesh, options,
      progress.part(static_cast<double>(round) / rounds, static_cast<double>(round + 1) / rounds));
    const std::vector<int> now = findBad(mesh);
    if (now.size() > bad.size())
    {
      // the guard counts corners against two normals, measureQuads quads against one: rare
      mesh.V = keptV;
      mesh.vertexTriangle = keptTriangle;
      mesh.vertexPoint = keptPoint;
      break;
    }
    const bool repaired = now.size() < bad.size();
    bad = now;
    if (!repaired)
    {
      break;
    }
  }
  progress.report(1.0);
  return { before, static_cast<int>(bad.size()) };
}

}
