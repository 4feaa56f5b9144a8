// SurfaceRepair.cxx: points merged, and makeManifold: a triangle soup made a manifold, consistently
// oriented surface.
#include "SurfaceRepair.h"

#include "EdgeGroups.h"
#include "NearbyPoints.h"
#include "UnionFind.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace quadcover
{
namespace
{
/// Two triangles joined across an edge: their corners 3f+k (the edge is edge k of face f).
struct Glue
{
  int c0, c1;
};

/**
 * Pairs the n > 2 triangles around one edge (a, b), a < b. First, a patch (`patch`: triangles
 * joined through edges of two triangles) with exactly two triangles around the edge that agree in
 * orientation keeps them together: its surface passes through the edge whatever else stands on
 * it (a fin leaning into the solid it stands on lies between the solid's two faces, next to
 * both, and would otherwise take one of them, leaving the other joined to the pair around both
 * points). Then, around the edge's axis d = b - a, a triangle running a -> b has its normal on
 * the side of positive rotation, so the solid it bounds lies on the side of negative rotation:
 * its partner is its neighbour that way, if that one runs b -> a (agrees in orientation) and is
 * not paired yet. A triangle of zero area has no side: it only counts among the left over. Two
 * triangles left over are paired with each other (an orientation that disagrees is put right
 * afterwards).
 */
void pairAroundEdge(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const std::vector<int>& patch, const int* corners, int n, std::vector<Glue>& glue)
{
  const int a = std::min(tail(F, corners[0]), head(F, corners[0]));
  const int b = std::max(tail(F, corners[0]), head(F, corners[0]));
  const Eigen::Vector3d d = (V.row(b) - V.row(a)).transpose().normalized();
  struct Sheet
  {
    double angle;
    int corner;
    bool forward; // runs a -> b
  };
  std::vector<Sheet> sheets;
  std::vector<int> flat; // zero-area triangles
  Eigen::Vector3d e1 = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i)
  {
    const int c = corners[i];
    const Eigen::Vector3d w = (V.row(F(c / 3, (c % 3 + 2) % 3)) - V.row(a)).transpose();
    const Eigen::Vector3d across = w - w.dot(d) * d;
    if (e1.squaredNorm() == 0.0 && across.squaredNorm() > 0.0)
    {
      e1 = across.normalized();
    }
    if (across.squaredNorm() == 0.0)
    {
      flat.push_back(c); // no direction around the edge: only paired with what is left over
      continue;
    }
    const Eigen::Vector3d e2 = d.cross(e1);
    sheets.push_back({ std::atan2(across.dot(e2), across.dot(e1)), c, tail(F, c) == a });
  }
  n = static_cast<int>(sheets.size()); // from here on, the triangles with a side
  std::sort(sheets.begin(), sheets.end(), [](const Sheet& x, const Sheet& y) {
    return x.angle != y.angle ? x.angle < y.angle : x.corner < y.corner;
  });
  std::vector<char> paired(n, 0);
  std::map<int, std::vector<int>> ofPatch; // the sheets of each patch
  for (int i = 0; i < n; ++i)
  {
    ofPatch[patch[sheets[i].corner / 3]].push_back(i);
  }
  for (const auto& [p, members] : ofPatch)
  {
    if (members.size() == 2 && sheets[members[0]].forward != sheets[members[1]].forward)
    {
      const int i = sheets[members[0]].forward ? members[0] : members[1];
      const int j = members[0] + members[1] - i;
      glue.push_back({ sheets[i].corner, sheets[j].corner });
      paired[i] = paired[j] = 1;
    }
  }
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + n - 1) % n; // the neighbour on the side of negative rotation
    if (sheets[i].forward && !sheets[j].forward && !paired[i] && !paired[j])
    {
      glue.push_back({ sheets[i].corner, sheets[j].corner });
      paired[i] = paired[j] = 1;
    }
  }
  std::vector<int> left;
  for (int i = 0; i < n; ++i)
  {
    if (!paired[i])
    {
      left.push_back(sheets[i].corner);
    }
  }
  left.insert(left.end(), flat.begin(), flat.end());
  if (left.size() == 2)
  {
    glue.push_back({ left[0], left[1] });
  }
}

