// QuadPatching.cxx: patchQuadMesh, the holes inside the surface filled with quads.
#include "QuadPatching.h"

#include "QuadMeshAdjacency.h"
#include "ScaledJacobian.h"
#include "SurfaceLocator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
/// A quad to add: its corners and the triangle under its centre.
struct NewQuad
{
  Eigen::Vector4i corners;
  int triangle;
};

/// A hole's fill: the quads, and the new point at its middle (if any) with its triangle.
struct Fill
{
  std::vector<NewQuad> quads;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  int centreTriangle = -1;
  int turned = 0;
  double worstCorner = 1.0; ///< the smallest scaled Jacobian of its quads
};

class Patcher
{
public:
  Patcher(
    const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo, QuadMesh& q)
    : V_(V)
    , F_(F)
    , topo_(topo)
    , q_(q)
  {
    for (Eigen::Index i = 0; i < q.Q.rows(); ++i)
    {
      quads_.push_back({ q.Q.row(i).transpose(), q.quadTriangle[i] });
    }
    removed_.assign(quads_.size(), 0);
    for (int v = 0; v < static_cast<int>(q.V.rows()); ++v)
    {
      onBoundary_.push_back(onSurfaceBoundary(V, F, topo, q, v) ? 1 : 0);
    }
  }

  /// Fills the holes, taking in a ring of quads around a fill that would face against the
  /// surface, up to three times; a ring whose grown hole is then not filled is put back and the
  /// hole it was taken around filled as it was. Loops longer than longestLoop() are left open.
  void fillHoles(QuadPatchResult& r)
  {
    std::vector<Ring> rings; // taken in the round before
    for (int round = 0; round < 4; ++round)
    {
      std::vector<std::vector<int>> growing; // loops to take a ring in around
      const std::vector<Loop> loops = boundaryLoops();
      const std::vector<char> fillable = disksMissing(loops);
      const std::vector<int> ringAt = ringOfPoints(rings);
      std::vector<char> unfilled(rings.size(), 0), filled(rings.size(), 0);
      for (const Loop& loop : loops)
      {
        bool done = false;
        if (loop.inside && fillable[componentOf(loop)] && !loop.pinched &&
          loop.points.size() % 2 == 0 && loop.points.size() <= longestLoop())
        {
          Fill fill = bestFill(loop.points);
          if (fill.turned > 0 && round < 3)
          {
            growing.push_back(loop.points);
            continue;
          }
          commit(fill);
          ++r.holesFilled;
          r.quadsAdded += static_cast<int>(fill.quads.size());
          done = true;
        }
        for (const int p : loop.points)
        {
          if (p < static_cast<int>(ringAt.size()) && ringAt[p] >= 0)
          {
            (done ? filled : unfilled)[ringAt[p]] = 1;
          }
        }
      }
      std::set<std::pair<int, int>> taken; // the mesh's half-edges, once a ring is to go back
      for (size_t i = 0; i < rings.size(); ++i)
      {
        if (!unfilled[i] || filled[i])
        {
          continue;
        }
        if (taken.empty())
        {
          addHalfEdges(taken);
        }
        if (putBack(rings[i], taken))
        {
          const size_t first = quads_.size();
          const Fill fill = bestFill(rings[i].loop);
          commit(fill);
          addHalfEdges(taken, first);
          ++r.holesFilled;
          r.quadsAdded += static_cast<int>(fill.quads.size());
        }
      }
      if (growing.empty())
      {
        break;
      }
      rings = takeIn(growing);
    }
    r.holesLeft = holesOpened(boundaryLoops());
  }

