// CreaseSnapping.cxx: snapToCreases.
#include "CreaseSnapping.h"

#include "QuadFacing.h"
#include "QuadMeshAdjacency.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
/// The closest point of a crease to a quad vertex: on edge e at e's start + t (end - start).
struct CreasePoint
{
  double distance = std::numeric_limits<double>::infinity();
  int edge = -1;
  double t = 0.0;
};

class Snapper
{
public:
  Snapper(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
    const std::vector<char>& sharp, const SurfaceLocator& surface, QuadMesh& mesh)
    : V_(V)
    , F_(F)
    , topo_(topo)
    , sharp_(sharp)
    , surface_(surface)
    , mesh_(mesh)
    , visited_(F.rows(), 0)
  {
    meanEdge_ = meanQuadEdge(mesh);
    findReach();
    sharpDegree_.assign(V.rows(), 0);
    for (int e = 0; e < topo.numEdges(); ++e)
    {
      if (sharp[e])
      {
        ++sharpDegree_[topo.edges(e, 0)];
        ++sharpDegree_[topo.edges(e, 1)];
      }
    }
  }

  /// Each quad edge whose ends lie on the two sides of the crease nearest to its nearer end
  /// moves that end onto it. Vertices on the boundary (the quads' or the surface's) stay, and so
  /// do those whose nearest crease point is the end of a crease (beside it, not across it) or
  /// which lie on a crease already. Then acrossWalls.
  std::vector<int> run()
  {
    const int nV = static_cast<int>(mesh_.V.rows());
    const std::vector<char> boundary = quadMeshBoundary(mesh_);
    const std::vector<char> nearCrease = trianglesNearCreases();
    std::vector<CreasePoint> closest(nV), target(nV);
    for (int v = 0; v < nV; ++v)
    {
      if (nearCrease[mesh_.vertexTriangle[v]] && !boundary[v] &&
        !onSurfaceBoundary(V_, F_, topo_, mesh_, v) && !liesOnCrease(v))
      {
        closest[v] = closestCrease(v);
      }
    }
    for (int i = 0; i < static_cast<int>(mesh_.Q.rows()); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int a = mesh_.Q(i, k), b = mesh_.Q(i, (k + 1) % 4);
        if (closest[a].edge < 0 || closest[b].edge < 0)
        {
          continue;
        }
        const int near = closest[a].distance <= closest[b].distance ? a : b;
        const CreasePoint& p = closest[near];
        if (side(a, p) != side(b, p) && !atCreaseEnd(p))
        {
          target[near] = p;
        }
      }
    }
    acrossWalls(closest, target);
    return apply(target);
  }

  /// On a wall about a quad high between two creases (a thin plate's rim, thinStripGridScale),
  /// a quad edge up the wall can have its lower end moved onto the lower crease while its upper
  /// end, beside the upper crease but no nearer to it than the lower end is to the lower one,
  /// stays: the row of quads then reaches past the upper crease (the 0.02-high frame of Data/ at
  /// 6,500 quads: Hausdorff distance 0.41%; with this, 0.00%). So where one end of a quad edge
  /// moves onto a crease and the other, not moved, lies across its own nearest crease from the
  /// first end, and the two creases bound a wall (wallBetween), the other end moves onto its
  /// crease too.
  void acrossWalls(const std::vector<CreasePoint>& closest, std::vector<CreasePoint>& target) const
  {
    const std::vector<CreasePoint> first = target;
    for (int i = 0; i < static_cast<int>(mesh_.Q.rows()); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        for (int turn = 0; turn < 2; ++turn)
        {
          const int a = mesh_.Q(i, (k + turn) % 4), b = mesh_.Q(i, (k + 1 - turn) % 4);
          const CreasePoint& p = closest[b];
          if (first[a].edge >= 0 && first[b].edge < 0 && target[b].edge < 0 && p.edge >= 0 &&
            p.edge != first[a].edge && side(a, p) != side(b, p) && !atCreaseEnd(p) &&
            wallBetween(first[a].edge, p.edge))
          {
            target[b] = p;
          }
        }
      }
    }
  }

  /// Whether sharp edges e and g bound a wall: a triangle at e and one at g nearly parallel (the
  /// wall, cosine above 0.9), and their other two triangles facing apart (the plate's faces); a
  /// triangle of no area (zero normal, SurfaceLocator::normal) bounds none.
  bool wallBetween(int e, int g) const
  {
    for (int i = 0; i < 2; ++i)
    {
      for (int j = 0; j < 2; ++j)
      {
        const int we = topo_.edgeFaces(e, i), wg = topo_.edgeFaces(g, j);
        const int oe = topo_.edgeFaces(e, 1 - i), og = topo_.edgeFaces(g, 1 - j);
        if (we >= 0 && wg >= 0 && oe >= 0 && og >= 0 &&
          surface_.normal(we).dot(surface_.normal(wg)) > 0.9 &&
          surface_.normal(oe).dot(surface_.normal(og)) < 0)
        {
          return true;
        }
      }
    }
    return false;
  }

  /**
   * Where a grid line crosses a crease, the snapping leaves a quad with two opposite corners
   * on the crease and the crease along its diagonal between them (a step): its corner nearer
   * the crease (of the other two) moves towards it, StepShare of the way to its closest crease
   * point (on its side: see moveBeside), so that two of the quad's edges run along the crease
   * (the rest of the way left, so that the corner there stays below a straight angle). Kept
   * where none of the vertex's quads is then worse than StepWorst and worse than before.
   * Returns the vertices moved.
   */
  std::vector<int> straightenSteps()
  {
    const int nV = static_cast<int>(mesh_.V.rows());
    const std::vector<char> boundary = quadMeshBoundary(mesh_);
    const VertexQuads around = vertexQuads(mesh_);
    std::vector<char> onCrease(nV, 0), moved(nV, 0);
    for (int v = 0; v < nV; ++v)
    {
      onCrease[v] = liesOnCrease(v);
    }
    std::vector<int> result;
    for (int i = 0; i < static_cast<int>(mesh_.Q.rows()); ++i)
    {
      for (int k = 0; k < 2; ++k)
      {
        const int a = mesh_.Q(i, k), b = mesh_.Q(i, k + 1), c = mesh_.Q(i, (k + 2) % 4),
                  d = mesh_.Q(i, (k + 3) % 4);
        if (!onCrease[a] || !onCrease[c] || onCrease[b] || onCrease[d] || moved[b] || moved[d] ||
          boundary[b] || boundary[d])
        {
          continue;
        }
        const int v = stepCorner(a, b, c, d);
        if (v >= 0 && !onSurfaceBoundary(V_, F_, topo_, mesh_, v) && moveBeside(v, around))
        {
          moved[v] = 1;
          result.push_back(v);
        }
      }
    }
    return result;
  }

