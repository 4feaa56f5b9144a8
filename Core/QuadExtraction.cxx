// QuadExtraction.cxx: extractQuads, one quad per grid cell of an integer-grid map, its corners
// found by walking in (u, v) across edges and seams.
#include "QuadExtraction.h"

#include "QuadOverlaps.h"
#include "UnionFind.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace quadcover
{
namespace
{
using Complex = std::complex<double>;

double cross(Complex a, Complex b)
{
  return a.real() * b.imag() - a.imag() * b.real();
}

/// The distance from p to the segment from a to b.
double distanceToSegment(Complex p, Complex a, Complex b)
{
  const Complex d = b - a;
  const double t =
    std::norm(d) > 0 ? std::clamp(std::real((p - a) * std::conj(d)) / std::norm(d), 0.0, 1.0) : 0.0;
  return std::abs(a + t * d - p);
}

Complex turn(Complex z, int r)
{
  for (int q = 0; q < r; ++q)
  {
    z *= Complex(0, 1);
  }
  return z;
}

/// Where a grid point was found: identity (kind: 0 point, 1 edge, 2 inside a triangle; the
/// element; integer (u, v) in the element's chart), triangle and barycentric coordinates.
using Key = std::tuple<int, int, long long, long long>;

struct Location
{
  Key key;
  int triangle = -1;
  Eigen::Vector3d bary;
};

/// Cuts the cells out of the map: the transitions read off it, the walks to the corners, the
/// corners' identities, and the quads and vertices found so far.
class Extractor
{
public:
  Extractor(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
    const Eigen::MatrixXd& uv, const QuadExtractionOptions& options, QuadMesh& out)
    : V(V)
    , F(F)
    , topo(topo)
    , uv(uv)
    , options(options)
    , out(out)
  {
    const int nF = static_cast<int>(F.rows());
    flipped.assign(nF, 0);
    flat.assign(nF, 0);
    for (int f = 0; f < nF; ++f)
    {
      const double area = cross(z(f, 1) - z(f, 0), z(f, 2) - z(f, 0));
      flipped[f] = !(area > 0);
      const double longest = std::max({ std::norm(z(f, 1) - z(f, 0)), std::norm(z(f, 2) - z(f, 1)),
        std::norm(z(f, 0) - z(f, 2)) });
      flat[f] = flipped[f] && std::abs(area) <= options.flatTolerance * longest;
    }
    // transitions z_g = i^r z_f + t across every inner edge, read off the map
    rotation = Eigen::MatrixX3i::Zero(nF, 3);
    translation.assign(3 * static_cast<std::size_t>(nF), Complex(0, 0));
    forEachNeighbor(topo, [&](int f, int k, int) { readTransition(f, k); });
    gluePoints();
  }

  /// Every cell whose centre a triangle holds, in the order of the triangles, then the overlaps
  /// removed and the vertices no quad uses dropped. The triangles take the first 60% of the
  /// progress, the overlaps most of the rest: on a fine grid their ordered maps take about as
  /// long as the cells.
  void run(const Progress& progress)
  {
    const int nF = static_cast<int>(F.rows());
    const int stride = std::max(1, nF / 100);
    for (int f = 0; f < nF; ++f)
    {
      if (f % stride == 0)
      {
        progress.report(0.6 * f / nF);
      }
      if (!flipped[f])
      {
        cutCellsOf(f);
      }
    }
    out.cellsConflicting +=
      removeOverlappingQuads(quads, out.quadTriangle, progress.part(0.6, 0.95));
    keepUsedVertices();
  }

private:
  Complex z(int f, int k) const { return { uv(f, 2 * k), uv(f, 2 * k + 1) }; }

  /// The transition across inner edge k of f to its neighbour g: the quarter turn that best maps
  /// the edge's image in f onto its image in g, and the translation, snapped to the integers
  /// when it is within 1e-6 of them (counted when it is not).
  void readTransition(int f, int k)
  {
    const int g = topo.faceNeighbors(f, k);
    const Complex fa = z(f, k);
    const Complex fb = z(f, (k + 1) % 3);
    const Complex ga = z(g, MeshTopology::cornerOf(F, g, F(f, k)));
    const Complex gb = z(g, MeshTopology::cornerOf(F, g, F(f, (k + 1) % 3)));
    int best = 0;
    double bestError = 1e300;
    for (int r = 0; r < 4; ++r)
    {
      const double error = std::abs((gb - ga) - turn(fb - fa, r));
      if (error < bestError)
      {
        best = r;
        bestError = error;
      }
    }
    Complex t = ga - turn(fa, best);
    const Complex rounded(std::round(t.real()), std::round(t.imag()));
    if (std::abs(t - rounded) < 1e-6)
    {
      t = rounded;
    }
    else if (f < g)
    {
      ++out.nonIntegerTransitions;
    }
    rotation(f, k) = best;
    translation[3 * f + k] = t;
  }

  /// Points the map puts at one place: the ends of an edge whose image is a point, and the
  /// corners opposite an edge on its two sides (a flat triangle's corner on the edge, where its
  /// neighbour's is). A grid point there is one vertex, whichever triangle finds it (a branch
  /// point next to a boundary corner on the boundary's line, the two joined by slivers, gave two
  /// vertices and tore the quads apart). A map without flipped triangles glues no points.
  void gluePoints()
  {
    const int nV = static_cast<int>(V.rows());
    std::vector<int> parent(nV);
    std::iota(parent.begin(), parent.end(), 0);
    const double near = options.pointTolerance;
    forEachNeighbor(topo, [&](int f, int k, int g) {
      if (!flipped[f] && !flipped[g])
      {
        return; // two triangles of positive area: their opposite corners are on either side
      }
      if (std::abs(z(f, k) - z(f, (k + 1) % 3)) <= near)
      {
        unite(parent, F(f, k), F(f, (k + 1) % 3));
      }
      const int d =
        3 - MeshTopology::cornerOf(F, g, F(f, k)) - MeshTopology::cornerOf(F, g, F(f, (k + 1) % 3));
      if (std::abs(across(f, k, z(f, (k + 2) % 3)) - z(g, d)) <= near)
      {
        unite(parent, F(f, (k + 2) % 3), F(g, d));
      }
    });
    pointAlias.resize(nV);
    for (int v = 0; v < nV; ++v)
    {
      pointAlias[v] = findRoot(parent, v);
    }
  }

  Eigen::Vector3d barycentric(int f, Complex q) const
  {
    const Complex a = z(f, 0), b = z(f, 1), c = z(f, 2);
    const double area = cross(b - a, c - a);
    return Eigen::Vector3d(cross(b - q, c - q), cross(c - q, a - q), cross(a - q, b - q)) / area;
  }

  Complex across(int f, int k, Complex q) const
  {
    return turn(q, rotation(f, k)) + translation[3 * f + k];
  }

  /// Follows the straight segment from p (in triangle f, f's chart) to q across edges and seams
  /// to the triangle holding q. Around a cone the (u, v) plane has several sheets, and only the
  /// straight segment stays on the sheet of the cell it starts in (a walk that merely steps
  /// towards q can go around a cone the other way and find q on another sheet: another vertex).
  bool walkLine(int f, Complex p, Complex q, Location& at) const
  {
    int entered = -1; // the edge of f we came in through
    // into the neighbour g across f's edge: p and q in its chart, the edge it is entered by
    auto crossInto = [&](int edge, int g) {
      const int shared = topo.faceEdges(f, edge);
      p = across(f, edge, p);
      q = across(f, edge, q);
      f = g;
      entered = -1;
      for (int k = 0; k < 3; ++k)
      {
        entered = topo.faceEdges(f, k) == shared ? k : entered;
      }
    };
    for (int step = 0; step < options.maximumWalk; ++step)
    {
      if (flipped[f] && !(flat[f] && entered >= 0))
      {
        return false;
      }
      if (flipped[f])
      {
        // A triangle whose image is a segment (a sliver next to a boundary line, or a cone's
        // point on that line: nothing can give it area) holds no cell, but the segment p -> q
        // crosses it: out through the other edge whose image p lies on.
        int exit = -1;
        double nearest = 1e300;
        for (int edge = 0; edge < 3; ++edge)
        {
          if (edge == entered)
          {
            continue;
          }
          const double distance = distanceToSegment(p, z(f, edge), z(f, (edge + 1) % 3));
          if (distance < nearest)
          {
            nearest = distance;
            exit = edge;
          }
        }
        const int g = topo.faceNeighbors(f, exit);
        if (g < 0)
        {
          return false;
        }
        crossInto(exit, g);
        continue;
      }
      const Eigen::Vector3d bq = barycentric(f, q);
      if (bq.minCoeff() >= -options.tolerance)
      {
        identify(f, q, bq, at);
        return true;
      }
      const Eigen::Vector3d bp = barycentric(f, p).cwiseMax(0.0);
      // leave through the edge whose coordinate reaches 0 first along p -> q
      int exit = -1;
      double first = 1e300;
      for (int k = 0; k < 3; ++k)
      {
        const int edge = (k + 1) % 3;
        if (!(bq[k] < -options.tolerance) || edge == entered)
        {
          continue;
        }
        const double t = bp[k] / (bp[k] - bq[k]);
        if (t < first)
        {
          first = t;
          exit = k;
        }
      }
      if (exit < 0)
      {
        return false;
      }
      const int edge = (exit + 1) % 3;
      const int g = topo.faceNeighbors(f, edge);
      if (g < 0)
      {
        return false; // beyond the boundary
      }
      p += first * (q - p);
      crossInto(edge, g);
    }
    return false;
  }

  /// Walks from triangle f towards q (in f's chart) to the triangle holding q: the fallback
  /// where the straight segment cannot be followed (a flipped triangle on it).
  bool walk(int f, Complex q, Location& at) const
  {
    unsigned long long random = 0x9E3779B97F4A7C15ULL;
    for (int step = 0; step < options.maximumWalk; ++step)
    {
      if (flipped[f])
      {
        return false;
      }
      const Eigen::Vector3d b = barycentric(f, q);
      int k = 0;
      b.minCoeff(&k);
      if (b[k] >= -options.tolerance)
      {
        identify(f, q, b, at);
        return true;
      }
      if (step >= 64)
      {
        // Always stepping towards the most negative coordinate can cycle on meshes far from
        // Delaunay; a random choice among the negative ones cannot (stochastic visibility walk).
        random = random * 6364136223846793005ULL + 1442695040888963407ULL;
        int choices[3];
        int count = 0;
        for (int c = 0; c < 3; ++c)
        {
          if (b[c] < -options.tolerance)
          {
            choices[count++] = c;
          }
        }
        k = choices[(random >> 33) % static_cast<unsigned long long>(count)];
      }
      const int edge = (k + 1) % 3; // the edge opposite corner k
      const int g = topo.faceNeighbors(f, edge);
      if (g < 0)
      {
        return false; // beyond the boundary
      }
      q = across(f, edge, q);
      f = g;
    }
    return false;
  }

  void identify(int f, Complex q, Eigen::Vector3d b, Location& at) const
  {
    // A grid point next to a point of the surface is that point. By the barycentric tolerance
    // alone, a grid point about that far from a point would be the point in one triangle of its
    // fan and on an edge or inside another (the tolerance scales with each triangle's shape), and
    // cells reaching it from different triangles would not share the corner (a symmetric torus
    // whose grid lines pass within 1e-6 of its points lost a band of quads). The distance in
    // (u, v) is the same in every chart, so every triangle of the fan agrees.
    int nearest = -1;
    double nearestDistance = options.pointTolerance;
    for (int k = 0; k < 3; ++k)
    {
      const double d = std::abs(z(f, k) - q);
      if (d <= nearestDistance)
      {
        nearest = k;
        nearestDistance = d;
      }
    }
    if (nearest >= 0)
    {
      at.triangle = f;
      at.bary = Eigen::Vector3d::Unit(nearest);
      at.key = { 0, pointAlias[F(f, nearest)], 0, 0 };
      return;
    }
    int zeros = 0;
    int zero = -1;
    for (int k = 0; k < 3; ++k)
    {
      if (std::abs(b[k]) <= options.tolerance)
      {
        ++zeros;
        zero = k;
        b[k] = 0.0;
      }
    }
    b = b.cwiseMax(0.0);
    b /= b.sum();
    at.triangle = f;
    at.bary = b;
    if (zeros >= 2)
    {
      int k = 0;
      b.maxCoeff(&k);
      at.key = { 0, pointAlias[F(f, k)], 0, 0 };
      return;
    }
    if (zeros == 1)
    {
      at.key = edgeKey(f, (zero + 1) % 3, q);
      return;
    }
    at.key = { 2, f, std::llround(q.real()), std::llround(q.imag()) };
  }

  /// The identity of grid point q (f's chart) on edge k of f: the edge and q in the chart of the
  /// edge's first triangle.
  Key ownEdgeKey(int f, int k, Complex q) const
  {
    const int e = topo.faceEdges(f, k);
    const int owner = topo.edgeFaces(e, 0);
    if (owner != f && topo.faceNeighbors(f, k) == owner)
    {
      q = across(f, k, q);
    }
    return { 1, e, std::llround(q.real()), std::llround(q.imag()) };
  }

  /// The identity of grid point q (f's chart) on edge k of f. Beyond the edge, flat triangles
  /// may lie on the same line in (u, v) (a strip the map squeezed onto a boundary's line): the
  /// grid point is on their edges and points too, and the triangles on the strip's other side
  /// find it there. It gets the least identity of all those, whichever side finds it (else the
  /// quads on the two sides of the strip do not share their corners, and come apart).
  Key edgeKey(int f, int k, Complex q) const
  {
    Key best = ownEdgeKey(f, k, q);
    std::vector<std::pair<int, Complex>> stack;
    std::vector<int> seen;
    const int g = topo.faceNeighbors(f, k);
    if (g >= 0 && flat[g])
    {
      stack.emplace_back(g, across(f, k, q));
      seen.push_back(g);
    }
    while (!stack.empty())
    {
      const auto [h, qh] = stack.back();
      stack.pop_back();
      for (int j = 0; j < 3; ++j)
      {
        if (std::abs(z(h, j) - qh) <= options.pointTolerance)
        {
          best = std::min(best, Key{ 0, pointAlias[F(h, j)], 0, 0 });
        }
        if (distanceToSegment(qh, z(h, j), z(h, (j + 1) % 3)) > options.pointTolerance)
        {
          continue; // q is not on this edge
        }
        best = std::min(best, ownEdgeKey(h, j, qh));
        const int n = topo.faceNeighbors(h, j);
        if (n >= 0 && flat[n] && std::find(seen.begin(), seen.end(), n) == seen.end())
        {
          stack.emplace_back(n, across(h, j, qh));
          seen.push_back(n);
        }
      }
    }
    return best;
  }

  /// Does triangle f hold the cell centre c (in its chart), up to the tolerance? A centre on an
  /// edge or a point is held by several triangles; the quads they give are the same and are
  /// merged later (deciding here which one owns it would need both sides to agree to the last
  /// bit across seams).
  bool holds(int f, Complex c) const { return barycentric(f, c).minCoeff() >= -options.tolerance; }

  /// The cells whose centres triangle f holds, each cut out as a quad.
  void cutCellsOf(int f)
  {
    double lo[2] = { 1e300, 1e300 };
    double hi[2] = { -1e300, -1e300 };
    for (int k = 0; k < 3; ++k)
    {
      lo[0] = std::min(lo[0], uv(f, 2 * k));
      hi[0] = std::max(hi[0], uv(f, 2 * k));
      lo[1] = std::min(lo[1], uv(f, 2 * k + 1));
      hi[1] = std::max(hi[1], uv(f, 2 * k + 1));
    }
    for (long long a = std::llround(std::floor(lo[0] - 0.5)); a + 0.5 <= hi[0] + 1e-9; ++a)
    {
      for (long long b = std::llround(std::floor(lo[1] - 0.5)); b + 0.5 <= hi[1] + 1e-9; ++b)
      {
        const Complex c(a + 0.5, b + 0.5);
        if (c.real() < lo[0] - 1e-9 || c.imag() < lo[1] - 1e-9 || !holds(f, c))
        {
          continue;
        }
        cutCell(f, c);
      }
    }
  }

  /// The quad of the cell with centre c (in triangle f's chart): its four corners reached and
  /// identified, or the reason it gives none counted.
  void cutCell(int f, Complex c)
  {
    const Complex offsets[4] = { { -0.5, -0.5 }, { 0.5, -0.5 }, { 0.5, 0.5 }, { -0.5, 0.5 } };
    std::array<int, 4> quad;
    for (int i = 0; i < 4; ++i)
    {
      Location at;
      if (!reach(f, c, c + offsets[i], at))
      {
        ++out.cellsOffSurface;
        return;
      }
      quad[i] = vertexAt(at);
    }
    std::array<int, 4> sorted = quad;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    {
      ++out.cellsDegenerate;
      return;
    }
    quads.push_back(quad);
    out.quadTriangle.push_back(f);
  }

  /// Finds the triangle holding corner q of the cell with centre c: along the straight segment,
  /// or else (counted) by stepping towards it.
  bool reach(int f, Complex c, Complex q, Location& at)
  {
    if (walkLine(f, c, q, at))
    {
      return true;
    }
    ++out.walkFallbacks;
    return walk(f, q, at);
  }

  /// The vertex at a location: the one its identity already has, or a new one.
  int vertexAt(const Location& at)
  {
    auto [it, added] = vertexOf.emplace(at.key, static_cast<int>(positions.size()));
    if (added)
    {
      const Eigen::Vector3d p = at.bary[0] * V.row(F(at.triangle, 0)).transpose() +
        at.bary[1] * V.row(F(at.triangle, 1)).transpose() +
        at.bary[2] * V.row(F(at.triangle, 2)).transpose();
      positions.push_back(p);
      out.vertexTriangle.push_back(at.triangle);
      out.vertexPoint.push_back(std::get<0>(at.key) == 0 ? std::get<1>(at.key) : -1);
    }
    return it->second;
  }

  /// Fills out.V and out.Q with the vertices the quads use, in the order they are first used.
  void keepUsedVertices()
  {
    std::vector<int> newId(positions.size(), -1);
    int used = 0;
    for (const auto& q : quads)
    {
      for (const int v : q)
      {
        if (newId[v] < 0)
        {
          newId[v] = used++;
        }
      }
    }
    out.V.resize(used, 3);
    std::vector<int> triangle(used), point(used);
    for (std::size_t v = 0; v < positions.size(); ++v)
    {
      if (newId[v] >= 0)
      {
        out.V.row(newId[v]) = positions[v].transpose();
        triangle[newId[v]] = out.vertexTriangle[v];
        point[newId[v]] = out.vertexPoint[v];
      }
    }
    out.vertexTriangle = triangle;
    out.vertexPoint = point;
    out.Q.resize(static_cast<Eigen::Index>(quads.size()), 4);
    for (std::size_t i = 0; i < quads.size(); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        out.Q(static_cast<Eigen::Index>(i), k) = newId[quads[i][k]];
      }
    }
  }

  const Eigen::MatrixX3d& V;
  const Eigen::MatrixX3i& F;
  const MeshTopology& topo;
  const Eigen::MatrixXd& uv;
  const QuadExtractionOptions& options;
  QuadMesh& out;
  std::vector<char> flipped;        ///< per triangle: its (u, v) image not counterclockwise
  std::vector<char> flat;           ///< of those, the ones whose image is a segment (flatTolerance)
  std::vector<int> pointAlias;      ///< #V: the point a vertex on this point is identified by
  Eigen::MatrixX3i rotation;        ///< #F x 3: the quarter turns r of the transitions
  std::vector<Complex> translation; ///< 3 #F: the translations t of the transitions
  /// the vertex of each corner identity, and the vertices' positions (out.vertexTriangle and
  /// out.vertexPoint hold the rest until keepUsedVertices)
  std::map<Key, int> vertexOf;
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 4>> quads; ///< found so far, with out.quadTriangle
};
}

QuadMesh extractQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixXd& cornerUV, const QuadExtractionOptions& options,
  const Progress& progress)
{
  progress.report(0.0);
  if (cornerUV.rows() != F.rows() || cornerUV.cols() != 6 || topo.numFaces != F.rows() ||
    topo.numVertices != V.rows())
  {
    throw std::invalid_argument("extractQuads: sizes do not match");
  }
  if (!topo.isManifold())
  {
    throw std::invalid_argument("extractQuads: " + topo.describeDefects());
  }
  if (!cornerUV.allFinite())
  {
    throw std::invalid_argument("extractQuads: the map has non-finite values");
  }
  QuadMesh out;
  Extractor extractor(V, F, topo, cornerUV, options, out);
  extractor.run(progress);
  progress.report(1.0);
  return out;
}

}
