#include "QuadExtraction.h"

#include "UnionFind.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <stdexcept>
#include <tuple>

namespace quadcover
{
namespace
{
using Complex = std::complex<double>;

double cross(Complex a, Complex b)
{
  return a.real() * b.imag() - a.imag() * b.real();
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
struct Location
{
  std::tuple<int, int, long long, long long> key;
  int triangle = -1;
  Eigen::Vector3d bary;
};

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
    for (int f = 0; f < nF; ++f)
    {
      flipped[f] = !(cross(z(f, 1) - z(f, 0), z(f, 2) - z(f, 0)) > 0);
    }
    // transitions z_g = i^r z_f + t across every inner edge, read off the map
    rotation = Eigen::MatrixX3i::Zero(nF, 3);
    translation.assign(3 * static_cast<std::size_t>(nF), Complex(0, 0));
    for (int f = 0; f < nF; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo.faceNeighbors(f, k);
        if (g < 0)
        {
          continue;
        }
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
    }
  }

  Complex z(int f, int k) const { return { uv(f, 2 * k), uv(f, 2 * k + 1) }; }

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
    for (int step = 0; step < options.maximumWalk; ++step)
    {
      if (flipped[f])
      {
        return false;
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
      const int shared = topo.faceEdges(f, edge);
      p = across(f, edge, p);
      q = across(f, edge, q);
      f = g;
      entered = -1;
      for (int k = 0; k < 3; ++k)
      {
        entered = topo.faceEdges(f, k) == shared ? k : entered;
      }
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
      at.key = { 0, F(f, k), 0, 0 };
      return;
    }
    if (zeros == 1)
    {
      const int edge = (zero + 1) % 3;
      const int e = topo.faceEdges(f, edge);
      const int owner = topo.edgeFaces(e, 0);
      if (owner != f && topo.faceNeighbors(f, edge) == owner)
      {
        q = across(f, edge, q);
      }
      at.key = { 1, e, std::llround(q.real()), std::llround(q.imag()) };
      return;
    }
    at.key = { 2, f, std::llround(q.real()), std::llround(q.imag()) };
  }

  /// Does triangle f hold the cell centre c (in its chart), up to the tolerance? A centre on an
  /// edge or a point is held by several triangles; the quads they give are the same and are
  /// merged later (deciding here which one owns it would need both sides to agree to the last
  /// bit across seams).
  bool holds(int f, Complex c) const { return barycentric(f, c).minCoeff() >= -options.tolerance; }

  void run()
  {
    const int nF = static_cast<int>(F.rows());
    std::map<std::tuple<int, int, long long, long long>, int> vertexOf;
    std::vector<Eigen::Vector3d> positions;
    std::vector<std::array<int, 4>> quads;
    const Complex offsets[4] = { { -0.5, -0.5 }, { 0.5, -0.5 }, { 0.5, 0.5 }, { -0.5, 0.5 } };
    for (int f = 0; f < nF; ++f)
    {
      if (flipped[f])
      {
        continue;
      }
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
          std::array<int, 4> quad;
          bool found = true;
          for (int i = 0; i < 4 && found; ++i)
          {
            Location at;
            found = walkLine(f, c, c + offsets[i], at);
            if (!found)
            {
              ++out.walkFallbacks;
              found = walk(f, c + offsets[i], at);
            }
            if (!found)
            {
              break;
            }
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
            quad[i] = it->second;
          }
          if (!found)
          {
            ++out.cellsOffSurface;
            continue;
          }
          std::array<int, 4> sorted = quad;
          std::sort(sorted.begin(), sorted.end());
          if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
          {
            ++out.cellsDegenerate;
            continue;
          }
          quads.push_back(quad);
          out.quadTriangle.push_back(f);
        }
      }
    }
    removeConflicts(quads);
    // keep the vertices quads use, in order
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

  void removeConflicts(std::vector<std::array<int, 4>>& quads)
  {
    out.cellsConflicting += removeOverlappingQuads(quads, out.quadTriangle);
  }

private:
  const Eigen::MatrixX3d& V;
  const Eigen::MatrixX3i& F;
  const MeshTopology& topo;
  const Eigen::MatrixXd& uv;
  const QuadExtractionOptions& options;
  QuadMesh& out;
  std::vector<char> flipped;
  Eigen::MatrixX3i rotation;
  std::vector<Complex> translation;
};
}

