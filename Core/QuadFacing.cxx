// QuadFacing.cxx: quadFacing, turnedQuads and repairFacing.
#include "QuadFacing.h"

#include "BoundaryPaths.h"
#include "Parallel.h"
#include "QuadMeshAdjacency.h"
#include "ScaledJacobian.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

Eigen::Vector3d corner(const QuadMesh& mesh, int i, int k)
{
  return mesh.V.row(mesh.Q(i, k)).transpose();
}

/// A point of the surface a vertex may move to.
struct Candidate
{
  Eigen::Vector3d point;
  int triangle;
  int surfacePoint; ///< the input point it is, or -1
};

/// The moves of repairFacing: the quads around each vertex, which vertices may move, and the
/// search for the best point of each.
class FacingRepairer
{
public:
  FacingRepairer(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
    const SurfaceLocator& surface, QuadFacingMemo* facings, QuadMesh& mesh)
    : V_(V)
    , F_(F)
    , topo_(topo)
    , surface_(surface)
    , ownFacings_(surface)
    , facings_(facings ? *facings : ownFacings_)
    , mesh_(mesh)
    , boundary_(V, F, topo, BoundaryCornerTurn)
  {
    collectVertexQuads();
    findFixed();
    budget_ = static_cast<long long>(Budget) * mesh.Q.rows() + 10 * BudgetBase;
  }

  /// The quads facing against the surface or turned inside out.
  std::vector<int> badQuads() const
  {
    std::vector<int> list;
    for (int i = 0; i < static_cast<int>(mesh_.Q.rows()); ++i)
    {
      if (quality(i) <= 0)
      {
        list.push_back(i);
      }
    }
    return list;
  }

  /// The vertices that may move of the quads and of those within `rings` quad rings of them.
  std::vector<int> region(const std::vector<int>& quads, int rings) const
  {
    const std::vector<char> in = verticesNear(mesh_, quads, rings);
    std::vector<int> list;
    for (int v = 0; v < static_cast<int>(in.size()); ++v)
    {
      if (in[v] && !fixed_[v])
      {
        list.push_back(v);
      }
    }
    return list;
  }

  /// Whether the work done (quad measurements) is within the budget: an average of
  /// FacingRepair::budget measurements a quad.
  bool withinBudget() const { return evaluations_ <= budget_; }

  long long evaluations() const { return evaluations_; }

  /// Moves v to the candidate point that makes the worst of its quads best, if that is better
  /// by a margin, v's quads are not all fine already and no more of them face against the
  /// surface: a corner turned inside out leaves a valid mesh, a quad against the surface does
  /// not (VTK's sphere source at 300 x 150, 6,500 quads: a quad with a corner at scaled Jacobian
  /// about -0.3 beside a split pole's quarter was traded for one facing against it at cosine
  /// -0.13); true when it moved.
  bool improve(int v)
  {
    if (fixed_[v])
    {
      return false;
    }
    const Score now = vertexScore(v);
    if (now.worst >= Fine)
    {
      return false;
    }
    const Eigen::Vector3d old = mesh_.V.row(v);
    const int oldTriangle = mesh_.vertexTriangle[v];
    double best = now.worst + 1e-3;
    const Candidate* chosen = nullptr;
    const std::vector<Candidate> candidates = candidatesOf(v);
    for (const Candidate& c : candidates)
    {
      // scored on its own triangle, which quadFacing reads where another component is nearer
      mesh_.V.row(v) = c.point.transpose();
      mesh_.vertexTriangle[v] = c.triangle;
      if (vertexShape(v) <= best)
      {
        continue; // the score is at most the shape's
      }
      const Score score = vertexScore(v);
      if (score.worst > best && score.against <= now.against)
      {
        best = score.worst;
        chosen = &c;
      }
    }
    mesh_.V.row(v) = old.transpose();
    mesh_.vertexTriangle[v] = oldTriangle;
    if (!chosen)
    {
      return false;
    }
    mesh_.V.row(v) = chosen->point.transpose();
    mesh_.vertexTriangle[v] = chosen->triangle;
    mesh_.vertexPoint[v] = chosen->surfacePoint;
    if (places_[v].loop >= 0)
    {
      places_[v] = boundary_.placeOf(chosen->point, chosen->triangle, chosen->surfacePoint);
      fixed_[v] = places_[v].loop < 0;
    }
    return true;
  }

private:
  /// A vertex whose quads all score at least this is left where it is.
  static constexpr double Fine = 0.2;
  /// The work budget: quad measurements per quad of the mesh, plus ten times this many. Repairs
  /// that succeed take 1 to 10 per quad; one that cannot succeed stops there, in about the time
  /// the extraction took.
  static constexpr int Budget = 40;
  static constexpr int BudgetBase = 10000;
  /// A boundary point where the surface's boundary turns by more than this (radians) is a corner:
  /// a quad vertex there stays, and none slides past it.
  static constexpr double BoundaryCornerTurn = Pi / 6;
  long long budget_ = 0;