  /// Writes the quads back, without the points no quad uses.
  void finish()
  {
    std::vector<NewQuad> kept;
    for (size_t i = 0; i < quads_.size(); ++i)
    {
      if (!removed_[i])
      {
        kept.push_back(quads_[i]);
      }
    }
    q_.Q.resize(static_cast<Eigen::Index>(kept.size()), 4);
    q_.quadTriangle.resize(kept.size());
    for (size_t i = 0; i < kept.size(); ++i)
    {
      q_.Q.row(static_cast<Eigen::Index>(i)) = kept[i].corners.transpose();
      q_.quadTriangle[i] = kept[i].triangle;
    }
    removeUnusedVertices(q_);
  }

private:
  struct Loop
  {
    std::vector<int> points; ///< in the direction of the quads' own edges along it
    bool pinched = false;    ///< passes a point twice
    bool inside = true;      ///< no point on the surface's boundary
  };

  Eigen::Vector3d point(int v) const { return q_.V.row(v).transpose(); }
  Eigen::Vector3d surfacePoint(int p) const { return V_.row(p).transpose(); }
  Eigen::Vector3d triangleNormal(int t) const
  {
    const Eigen::Vector3d a = surfacePoint(F_(t, 0));
    return (surfacePoint(F_(t, 1)) - a).cross(surfacePoint(F_(t, 2)) - a);
  }



  /// Whether the quad faces against the surface triangle closest to its centre.
  bool turned(const Eigen::Vector4i& c) const
  {
    const Eigen::Vector3d centre = (point(c[0]) + point(c[1]) + point(c[2]) + point(c[3])) / 4.0;
    const int triangle = closest(centre, nearbyTriangles({ c[0], c[1], c[2], c[3] })).second;
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
    {
      n += (point(c[k]) - centre).cross(point(c[(k + 1) % 4]) - centre);
    }
    return triangle < 0 || !(n.dot(triangleNormal(triangle)) > 0);
  }

  /// A ring of quads taken in around a hole: the hole's loop, and the quads.
  struct Ring
  {
    std::vector<int> loop;
    std::vector<int> quads;
  };

  /// For each loop, the quads (not yet removed) with a corner on it removed, except those that
  /// touch the surface's boundary (cutting them out would open the hole onto it); a quad that
  /// touches two loops goes with the first.
  std::vector<Ring> takeIn(const std::vector<std::vector<int>>& loops)
  {
    std::vector<Ring> rings(loops.size());
    std::vector<int> owner(q_.V.rows(), -1); // the first loop through each point
    for (size_t g = loops.size(); g-- > 0;)
    {
      rings[g].loop = loops[g];
      for (const int p : loops[g])
      {
        owner[p] = static_cast<int>(g);
      }
    }
    for (size_t i = 0; i < quads_.size(); ++i)
    {
      int first = -1;
      bool boundary = false;
      for (int k = 0; k < 4; ++k)
      {
        const int g = owner[quads_[i].corners[k]];
        first = g >= 0 && (first < 0 || g < first) ? g : first;
        boundary = boundary || onBoundary_[quads_[i].corners[k]];
      }
      if (!removed_[i] && first >= 0 && !boundary)
      {
        removed_[i] = 1;
        rings[first].quads.push_back(static_cast<int>(i));
      }
    }
    return rings;
  }

  /// Per quad vertex, the ring (index into `rings`) whose quads had it as a corner, or -1.
  std::vector<int> ringOfPoints(const std::vector<Ring>& rings) const
  {
    std::vector<int> ring(q_.V.rows(), -1);
    for (size_t r = 0; r < rings.size(); ++r)
    {
      for (const int i : rings[r].quads)
      {
        for (int k = 0; k < 4; ++k)
        {
          ring[quads_[i].corners[k]] = static_cast<int>(r);
        }
      }
    }
    return ring;
  }

  /// The half-edges (a corner to the next) of the quads from `from` on that are not removed.
  void addHalfEdges(std::set<std::pair<int, int>>& taken, size_t from = 0) const
  {
    for (size_t i = from; i < quads_.size(); ++i)
    {
      for (int k = 0; !removed_[i] && k < 4; ++k)
      {
        taken.insert({ quads_[i].corners[k], quads_[i].corners[(k + 1) % 4] });
      }
    }
  }