int removeOverlappingQuads(std::vector<std::array<int, 4>>& quads, std::vector<int>& owner)
{
  if (owner.size() != quads.size())
  {
    throw std::invalid_argument("removeOverlappingQuads: one owner per quad expected");
  }
  std::map<std::array<int, 4>, int> seen;
  std::vector<char> keep(quads.size(), 1);
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    std::array<int, 4> key = quads[i];
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    if (!seen.emplace(key, static_cast<int>(i)).second)
    {
      keep[i] = 0; // the same cell, from another triangle holding its centre
    }
  }
  std::map<std::pair<int, int>, int> directed;
  std::map<std::pair<int, int>, int> undirected;
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    for (int k = 0; k < 4 && keep[i]; ++k)
    {
      const int a = quads[i][k], b = quads[i][(k + 1) % 4];
      ++directed[{ a, b }];
      ++undirected[{ std::min(a, b), std::max(a, b) }];
    }
  }
  int removed = 0;
  std::vector<std::array<int, 4>> kept;
  std::vector<int> keptOwner;
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    for (int k = 0; k < 4 && keep[i]; ++k)
    {
      const int a = quads[i][k], b = quads[i][(k + 1) % 4];
      if (directed[{ a, b }] > 1 || undirected[{ std::min(a, b), std::max(a, b) }] > 2)
      {
        keep[i] = 0;
        ++removed;
      }
    }
    if (keep[i])
    {
      kept.push_back(quads[i]);
      keptOwner.push_back(owner[i]);
    }
  }
  quads.swap(kept);
  owner.swap(keptOwner);
  return removed;
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
  extractor.run();
  return out;
}

namespace
{
/// The smallest scaled Jacobian over a quad's corners, against the quad's own normal (its
/// diagonals' cross product); 0 at a corner with a zero-length edge.
double quadScaledJacobian(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q, int i)
{
  const Eigen::Vector3d n = (Eigen::Vector3d(V.row(Q(i, 2)) - V.row(Q(i, 0))))
                              .cross(Eigen::Vector3d(V.row(Q(i, 3)) - V.row(Q(i, 1))))
                              .normalized();
  double smallest = 1.0;
  for (int k = 0; k < 4; ++k)
  {
    const Eigen::Vector3d next = V.row(Q(i, (k + 1) % 4)) - V.row(Q(i, k));
    const Eigen::Vector3d prev = V.row(Q(i, (k + 3) % 4)) - V.row(Q(i, k));
    const double ln = next.norm(), lp = prev.norm();
    const double sj = ln > 0 && lp > 0 ? next.cross(prev).dot(n) / (ln * lp) : 0.0;
    smallest = std::min(smallest, std::isfinite(sj) ? sj : 0.0);
  }
  return smallest;
}
}

