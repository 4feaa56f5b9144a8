// CurvatureSizing.cxx: curvatureGridScale.
#include "CurvatureSizing.h"

#include "ThinStrips.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace quadcover
{
namespace
{
/// Area-weighted unit normals of the points (0 where a point has no triangle of nonzero area).
Eigen::MatrixX3d pointNormals(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  Eigen::MatrixX3d normal = Eigen::MatrixX3d::Zero(V.rows(), 3);
  for (int f = 0; f < F.rows(); ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::RowVector3d n = (b - a).cross(c - a).transpose(); // twice the area, as weight
    for (int k = 0; k < 3; ++k)
    {
      normal.row(F(f, k)) += n;
    }
  }
  for (Eigen::Index v = 0; v < normal.rows(); ++v)
  {
    const double length = normal.row(v).norm();
    normal.row(v) =
      length > 0 ? Eigen::RowVector3d(normal.row(v) / length) : Eigen::RowVector3d::Zero();
  }
  return normal;
}

/// Normals averaged with their edge neighbours (half each point's own, half its neighbours'
/// mean), `rounds` times, and made unit again; a point on a crease (`onCrease`) is no neighbour.
void smoothNormals(
  const MeshTopology& topo, const std::vector<char>& onCrease, int rounds, Eigen::MatrixX3d& normal)
{
  const int nE = topo.numEdges();
  Eigen::VectorXd count = Eigen::VectorXd::Zero(normal.rows()); // edge neighbours per point
  for (int e = 0; e < nE; ++e)
  {
    count[topo.edges(e, 0)] += onCrease[topo.edges(e, 1)] ? 0 : 1;
    count[topo.edges(e, 1)] += onCrease[topo.edges(e, 0)] ? 0 : 1;
  }
  Eigen::MatrixX3d sum(normal.rows(), 3);
  for (int round = 0; round < rounds; ++round)
  {
    sum.setZero();
    for (int e = 0; e < nE; ++e)
    {
      const int a = topo.edges(e, 0), b = topo.edges(e, 1);
      if (!onCrease[b])
        sum.row(a) += normal.row(b);
      if (!onCrease[a])
        sum.row(b) += normal.row(a);
    }
    for (Eigen::Index v = 0; v < normal.rows(); ++v)
    {
      if (count[v] > 0)
      {
        const Eigen::RowVector3d mixed = 0.5 * normal.row(v) + 0.5 * sum.row(v) / count[v];
        const double length = mixed.norm();
        if (length > 0)
        {
          normal.row(v) = mixed / length;
        }
      }
    }
  }
}
}

Eigen::VectorXd curvatureGridScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, double edgeLength, double edgeOverRadius, double maximumRefinement,
  const std::vector<char>& creases, double gradation)
{
  if (!(edgeOverRadius > 0) || !(maximumRefinement > 1) || !(edgeLength > 0) ||
    !std::isfinite(edgeLength) || topo.numEdges() == 0)
  {
    return {};
  }
  const int nE = topo.numEdges();
  double meanEdge = 0.0;
  for (int e = 0; e < nE; ++e)
  {
    meanEdge += (V.row(topo.edges(e, 0)) - V.row(topo.edges(e, 1))).norm();
  }
  meanEdge /= nE;
  // a random walk of n rounds of half-steps spreads over about sqrt(n / 2) edges: a grid edge
  // takes n = 2 (edgeLength / meanEdge)^2 rounds (capped: a mesh far finer than the grid). Half a
  // grid edge left the detail of scans in (armadillo's whole body finer, its Hausdorff distance
  // 0.76 -> 1.00%), two grid edges smoothed bunny-lowres's ears away (0.79 -> 1.16%).
  const double ratio = meanEdge > 0 ? edgeLength / meanEdge : 0.0;
  const int rounds = static_cast<int>(std::min(200.0, std::floor(2.0 * ratio * ratio)));
  std::vector<char> onCrease(static_cast<std::size_t>(topo.numVertices), 0);
  for (int e = 0; e < nE && e < static_cast<int>(creases.size()); ++e)
  {
    if (creases[e])
    {
      onCrease[topo.edges(e, 0)] = onCrease[topo.edges(e, 1)] = 1;
    }
  }
  Eigen::MatrixX3d normal = pointNormals(V, F);
  smoothNormals(topo, onCrease, rounds, normal);

  const double smallest = edgeLength / maximumRefinement;
  std::vector<double> size(static_cast<std::size_t>(topo.numVertices), edgeLength);
  bool finer = false;
  for (int e = 0; e < nE; ++e)
  {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    const double length = (V.row(a) - V.row(b)).norm();
    const Eigen::Vector3d na = normal.row(a), nb = normal.row(b);
    if (onCrease[a] || onCrease[b] || !(length > 0) || !(na.squaredNorm() > 0) ||
      !(nb.squaredNorm() > 0))
    {
      continue;
    }
    const double turn = std::atan2(na.cross(nb).norm(), na.dot(nb));
    // the radius of curvature along the edge: length / turn; the size it asks for
    if (!(turn * edgeLength > edgeOverRadius * length))
    {
      continue;
    }
    const double wanted = std::max(smallest, edgeOverRadius * length / turn);
    size[a] = std::min(size[a], wanted);
    size[b] = std::min(size[b], wanted);
    finer = true;
  }
  if (!finer)
  {
    return {};
  }
  spreadGridSizes(V, topo, gradation, size);
  return faceGridScale(F, size, edgeLength);
}

}