  /// Puts the ring's quads back, unless one of their half-edges is `taken` (by a quad of the
  /// mesh: a fill committed since), and adds theirs. @return whether they went back
  bool putBack(const Ring& ring, std::set<std::pair<int, int>>& taken)
  {
    for (const int i : ring.quads)
    {
      for (int k = 0; k < 4; ++k)
      {
        if (taken.count({ quads_[i].corners[k], quads_[i].corners[(k + 1) % 4] }))
        {
          return false;
        }
      }
    }
    for (const int i : ring.quads)
    {
      removed_[i] = 0;
      for (int k = 0; k < 4; ++k)
      {
        taken.insert({ quads_[i].corners[k], quads_[i].corners[(k + 1) % 4] });
      }
    }
    return true;
  }

  /// The longest loop a fill is tried on: a fill costs the loop's length times the triangles
  /// near it (about ten a loop point), so that, with at most sqrt(#quads) + 64 points, filling a
  /// hole costs no more than a pass over the mesh; longer loops (the map failed over a large
  /// part of the surface, and one fan of quads would cover it badly anyway) are left open.
  size_t longestLoop() const
  {
    return static_cast<size_t>(std::sqrt(static_cast<double>(quads_.size()))) + 64;
  }

  std::vector<Loop> boundaryLoops() const
  {
    std::vector<std::pair<int, int>> halfEdges; // each once, in order
    for (size_t i = 0; i < quads_.size(); ++i)
    {
      for (int k = 0; !removed_[i] && k < 4; ++k)
      {
        halfEdges.emplace_back(quads_[i].corners[k], quads_[i].corners[(k + 1) % 4]);
      }
    }
    std::sort(halfEdges.begin(), halfEdges.end());
    halfEdges.erase(std::unique(halfEdges.begin(), halfEdges.end()), halfEdges.end());
    std::map<int, std::vector<int>> next; // boundary half-edges leaving each point
    for (const auto& [a, b] : halfEdges)
    {
      if (!std::binary_search(halfEdges.begin(), halfEdges.end(), std::make_pair(b, a)))
      {
        next[a].push_back(b);
      }
    }
    std::vector<Loop> loops;
    std::map<int, size_t> taken; // boundary half-edges walked, per start point
    for (const auto& [start, heads] : next)
    {
      while (taken[start] < heads.size())
      {
        Loop loop;
        int p = start;
        do
        {
          loop.points.push_back(p);
          loop.pinched = loop.pinched || next[p].size() != 1;
          loop.inside = loop.inside && !onBoundary_[p];
          const size_t slot = std::min(taken[p]++, next[p].size() - 1);
          p = next[p][slot];
        } while (p != start && loop.points.size() <= halfEdges.size());
        if (loop.pinched && p == start)
        {
          splitAtRepeats(loop, loops);
        }
        else
        {
          loops.push_back(std::move(loop));
        }
      }
    }
    return loops;
  }

  /// The loops inside the surface (no point on its boundary) that are not its own holes: per
  /// component, those beyond its boundary loops that no loop of the quads touches (where the
  /// quads stop short of a hole of the surface, their loop around it lies inside it too).
  int holesOpened(const std::vector<Loop>& loops) const
  {
    const int nc = topo_.numComponents();
    std::vector<int> inside(nc, 0), own(nc, 0);
    for (int c = 0; c < nc; ++c)
    {
      own[c] = topo_.components[c].numBoundaryLoops;
    }
    for (const Loop& loop : loops)
    {
      if (loop.inside)
      {
        ++inside[componentOf(loop)];
      }
      else
      {
        --own[componentOf(loop)]; // a hole of the surface the quads reach
      }
    }
    int opened = 0;
    for (int c = 0; c < nc; ++c)
    {
      opened += std::max(0, inside[c] - std::max(0, own[c]));
    }
    return opened;
  }