QuadQuality measureQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q)
{
  QuadQuality m;
  const int nV = static_cast<int>(V.rows());
  const int nQ = static_cast<int>(Q.rows());
  m.faces = nQ;
  std::map<std::pair<int, int>, std::array<int, 2>> edges; // (faces, same-direction clashes)
  std::vector<char> usedVertex(nV, 0);
  std::vector<double> angles;
  angles.reserve(4 * static_cast<std::size_t>(nQ));
  m.scaledJacobian.resize(nQ);
  double jacobianSum = 0.0;
  m.minScaledJacobian = nQ > 0 ? 1.0 : 0.0;
  std::map<std::pair<int, int>, int> directed;
  for (int i = 0; i < nQ; ++i)
  {
    std::array<int, 4> q = { Q(i, 0), Q(i, 1), Q(i, 2), Q(i, 3) };
    std::array<int, 4> sorted = q;
    std::sort(sorted.begin(), sorted.end());
    m.quads += std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    for (int k = 0; k < 4; ++k)
    {
      usedVertex[q[k]] = 1;
      const int a = q[k], b = q[(k + 1) % 4];
      auto& e = edges[{ std::min(a, b), std::max(a, b) }];
      ++e[0];
      if (++directed[{ a, b }] > 1)
      {
        ++e[1];
      }
      const Eigen::Vector3d next = V.row(q[(k + 1) % 4]) - V.row(q[k]);
      const Eigen::Vector3d prev = V.row(q[(k + 3) % 4]) - V.row(q[k]);
      const double ln = next.norm(), lp = prev.norm();
      if (ln > 0 && lp > 0)
      {
        angles.push_back(std::acos(std::clamp(next.dot(prev) / (ln * lp), -1.0, 1.0)));
      }
    }
    const double smallest = quadScaledJacobian(V, Q, i);
    m.scaledJacobian[i] = smallest;
    m.minScaledJacobian = std::min(m.minScaledJacobian, smallest);
    jacobianSum += smallest;
  }
  m.meanScaledJacobian = nQ > 0 ? jacobianSum / nQ : 0.0;
  m.valence = Eigen::VectorXi::Zero(nV);
  std::vector<char> boundary(nV, 0);
  std::vector<double> lengths;
  std::vector<int> parent(nV);
  for (int v = 0; v < nV; ++v)
  {
    parent[v] = v;
  }
  std::vector<int> boundaryParent(nV);
  for (int v = 0; v < nV; ++v)
  {
    boundaryParent[v] = v;
  }
  for (const auto& [e, count] : edges)
  {
    ++m.valence[e.first];
    ++m.valence[e.second];
    lengths.push_back((V.row(e.first) - V.row(e.second)).norm());
    unite(parent, e.first, e.second);
    if (count[0] > 2 || count[1] > 0)
    {
      ++m.nonManifoldEdges;
    }
    if (count[0] == 1)
    {
      ++m.boundaryEdges;
      boundary[e.first] = boundary[e.second] = 1;
      unite(boundaryParent, e.first, e.second);
    }
  }
  auto rsd = [](const std::vector<double>& x) {
    if (x.empty())
    {
      return 0.0;
    }
    double mean = 0.0;
    for (const double v : x)
    {
      mean += v;
    }
    mean /= static_cast<double>(x.size());
    double var = 0.0;
    for (const double v : x)
    {
      var += (v - mean) * (v - mean);
    }
    var /= static_cast<double>(x.size());
    return mean > 0 ? std::sqrt(var) / mean : 0.0;
  };
  m.edgeLengthRSD = rsd(lengths);
  m.angleRSD = rsd(angles);
  for (int v = 0; v < nV; ++v)
  {
    if (!usedVertex[v])
    {
      continue;
    }
    ++m.vertices;
    if (boundary[v])
    {
      m.irregularBoundary += m.valence[v] != 2 && m.valence[v] != 3;
      m.boundaryLoops += findRoot(boundaryParent, v) == v;
    }
    else
    {
      m.irregularInner += m.valence[v] != 4;
    }
    m.components += findRoot(parent, v) == v;
  }
  m.eulerCharacteristic = m.vertices - static_cast<int>(edges.size()) + m.faces;
  return m;
}

namespace
{
/// The point of triangle (a, b, c) closest to p.
Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a;
  const Eigen::Vector3d n = ab.cross(ac);
  const double nn = n.squaredNorm();
  if (nn > 0)
  {
    // barycentric coordinates of p's projection onto the plane
    const Eigen::Vector3d ap = p - a;
    const double beta = ap.cross(ac).dot(n) / nn;
    const double gamma = ab.cross(ap).dot(n) / nn;
    if (beta >= 0 && gamma >= 0 && beta + gamma <= 1)
    {
      return a + beta * ab + gamma * ac;
    }
  }
  auto onSegment = [&](const Eigen::Vector3d& s, const Eigen::Vector3d& t) -> Eigen::Vector3d {
    const Eigen::Vector3d d = t - s;
    const double dd = d.squaredNorm();
    const double x = dd > 0 ? std::clamp((p - s).dot(d) / dd, 0.0, 1.0) : 0.0;
    return s + x * d;
  };
  Eigen::Vector3d best = onSegment(a, b);
  for (const Eigen::Vector3d& q : { onSegment(b, c), onSegment(c, a) })
  {
    if ((q - p).squaredNorm() < (best - p).squaredNorm())
    {
      best = q;
    }
  }
  return best;
}
}

