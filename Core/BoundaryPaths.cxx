// BoundaryPaths.cxx: the boundary loops as paths between corners.
#include "BoundaryPaths.h"

#include "FrameField.h"
#include "SurfaceLocator.h"

#include <cmath>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// The triangle whose boundary edge joins a and b (either way), or -1.
int boundaryFace(const Eigen::MatrixX3i& F, const MeshTopology& topo, int a, int b)
{
  for (int j = topo.ringOffsets[a]; j < topo.ringOffsets[a + 1]; ++j)
  {
    const int f = topo.ringFaces[j];
    for (int k = 0; k < 3; ++k)
    {
      const int p = F(f, k), q = F(f, (k + 1) % 3);
      if (topo.faceNeighbors(f, k) < 0 && ((p == a && q == b) || (p == b && q == a)))
      {
        return f;
      }
    }
  }
  return -1;
}
}

BoundaryPaths::BoundaryPaths(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo, double cornerTurn)
  : V_(V)
  , F_(F)
  , topo_(topo)
  , loopOf_(V.rows(), -1)
  , placeInLoop_(V.rows(), -1)
  , corner_(V.rows(), 0)
{
  const int loops = static_cast<int>(topo.boundaryLoops.size());
  if (loops == 0)
  {
    return;
  }
  edgeFace_.resize(loops);
  for (int l = 0; l < loops; ++l)
  {
    const std::vector<int>& loop = topo.boundaryLoops[l];
    const int n = static_cast<int>(loop.size());
    for (int i = 0; i < n; ++i)
    {
      if (loopOf_[loop[i]] >= 0)
      {
        corner_[loop[i]] = 1; // on the boundary twice: no slide passes it
      }
      loopOf_[loop[i]] = l;
      placeInLoop_[loop[i]] = i;
      edgeFace_[l].push_back(boundaryFace(F, topo, loop[i], loop[(i + 1) % n]));
    }
  }
  const Eigen::VectorXd turn = angleDefects(V, F, topo);
  for (int p = 0; p < static_cast<int>(V.rows()); ++p)
  {
    corner_[p] |= loopOf_[p] >= 0 && std::abs(turn[p]) > cornerTurn;
  }
}

BoundaryPaths::Place BoundaryPaths::placeOf(const Eigen::Vector3d& p, int triangle, int point) const
{
  if (point >= 0)
  {
    if (point >= static_cast<int>(loopOf_.size()) || loopOf_[point] < 0 || corner_[point])
    {
      return {};
    }
    return { loopOf_[point], placeInLoop_[point] };
  }
  if (triangle < 0 || triangle >= F_.rows())
  {
    return {};
  }
  for (int k = 0; k < 3; ++k)
  {
    const int a = F_(triangle, k), b = F_(triangle, (k + 1) % 3);
    if (topo_.faceNeighbors(triangle, k) >= 0 || loopOf_[a] < 0 || loopOf_[a] != loopOf_[b])
    {
      continue;
    }
    const Eigen::Vector3d pa = V_.row(a), pb = V_.row(b);
    if ((closestOnSegment(p, pa, pb) - p).norm() > 1e-7 * (pb - pa).norm())
    {
      continue;
    }
    const int l = loopOf_[a], n = static_cast<int>(edgeFace_[l].size());
    const int i = placeInLoop_[a], j = placeInLoop_[b];
    if ((i + 1) % n == j && edgeFace_[l][i] == triangle)
    {
      return { l, i };
    }
    if ((j + 1) % n == i && edgeFace_[l][j] == triangle)
    {
      return { l, j };
    }
  }
  return {};
}

std::vector<BoundaryPaths::Stop> BoundaryPaths::slides(
  const Place& place, const Eigen::Vector3d& p, const std::vector<double>& distances) const
{
  std::vector<Stop> stops;
  if (place.loop >= 0)
  {
    walk(place, p, distances, true, stops);
    walk(place, p, distances, false, stops);
  }
  return stops;
}

void BoundaryPaths::walk(const Place& place, const Eigen::Vector3d& p,
  const std::vector<double>& distances, bool forward, std::vector<Stop>& stops) const
{
  const std::vector<int>& loop = topo_.boundaryLoops[place.loop];
  const int n = static_cast<int>(loop.size());
  int edge = place.edge;
  Eigen::Vector3d from = p;
  double travelled = 0.0;
  std::size_t next = 0; // the next of the (ascending) distances to reach
  for (int step = 0; step < n && next < distances.size(); ++step)
  {
    const int to = forward ? loop[(edge + 1) % n] : loop[edge];
    const Eigen::Vector3d target = V_.row(to);
    const double length = (target - from).norm();
    const int face = edgeFace_[place.loop][edge];
    if (face < 0)
    {
      return;
    }
    for (; next < distances.size() && distances[next] < travelled + length; ++next)
    {
      const double s = (distances[next] - travelled) / length;
      stops.push_back({ from + s * (target - from), face, -1 });
    }
    travelled += length;
    if (corner_[to])
    {
      return;
    }
    stops.push_back({ target, face, to });
    from = target;
    edge = forward ? (edge + 1) % n : (edge + n - 1) % n;
  }
}

}