/// The glue across every edge with exactly two triangles and, given the patches (the
/// components of that glue), the pairs around the edges with more (their number in cutEdges).
std::vector<Glue> glueEdges(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const std::vector<int>* patch, int* cutEdges)
{
  const EdgeGroups groups = groupEdges(F);
  std::vector<Glue> glue;
  for (size_t g = 0; g + 1 < groups.offsets.size(); ++g)
  {
    const int begin = groups.offsets[g], n = groups.offsets[g + 1] - begin;
    if (n == 2)
    {
      glue.push_back({ groups.corners[begin], groups.corners[begin + 1] });
    }
    else if (n > 2 && patch)
    {
      pairAroundEdge(V, F, *patch, groups.corners.data() + begin, n, glue);
      ++*cutEdges;
    }
  }
  return glue;
}

/**
 * Which triangles to reverse so that glued neighbours agree: a walk over the glue, per component
 * (numbered in order of their lowest triangle) the side with more area keeping the input's
 * orientation.
 * @param[in]  turned   #F, 1 for a triangle already reversed against the input
 * @param[out] conflict the first component that cannot be oriented (0-based), -1 if none
 * @param[out] components the number of components
 * @param[out] component  #F, each triangle's component
 */
std::vector<char> orientation(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const std::vector<Glue>& glue, const std::vector<char>& turned, int& conflict, int& components,
  std::vector<int>& component)
{
  const int nf = static_cast<int>(F.rows());
  // adjacency as CSR: for each face, (neighbour, 1 if the two run the edge the same way)
  std::vector<int> offsets(nf + 1, 0);
  for (const Glue& g : glue)
  {
    ++offsets[g.c0 / 3 + 1];
    ++offsets[g.c1 / 3 + 1];
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::pair<int, char>> adjacent(offsets.back());
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (const Glue& g : glue)
  {
    const char same = tail(F, g.c0) == tail(F, g.c1) ? 1 : 0;
    adjacent[fill[g.c0 / 3]++] = { g.c1 / 3, same };
    adjacent[fill[g.c1 / 3]++] = { g.c0 / 3, same };
  }
  std::vector<char> reverse(nf, 0);
  component.assign(nf, -1);
  std::vector<int> stack, members;
  conflict = -1;
  components = 0;
  for (int seed = 0; seed < nf; ++seed)
  {
    if (component[seed] >= 0)
    {
      continue;
    }
    const int c = components++;
    component[seed] = c;
    stack.assign(1, seed);
    members.clear();
    double areaKept = 0.0, areaReversed = 0.0;
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      members.push_back(f);
      const Eigen::Vector3d p = V.row(F(f, 0)).transpose();
      const double area =
        (V.row(F(f, 1)).transpose() - p).cross(V.row(F(f, 2)).transpose() - p).norm();
      (reverse[f] != turned[f] ? areaReversed : areaKept) += area;
      for (int i = offsets[f]; i < offsets[f + 1]; ++i)
      {
        const int g = adjacent[i].first;
        const char wanted = reverse[f] ^ adjacent[i].second;
        if (component[g] < 0)
        {
          component[g] = c;
          reverse[g] = wanted;
          stack.push_back(g);
        }
        else if (reverse[g] != wanted && conflict < 0)
        {
          conflict = c;
        }
      }
    }
    if (areaReversed > areaKept)
    {
      for (const int f : members)
      {
        reverse[f] = !reverse[f];
      }
    }
  }
  return reverse;
}

void reverseFaces(Eigen::MatrixX3i& F, const std::vector<char>& reverse)
{
  for (int f = 0; f < static_cast<int>(F.rows()); ++f)
  {
    if (reverse[f])
    {
      std::swap(F(f, 1), F(f, 2));
    }
  }
}