QuadRelaxReport relaxQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh, const QuadRelaxOptions& options,
  const Progress& progress)
{
  progress.report(0.0);
  const int nF = static_cast<int>(F.rows());
  const int nV = static_cast<int>(mesh.V.rows());
  const int nQ = static_cast<int>(mesh.Q.rows());
  if (topo.numFaces != nF || static_cast<int>(mesh.vertexTriangle.size()) != nV ||
    static_cast<int>(mesh.vertexPoint.size()) != nV ||
    (!options.movable.empty() && static_cast<int>(options.movable.size()) != nV))
  {
    throw std::invalid_argument("relaxQuads: sizes do not match");
  }
  if (!(options.step > 0 && options.step <= 1))
  {
    throw std::invalid_argument("relaxQuads: the step must be in (0, 1]");
  }
  QuadRelaxReport report;
  if (options.relaxationIterations <= 0 || nQ == 0)
  {
    return report;
  }
  for (int i = 0; i < nQ; ++i)
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
    if (t < 0 || t >= nF)
    {
      throw std::invalid_argument("relaxQuads: a vertex lies in no input triangle");
    }
  }

  // input normals, and the edges no vertex crosses (boundary, crease, non-manifold)
  Eigen::MatrixX3d normal(nF, 3);
  for (int f = 0; f < nF; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    normal.row(f) = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
  }
  const double creaseCos = std::cos(options.featureAngle * 3.14159265358979323846 / 180.0);
  std::vector<char> blocked(topo.numEdges(), 1);
  std::vector<char> pointOnCrease(V.rows(), 0);
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
      pointOnCrease[topo.edges(e, 0)] = pointOnCrease[topo.edges(e, 1)] = 1;
    }
  }

  // fixed vertices: on the quad mesh's boundary, or on an input crease or boundary
  std::vector<char> fixed(nV, 0);
  {
    std::map<std::pair<int, int>, int> edgeCount;
    for (int i = 0; i < nQ; ++i)
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
        fixed[edge.first] = fixed[edge.second] = 1;
      }
    }
  }
  for (int v = 0; v < nV; ++v)
  {
    if (mesh.vertexPoint[v] >= 0)
    {
      fixed[v] |= pointOnCrease[mesh.vertexPoint[v]];
      continue;
    }
    // on an edge of its triangle? (relative distance to the edge's line)
    const int f = mesh.vertexTriangle[v];
    const Eigen::Vector3d p = mesh.V.row(v);
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d a = V.row(F(f, k)), b = V.row(F(f, (k + 1) % 3));
      const double length = (b - a).norm();
      if (blocked[topo.faceEdges(f, k)] && length > 0 &&
        (p - a).cross(b - a).norm() <= 1e-6 * length * length)
      {
        fixed[v] = 1;
      }
    }
  }
  for (int v = 0; v < nV; ++v)
  {
    report.fixedVertices += fixed[v];
  }

  // the quads of each vertex (CSR)
  std::vector<int> offsets(nV + 1, 0), quadsOf(4 * static_cast<std::size_t>(nQ));
  for (int i = 0; i < nQ; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      ++offsets[mesh.Q(i, k) + 1];
    }
  }
  for (int v = 0; v < nV; ++v)
  {
    offsets[v + 1] += offsets[v];
  }
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int i = 0; i < nQ; ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        quadsOf[fill[mesh.Q(i, k)]++] = i;
      }
    }
  }
  double meanEdge = 0.0;
  for (int i = 0; i < nQ; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      meanEdge += (mesh.V.row(mesh.Q(i, k)) - mesh.V.row(mesh.Q(i, (k + 1) % 4))).norm();
    }
  }
  meanEdge /= 4.0 * nQ;

  auto closestIn = [&](int f, const Eigen::Vector3d& p) {
    return closestOnTriangle(p, V.row(F(f, 0)), V.row(F(f, 1)), V.row(F(f, 2)));
  };
  // Candidate triangles next to f: across its free edges, and around its corners up to a
  // blocked edge.
  std::vector<int> candidates;
  auto gatherCandidates = [&](int f) {
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
  };
  auto project = [&](int& f, const Eigen::Vector3d& p) {
    Eigen::Vector3d best = closestIn(f, p);
    double distance = (best - p).squaredNorm();
    for (int step = 0; step < 64; ++step)
    {
      gatherCandidates(f);
      int next = -1;
      for (const int g : candidates)
      {
        const Eigen::Vector3d q = closestIn(g, p);
        const double d = (q - p).squaredNorm();
        if (d < distance * (1.0 - 1e-12) - 1e-300)
        {
          distance = d;
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
  };
  // The corners of v's quads: how many are not positive, and the worst, each measured against
  // the input's normal at the corner and against the quad's own normal (its diagonals' cross
  // product, as measureQuads does).
  struct Corners
  {
    int inverted = 0;
    double worst = 1.0;
  };
  auto cornersOf = [&](int v) {
    Corners r;
    for (int j = offsets[v]; j < offsets[v + 1]; ++j)
    {
      const int i = quadsOf[j];
      const Eigen::Vector3d own =
        (Eigen::Vector3d(mesh.V.row(mesh.Q(i, 2)) - mesh.V.row(mesh.Q(i, 0))))
          .cross(Eigen::Vector3d(mesh.V.row(mesh.Q(i, 3)) - mesh.V.row(mesh.Q(i, 1))))
          .normalized();
      for (int k = 0; k < 4; ++k)
      {
        const int c = mesh.Q(i, k);
        const Eigen::Vector3d next = mesh.V.row(mesh.Q(i, (k + 1) % 4)) - mesh.V.row(c);
        const Eigen::Vector3d prev = mesh.V.row(mesh.Q(i, (k + 3) % 4)) - mesh.V.row(c);
        const double ln = next.norm(), lp = prev.norm();
        const Eigen::Vector3d n = normal.row(mesh.vertexTriangle[c]);
        for (const Eigen::Vector3d& reference : { n, own })
        {
          double sj = ln > 0 && lp > 0 ? next.cross(prev).dot(reference) / (ln * lp) : -1.0;
          sj = std::isfinite(sj) ? sj : -1.0;
          r.inverted += sj <= 0;
          r.worst = std::min(r.worst, sj);
        }
      }
    }
    return r;
  };

  for (int iteration = 0; iteration < options.relaxationIterations; ++iteration)
  {
    for (int v = 0; v < nV; ++v)
    {
      if (fixed[v] || offsets[v] == offsets[v + 1] ||
        (!options.movable.empty() && !options.movable[v]))
      {
        continue;
      }
      Eigen::Vector3d target = Eigen::Vector3d::Zero();
      double weight = 0.0;
      for (int j = offsets[v]; j < offsets[v + 1]; ++j)
      {
        const int i = quadsOf[j];
        const Eigen::Vector3d p0 = mesh.V.row(mesh.Q(i, 0)), p1 = mesh.V.row(mesh.Q(i, 1));
        const Eigen::Vector3d p2 = mesh.V.row(mesh.Q(i, 2)), p3 = mesh.V.row(mesh.Q(i, 3));
        const double area = 0.5 * (p2 - p0).cross(p3 - p1).norm();
        target += area * 0.25 * (p0 + p1 + p2 + p3);
        weight += area;
      }
      if (!(weight > 0))
      {
        continue;
      }
      const Eigen::Vector3d old = mesh.V.row(v);
      const int oldTriangle = mesh.vertexTriangle[v];
      const Eigen::Vector3d n = normal.row(oldTriangle);
      Eigen::Vector3d move = options.step * (target / weight - old);
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
        continue;
      }
      if ((moved - old).squaredNorm() > 0)
      {
        mesh.vertexPoint[v] = -1;
      }
      report.maxMove = std::max(report.maxMove, (moved - old).norm() / meanEdge);
    }
  }
  return report;
}

int countInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q)
{
  int count = 0;
  for (int i = 0; i < static_cast<int>(Q.rows()); ++i)
  {
    count += !(quadScaledJacobian(V, Q, i) > 0);
  }
  return count;
}

