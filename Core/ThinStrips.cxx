// ThinStrips.cxx: the local grid size that keeps strips and walls narrower than a grid edge.
#include "ThinStrips.h"

#include "NearbyPoints.h"
#include "SurfaceDisks.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
/// How much faster than around a strip the grid grows back around a wall: the band of finer
/// cells along a thin plate's rim (four times the rim's shortfall from a grid edge wide at the
/// strips' gradation) took most of the plate's quads at a few hundred quads (a plate 2 x 1 x
/// 0.02 at 1,000 quads: 1,630 quads; twice as fast, 1,322, its faces as close to the plate).
constexpr double WallGradation = 2.0;

/// A side of a strip: a boundary edge, or a crease edge seen from one of its two triangles; its
/// points, ends and inward direction (in its triangle's plane), and for a crease the unit normal
/// of the triangle across it (zero for a boundary edge).
struct StripSide
{
  int a, b;
  Eigen::Vector3d p, q, inward;
  Eigen::Vector3d beyond = Eigen::Vector3d::Zero();
};

/// Adds edge k of triangle f as a side of the surface in f, with the unit normal across it (zero
/// for none); not an edge of no length or a triangle of no area.
void sideOf(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int f, int k,
  const Eigen::Vector3d& beyond, std::vector<StripSide>& edges)
{
  const int a = F(f, k), b = F(f, (k + 1) % 3), c = F(f, (k + 2) % 3);
  const Eigen::Vector3d p = V.row(a).transpose(), q = V.row(b).transpose();
  const Eigen::Vector3d normal = (q - p).cross(V.row(c).transpose() - p);
  const Eigen::Vector3d inward = normal.cross(q - p);
  if (inward.norm() > 0)
  {
    edges.push_back({ a, b, p, q, inward.normalized(), beyond });
  }
}

/// The boundary edges, then both sides of each crease edge (creases: #E or empty).
std::vector<StripSide> stripSides(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const std::vector<char>& creases)
{
  std::vector<StripSide> edges;
  for (int f = 0; f < topo.numFaces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (topo.faceNeighbors(f, k) < 0 && topo.edgeFaceCount[topo.faceEdges(f, k)] == 1)
      {
        sideOf(V, F, f, k, Eigen::Vector3d::Zero(), edges);
      }
    }
  }
  if (creases.size() != static_cast<std::size_t>(topo.numEdges()))
  {
    return edges;
  }
  for (int f = 0; f < topo.numFaces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      if (g < 0 || !creases[topo.faceEdges(f, k)])
      {
        continue;
      }
      const Eigen::Vector3d across =
        (V.row(F(g, 1)) - V.row(F(g, 0))).cross(V.row(F(g, 2)) - V.row(F(g, 0))).transpose();
      if (across.norm() > 0)
      {
        sideOf(V, F, f, k, across.normalized(), edges);
      }
    }
  }
  return edges;
}

/// The nearest points s on segment (p0, p1) and t on (q0, q1).
std::pair<Eigen::Vector3d, Eigen::Vector3d> nearestPoints(const Eigen::Vector3d& p0,
  const Eigen::Vector3d& p1, const Eigen::Vector3d& q0, const Eigen::Vector3d& q1)
{
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double c = d1.dot(r), b = d1.dot(d2), denom = a * e - b * b;
  double s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = e > 0 ? (b * s + f) / e : 0.0;
  if (t < 0 || t > 1)
  {
    t = std::clamp(t, 0.0, 1.0);
    s = a > 0 ? std::clamp((t * b - c) / a, 0.0, 1.0) : 0.0;
  }
  return { p0 + s * d1, q0 + t * d2 };
}

/// Whether x and y are sides of one kind that may bound a strip: two boundary edges, or two
/// crease sides whose triangles across face apart, turned by more than 90 degrees from each
/// other (a wall: the rim of a thin plate, between its two faces). Where the surface turns less
/// across the two creases (a step), quads can cross the strip without turning over.
bool sidesOfAStrip(const StripSide& x, const StripSide& y)
{
  const bool xCrease = x.beyond.squaredNorm() > 0, yCrease = y.beyond.squaredNorm() > 0;
  return xCrease == yCrease && (!xCrease || x.beyond.dot(y.beyond) < 0);
}

/// The width of the strip between two sides that face each other, else -1.
double stripWidth(const StripSide& x, const StripSide& y)
{
  if (x.a == y.a || x.a == y.b || x.b == y.a || x.b == y.b || x.inward.dot(y.inward) > -0.5 ||
    !sidesOfAStrip(x, y))
  {
    return -1.0;
  }
  const auto [s, t] = nearestPoints(x.p, x.q, y.p, y.q);
  const Eigen::Vector3d d = t - s;
  const double width = d.norm();
  const bool facing = d.dot(x.inward) > 0.5 * width && -d.dot(y.inward) > 0.5 * width;
  return width > 0 && facing ? width : -1.0;
}

/// For each side, the later ones that may lie within `reach` of it: those whose middles
/// lie within reach plus the longest edge of its own (nearbyPoints).
std::vector<std::vector<int>> nearbySides(const std::vector<StripSide>& edges, double reach)
{
  double longest = 0.0;
  std::vector<Eigen::Vector3d> middles;
  middles.reserve(edges.size());
  for (const StripSide& e : edges)
  {
    longest = std::max(longest, (e.q - e.p).norm());
    middles.push_back(0.5 * (e.p + e.q));
  }
  return nearbyPoints(middles, reach + longest);
}

}