/// Gives the corners of each point that no glue joins their own copy of the point (the fan of
/// the lowest corner keeps it). @return for each copy, the point it copies
std::vector<int> splitFans(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, const std::vector<Glue>& glue)
{
  const int nc = 3 * static_cast<int>(F.rows());
  std::vector<int> parent(nc);
  std::iota(parent.begin(), parent.end(), 0);
  auto cornerAt = [&](int f, int p) { return 3 * f + (F(f, 0) == p ? 0 : (F(f, 1) == p ? 1 : 2)); };
  for (const Glue& g : glue)
  {
    for (const int p : { tail(F, g.c0), head(F, g.c0) })
    {
      unite(parent, cornerAt(g.c0 / 3, p), cornerAt(g.c1 / 3, p));
    }
  }
  // corners are visited in order, so the fan of a point's lowest corner is met first
  std::vector<int> firstRoot(V.rows(), -1), newPoint(nc, -1), copies;
  int next = static_cast<int>(V.rows());
  for (int c = 0; c < nc; ++c)
  {
    const int p = F(c / 3, c % 3), r = findRoot(parent, c);
    if (firstRoot[p] < 0)
    {
      firstRoot[p] = r;
    }
    if (r != firstRoot[p] && newPoint[r] < 0)
    {
      newPoint[r] = next++;
      copies.push_back(p);
    }
  }
  for (int c = 0; c < nc; ++c)
  {
    const int r = findRoot(parent, c);
    if (newPoint[r] >= 0)
    {
      F(c / 3, c % 3) = newPoint[r];
    }
  }
  const Eigen::Index old = V.rows();
  V.conservativeResize(old + static_cast<Eigen::Index>(copies.size()), 3);
  for (size_t i = 0; i < copies.size(); ++i)
  {
    V.row(old + static_cast<Eigen::Index>(i)) = V.row(copies[i]);
  }
  return copies;
}
}

ManifoldRepair makeManifold(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F)
{
  ManifoldRepair repair;
  int conflict = -1, components = 0;
  // 1. patches oriented first, so that the pairing around cut edges can go by patch and
  // orientation
  std::vector<int> patch, component;
  const std::vector<char> first = orientation(V, F, glueEdges(V, F, nullptr, nullptr),
    std::vector<char>(F.rows(), 0), conflict, components, patch);
  reverseFaces(F, first);
  // 2., 3. the edges cut apart, the points split into their fans (a cut edge whose sheets meet
  // again around both its points keeps more than two triangles: the caller checks and refuses)
  const std::vector<Glue> glue = glueEdges(V, F, &patch, &repair.cutEdges);
  repair.copies = splitFans(V, F, glue);
  // 4. each component oriented as a whole, against the input's orientation
  const std::vector<char> second = orientation(V, F, glue, first, conflict, components, component);
  if (conflict >= 0)
  {
    throw std::invalid_argument("component " + std::to_string(conflict + 1) + " of " +
      std::to_string(components) +
      " is not orientable (like a Moebius strip); QuadCover needs an orientable surface");
  }
  reverseFaces(F, second);
  for (int f = 0; f < static_cast<int>(F.rows()); ++f)
  {
    if (first[f] != second[f])
    {
      repair.reversed.push_back(f);
    }
  }
  return repair;
}

