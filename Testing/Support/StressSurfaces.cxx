// StressSurfaces.cxx: the generated surfaces that stress the remesher where real inputs do: a
// tube whose width varies six-fold, parts thinner than a quad, CAD-like blocks with sharp creases,
// turned parts whose creases are circles.
#include "Surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
}

Surface makeDumbbell(double length, double bulb, double neck, int nAround, int nAlong)
{
  if (!(length > 0 && bulb > 0 && neck > 0 && neck <= bulb) || nAround < 3 || nAlong < 2)
  {
    throw std::invalid_argument(
      "makeDumbbell: need length, bulb > 0, 0 < neck <= bulb, nAround >= 3, nAlong >= 2");
  }
  Surface s;
  s.name = "dumbbell";
  const int rings = nAlong - 1;
  s.V.resize(rings * nAround + 2, 3);
  for (int j = 0; j < rings; ++j)
  {
    const double t = Pi * (j + 1) / nAlong;
    const double st = std::sin(t);
    const double radius = st * (bulb - (bulb - neck) * std::pow(st, 8));
    for (int i = 0; i < nAround; ++i)
    {
      const double a = 2 * Pi * i / nAround;
      s.V.row(j * nAround + i) << radius * std::cos(a), radius * std::sin(a), -length * std::cos(t);
    }
  }
  const int south = rings * nAround, north = south + 1;
  s.V.row(south) << 0, 0, -length;
  s.V.row(north) << 0, 0, length;
  std::vector<Eigen::Vector3i> faces;
  auto id = [&](int j, int i) { return j * nAround + (i % nAround); };
  for (int i = 0; i < nAround; ++i)
  {
    faces.emplace_back(south, id(0, i + 1), id(0, i));
    faces.emplace_back(north, id(rings - 1, i), id(rings - 1, i + 1));
    for (int j = 0; j + 1 < rings; ++j)
    {
      faces.emplace_back(id(j, i), id(j, i + 1), id(j + 1, i + 1));
      faces.emplace_back(id(j, i), id(j + 1, i + 1), id(j + 1, i));
    }
  }
  s.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    s.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  }
  return s;
}

Surface makeBlocks(
  const std::vector<Eigen::Vector3i>& cells, const Eigen::Vector3d& cellSize, double edge)
{
  if (cells.empty() || !(cellSize.minCoeff() > 0) || !(edge > 0))
  {
    throw std::invalid_argument("makeBlocks: need cells, a positive cell size and edge length");
  }
  Eigen::Vector3i steps;
  for (int d = 0; d < 3; ++d)
  {
    steps[d] = std::max(1, static_cast<int>(std::lround(cellSize[d] / edge)));
  }
  std::map<std::array<int, 3>, char> occupied;
  for (const Eigen::Vector3i& c : cells)
  {
    occupied[{ c.x(), c.y(), c.z() }] = 1;
  }
  Surface s;
  s.name = "blocks";
  std::map<std::array<int, 3>, int> points; // lattice point -> index
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Vector3i> faces;
  auto point = [&](const std::array<int, 3>& q) {
    const auto [it, added] = points.emplace(q, static_cast<int>(P.size()));
    if (added)
    {
      P.emplace_back(q[0] * cellSize[0] / steps[0], q[1] * cellSize[1] / steps[1],
        q[2] * cellSize[2] / steps[2]);
    }
    return it->second;
  };
  for (const Eigen::Vector3i& c : cells)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (const int side : { -1, 1 })
      {
        std::array<int, 3> next{ c.x(), c.y(), c.z() };
        next[a] += side;
        if (occupied.count(next))
        {
          continue;
        }
        // the face at the cell's side, spanned by the two other axes (b, e) with e_b x e_e = e_a
        const int b = (a + 1) % 3, e = (a + 2) % 3;
        for (int u = 0; u < steps[b]; ++u)
        {
          for (int v = 0; v < steps[e]; ++v)
          {
            std::array<int, 4> corner;
            const int du[4] = { 0, 1, 1, 0 }, dv[4] = { 0, 0, 1, 1 };
            for (int k = 0; k < 4; ++k)
            {
              std::array<int, 3> q;
              q[a] = (c[a] + (side > 0 ? 1 : 0)) * steps[a];
              q[b] = c[b] * steps[b] + u + du[k];
              q[e] = c[e] * steps[e] + v + dv[k];
              corner[k] = point(q);
            }
            if (side < 0)
            {
              std::swap(corner[1], corner[3]);
            }
            faces.emplace_back(corner[0], corner[1], corner[2]);
            faces.emplace_back(corner[0], corner[2], corner[3]);
          }
        }
      }
    }
  }
  s.V.resize(static_cast<Eigen::Index>(P.size()), 3);
  for (std::size_t i = 0; i < P.size(); ++i)
  {
    s.V.row(static_cast<Eigen::Index>(i)) = P[i].transpose();
  }
  s.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    s.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  }
  return s;
}

Surface makeThinPlate(double width, double depth, double thickness, double edge)
{
  Surface s = makeBlocks({ Eigen::Vector3i(0, 0, 0) }, Eigen::Vector3d(width, depth, thickness), edge);
  s.name = "plate";
  return s;
}

