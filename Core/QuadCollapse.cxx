// QuadCollapse.cxx: removeTurnedQuads, quads that face against the surface removed as ears or
// collapsed along a diagonal.
#include "QuadCollapse.h"

#include "QuadFacing.h"
#include "QuadMeshAdjacency.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
class Collapser
{
public:
  Collapser(const QuadJudge& judge, QuadMesh& mesh)
    : judge_(judge)
    , mesh_(mesh)
    , removed_(static_cast<std::size_t>(mesh.Q.rows()), 0)
    , quadsOf_(static_cast<std::size_t>(mesh.V.rows()))
  {
    for (int q = 0; q < static_cast<int>(mesh.Q.rows()); ++q)
    {
      for (int k = 0; k < 4; ++k)
      {
        quadsOf_[mesh.Q(q, k)].push_back(q);
      }
    }
  }

  /// Removes quad q if it is an ear (three edges on the boundary, its two corners there on no
  /// other quad). @return whether it was removed
  bool removeEar(int q)
  {
    int inner = -1, boundary = 0;
    for (int k = 0; k < 4; ++k)
    {
      if (quadsOnEdge(corner(q, k), corner(q, k + 1)) == 1)
      {
        ++boundary;
      }
      else
      {
        inner = k;
      }
    }
    if (boundary != 3 || quadsOnEdge(corner(q, inner), corner(q, inner + 1)) != 2 ||
      quadsOf_[corner(q, inner + 2)].size() != 1 || quadsOf_[corner(q, inner + 3)].size() != 1)
    {
      return false;
    }
    remove(q);
    return true;
  }

  /// Collapses quad q along the diagonal and to the point that leave its neighbours' worst (the
  /// judge's) best, when that is above 0. @return whether it was collapsed
  bool collapse(int q)
  {
    Choice best;
    for (int s = 0; s < 2; ++s)
    {
      if (!collapsible(q, s))
      {
        continue;
      }
      const int a = corner(q, s), e = corner(q, s + 2);
      const bool eKept = onBoundary(e); // (collapsible: not both on the boundary)
      const int keep = eKept ? e : a, gone = eKept ? a : e;
      std::vector<Place> places{ placeOf(keep) };
      if (!onBoundary(keep))
      {
        places.push_back(placeOf(gone));
        const SurfaceLocator::Hit hit = judge_.closest(0.5 * (point(a) + point(e)));
        if (hit.triangle >= 0)
        {
          places.push_back({ hit.point, hit.triangle, -1 });
        }
      }
      for (const Place& place : places)
      {
        const double worst = tryMerge(q, keep, gone, place);
        if (worst > best.worst)
        {
          best = { worst, keep, gone, place };
        }
      }
    }
    if (!(best.worst > 0.0))
    {
      return false;
    }
    merge(q, best.keep, best.gone, best.place);
    return true;
  }

  bool removed(int q) const { return removed_[q] != 0; }

  /// The mesh without the removed quads and the points no quad uses.
  void finish()
  {
    const int nQ = static_cast<int>(mesh_.Q.rows());
    int kept = 0;
    for (int q = 0; q < nQ; ++q)
    {
      if (!removed_[q])
      {
        mesh_.Q.row(kept) = mesh_.Q.row(q);
        mesh_.quadTriangle[kept] = mesh_.quadTriangle[q];
        ++kept;
      }
    }
    mesh_.Q.conservativeResize(kept, 4);
    mesh_.quadTriangle.resize(static_cast<std::size_t>(kept));
    removeUnusedVertices(mesh_);
  }

private:
  /// Where a kept point goes: its position, triangle and input point (or -1).
  struct Place
  {
    Eigen::Vector3d point;
    int triangle;
    int inputPoint;
  };

  struct Choice
  {
    double worst = -std::numeric_limits<double>::infinity();
    int keep = -1, gone = -1;
    Place place{ Eigen::Vector3d::Zero(), -1, -1 };
  };

  int corner(int q, int k) const { return mesh_.Q(q, ((k % 4) + 4) % 4); }
  Eigen::Vector3d point(int v) const { return mesh_.V.row(v).transpose(); }
  Place placeOf(int v) const { return { point(v), mesh_.vertexTriangle[v], mesh_.vertexPoint[v] }; }

  /// The quads with edge (u, v).
  int quadsOnEdge(int u, int v) const
  {
    int count = 0;
    for (const int q : quadsOf_[u])
    {
      for (int k = 0; k < 4; ++k)
      {
        count += corner(q, k) == u && (corner(q, k + 1) == v || corner(q, k - 1) == v);
      }
    }
    return count;
  }

  /// The points v shares an edge with.
  std::vector<int> neighbours(int v) const
  {
    std::vector<int> list;
    for (const int q : quadsOf_[v])
    {
      for (int k = 0; k < 4; ++k)
      {
        if (corner(q, k) == v)
        {
          list.push_back(corner(q, k + 1));
          list.push_back(corner(q, k - 1));
        }
      }
    }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    return list;
  }

  bool onBoundary(int v) const
  {
    for (const int w : neighbours(v))
    {
      if (quadsOnEdge(v, w) != 2)
      {
        return true;
      }
    }
    return false;
  }