void spreadGridSizes(
  const Eigen::MatrixX3d& V, const MeshTopology& topo, double gradation, std::vector<double>& size)
{
  gradation = std::max(0.0, gradation); // a negative one would never settle
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int v = 0; v < static_cast<int>(size.size()); ++v)
  {
    queue.push({ size[v], v });
  }
  std::vector<std::vector<int>> neighbours(size.size());
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    neighbours[topo.edges(e, 0)].push_back(topo.edges(e, 1));
    neighbours[topo.edges(e, 1)].push_back(topo.edges(e, 0));
  }
  while (!queue.empty())
  {
    const auto [s, v] = queue.top();
    queue.pop();
    if (s > size[v])
    {
      continue;
    }
    for (const int w : neighbours[v])
    {
      const double through = s + gradation * (V.row(v) - V.row(w)).norm();
      if (through < size[w])
      {
        size[w] = through;
        queue.push({ through, w });
      }
    }
  }
}

Eigen::VectorXd thinStripGridScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, double edgeLength, double maximumRefinement,
  const std::vector<char>& creases, double gradation)
{
  if (!(maximumRefinement > 1) || !(edgeLength > 0) || !std::isfinite(edgeLength))
  {
    return {};
  }
  const std::vector<StripSide> edges = stripSides(V, F, topo, creases);
  const std::vector<std::vector<int>> near = nearbySides(edges, edgeLength);
  const double smallest = edgeLength / maximumRefinement;
  // the sizes the strips ask for, and those the walls ask for (which grow back faster)
  std::array<std::vector<double>, 2> size;
  size.fill(std::vector<double>(static_cast<std::size_t>(topo.numVertices), edgeLength));
  std::array<bool, 2> thin{ false, false };
  for (std::size_t i = 0; i < edges.size(); ++i)
  {
    for (const int j : near[i])
    {
      const double width = stripWidth(edges[i], edges[j]);
      // a wall lower than the finest cell allowed is left alone: no grid here gives it a cell,
      // and the quads across it bend over less than that (the rim of a scan's ear, a few
      // hundredths of a grid edge high: refined, the map kept a point wound the wrong way)
      const int wall = edges[i].beyond.squaredNorm() > 0 ? 1 : 0;
      if (width < 0 || width >= edgeLength || (wall && width < smallest))
      {
        continue;
      }
      thin[wall] = true;
      const double wanted = std::max(width, smallest);
      for (const int v : { edges[i].a, edges[i].b, edges[j].a, edges[j].b })
      {
        size[wall][v] = std::min(size[wall][v], wanted);
      }
    }
  }
  if (!thin[0] && !thin[1])
  {
    return {};
  }
  for (int wall = 0; wall < 2; ++wall)
  {
    if (thin[wall])
    {
      spreadGridSizes(V, topo, wall ? WallGradation * gradation : gradation, size[wall]);
    }
  }
  for (int v = 0; v < topo.numVertices; ++v)
  {
    size[0][v] = std::min(size[0][v], size[1][v]);
  }
  return faceGridScale(F, size[0], edgeLength);
}

Eigen::VectorXd shortLoopGridScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixX3d& edgeLengths, const std::vector<int>& points,
  double edgeLength, double maximumRefinement, double gradation)
{
  // A ball wraps around a loop once its radius is about half the loop's length: loops up to
  // about 2 Reach grid edges long are seen, and each point asks for a grid edge of Share times
  // that radius, about a third of its loop. (Half of it, four grid edges around, gave a small
  // slab of three square tunnels 2.4 times the quads asked at 100 quads, where a uniform grid
  // and a third gave 1.7 times, and no isosurface more valid runs.)
  constexpr double Reach = 2.0;
  constexpr double Share = 2.0 / 3.0;
  constexpr int BisectionSteps = 8; // the radius to 1/256 of the reach
  if (!(maximumRefinement > 1) || !(edgeLength > 0) || !std::isfinite(edgeLength))
  {
    return {};
  }
  const double smallest = edgeLength / maximumRefinement;
  DiskTest disk(F, topo, edgeLengths);
  std::vector<double> size(static_cast<std::size_t>(topo.numVertices), edgeLength);
  bool thin = false;
  for (const int p : points)
  {
    double high = Reach * edgeLength;
    if (disk.ball(p, high, true) != DiskTest::Ball::NotDisk)
    {
      continue;
    }
    double low = 0.0; // the largest radius known to give a disk (a point's own ring is one)
    for (int step = 0; step < BisectionSteps; ++step)
    {
      const double middle = 0.5 * (low + high);
      (disk.ball(p, middle, true) == DiskTest::Ball::Disk ? low : high) = middle;
    }
    const double wanted = std::max(Share * low, smallest);
    if (low > 0 && wanted < size[p]) // (no radius gave a disk: nothing to go by)
    {
      size[p] = wanted;
      thin = true;
    }
  }
  if (!thin)
  {
    return {};
  }
  spreadGridSizes(V, topo, gradation, size);
  return faceGridScale(F, size, edgeLength);
}

Eigen::VectorXd faceGridScale(
  const Eigen::MatrixX3i& F, const std::vector<double>& size, double edgeLength)
{
  Eigen::VectorXd scale(F.rows());
  for (int f = 0; f < F.rows(); ++f)
  {
    scale[f] = (size[F(f, 0)] + size[F(f, 1)] + size[F(f, 2)]) / (3 * edgeLength);
  }
  return scale;
}
}
