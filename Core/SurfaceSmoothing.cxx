// SurfaceSmoothing.cxx: rough components found and smoothed by Taubin's steps.
#include "SurfaceSmoothing.h"

#include "FrameField.h"
#include "MatchingAngles.h"

#include <Eigen/Geometry>

#include <cmath>

namespace quadcover
{
using detail::Pi;

bool Roughness::rough() const
{
  return foldedEdges > RoughFoldedShare * innerEdges &&
    signChanges > RoughSignChangeShare * edges && foldedEdges >= RoughMinimumEdges &&
    signChanges >= RoughMinimumEdges;
}

std::vector<Roughness> componentRoughness(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  std::vector<Roughness> result(topo.numComponents());
  const FaceBases bases = computeFaceBases(V, F, topo);
  const Eigen::VectorXd defect = angleDefects(V, F, topo);
  const double cosFold = std::cos(RoughFoldAngle * Pi / 180.0);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    const int c = topo.vertexComponent[a];
    if (c < 0)
    {
      continue;
    }
    Roughness& r = result[c];
    ++r.edges;
    if (topo.edgeFaceCount[e] == 2)
    {
      ++r.innerEdges;
      const Eigen::Vector3d n = bases.normal.row(topo.edgeFaces(e, 0));
      const Eigen::Vector3d m = bases.normal.row(topo.edgeFaces(e, 1));
      r.foldedEdges += n.dot(m) < cosFold ? 1 : 0;
    }
    const bool inner = !topo.boundaryVertex[a] && !topo.boundaryVertex[b];
    r.signChanges += inner && std::abs(defect[a]) > RoughDefect &&
        std::abs(defect[b]) > RoughDefect && (defect[a] > 0) != (defect[b] > 0)
      ? 1
      : 0;
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
  if (moved == 0)
  {
    return 0;
  }
  // each moving point's neighbours, through its edges
  std::vector<std::vector<int>> neighbours(V.rows());
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
  Eigen::MatrixX3d step(V.rows(), 3);
  for (int pass = 0; pass < 2 * RoughSmoothingPasses; ++pass)
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
  return moved;
}
}