  /// Can quad q be collapsed along the diagonal from corner s, keeping the mesh manifold and
  /// all quads?
  bool collapsible(int q, int s) const
  {
    const int a = corner(q, s), b = corner(q, s + 1), e = corner(q, s + 2), d = corner(q, s + 3);
    if (a == e || b == d || a == b || a == d || e == b || e == d)
    {
      return false;
    }
    for (const int p : quadsOf_[a])
    {
      if (p != q && std::count(quadsOf_[e].begin(), quadsOf_[e].end(), p) > 0)
      {
        return false; // a second quad on both: it would lose a corner
      }
    }
    std::vector<int> common;
    const std::vector<int> na = neighbours(a), ne = neighbours(e);
    std::set_intersection(na.begin(), na.end(), ne.begin(), ne.end(), std::back_inserter(common));
    std::vector<int> sides{ std::min(b, d), std::max(b, d) };
    if (common != sides || (onBoundary(a) && onBoundary(e)))
    {
      return false;
    }
    for (const int x : { b, d })
    {
      const std::size_t quads = quadsOf_[x].size();
      const bool boundary = onBoundary(x);
      if (quads < 2 || (!boundary && quads < 4) ||
        (quadsOnEdge(a, x) == 1 && quadsOnEdge(e, x) == 1))
      {
        return false; // x would keep one quad, two inside, or be pinched between two loops
      }
    }
    return true;
  }

  /// Quad q's corner `gone` put onto `keep` in its other quads and keep moved to `place`, with q
  /// left out; the worst (the judge's) of keep's quads then, everything put back.
  double tryMerge(int q, int keep, int gone, const Place& place)
  {
    const std::vector<std::pair<int, Eigen::Vector4i>> saved = renumber(q, gone, keep);
    const Place was = placeOf(keep);
    set(keep, place);
    double worst = std::numeric_limits<double>::infinity();
    for (const int p : quadsOf_[keep])
    {
      worst = p == q ? worst : std::min(worst, judge_.worst(mesh_, p));
    }
    for (const auto& [p, corners] : saved)
    {
      worst = std::min(worst, judge_.worst(mesh_, p));
      mesh_.Q.row(p) = corners.transpose();
    }
    set(keep, was);
    return worst;
  }

  /// The collapse tryMerge measured, made.
  void merge(int q, int keep, int gone, const Place& place)
  {
    const std::vector<std::pair<int, Eigen::Vector4i>> moved = renumber(q, gone, keep);
    set(keep, place);
    remove(q);
    for (const auto& entry : moved)
    {
      quadsOf_[keep].push_back(entry.first);
    }
    std::sort(quadsOf_[keep].begin(), quadsOf_[keep].end());
    quadsOf_[gone].clear();
    for (const int p : quadsOf_[keep])
    {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k)
      {
        centre += point(corner(p, k)) / 4.0;
      }
      mesh_.quadTriangle[p] = judge_.closest(centre).triangle;
    }
  }

  /// Corner `from` of the quads other than q renamed `to`; returns those quads' corners before.
  std::vector<std::pair<int, Eigen::Vector4i>> renumber(int q, int from, int to)
  {
    std::vector<std::pair<int, Eigen::Vector4i>> saved;
    for (const int p : quadsOf_[from])
    {
      if (p == q)
      {
        continue;
      }
      saved.emplace_back(p, mesh_.Q.row(p).transpose());
      for (int k = 0; k < 4; ++k)
      {
        mesh_.Q(p, k) = mesh_.Q(p, k) == from ? to : mesh_.Q(p, k);
      }
    }
    return saved;
  }

  void set(int v, const Place& place)
  {
    mesh_.V.row(v) = place.point.transpose();
    mesh_.vertexTriangle[v] = place.triangle;
    mesh_.vertexPoint[v] = place.inputPoint;
  }

  void remove(int q)
  {
    removed_[q] = 1;
    for (int k = 0; k < 4; ++k)
    {
      std::vector<int>& list = quadsOf_[corner(q, k)];
      list.erase(std::remove(list.begin(), list.end(), q), list.end());
    }
  }

  const QuadJudge& judge_;
  QuadMesh& mesh_;
  std::vector<char> removed_;
  std::vector<std::vector<int>> quadsOf_; ///< per point, its quads not removed, in index order
};
}

QuadCollapseResult removeTurnedQuads(
  const SurfaceLocator& surface, const std::vector<int>& quads, QuadMesh& mesh)
{
  const QuadJudge judge{ [&](const QuadMesh& m, int q) { return quadWorstOf(surface, m, q); },
    [&](const Eigen::Vector3d& p) { return surface.closest(p); } };
  return removeTurnedQuads(judge, quads, mesh);
}

QuadCollapseResult removeTurnedQuads(
  const QuadJudge& judge, const std::vector<int>& quads, QuadMesh& mesh)
{
  QuadCollapseResult result;
  if (quads.empty())
  {
    return result;
  }
  Collapser collapser(judge, mesh);
  for (const int q : quads)
  {
    if (collapser.removed(q) || judge.worst(mesh, q) > 0.0)
    {
      continue; // gone, or mended by a collapse beside it
    }
    if (collapser.removeEar(q))
    {
      ++result.ears;
    }
    else if (collapser.collapse(q))
    {
      ++result.collapsed;
    }
  }
  if (result.ears + result.collapsed > 0)
  {
    collapser.finish();
  }
  return result;
}

}