  /// quadWorstOf, counted against the budget.
  double quality(int i) const
  {
    ++evaluations_;
    return facings_.worst(mesh_, i);
  }

  /// Of v's quads: the worst quality, and how many face against the surface (quadFacing below
  /// 0), each quad measured once.
  struct Score
  {
    double worst = 1.0;
    int against = 0;
  };
  Score vertexScore(int v) const
  {
    Score s;
    for (int j = offsets_[v]; j < offsets_[v + 1]; ++j)
    {
      const int i = quadsOf_[j];
      ++evaluations_;
      const double facing = facings_.facing(mesh_, i);
      s.worst = std::min({ s.worst, facing, quadScaledJacobian(mesh_.V, mesh_.Q, i) });
      s.against += facing < 0.0;
    }
    return s;
  }

  /// The smallest quadScaledJacobian of v's quads (an upper bound of vertexScore).
  double vertexShape(int v) const
  {
    double worst = 1.0;
    for (int j = offsets_[v]; j < offsets_[v + 1]; ++j)
    {
      worst = std::min(worst, quadScaledJacobian(mesh_.V, mesh_.Q, quadsOf_[j]));
    }
    return worst;
  }

  void collectVertexQuads()
  {
    VertexQuads adjacency = vertexQuads(mesh_);
    offsets_ = std::move(adjacency.offsets);
    quadsOf_ = std::move(adjacency.quads);
  }

  /// The vertices that stay: those in no triangle, on the quad mesh's boundary but not the
  /// surface's or the other way round, and on the surface's corners. Those on both boundaries
  /// elsewhere slide along the surface's (places_).
  void findFixed()
  {
    fixed_ = quadMeshBoundary(mesh_);
    places_.assign(fixed_.size(), BoundaryPaths::Place());
    for (int v = 0; v < static_cast<int>(fixed_.size()); ++v)
    {
      const int t = mesh_.vertexTriangle[v];
      const bool onSurface = t >= 0 && t < F_.rows() && onSurfaceBoundary(V_, F_, topo_, mesh_, v);
      if (fixed_[v] && onSurface)
      {
        places_[v] = boundary_.placeOf(mesh_.V.row(v).transpose(), t, mesh_.vertexPoint[v]);
        fixed_[v] = places_[v].loop < 0;
        continue;
      }
      fixed_[v] |= t < 0 || t >= F_.rows() || onSurface;
    }
  }

