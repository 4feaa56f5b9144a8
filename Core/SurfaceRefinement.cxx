// SurfaceRefinement.cxx: refineCoarseComponents and refineLongEdges.
#include "SurfaceRefinement.h"

#include "MeshTopology.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace quadcover
{
namespace
{
/// The points: the input's, then the midpoints added so far, each edge's once.
class Points
{
public:
  explicit Points(const Eigen::MatrixX3d& V)
    : V_(V)
  {}

  Eigen::Vector3d operator[](int i) const
  {
    return i < V_.rows() ? Eigen::Vector3d(V_.row(i).transpose()) : added_[i - V_.rows()];
  }

  /// The midpoint of the edge (a, b), added the first time it is asked for (and then listed in
  /// `listed` as its two points, the lower first).
  int midpoint(int a, int b, std::vector<std::array<int, 2>>& listed)
  {
    const std::pair<int, int> edge(std::min(a, b), std::max(a, b));
    const int next = static_cast<int>(V_.rows() + added_.size());
    const auto [it, isNew] = middle_.emplace(edge, next);
    if (isNew)
    {
      added_.push_back(0.5 * ((*this)[edge.first] + (*this)[edge.second]));
      listed.push_back({ edge.first, edge.second });
    }
    return it->second;
  }

  /// The input's points, then the midpoints.
  Eigen::MatrixX3d all() const
  {
    const Eigen::Index nV = V_.rows();
    Eigen::MatrixX3d out(nV + static_cast<Eigen::Index>(added_.size()), 3);
    out.topRows(nV) = V_;
    for (std::size_t i = 0; i < added_.size(); ++i)
    {
      out.row(nV + static_cast<Eigen::Index>(i)) = added_[i].transpose();
    }
    return out;
  }

private:
  const Eigen::MatrixX3d& V_;
  std::vector<Eigen::Vector3d> added_;
  std::map<std::pair<int, int>, int> middle_;
};

/// One 1-to-4 split of the triangles: midpoints shared across edges (an edge of one split is
/// never an edge of an earlier one, so the points' midpoints serve every split).
void splitOnce(Points& points, std::vector<Eigen::Vector3i>& triangles, std::vector<int>& parent,
  Refinement& r)
{
  auto middle = [&](int a, int b) { return points.midpoint(a, b, r.midpoints); };
  std::vector<Eigen::Vector3i> split;
  std::vector<int> splitParent;
  split.reserve(4 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Eigen::Vector3i& c = triangles[t];
    const int ab = middle(c[0], c[1]), bc = middle(c[1], c[2]), ca = middle(c[2], c[0]);
    for (const Eigen::Vector3i& child : { Eigen::Vector3i(c[0], ab, ca),
           Eigen::Vector3i(ab, c[1], bc), Eigen::Vector3i(ca, bc, c[2]),
           Eigen::Vector3i(ab, bc, ca) })
    {
      split.push_back(child);
      splitParent.push_back(parent[t]);
    }
  }
  triangles.swap(split);
  parent.swap(splitParent);
}
}

Refinement refineCoarseComponents(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, int minimumTriangles)
{
  Refinement r;
  const int nF = static_cast<int>(F.rows());
  r.parent.resize(nF);
  for (int f = 0; f < nF; ++f)
  {
    r.parent[f] = f;
  }
  if (minimumTriangles <= 0 || nF == 0)
  {
    return r;
  }
  const MeshTopology topo = buildTopology(F, static_cast<int>(V.rows()));
  std::vector<std::vector<int>> components(topo.numComponents());
  for (int f = 0; f < nF; ++f)
  {
    components[topo.faceComponent[f]].push_back(f);
  }
  std::vector<Eigen::Vector3i> all;
  std::vector<int> allParent;
  Points points(V);
  for (const std::vector<int>& faces : components)
  {
    std::vector<Eigen::Vector3i> triangles;
    std::vector<int> parent = faces;
    for (const int f : faces)
    {
      triangles.push_back(F.row(f).transpose());
    }
    if (static_cast<int>(faces.size()) < minimumTriangles)
    {
      r.refinedTriangles += static_cast<int>(faces.size());
      while (static_cast<int>(triangles.size()) < minimumTriangles)
      {
        splitOnce(points, triangles, parent, r);
      }
    }
    all.insert(all.end(), triangles.begin(), triangles.end());
    allParent.insert(allParent.end(), parent.begin(), parent.end());
  }
  if (r.refinedTriangles == 0)
  {
    return r; // F exactly as it was
  }
  V = points.all();
  F.resize(static_cast<Eigen::Index>(all.size()), 3);
  for (std::size_t t = 0; t < all.size(); ++t)
  {
    F.row(static_cast<Eigen::Index>(t)) = all[t].transpose();
  }
  r.parent = std::move(allParent);
  return r;
}

namespace
{
/// A triangle being refined: its corners, its parent and, per edge k, the parent's edge it lies
/// along (-1 inside).
struct Piece
{
  Eigen::Vector3i c;
  int parent;
  Eigen::Vector3i along;
};

/// The rounds of refineLongEdges over the triangles, their points and the shared midpoints.
class LongEdgeSplitter
{
public:
  LongEdgeSplitter(const Eigen::MatrixX3d& V, double maximumEdgeLength)
    : points_(V)
    , maximum2_(maximumEdgeLength * maximumEdgeLength)
  {}

  /// Splits the marked edges of every piece (one round); false when no edge was too long or
  /// the round would make more than `most` pieces (then nothing is split).
  bool round(std::vector<Piece>& pieces, std::vector<std::array<int, 2>>& midpoints, double most)
  {
    std::set<std::pair<int, int>> marked;
    for (const Piece& p : pieces)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (length2(p.c[k], p.c[(k + 1) % 3]) > maximum2_)
        {
          marked.insert(key(p.c[k], p.c[(k + 1) % 3]));
        }
      }
    }
    if (marked.empty())
    {
      return false;
    }
    closeUnderLongest(pieces, marked);
    // each split of an edge adds a piece on each of its sides
    double after = static_cast<double>(pieces.size());
    for (const Piece& p : pieces)
    {
      for (int k = 0; k < 3; ++k)
      {
        after += static_cast<double>(marked.count(key(p.c[k], p.c[(k + 1) % 3])));
      }
    }
    if (after > most)
    {
      return false;
    }
    std::vector<Piece> next;
    next.reserve(2 * pieces.size());
    for (const Piece& p : pieces)
    {
      split(p, marked, midpoints, next);
    }
    pieces.swap(next);
    return true;
  }

  const Points& points() const { return points_; }

private:
  static std::pair<int, int> key(int a, int b) { return { std::min(a, b), std::max(a, b) }; }

  double length2(int a, int b) const { return (points_[a] - points_[b]).squaredNorm(); }

  /// The longest edge of p (the lowest k on a tie).
  int longest(const Piece& p) const
  {
    int best = 0;
    for (int k = 1; k < 3; ++k)
    {
      if (length2(p.c[k], p.c[(k + 1) % 3]) > length2(p.c[best], p.c[(best + 1) % 3]))
      {
        best = k;
      }
    }
    return best;
  }

  /// Marks the longest edge of every piece with a marked edge, until none is added: each split
  /// piece is then bisected at its longest edge first.
  void closeUnderLongest(const std::vector<Piece>& pieces, std::set<std::pair<int, int>>& marked)
  {
    for (bool grew = true; grew;)
    {
      grew = false;
      for (const Piece& p : pieces)
      {
        const bool any = marked.count(key(p.c[0], p.c[1])) || marked.count(key(p.c[1], p.c[2])) ||
          marked.count(key(p.c[2], p.c[0]));
        const int k = longest(p);
        if (any && marked.insert(key(p.c[k], p.c[(k + 1) % 3])).second)
        {
          grew = true;
        }
      }
    }
  }

  /// p bisected at its edge k into two pieces of the same orientation.
  std::array<Piece, 2> bisect(const Piece& p, int k, std::vector<std::array<int, 2>>& midpoints)
  {
    const int a = p.c[k], b = p.c[(k + 1) % 3], o = p.c[(k + 2) % 3];
    const int m = points_.midpoint(a, b, midpoints);
    const int ab = p.along[k], bo = p.along[(k + 1) % 3], oa = p.along[(k + 2) % 3];
    return { Piece{ Eigen::Vector3i(a, m, o), p.parent, Eigen::Vector3i(ab, -1, oa) },
      Piece{ Eigen::Vector3i(m, b, o), p.parent, Eigen::Vector3i(ab, bo, -1) } };
  }

  /// p split at its marked edges (the longest first, then the others within its halves).
  void split(const Piece& p, const std::set<std::pair<int, int>>& marked,
    std::vector<std::array<int, 2>>& midpoints, std::vector<Piece>& out)
  {
    const int k = longest(p);
    if (!marked.count(key(p.c[k], p.c[(k + 1) % 3])))
    {
      out.push_back(p);
      return;
    }
    const std::array<Piece, 2> halves = this->bisect(p, k, midpoints);
    // the first half holds p's edge k + 2 as its edge 2, the second p's edge k + 1 as its edge 1
    const int edgeOf[2] = { 2, 1 };
    for (int h = 0; h < 2; ++h)
    {
      const Piece& half = halves[h];
      const int e = edgeOf[h];
      if (marked.count(key(half.c[e], half.c[(e + 1) % 3])))
      {
        const std::array<Piece, 2> quarters = this->bisect(half, e, midpoints);
        out.push_back(quarters[0]);
        out.push_back(quarters[1]);
      }
      else
      {
        out.push_back(half);
      }
    }
  }

  Points points_;
  const double maximum2_;
};
}

