// SurfaceSmoothing.cxx: rough components found and smoothed by Taubin's steps.
#include "SurfaceSmoothing.h"

#include "FrameField.h"

#include <Eigen/Geometry>

#include <cmath>

namespace quadcover
{

bool Roughness::rough() const
{
  return curvedPoints >= RoughMinimumPoints && curvatureLeft < RoughCurvatureLeft * curvature;
}

namespace
{
/// Each point's neighbours through its edges, for the points that `moves`.
std::vector<std::vector<int>> movingNeighbours(
  const MeshTopology& topo, const std::vector<char>& moves)
{
  std::vector<std::vector<int>> neighbours(moves.size());
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    if (moves[a])
    {
      neighbours[a].push_back(b);
    }
    if (moves[b])
    {
      neighbours[b].push_back(a);
    }
  }
  return neighbours;
}

/// `pairs` pairs of Taubin's steps (lambda 0.5, mu -0.53) on the points that `moves`.
void taubinSteps(
  Eigen::MatrixX3d& V, const MeshTopology& topo, const std::vector<char>& moves, int pairs)
{
  const std::vector<std::vector<int>> neighbours = movingNeighbours(topo, moves);
  Eigen::MatrixX3d step(V.rows(), 3);
  for (int pass = 0; pass < 2 * pairs; ++pass)
  {
    const double share = pass % 2 == 0 ? 0.5 : -0.53;
    step.setZero();
    for (Eigen::Index v = 0; v < V.rows(); ++v)
    {
      if (moves[v] && !neighbours[v].empty())
      {
        Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
        for (const int w : neighbours[v])
        {
          mean += V.row(w);
        }
        step.row(v) = share * (mean / static_cast<double>(neighbours[v].size()) - V.row(v));
      }
    }
    V += step;
  }
}
}

std::vector<Roughness> componentRoughness(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  std::vector<Roughness> result(topo.numComponents());
  const Eigen::VectorXd defect = angleDefects(V, F, topo);
  std::vector<char> inner(V.rows(), 0);
  for (Eigen::Index v = 0; v < V.rows(); ++v)
  {
    const int c = topo.vertexComponent[v];
    inner[v] = c >= 0 && !topo.boundaryVertex[v];
    if (inner[v])
    {
      result[c].curvature += std::abs(defect[v]);
      result[c].curvedPoints += std::abs(defect[v]) > RoughDefect ? 1 : 0;
    }
  }
  Eigen::MatrixX3d probe = V;
  taubinSteps(probe, topo, inner, RoughProbePasses);
  const Eigen::VectorXd left = angleDefects(probe, F, topo);
  for (Eigen::Index v = 0; v < V.rows(); ++v)
  {
    if (inner[v])
    {
      result[topo.vertexComponent[v]].curvatureLeft += std::abs(left[v]);
    }
  }
  return result;
}

int smoothRoughComponents(Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  const MeshTopology topo = buildTopology(F, static_cast<int>(V.rows()));
  const std::vector<Roughness> roughness = componentRoughness(V, F, topo);
  std::vector<char> moves(V.rows(), 0);
  int moved = 0;
  for (Eigen::Index v = 0; v < V.rows(); ++v)
  {
    const int c = topo.vertexComponent[v];
    moves[v] = c >= 0 && roughness[c].rough() && !topo.boundaryVertex[v];
    moved += moves[v];
  }
  if (moved > 0)
  {
    taubinSteps(V, topo, moves, RoughSmoothingPasses);
  }
  return moved;
}
}