  /// The longest edge of v's quads.
  double reach(int v) const
  {
    double longest = 0.0;
    for (int j = offsets_[v]; j < offsets_[v + 1]; ++j)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int i = quadsOf_[j];
        longest = std::max(longest, (corner(mesh_, i, k) - corner(mesh_, i, (k + 1) % 4)).norm());
      }
    }
    return longest;
  }

  /// The triangles connected to v's own (across edges) with a point within r of p, at most 256.
  std::vector<int> trianglesNear(int v, const Eigen::Vector3d& p, double r) const
  {
    std::vector<int> list{ mesh_.vertexTriangle[v] };
    std::vector<char> seen(F_.rows(), 0);
    seen[list[0]] = 1;
    for (std::size_t n = 0; n < list.size() && list.size() < 256; ++n)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo_.faceNeighbors(list[n], k);
        if (g >= 0 && !seen[g])
        {
          seen[g] = 1;
          if ((closestIn(g, p) - p).norm() <= r)
          {
            list.push_back(g);
          }
        }
      }
    }
    return list;
  }

  Eigen::Vector3d closestIn(int t, const Eigen::Vector3d& p) const
  {
    return surface_.closestIn(t, p);
  }

  /// The point of the listed triangles closest to p, as a candidate.
  Candidate projectOnto(const std::vector<int>& triangles, const Eigen::Vector3d& p) const
  {
    Candidate best{ p, -1, -1 };
    double distance = std::numeric_limits<double>::infinity();
    for (const int t : triangles)
    {
      if (surface_.lowerBound(t, p) >= distance)
      {
        continue;
      }
      const Eigen::Vector3d q = closestIn(t, p);
      if ((q - p).norm() < distance)
      {
        distance = (q - p).norm();
        best = { q, t, -1 };
      }
    }
    return best;
  }

  std::vector<Candidate> candidatesOf(int v) const;

  const Eigen::MatrixX3d& V_;
  const Eigen::MatrixX3i& F_;
  const MeshTopology& topo_;
  const SurfaceLocator& surface_;
  /// badQuads passes over every quad, few of them moved since the last: the caller's memo when
  /// given (the quads as it measured them before), else one of its own
  QuadFacingMemo ownFacings_;
  QuadFacingMemo& facings_;
  QuadMesh& mesh_;
  std::vector<int> offsets_; ///< #V + 1: where each vertex's quads start in quadsOf_
  std::vector<int> quadsOf_;
  const BoundaryPaths boundary_;
  std::vector<char> fixed_;
  std::vector<BoundaryPaths::Place> places_; ///< per vertex sliding along the boundary
  mutable long long evaluations_ = 0; ///< quality() calls, for the budget
};

/// Where v may go: points around it in its tangent plane at a few distances up to its longest
/// quad edge, put on the surface; the input points near it; the points of creases (edges sharper
/// than 60 degrees) nearest to it; the centre of its quads, put on the surface.
std::vector<Candidate> FacingRepairer::candidatesOf(int v) const
{
  const Eigen::Vector3d p = mesh_.V.row(v);
  const double r = reach(v);
  std::vector<Candidate> list;
  if (!(r > 0))
  {
    return list;
  }
  if (places_[v].loop >= 0)
  {
    for (const BoundaryPaths::Stop& s :
      boundary_.slides(places_[v], p, { 0.1 * r, 0.25 * r, 0.5 * r, 0.75 * r }))
    {
      list.push_back({ s.point, s.triangle, s.surfacePoint });
    }
    return list;
  }
  const std::vector<int> near = trianglesNear(v, p, r);
  Eigen::Vector3d n = surface_.normal(mesh_.vertexTriangle[v]);
  if (!(n.norm() > 0))
  {
    n = surface_.normal(std::max(0, surface_.closest(p).triangle));
  }
  if (!(n.norm() > 0))
  {
    return list; // no triangle of positive area
  }
  const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  for (const double radius : { 0.1, 0.25, 0.5, 0.75 })
  {
    for (int d = 0; d < 12; ++d)
    {
      const double a = 2 * Pi * d / 12;
      list.push_back(projectOnto(near, p + radius * r * (std::cos(a) * e1 + std::sin(a) * e2)));
    }
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int j = offsets_[v]; j < offsets_[v + 1]; ++j)
  {
    for (int k = 0; k < 4; ++k)
    {
      centre += corner(mesh_, quadsOf_[j], k) / (4.0 * (offsets_[v + 1] - offsets_[v]));
    }
  }
  list.push_back(projectOnto(near, centre));
  const double creaseCos = std::cos(Pi / 3);
  for (const int t : near)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int point = F_(t, k);
      if ((V_.row(point).transpose() - p).norm() <= r)
      {
        list.push_back({ V_.row(point).transpose(), t, point });
      }
      const int g = topo_.faceNeighbors(t, k);
      if (g > t && surface_.normal(t).dot(surface_.normal(g)) < creaseCos)
      {
        const Eigen::Vector3d q =
          closestOnSegment(p, V_.row(point).transpose(), V_.row(F_(t, (k + 1) % 3)).transpose());
        list.push_back({ q, t, -1 });
      }
    }
  }
  return list;
}
}