EdgeRefinement refineLongEdges(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  double maximumEdgeLength, int maximumTriangles)
{
  EdgeRefinement r;
  std::vector<Piece> pieces;
  pieces.reserve(static_cast<std::size_t>(F.rows()));
  for (int f = 0; f < static_cast<int>(F.rows()); ++f)
  {
    pieces.push_back({ F.row(f).transpose(), f, Eigen::Vector3i(0, 1, 2) });
  }
  LongEdgeSplitter splitter(V, maximumEdgeLength);
  if (maximumEdgeLength > 0 && std::isfinite(maximumEdgeLength))
  {
    while (splitter.round(pieces, r.midpoints, maximumTriangles))
    {}
  }
  r.V = splitter.points().all();
  r.F.resize(static_cast<Eigen::Index>(pieces.size()), 3);
  r.parentEdge.resize(static_cast<Eigen::Index>(pieces.size()), 3);
  r.parent.resize(pieces.size());
  std::vector<int> parts(static_cast<std::size_t>(F.rows()), 0);
  for (std::size_t t = 0; t < pieces.size(); ++t)
  {
    r.F.row(static_cast<Eigen::Index>(t)) = pieces[t].c.transpose();
    r.parentEdge.row(static_cast<Eigen::Index>(t)) = pieces[t].along.transpose();
    r.parent[t] = pieces[t].parent;
    ++parts[static_cast<std::size_t>(pieces[t].parent)];
  }
  r.refinedTriangles =
    static_cast<int>(std::count_if(parts.begin(), parts.end(), [](int n) { return n > 1; }));
  return r;
}

Eigen::MatrixX3i refinedMatching(const EdgeRefinement& r, const Eigen::MatrixX3i& matching)
{
  Eigen::MatrixX3i out(r.F.rows(), 3);
  for (Eigen::Index t = 0; t < r.F.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int e = r.parentEdge(t, k);
      out(t, k) = e >= 0 ? matching(r.parent[static_cast<std::size_t>(t)], e) : 0;
    }
  }
  return out;
}

}