Surface makeThinFrame(double edge)
{
  std::vector<Eigen::Vector3i> cells;
  for (int x = 0; x < 4; ++x)
  {
    for (int y = 0; y < 4; ++y)
    {
      if (!(x >= 1 && x <= 2 && y >= 1 && y <= 2))
      {
        cells.emplace_back(x, y, 0);
      }
    }
  }
  Surface s = makeBlocks(cells, Eigen::Vector3d(0.5, 0.5, 0.02), edge);
  s.name = "frame";
  return s;
}

Surface makeBracket(double edge)
{
  // a square frame of 4 x 4 cells with a 2 x 2 hole (genus 1), a wall of two cells' height along
  // one side, and a tab on the wall: convex and concave right-angle creases, corners of three
  std::vector<Eigen::Vector3i> cells;
  for (int x = 0; x < 4; ++x)
  {
    for (int y = 0; y < 4; ++y)
    {
      if (!(x >= 1 && x <= 2 && y >= 1 && y <= 2))
      {
        cells.emplace_back(x, y, 0);
      }
    }
    cells.emplace_back(x, 0, 1);
    cells.emplace_back(x, 0, 2);
  }
  cells.emplace_back(1, -1, 2);
  Surface s = makeBlocks(cells, Eigen::Vector3d(0.5, 0.5, 0.25), edge);
  s.name = "bracket";
  return s;
}

namespace
{
/// Triangles between two rings of points spread evenly around z from angle 0 (a ring of one point
/// is a pole), in the profile's order: a before b.
void zipRings(
  const std::vector<int>& a, const std::vector<int>& b, std::vector<Eigen::Vector3i>& faces)
{
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  if (na == 1 || nb == 1)
  {
    const bool poleFirst = na == 1;
    const std::vector<int>& ring = poleFirst ? b : a;
    const int pole = poleFirst ? a[0] : b[0];
    const int n = static_cast<int>(ring.size());
    for (int i = 0; i < n; ++i)
    {
      if (poleFirst)
      {
        faces.emplace_back(pole, ring[(i + 1) % n], ring[i]);
      }
      else
      {
        faces.emplace_back(ring[i], ring[(i + 1) % n], pole);
      }
    }
    return;
  }
  int i = 0, j = 0;
  while (i < na || j < nb)
  {
    // the next point around: a's (i + 1) / na against b's (j + 1) / nb, in exact integers
    const bool advanceA =
      i < na && (j == nb || (i + 1) * static_cast<long>(nb) <= (j + 1) * static_cast<long>(na));
    if (advanceA)
    {
      faces.emplace_back(a[i], a[(i + 1) % na], b[j % nb]);
      ++i;
    }
    else
    {
      faces.emplace_back(a[i % na], b[(j + 1) % nb], b[j]);
      ++j;
    }
  }
}
}

Surface makeTurnedPart(const std::vector<Eigen::Vector2d>& profile, double edge)
{
  const int np = static_cast<int>(profile.size());
  bool valid = np >= 3 && edge > 0 && profile.front().x() == 0.0 && profile.back().x() == 0.0;
  for (int k = 1; valid && k + 1 < np; ++k)
  {
    valid = profile[k].x() > 0.0 && (profile[k] - profile[k - 1]).norm() > 0.0;
  }
  if (!valid)
  {
    throw std::invalid_argument(
      "makeTurnedPart: need 3 or more distinct profile points, r = 0 at the ends only, edge > 0");
  }
  // the points along the profile: every profile point, and about `edge` apart between them
  std::vector<Eigen::Vector2d> along;
  for (int k = 0; k + 1 < np; ++k)
  {
    const Eigen::Vector2d d = profile[k + 1] - profile[k];
    const int steps = std::max(1, static_cast<int>(std::lround(d.norm() / edge)));
    for (int t = 0; t < steps; ++t)
    {
      along.push_back(profile[k] + d * (static_cast<double>(t) / steps));
    }
  }
  along.push_back(profile.back());
  Surface s;
  s.name = "turned part";
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> faces;
  std::vector<int> last;
  for (const Eigen::Vector2d& p : along)
  {
    const int n =
      p.x() > 0.0 ? std::max(8, static_cast<int>(std::lround(2.0 * Pi * p.x() / edge))) : 1;
    std::vector<int> ring(n);
    for (int i = 0; i < n; ++i)
    {
      const double a = 2.0 * Pi * i / n;
      ring[i] = static_cast<int>(points.size());
      points.emplace_back(p.x() * std::cos(a), p.x() * std::sin(a), p.y());
    }
    if (!last.empty())
    {
      zipRings(last, ring, faces);
    }
    last.swap(ring);
  }
  s.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    s.V.row(static_cast<Eigen::Index>(v)) = points[v].transpose();
  }
  s.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    s.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  }
  return s;
}

Surface makeSteppedShaft(double edge)
{
  Surface s = makeTurnedPart({ { 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 0.5 }, { 0.7, 0.5 }, { 0.7, 1.0 },
                               { 0.4, 1.0 }, { 0.4, 1.6 }, { 0.0, 1.6 } },
    edge);
  s.name = "stepped shaft";
  return s;
}
}