double quadWorstOf(const SurfaceLocator& surface, const QuadMesh& mesh, int i)
{
  return std::min(quadFacing(surface, mesh, i), quadScaledJacobian(mesh.V, mesh.Q, i));
}

namespace
{
/// The facing (cosine) at most of another component's sheet that a quad may be lifted off: one
/// facing back, as a hollow part's other wall does (-1); not one that crosses the quad's sheet, as
/// a teapot's handle does its body (a quad there at -0.02, which the repairs turn).
constexpr double OppositeSheet = -0.5;

/// A quad's centre, unit normal (zero for a quad of zero area) and mean edge.
struct QuadFrame
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double edge = 0.0;
};

QuadFrame frameOf(const QuadMesh& mesh, int i)
{
  QuadFrame q;
  for (int k = 0; k < 4; ++k)
  {
    q.centre += corner(mesh, i, k) / 4.0;
    q.edge += (corner(mesh, i, k) - corner(mesh, i, (k + 1) % 4)).norm() / 4.0;
  }
  const Eigen::Vector3d n = quadAreaVector(mesh.V, mesh.Q, i);
  if (n.norm() > 0)
  {
    q.normal = n.normalized();
  }
  return q;
}

/// The triangle (of `surface`) vertex v lies in, or -1.
int vertexTriangleOf(const SurfaceLocator& surface, const QuadMesh& mesh, int v)
{
  const int t = v < static_cast<int>(mesh.vertexTriangle.size()) ? mesh.vertexTriangle[v] : -1;
  return t < surface.numTriangles() ? t : -1;
}

/// The triangle (of `surface`) corner k of quad i lies in, or -1.
int cornerTriangle(const SurfaceLocator& surface, const QuadMesh& mesh, int i, int k)
{
  return vertexTriangleOf(surface, mesh, mesh.Q(i, k));
}

/// Whether the triangles `nearest` (to quad i's centre) all lie on components that none of the
/// quad's corners lies on; false where the surface's triangles are not labelled.
bool nearerAnotherComponent(
  const SurfaceLocator& surface, const QuadMesh& mesh, int i, const std::vector<int>& nearest)
{
  if (nearest.empty() || surface.component(nearest.front()) < 0)
  {
    return false;
  }
  for (const int t : nearest)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int own = cornerTriangle(surface, mesh, i, k);
      if (own >= 0 && surface.component(own) == surface.component(t))
      {
        return false;
      }
    }
  }
  return true;
}

/// The facing of a quad against the triangles its corners lie in: the smallest cosine (1 when
/// no corner has a triangle).
double facingOwnTriangles(
  const SurfaceLocator& surface, const QuadMesh& mesh, int i, const Eigen::Vector3d& normal)
{
  double facing = 1.0;
  for (int k = 0; k < 4; ++k)
  {
    const int t = cornerTriangle(surface, mesh, i, k);
    if (t >= 0)
    {
      facing = std::min(facing, normal.dot(surface.normal(t)));
    }
  }
  return facing;
}

/// How far a quad's centre lies below its own sheet: half its mean depth below its corners'
/// tangent planes (on a sphere the sheet under the centre lies half as deep as the centre); 0
/// where no corner has a triangle or the centre lies above them.
double depthBelowOwnSheet(
  const SurfaceLocator& surface, const QuadMesh& mesh, int i, const QuadFrame& q)
{
  double depth = 0.0;
  int corners = 0;
  for (int k = 0; k < 4; ++k)
  {
    const int t = cornerTriangle(surface, mesh, i, k);
    if (t >= 0)
    {
      depth += (corner(mesh, i, k) - q.centre).dot(surface.normal(t));
      ++corners;
    }
  }
  return corners > 0 ? std::max(0.0, 0.5 * depth / corners) : 0.0;
}

