// SurfaceLocator.cxx: closest points on segments, triangles and a whole surface.
#include "SurfaceLocator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadcover
{

Eigen::Vector3d closestOnSegment(
  const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const Eigen::Vector3d d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return a + t * d;
}

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
  Eigen::Vector3d best = closestOnSegment(p, a, b);
  for (const Eigen::Vector3d& q : { closestOnSegment(p, b, c), closestOnSegment(p, c, a) })
  {
    if ((q - p).squaredNorm() < (best - p).squaredNorm())
    {
      best = q;
    }
  }
  return best;
}

SurfaceLocator::SurfaceLocator(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
  : V_(V)
  , F_(F)
{
  const int nF = static_cast<int>(F.rows());
  normals_ = Eigen::MatrixX3d::Zero(nF, 3);
  centres_ = Eigen::MatrixX3d::Zero(nF, 3);
  // no bound for a triangle of zero area (it is not in the grid; a caller may still ask)
  radii_ = Eigen::VectorXd::Constant(nF, std::numeric_limits<double>::infinity());
  std::vector<int> listed;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  double edges = 0.0;
  for (int t = 0; t < nF; ++t)
  {
    const Eigen::Vector3d a = V.row(F(t, 0)), b = V.row(F(t, 1)), c = V.row(F(t, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0) || !std::isfinite(n.norm()))
    {
      continue;
    }
    normals_.row(t) = n.normalized().transpose();
    const Eigen::Vector3d centre = (a + b + c) / 3.0;
    centres_.row(t) = centre.transpose();
    radii_[t] = std::max({ (a - centre).norm(), (b - centre).norm(), (c - centre).norm() });
    listed.push_back(t);
    lo = lo.cwiseMin(a).cwiseMin(b).cwiseMin(c);
    hi = hi.cwiseMax(a).cwiseMax(b).cwiseMax(c);
    edges += (b - a).norm() + (c - b).norm() + (a - c).norm();
  }
  if (listed.empty())
  {
    offsets_.assign(2, 0);
    return;
  }
  origin_ = lo;
  const Eigen::Vector3d extent = hi - lo;
  cell_ = std::max(edges / (3.0 * listed.size()), 1e-300);
  const double cells = static_cast<double>(4 * listed.size() + 64);
  // at most about 4 cells a triangle, and at most 16 listings a triangle (large triangles)
  for (int attempt = 0;; ++attempt)
  {
    const Eigen::Vector3d n = (extent / cell_).array().ceil().max(1.0);
    if (n.prod() > cells)
    {
      cell_ *= std::cbrt(n.prod() / cells) * 1.01;
      continue;
    }
    size_ = n.cast<int>();
    std::size_t listings = 0;
    for (const int t : listed)
    {
      Eigen::Vector3i a = cellOf(V.row(F(t, 0))), b = a;
      for (int k = 1; k < 3; ++k)
      {
        a = a.cwiseMin(cellOf(V.row(F(t, k))));
        b = b.cwiseMax(cellOf(V.row(F(t, k))));
      }
      listings += static_cast<std::size_t>((b - a + Eigen::Vector3i::Ones()).prod());
    }
    if (listings <= 16 * listed.size() || attempt >= 20)
    {
      break;
    }
    cell_ *= 2.0;
  }
  const int numCells = size_.prod();
  offsets_.assign(static_cast<std::size_t>(numCells) + 1, 0);
  for (int pass = 0; pass < 2; ++pass)
  {
    std::vector<int> fill(offsets_.begin(), offsets_.end() - 1);
    for (const int t : listed)
    {
      Eigen::Vector3i a = cellOf(V.row(F(t, 0))), b = a;
      for (int k = 1; k < 3; ++k)
      {
        a = a.cwiseMin(cellOf(V.row(F(t, k))));
        b = b.cwiseMax(cellOf(V.row(F(t, k))));
      }
      for (int z = a.z(); z <= b.z(); ++z)
        for (int y = a.y(); y <= b.y(); ++y)
          for (int x = a.x(); x <= b.x(); ++x)
          {
            if (pass == 0)
            {
              ++offsets_[cellIndex(x, y, z) + 1];
            }
            else
            {
              triangles_[fill[cellIndex(x, y, z)]++] = t;
            }
          }
    }
    if (pass == 0)
    {
      for (int c = 0; c < numCells; ++c)
      {
        offsets_[c + 1] += offsets_[c];
      }
      triangles_.resize(offsets_.back());
    }
  }
}

Eigen::Vector3d SurfaceLocator::closestIn(int t, const Eigen::Vector3d& p) const
{
  return closestOnTriangle(p, V_.row(F_(t, 0)), V_.row(F_(t, 1)), V_.row(F_(t, 2)));
}

Eigen::Vector3i SurfaceLocator::cellOf(const Eigen::Vector3d& p) const
{
  Eigen::Vector3i c;
  for (int d = 0; d < 3; ++d)
  {
    const double x = std::floor((p[d] - origin_[d]) / cell_);
    c[d] = static_cast<int>(std::clamp(std::isfinite(x) ? x : 0.0, 0.0, size_[d] - 1.0));
  }
  return c;
}

template <typename Visit>
bool SurfaceLocator::visitRing(const Eigen::Vector3i& centre, int ring, Visit&& visit) const
{
  if (ring > size_.maxCoeff())
  {
    return false; // every cell visited
  }
  const Eigen::Vector3i lo = (centre.array() - ring).max(0);
  const Eigen::Vector3i hi = (centre.array() + ring).min(size_.array() - 1);
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x)
      {
        // only the shell: the inside was visited by the smaller rings
        const int shell = std::max({ std::abs(x - centre.x()), std::abs(y - centre.y()),
          std::abs(z - centre.z()) });
        if (shell != ring)
        {
          continue;
        }
        const int c = cellIndex(x, y, z);
        for (int j = offsets_[c]; j < offsets_[c + 1]; ++j)
        {
          visit(triangles_[j]);
        }
      }
  return true;
}