private:
  /// Of a quad's corners b and d (a and c on a crease), the one to move onto the crease that
  /// runs from a to c between them: -1 when none (the crease not along the diagonal, or b and d
  /// on one side of it).
  int stepCorner(int a, int b, int c, int d)
  {
    const CreasePoint pb = closestCrease(b), pd = closestCrease(d);
    if (pb.edge < 0 || pd.edge < 0 || atCreaseEnd(pb) || atCreaseEnd(pd))
    {
      return -1;
    }
    const Eigen::Vector3d middle = 0.5 * (mesh_.V.row(a) + mesh_.V.row(c)).transpose();
    const double diagonal = (mesh_.V.row(a) - mesh_.V.row(c)).norm();
    CreasePoint pm;
    closestOnEdge(middle, pb.edge, pm);
    closestOnEdge(middle, pd.edge, pm);
    if (!(pm.distance <= StepDiagonal * diagonal) || side(b, pm) == side(d, pm))
    {
      return -1;
    }
    return pb.distance <= pd.distance ? b : d;
  }

  /// Moves v beside its closest crease point, StepShare of the way there: to the surface's
  /// point closest to that, which must lie within a tenth of the rest of the way of it (so not
  /// across the crease, nor clamped into a triangle too narrow for it). Undone, returning
  /// false, when one of its quads gets worse than StepWorst and worse than it was.
  bool moveBeside(int v, const VertexQuads& around)
  {
    const CreasePoint p = closestCrease(v);
    const int e = p.edge;
    if (e < 0 || topo_.edgeFaceCount[e] != 2)
    {
      return false;
    }
    const Eigen::Vector3d old = mesh_.V.row(v);
    const Eigen::Vector3d onEdge =
      V_.row(topo_.edges(e, 0)) + p.t * (V_.row(topo_.edges(e, 1)) - V_.row(topo_.edges(e, 0)));
    const Eigen::Vector3d target = onEdge + (1.0 - StepShare) * (old - onEdge);
    const SurfaceLocator::Hit hit = surface_.closest(target);
    if (hit.triangle < 0 || !(hit.distance <= 0.1 * (target - onEdge).norm()))
    {
      return false;
    }
    std::vector<double> before;
    for (int j = around.offsets[v]; j < around.offsets[v + 1]; ++j)
    {
      before.push_back(quadWorstOf(surface_, mesh_, around.quads[j]));
    }
    const int oldTriangle = mesh_.vertexTriangle[v], oldPoint = mesh_.vertexPoint[v];
    mesh_.V.row(v) = hit.point;
    mesh_.vertexTriangle[v] = hit.triangle;
    mesh_.vertexPoint[v] = -1;
    for (int j = around.offsets[v]; j < around.offsets[v + 1]; ++j)
    {
      const double now = quadWorstOf(surface_, mesh_, around.quads[j]);
      if (now < StepWorst && now < before[j - around.offsets[v]])
      {
        mesh_.V.row(v) = old;
        mesh_.vertexTriangle[v] = oldTriangle;
        mesh_.vertexPoint[v] = oldPoint;
        return false;
      }
    }
    return true;
  }

  static constexpr double StepShare = 0.7, StepDiagonal = 0.1, StepWorst = 0.05;

  /// #F: 1 for the triangles whose centres lie within the longest reach of a vertex (3 mean
  /// quad edges) of a triangle on a sharp edge, by paths from centre to centre; only the vertices
  /// in them look for a crease.
  std::vector<char> trianglesNearCreases() const
  {
    const int nF = static_cast<int>(F_.rows());
    std::vector<double> distance(nF, std::numeric_limits<double>::infinity());
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (int e = 0; e < topo_.numEdges(); ++e)
    {
      for (int i = 0; sharp_[e] && i < topo_.edgeFaceCount[e] && i < 2; ++i)
      {
        const int f = topo_.edgeFaces(e, i);
        if (distance[f] > 0.0)
        {
          distance[f] = 0.0;
          queue.push({ 0.0, f });
        }
      }
    }
    const double limit = 3.0 * meanEdge_;
    while (!queue.empty())
    {
      const auto [d, f] = queue.top();
      queue.pop();
      if (d > distance[f])
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo_.faceNeighbors(f, k);
        const double next = g >= 0 ? d + (centre(f) - centre(g)).norm() : 0.0;
        if (g >= 0 && next < distance[g] && next <= limit)
        {
          distance[g] = next;
          queue.push({ next, g });
        }
      }
    }
    std::vector<char> near(nF, 0);
    for (int f = 0; f < nF; ++f)
    {
      near[f] = distance[f] <= limit;
    }
    return near;
  }

  Eigen::Vector3d centre(int f) const
  {
    return (V_.row(F_(f, 0)) + V_.row(F_(f, 1)) + V_.row(F_(f, 2))).transpose() / 3.0;
  }

  /// Is p an end point of its edge where a chain of sharp edges ends (one sharp edge there)?
  bool atCreaseEnd(const CreasePoint& p) const
  {
    if (p.t > 0.0 && p.t < 1.0)
    {
      return false;
    }
    return sharpDegree_[topo_.edges(p.edge, p.t == 0.0 ? 0 : 1)] == 1;
  }

  /// Which of the two triangles of p's crease edge quad vertex v lies towards (0 or 1): the one
  /// whose direction into it from the edge (in its plane, across the edge) v is further along.
  int side(int v, const CreasePoint& p) const
  {
    const int e = p.edge;
    if (topo_.edgeFaceCount[e] != 2)
    {
      return 0;
    }
    const Eigen::Vector3d a = V_.row(topo_.edges(e, 0)), b = V_.row(topo_.edges(e, 1));
    const Eigen::Vector3d c = a + p.t * (b - a);
    const Eigen::Vector3d x = Eigen::Vector3d(mesh_.V.row(v)) - c;
    const Eigen::Vector3d t = (b - a).normalized();
    double along[2];
    for (int i = 0; i < 2; ++i)
    {
      Eigen::Vector3d inward = centre(topo_.edgeFaces(e, i)) - a;
      inward -= inward.dot(t) * t;
      along[i] = inward.norm() > 0 ? x.dot(inward.normalized()) : 0.0;
    }
    return along[1] > along[0] ? 1 : 0;
  }

  /// Per vertex, its longest quad edge (at most 3 mean edges): how far a crease its edges cross
  /// can be from it.
  void findReach()
  {
    reach_.assign(mesh_.V.rows(), 0.0);
    for (int i = 0; i < static_cast<int>(mesh_.Q.rows()); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int a = mesh_.Q(i, k), b = mesh_.Q(i, (k + 1) % 4);
        const double length = std::min((mesh_.V.row(a) - mesh_.V.row(b)).norm(), 3.0 * meanEdge_);
        reach_[a] = std::max(reach_[a], length);
        reach_[b] = std::max(reach_[b], length);
      }
    }
  }

  /// Is v on a sharp edge: its input point an end of one, or on a sharp edge of its triangle?
  bool liesOnCrease(int v) const
  {
    const int f = mesh_.vertexTriangle[v];
    const Eigen::Vector3d p = mesh_.V.row(v);
    for (int k = 0; k < 3; ++k)
    {
      const int e = topo_.faceEdges(f, k);
      if (!sharp_[e])
      {
        continue;
      }
      const Eigen::Vector3d a = V_.row(F_(f, k)), b = V_.row(F_(f, (k + 1) % 3));
      const double length = (b - a).norm();
      if (mesh_.vertexPoint[v] == F_(f, k) || mesh_.vertexPoint[v] == F_(f, (k + 1) % 3) ||
        (length > 0 && (p - a).cross(b - a).norm() <= 1e-6 * length * length))
      {
        return true;
      }
    }
    return false;
  }

  /// The closest point of a sharp edge within v's reach (its longest quad edge): a walk over the
  /// triangles near v (within that distance of their bounding spheres), across any edge.
  CreasePoint closestCrease(int v)
  {
    const Eigen::Vector3d p = mesh_.V.row(v);
    CreasePoint best;
    std::vector<int> stack{ mesh_.vertexTriangle[v] }, seen;
    visited_[stack.back()] = 1;
    seen.push_back(stack.back());
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int e = topo_.faceEdges(f, k);
        if (sharp_[e])
        {
          closestOnEdge(p, e, best);
        }
        const int g = topo_.faceNeighbors(f, k);
        if (g >= 0 && !visited_[g] && near(p, g, reach_[v]))
        {
          visited_[g] = 1;
          seen.push_back(g);
          stack.push_back(g);
        }
      }
    }
    for (const int f : seen)
    {
      visited_[f] = 0;
    }
    if (!(best.distance < reach_[v]))
    {
      best = CreasePoint();
    }
    return best;
  }

  /// Is triangle f's bounding sphere within `within` of p?
  bool near(const Eigen::Vector3d& p, int f, double within) const
  {
    const Eigen::Vector3d a = V_.row(F_(f, 0)), b = V_.row(F_(f, 1)), c = V_.row(F_(f, 2));
    const Eigen::Vector3d middle = centre(f);
    const double radius =
      std::max({ (a - middle).norm(), (b - middle).norm(), (c - middle).norm() });
    return (p - middle).norm() - radius < within;
  }

  /// best, or the closest point of edge e to p where it is closer.
  void closestOnEdge(const Eigen::Vector3d& p, int e, CreasePoint& best) const
  {
    const Eigen::Vector3d a = V_.row(topo_.edges(e, 0)), b = V_.row(topo_.edges(e, 1));
    const double length2 = (b - a).squaredNorm();
    const double t = length2 > 0 ? std::clamp((p - a).dot(b - a) / length2, 0.0, 1.0) : 0.0;
    const double distance = (a + t * (b - a) - p).norm();
    if (distance < best.distance)
    {
      best = { distance, e, t };
    }
  }

  /// Moves the vertices onto their targets (not those already there); then, quad by quad from a
  /// list of the quads around them, undoes the longest move of a quad left facing against the
  /// surface or with a corner below 0.05 (quadWorstOf), and worse than it was, and looks at the
  /// quads around the vertex put back again. Returns the vertices moved, in order.
  std::vector<int> apply(const std::vector<CreasePoint>& target)
  {
    const int nV = static_cast<int>(mesh_.V.rows());
    const VertexQuads around = vertexQuads(mesh_);
    std::vector<double> before(mesh_.Q.rows(), 1.0);
    const Eigen::MatrixX3d oldV = mesh_.V;
    const std::vector<int> oldTriangle = mesh_.vertexTriangle, oldPoint = mesh_.vertexPoint;
    std::vector<char> moved(nV, 0), listed(mesh_.Q.rows(), 0);
    std::deque<int> check;
    const auto list = [&](int v) {
      for (int j = around.offsets[v]; j < around.offsets[v + 1]; ++j)
      {
        if (!listed[around.quads[j]])
        {
          listed[around.quads[j]] = 1;
          check.push_back(around.quads[j]);
        }
      }
    };
    for (int v = 0; v < nV; ++v)
    {
      if (target[v].edge >= 0 && target[v].distance > 1e-12 * meanEdge_)
      {
        moved[v] = 1;
        list(v);
      }
    }
    for (const int i : check)
    {
      before[i] = quadWorstOf(surface_, mesh_, i);
    }
    for (int v = 0; v < nV; ++v)
    {
      if (moved[v])
      {
        moveOnto(v, target[v]);
      }
    }
    constexpr double Worst = 0.05;
    while (!check.empty())
    {
      const int i = check.front();
      check.pop_front();
      listed[i] = 0;
      const double now = quadWorstOf(surface_, mesh_, i);
      int undo = -1;
      for (int k = 0; k < 4 && now < Worst && now < before[i]; ++k)
      {
        const int v = mesh_.Q(i, k);
        if (moved[v] && (undo < 0 || target[v].distance > target[undo].distance))
        {
          undo = v;
        }
      }
      if (undo >= 0)
      {
        mesh_.V.row(undo) = oldV.row(undo);
        mesh_.vertexTriangle[undo] = oldTriangle[undo];
        mesh_.vertexPoint[undo] = oldPoint[undo];
        moved[undo] = 0;
        list(undo);
      }
    }
    std::vector<int> result;
    for (int v = 0; v < nV; ++v)
    {
      if (moved[v])
      {
        result.push_back(v);
      }
    }
    return result;
  }

  /// v onto p, in the triangle of p's edge on v's side.
  void moveOnto(int v, const CreasePoint& p)
  {
    const int e = p.edge;
    const int a = topo_.edges(e, 0), b = topo_.edges(e, 1);
    const int onSide = side(v, p);
    mesh_.V.row(v) = V_.row(a) + p.t * (V_.row(b) - V_.row(a));
    mesh_.vertexTriangle[v] = topo_.edgeFaces(e, topo_.edgeFaceCount[e] == 2 ? onSide : 0);
    mesh_.vertexPoint[v] = p.t == 0.0 ? a : (p.t == 1.0 ? b : -1);
  }

  const Eigen::MatrixX3d& V_;
  const Eigen::MatrixX3i& F_;
  const MeshTopology& topo_;
  const std::vector<char>& sharp_;
  const SurfaceLocator& surface_;
  QuadMesh& mesh_;
  std::vector<char> visited_;
  double meanEdge_ = 0.0;
  std::vector<double> reach_;
  std::vector<int> sharpDegree_; ///< #V of the input: sharp edges at each point
};
}

namespace
{
/// Is there anything to snap: quads, and a sharp edge?
bool anyCrease(const QuadMesh& mesh, const std::vector<char>& sharp)
{
  return mesh.Q.rows() > 0 && std::find(sharp.begin(), sharp.end(), 1) != sharp.end();
}
}

std::vector<int> snapToCreases(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const std::vector<char>& sharp, const SurfaceLocator& surface,
  QuadMesh& mesh)
{
  return anyCrease(mesh, sharp) ? Snapper(V, F, topo, sharp, surface, mesh).run()
                                : std::vector<int>();
}

std::vector<int> straightenCreaseSteps(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const std::vector<char>& sharp, const SurfaceLocator& surface,
  QuadMesh& mesh)
{
  return anyCrease(mesh, sharp) ? Snapper(V, F, topo, sharp, surface, mesh).straightenSteps()
                                : std::vector<int>();
}
}