/// quadFacing's measure against the surface closest to the centre (over every component), and
/// whether the quad is one liftOffOtherComponents lifts: that surface faces back at it (at most
/// OppositeSheet) and lies on other components than its corners, while the quad faces as its
/// corners' triangles do, its centre lies below them, and lifted onto its own sheet along the
/// quad's normal it faces the surface closest to it there (the walls of a hollow part closer than
/// the quad bulges). Elsewhere (components that cross, as a teapot's spout and body) the quad is
/// measured as closest, for the repairs to move its corners.
std::pair<double, bool> facingClosest(
  const SurfaceLocator& surface, const QuadMesh& mesh, int i, const QuadFrame& q)
{
  const std::vector<int> nearest = surface.nearlyClosest(q.centre, 1e-3 * q.edge);
  double facing = 1.0;
  for (const int t : nearest)
  {
    facing = std::min(facing, q.normal.dot(surface.normal(t)));
  }
  if (!(facing <= OppositeSheet) || !nearerAnotherComponent(surface, mesh, i, nearest) ||
    facingOwnTriangles(surface, mesh, i, q.normal) <= 0)
  {
    return { facing, false };
  }
  const double depth = depthBelowOwnSheet(surface, mesh, i, q);
  if (!(depth > 0))
  {
    return { facing, false };
  }
  // the centre lifted onto its own sheet faces the surface closest to it there
  const Eigen::Vector3d lifted = q.centre + depth * q.normal;
  for (const int t : surface.nearlyClosest(lifted, 1e-3 * q.edge))
  {
    if (!(q.normal.dot(surface.normal(t)) > 0))
    {
      return { facing, false };
    }
  }
  return { facing, true };
}
}

double quadFacing(const SurfaceLocator& surface, const QuadMesh& mesh, int i)
{
  const QuadFrame q = frameOf(mesh, i);
  if (!(q.normal.squaredNorm() > 0))
  {
    return -1.0;
  }
  const auto [facing, liftable] = facingClosest(surface, mesh, i, q);
  return liftable ? facingOwnTriangles(surface, mesh, i, q.normal) : facing;
}

namespace
{
/// Whether quad i is one liftOffOtherComponents lifts (facingClosest's flag).
bool liftable(const SurfaceLocator& surface, const QuadMesh& mesh, int i)
{
  const QuadFrame q = frameOf(mesh, i);
  return q.normal.squaredNorm() > 0 && facingClosest(surface, mesh, i, q).second;
}
}

std::vector<int> quadsToLift(const SurfaceLocator& surface, const QuadMesh& mesh)
{
  std::vector<int> list;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    if (liftable(surface, mesh, i))
    {
      list.push_back(i);
    }
  }
  return list;
}

SheetLift liftOffOtherComponents(const SurfaceLocator& surface, QuadMesh& mesh)
{
  std::vector<double> lift(static_cast<std::size_t>(mesh.V.rows()), 0.0);
  for (const int i : quadsToLift(surface, mesh))
  {
    const double depth = depthBelowOwnSheet(surface, mesh, i, frameOf(mesh, i));
    for (int k = 0; k < 4; ++k)
    {
      lift[mesh.Q(i, k)] = std::max(lift[mesh.Q(i, k)], depth);
    }
  }
  SheetLift result;
  std::vector<char> moved(lift.size(), 0);
  for (int v = 0; v < static_cast<int>(lift.size()); ++v)
  {
    const int t = vertexTriangleOf(surface, mesh, v);
    if (lift[v] > 0 && t >= 0)
    {
      mesh.V.row(v) += lift[v] * surface.normal(t).transpose();
      mesh.vertexPoint[v] = -1; // off the input: on none of its points (its triangle kept)
      moved[v] = 1;
      ++result.liftedVertices;
    }
  }
  // whether a quad is to lift depends on its own corners only: only those with a corner moved
  // can have changed
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    const bool touched =
      moved[mesh.Q(i, 0)] || moved[mesh.Q(i, 1)] || moved[mesh.Q(i, 2)] || moved[mesh.Q(i, 3)];
    result.remaining += touched && liftable(surface, mesh, i);
  }
  return result;
}