double SurfaceLocator::beyondRing(
  const Eigen::Vector3d& p, const Eigen::Vector3i& centre, int ring) const
{
  double bound = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d)
  {
    if (centre[d] - ring > 0)
    {
      bound = std::min(bound, p[d] - (origin_[d] + (centre[d] - ring) * cell_));
    }
    if (centre[d] + ring < size_[d] - 1)
    {
      bound = std::min(bound, origin_[d] + (centre[d] + ring + 1) * cell_ - p[d]);
    }
  }
  return std::max(bound, 0.0);
}

SurfaceLocator::Hit SurfaceLocator::closest(const Eigen::Vector3d& p) const
{
  Hit hit;
  const Eigen::Vector3i centre = cellOf(p);
  for (int ring = 0; visitRing(centre, ring, [&](int t) {
         if (beyond(t, p, hit.distance))
         {
           return;
         }
         const Eigen::Vector3d q = closestIn(t, p);
         const double d = (q - p).norm();
         if (d < hit.distance || (d == hit.distance && t < hit.triangle))
         {
           hit = { q, t, d };
         }
       });
       ++ring)
  {
    if (hit.distance <= beyondRing(p, centre, ring))
    {
      break;
    }
  }
  return hit;
}

std::vector<int> SurfaceLocator::nearlyClosest(const Eigen::Vector3d& p, double slack) const
{
  // one search: every triangle within the closest distance so far plus the slack is kept, and
  // the ones that the closest found later leaves out are dropped at the end
  std::vector<std::pair<double, int>> near;
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Vector3i centre = cellOf(p);
  for (int ring = 0; visitRing(centre, ring, [&](int t) {
         if (beyond(t, p, best + slack))
         {
           return;
         }
         const double d = (closestIn(t, p) - p).norm();
         if (d <= best + slack)
         {
           near.emplace_back(d, t);
           best = std::min(best, d);
         }
       });
       ++ring)
  {
    if (best + slack <= beyondRing(p, centre, ring))
    {
      break;
    }
  }
  std::vector<int> list;
  for (const auto& [d, t] : near)
  {
    if (d <= best + slack)
    {
      list.push_back(t);
    }
  }
  std::sort(list.begin(), list.end());
  list.erase(std::unique(list.begin(), list.end()), list.end());
  return list;
}

}
