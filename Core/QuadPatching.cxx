// QuadPatching.cxx: patchQuadMesh, the holes inside the surface filled with quads.
#include "QuadPatching.h"

#include "ScaledJacobian.h"
#include "SurfaceLocator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <map>
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
      onBoundary_.push_back(onSurfaceBoundary(v) ? 1 : 0);
    }
  }

  /// Fills the holes, taking in a ring of quads around a fill that would face against the
  /// surface, up to three times.
  void fillHoles(QuadPatchResult& r)
  {
    for (int round = 0; round < 4; ++round)
    {
      std::vector<char> grow(q_.V.rows(), 0);
      bool growing = false;
      const std::vector<Loop> loops = boundaryLoops();
      const std::vector<char> fillable = disksMissing(loops);
      for (const Loop& loop : loops)
      {
        if (!loop.inside || !fillable[componentOf(loop)])
        {
          continue;
        }
        if (loop.pinched || loop.points.size() % 2 != 0)
        {
          continue;
        }
        Fill fill = bestFill(loop.points);
        if (fill.turned > 0 && round < 3)
        {
          for (const int p : loop.points)
          {
            grow[p] = 1;
          }
          growing = true;
          continue;
        }
        commit(fill);
        ++r.holesFilled;
        r.quadsAdded += static_cast<int>(fill.quads.size());
      }
      if (!growing)
      {
        break;
      }
      removeTouching(grow);
    }
    for (const Loop& loop : boundaryLoops())
    {
      r.holesLeft += loop.inside ? 1 : 0;
    }
  }

  /// Writes the quads back, without the points no quad uses.
  void finish()
  {
    std::vector<int> newIndex(q_.V.rows(), -1);
    int used = 0;
    std::vector<NewQuad> kept;
    for (size_t i = 0; i < quads_.size(); ++i)
    {
      if (!removed_[i])
      {
        kept.push_back(quads_[i]);
        for (int k = 0; k < 4; ++k)
        {
          int& index = newIndex[quads_[i].corners[k]];
          index = index < 0 ? used++ : index;
        }
      }
    }
    QuadMesh out = q_;
    out.V.resize(used, 3);
    out.vertexTriangle.assign(used, -1);
    out.vertexPoint.assign(used, -1);
    for (int v = 0; v < static_cast<int>(newIndex.size()); ++v)
    {
      if (newIndex[v] >= 0)
      {
        out.V.row(newIndex[v]) = q_.V.row(v);
        out.vertexTriangle[newIndex[v]] = q_.vertexTriangle[v];
        out.vertexPoint[newIndex[v]] = q_.vertexPoint[v];
      }
    }
    out.Q.resize(static_cast<Eigen::Index>(kept.size()), 4);
    out.quadTriangle.resize(kept.size());
    for (size_t i = 0; i < kept.size(); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        out.Q(static_cast<Eigen::Index>(i), k) = newIndex[kept[i].corners[k]];
      }
      out.quadTriangle[i] = kept[i].triangle;
    }
    q_ = std::move(out);
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

  /// Whether quad vertex v lies on a boundary edge of the surface.
  bool onSurfaceBoundary(int v) const
  {
    if (q_.vertexPoint[v] >= 0)
    {
      return topo_.boundaryVertex[q_.vertexPoint[v]] != 0; // on a point of the surface
    }
    const int t = q_.vertexTriangle[v];
    if (t < 0)
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (topo_.faceNeighbors(t, k) < 0)
      {
        const Eigen::Vector3d a = surfacePoint(F_(t, k)), b = surfacePoint(F_(t, (k + 1) % 3));
        if ((closestOnSegment(point(v), a, b) - point(v)).norm() <= 1e-7 * (b - a).norm())
        {
          return true;
        }
      }
    }
    return false;
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

  /// Removes the quads (not yet removed) with a corner marked, except those that touch the
  /// surface's boundary (cutting them out would open the hole onto it).
  void removeTouching(const std::vector<char>& marked)
  {
    for (size_t i = 0; i < quads_.size(); ++i)
    {
      bool hit = false, boundary = false;
      for (int k = 0; k < 4; ++k)
      {
        hit = hit || marked[quads_[i].corners[k]];
        boundary = boundary || onBoundary_[quads_[i].corners[k]];
      }
      removed_[i] = removed_[i] || (hit && !boundary);
    }
  }

  std::vector<Loop> boundaryLoops() const
  {
    std::map<std::pair<int, int>, int> halfEdges;
    for (size_t i = 0; i < quads_.size(); ++i)
    {
      for (int k = 0; !removed_[i] && k < 4; ++k)
      {
        ++halfEdges[{ quads_[i].corners[k], quads_[i].corners[(k + 1) % 4] }];
      }
    }
    std::map<int, std::vector<int>> next; // boundary half-edges leaving each point
    for (const auto& [edge, count] : halfEdges)
    {
      if (halfEdges.find({ edge.second, edge.first }) == halfEdges.end())
      {
        next[edge.first].push_back(edge.second);
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