  /// The surface's component a loop lies on.
  int componentOf(const Loop& loop) const
  {
    return topo_.faceComponent[q_.vertexTriangle[loop.points.front()]];
  }

  /// Per component of the surface, whether its holes are all disks that went missing: its quads'
  /// Euler characteristic plus one per hole is the component's own. (Where a band around a
  /// torus's tube went missing, its two loops are no disks: filling them would make a sphere.)
  std::vector<char> disksMissing(const std::vector<Loop>& loops) const
  {
    const int nc = topo_.numComponents();
    std::vector<long long> chi(nc, 0);
    std::vector<int> vertexComponent(q_.V.rows(), -1);
    std::map<std::pair<int, int>, int> edges;
    for (size_t i = 0; i < quads_.size(); ++i)
    {
      if (removed_[i] || quads_[i].triangle < 0)
      {
        continue;
      }
      const int c = topo_.faceComponent[quads_[i].triangle];
      ++chi[c];
      for (int k = 0; k < 4; ++k)
      {
        const int a = quads_[i].corners[k], b = quads_[i].corners[(k + 1) % 4];
        if (vertexComponent[a] < 0)
        {
          vertexComponent[a] = c;
          ++chi[c];
        }
        if (edges.emplace(std::make_pair(std::min(a, b), std::max(a, b)), c).second)
        {
          --chi[c];
        }
      }
    }
    for (const Loop& loop : loops)
    {
      chi[componentOf(loop)] += loop.inside ? 1 : 0;
    }
    std::vector<char> fillable(nc, 0);
    for (int c = 0; c < nc; ++c)
    {
      fillable[c] = chi[c] == topo_.components[c].eulerCharacteristic ? 1 : 0;
    }
    return fillable;
  }

  /// Splits a closed loop that passes points more than once into simple loops (each filled on
  /// its own; together they close the pinch).
  static void splitAtRepeats(const Loop& loop, std::vector<Loop>& loops)
  {
    std::vector<int> stack;
    std::map<int, size_t> position; // of a point on the stack
    for (const int p : loop.points)
    {
      const auto found = position.find(p);
      if (found != position.end())
      {
        Loop simple;
        simple.points.assign(
          stack.begin() + static_cast<std::ptrdiff_t>(found->second), stack.end());
        simple.inside = loop.inside;
        for (size_t i = found->second + 1; i < stack.size(); ++i)
        {
          position.erase(stack[i]);
        }
        stack.resize(found->second + 1);
        loops.push_back(std::move(simple));
        continue;
      }
      position[p] = stack.size();
      stack.push_back(p);
    }
    Loop rest;
    rest.points = stack;
    rest.inside = loop.inside;
    loops.push_back(std::move(rest));
  }

  /// The surface triangles near the points: theirs, and two rings of neighbours.
  std::vector<int> nearbyTriangles(const std::vector<int>& points) const
  {
    std::vector<int> list;
    for (const int p : points)
    {
      list.push_back(q_.vertexTriangle[p]);
    }
    for (int ring = 0; ring < 2; ++ring)
    {
      const size_t n = list.size();
      for (size_t i = 0; i < n; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          if (list[i] >= 0 && topo_.faceNeighbors(list[i], k) >= 0)
          {
            list.push_back(topo_.faceNeighbors(list[i], k));
          }
        }
      }
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    list.erase(std::remove(list.begin(), list.end(), -1), list.end());
    return list;
  }