std::vector<char> redundantTriangles(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  const int nf = static_cast<int>(F.rows());
  std::vector<char> remove(nf, 0);
  std::vector<std::array<int, 4>> sorted(nf); // the three points sorted, then the face
  for (int f = 0; f < nf; ++f)
  {
    sorted[f] = { F(f, 0), F(f, 1), F(f, 2), f };
    std::sort(sorted[f].begin(), sorted[f].begin() + 3);
  }
  std::sort(sorted.begin(), sorted.end());
  for (int i = 1; i < nf; ++i)
  {
    if (std::equal(sorted[i].begin(), sorted[i].begin() + 3, sorted[i - 1].begin()))
    {
      remove[sorted[i][3]] = 1;
    }
  }
  if (V.rows() == 0)
  {
    return remove;
  }
  std::vector<int> parent(V.rows());
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < nf; ++f)
  {
    unite(parent, F(f, 0), F(f, 1));
    unite(parent, F(f, 0), F(f, 2));
  }
  std::vector<double> area(V.rows(), 0.0);
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)).transpose();
    area[findRoot(parent, F(f, 0))] +=
      (V.row(F(f, 1)).transpose() - a).cross(V.row(F(f, 2)).transpose() - a).norm() / 2;
  }
  const double diagonal = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
  for (int f = 0; f < nf; ++f)
  {
    remove[f] = remove[f] || !(area[findRoot(parent, F(f, 0))] > 1e-24 * diagonal * diagonal);
  }
  return remove;
}

MergedPoints mergeCoincidentPoints(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, double tolerance)
{
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
  {
    throw std::invalid_argument("mergeCoincidentPoints: the tolerance must be finite and >= 0");
  }
  const int nv = static_cast<int>(V.rows());
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= nv))
  {
    throw std::invalid_argument("mergeCoincidentPoints: a point index is out of range");
  }
  // cells far wider than the tolerance: a point is within it of at most its own cell's sides
  // on a few axes, so most look in one cell. With tolerance 0, cells of a billionth of the
  // points' extent (equal points share one).
  double extent = 0.0;
  if (nv > 0)
  {
    extent = (V.colwise().maxCoeff() - V.colwise().minCoeff()).maxCoeff();
  }
  const double width = tolerance > 0.0
    ? 1024.0 * tolerance
    : (extent > 0.0 && std::isfinite(extent) ? 1e-9 * extent : 1.0);
  const double tolerance2 = tolerance * tolerance;
  using Cell = std::array<std::int64_t, 3>;
  // per key: the merged points in its cell (a collision of keys only adds candidates)
  std::unordered_map<std::uint64_t, std::vector<int>> cells;
  cells.reserve(static_cast<std::size_t>(nv));
  MergedPoints out;
  out.pointOf.assign(nv, -1);
  const auto cellAt = [&](const Eigen::RowVector3d& x, Cell& c, std::array<int, 3>& side) {
    for (int a = 0; a < 3; ++a)
    {
      const double t = std::floor(x[a] / width);
      c[a] = static_cast<std::int64_t>(std::clamp(t, -4.0e18, 4.0e18));
      const double within = x[a] - t * width;
      // (twice the tolerance: x / width loses bits on coordinates far from the origin)
      side[a] = within <= 2.0 * tolerance ? -1 : (width - within <= 2.0 * tolerance ? 1 : 0);
    }
  };
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int p = F(f, k);
      if (out.pointOf[p] >= 0)
      {
        continue;
      }
      const Eigen::RowVector3d x = V.row(p);
      Cell c;
      std::array<int, 3> side;
      cellAt(x, c, side);
      int found = -1;
      // the own cell, and the neighbours across the sides the point is near
      for (int dx = std::min(0, side[0]); dx <= std::max(0, side[0]); ++dx)
        for (int dy = std::min(0, side[1]); dy <= std::max(0, side[1]); ++dy)
          for (int dz = std::min(0, side[2]); dz <= std::max(0, side[2]); ++dz)
          {
            const auto it = cells.find(cellHash({ c[0] + dx, c[1] + dy, c[2] + dz }));
            if (it == cells.end())
            {
              continue;
            }
            for (const int m : it->second)
            {
              if ((found < 0 || m < found) &&
                (V.row(out.source[m]) - x).squaredNorm() <= tolerance2)
              {
                found = m;
              }
            }
          }
      if (found < 0)
      {
        found = static_cast<int>(out.source.size());
        out.source.push_back(p);
        cells[cellHash(c)].push_back(found);
      }
      out.pointOf[p] = found;
    }
  }
  return out;
}
}