std::vector<int> turnedQuads(const SurfaceLocator& surface, const QuadMesh& mesh)
{
  std::vector<int> list;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    if (quadFacing(surface, mesh, i) <= 0)
    {
      list.push_back(i);
    }
  }
  return list;
}

std::vector<int> turnedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const QuadMesh& q)
{
  return turnedQuads(SurfaceLocator(V, F), q);
}

Eigen::Matrix<double, 4, 3> QuadFacingMemo::cornersOf(const QuadMesh& mesh, int i)
{
  Eigen::Matrix<double, 4, 3> at;
  for (int k = 0; k < 4; ++k)
  {
    at.row(k) = mesh.V.row(mesh.Q(i, k));
  }
  return at;
}

bool QuadFacingMemo::stale(const QuadMesh& mesh, int i)
{
  const std::size_t nQ = static_cast<std::size_t>(mesh.Q.rows());
  if (facing_.size() != nQ)
  {
    corners_.resize(nQ);
    facing_.assign(nQ, std::numeric_limits<double>::quiet_NaN());
  }
  return std::isnan(facing_[i]) || cornersOf(mesh, i) != corners_[i];
}

double QuadFacingMemo::facing(const QuadMesh& mesh, int i)
{
  if (this->stale(mesh, i))
  {
    corners_[i] = cornersOf(mesh, i);
    facing_[i] = quadFacing(surface_, mesh, i);
  }
  return facing_[i];
}

double QuadFacingMemo::worst(const QuadMesh& mesh, int i)
{
  return std::min(this->facing(mesh, i), quadScaledJacobian(mesh.V, mesh.Q, i));
}

std::vector<int> QuadFacingMemo::turned(const QuadMesh& mesh)
{
  std::vector<int> stale;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    if (this->stale(mesh, i))
    {
      stale.push_back(i);
    }
  }
  // each quad's own entries written: the same figures on any number of threads
  parallelFor(static_cast<int>(stale.size()), threads_, [&](int begin, int end, int) {
    for (int j = begin; j < end; ++j)
    {
      corners_[stale[j]] = cornersOf(mesh, stale[j]);
      facing_[stale[j]] = quadFacing(surface_, mesh, stale[j]);
    }
  });
  std::vector<int> list;
  for (int i = 0; i < static_cast<int>(mesh.Q.rows()); ++i)
  {
    if (facing_[i] <= 0)
    {
      list.push_back(i);
    }
  }
  return list;
}

FacingRepair repairFacing(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const SurfaceLocator& surface, QuadMesh& mesh, QuadFacingMemo* facings)
{
  FacingRepairer repairer(V, F, topo, surface, facings, mesh);
  std::vector<int> bad = repairer.badQuads();
  FacingRepair r;
  r.before = r.after = static_cast<int>(bad.size());
  if (bad.empty())
  {
    return r;
  }
  const QuadMesh kept = mesh;
  std::vector<char> moved(mesh.V.rows(), 0);
  for (int rings = 0; rings < 4 && !bad.empty() && repairer.withinBudget(); ++rings)
  {
    const std::vector<int> region = repairer.region(bad, rings);
    for (int sweep = 0; sweep < 8; ++sweep)
    {
      bool any = false;
      for (const int v : region)
      {
        if (!repairer.withinBudget())
        {
          break;
        }
        if (repairer.improve(v))
        {
          moved[v] = 1;
          any = true;
        }
      }
      if (!any)
      {
        break;
      }
    }
    bad = repairer.badQuads();
  }
  r.after = static_cast<int>(bad.size());
  r.measurements = repairer.evaluations();
  if (r.after > r.before)
  {
    mesh = kept;
    r.after = r.before;
    return r;
  }
  r.movedVertices = static_cast<int>(std::count(moved.begin(), moved.end(), 1));
  return r;
}

}