  /// The point of the listed triangles closest to p, and its triangle.
  std::pair<Eigen::Vector3d, int> closest(
    const Eigen::Vector3d& p, const std::vector<int>& triangles) const
  {
    std::pair<Eigen::Vector3d, int> best{ p, -1 };
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const int t : triangles)
    {
      const Eigen::Vector3d c = closestOnTriangle(
        p, surfacePoint(F_(t, 0)), surfacePoint(F_(t, 1)), surfacePoint(F_(t, 2)));
      if ((c - p).squaredNorm() < bestDistance)
      {
        bestDistance = (c - p).squaredNorm();
        best = { c, t };
      }
    }
    return best;
  }

  /// Fills a loop of four with one quad, a longer one with a fan around a new point, the better
  /// of its two fans.
  Fill bestFill(const std::vector<int>& loop)
  {
    const int n = static_cast<int>(loop.size());
    const std::vector<int> near = nearbyTriangles(loop);
    const int centre = static_cast<int>(q_.V.rows()); // the new point's index, if it is added
    Fill best;
    for (int phase = 0; phase < (n == 4 ? 1 : 2); ++phase)
    {
      Fill fill;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (const int p : loop)
      {
        mean += point(p) / n;
      }
      std::tie(fill.centre, fill.centreTriangle) = closest(mean, near);
      auto at = [&](int i) { return loop[(i + phase) % n]; };
      for (int i = 0; i < (n == 4 ? 1 : n / 2); ++i)
      {
        // against the loop's direction: the quads along it run it the other way
        const Eigen::Vector4i c = n == 4
          ? Eigen::Vector4i(at(3), at(2), at(1), at(0))
          : Eigen::Vector4i(centre, at(2 * i + 2), at(2 * i + 1), at(2 * i));
        fill.quads.push_back({ c, -1 });
      }
      score(fill, near, n == 4 ? -1 : centre);
      if (best.quads.empty() || fill.turned < best.turned ||
        (fill.turned == best.turned && fill.worstCorner > best.worstCorner))
      {
        best = fill;
      }
    }
    return best;
  }

  /// The fill's quads' triangles, how many face against them, and its worst corner.
  void score(Fill& fill, const std::vector<int>& near, int centre)
  {
    auto at = [&](int v) { return v == centre ? fill.centre : point(v); };
    for (NewQuad& quad : fill.quads)
    {
      Eigen::Matrix<double, 4, 3> corners;
      for (int k = 0; k < 4; ++k)
      {
        corners.row(k) = at(quad.corners[k]).transpose();
      }
      const Eigen::Vector3d middle = corners.colwise().mean().transpose();
      quad.triangle = closest(middle, near).second;
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k)
      {
        n += (corners.row(k).transpose() - middle)
               .cross(corners.row((k + 1) % 4).transpose() - middle);
      }
      fill.turned += quad.triangle < 0 || !(n.dot(triangleNormal(quad.triangle)) > 0) ? 1 : 0;
      const Eigen::MatrixX3d positions = corners;
      const Eigen::MatrixX4i single = Eigen::RowVector4i(0, 1, 2, 3);
      fill.worstCorner = std::min(fill.worstCorner, quadScaledJacobian(positions, single, 0));
    }
  }

  void commit(const Fill& fill)
  {
    bool centre = false;
    for (const NewQuad& quad : fill.quads)
    {
      centre = centre || quad.corners[0] == q_.V.rows();
    }
    if (centre)
    {
      const Eigen::Index v = q_.V.rows();
      q_.V.conservativeResize(v + 1, 3);
      q_.V.row(v) = fill.centre.transpose();
      q_.vertexTriangle.push_back(fill.centreTriangle);
      q_.vertexPoint.push_back(-1);
      onBoundary_.push_back(0);
    }
    for (const NewQuad& quad : fill.quads)
    {
      quads_.push_back(quad);
      removed_.push_back(0);
    }
  }

  const Eigen::MatrixX3d& V_;
  const Eigen::MatrixX3i& F_;
  const MeshTopology& topo_;
  QuadMesh& q_;
  std::vector<NewQuad> quads_;
  std::vector<char> removed_;
  std::vector<char> onBoundary_; ///< per quad vertex
};
}

QuadPatchResult patchQuadMesh(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo, QuadMesh& q)
{
  QuadPatchResult r;
  Patcher patcher(V, F, topo, q);
  patcher.fillHoles(r);
  patcher.finish();
  return r;
}

}