std::pair<int, int> repairInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadMesh& mesh, int rings, int iterations, int rounds)
{
  const int nV = static_cast<int>(mesh.V.rows());
  auto inverted = [&]() {
    std::vector<int> bad;
    for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
    {
      if (!(quadScaledJacobian(mesh.V, mesh.Q, i) > 0))
      {
        bad.push_back(i);
      }
    }
    return bad;
  };
  std::vector<int> bad = inverted();
  const int before = static_cast<int>(bad.size());
  for (int round = 0; round < rounds && !bad.empty(); ++round)
  {
    QuadRelaxOptions options;
    options.relaxationIterations = iterations;
    options.movable.assign(nV, 0);
    for (const int i : bad)
    {
      for (int k = 0; k < 4; ++k)
      {
        options.movable[mesh.Q(i, k)] = 1;
      }
    }
    // grow by quad rings: every vertex of a quad with a movable vertex
    for (int ring = 0; ring < rings; ++ring)
    {
      std::vector<char> grown = options.movable;
      for (int i = 0; i < mesh.Q.rows(); ++i)
      {
        const bool touches = options.movable[mesh.Q(i, 0)] || options.movable[mesh.Q(i, 1)] ||
          options.movable[mesh.Q(i, 2)] || options.movable[mesh.Q(i, 3)];
        for (int k = 0; k < 4 && touches; ++k)
        {
          grown[mesh.Q(i, k)] = 1;
        }
      }
      options.movable.swap(grown);
    }
    const Eigen::MatrixX3d keptV = mesh.V;
    const std::vector<int> keptTriangle = mesh.vertexTriangle, keptPoint = mesh.vertexPoint;
    relaxQuads(V, F, topo, mesh, options);
    const std::vector<int> now = inverted();
    if (now.size() > bad.size())
    {
      // the guard counts corners against two normals, measureQuads quads against one: rare
      mesh.V = keptV;
      mesh.vertexTriangle = keptTriangle;
      mesh.vertexPoint = keptPoint;
      break;
    }
    const bool progress = now.size() < bad.size();
    bad = now;
    if (!progress)
    {
      break;
    }
  }
  return { before, static_cast<int>(bad.size()) };
}

}
