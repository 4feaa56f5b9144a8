// QuadQuality.cxx: measureQuads and the count of inverted quads.
#include "QuadQuality.h"

#include "ScaledJacobian.h"
#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
/// What measureQuads gathers on its way from the faces to the edges to the vertices.
struct Tally
{
  explicit Tally(int nV)
    : usedVertex(nV, 0)
    , boundary(nV, 0)
    , parent(nV)
    , boundaryParent(nV)
  {
    std::iota(parent.begin(), parent.end(), 0);
    std::iota(boundaryParent.begin(), boundaryParent.end(), 0);
  }

  /// each edge (a < b) once, in order, with (faces, same-direction clashes)
  std::vector<std::pair<std::pair<int, int>, std::array<int, 2>>> edges;
  std::vector<char> usedVertex;
  std::vector<double> angles;
  std::vector<double> lengths;
  std::vector<char> boundary;      ///< vertices on a boundary edge
  std::vector<int> parent;         ///< components, through all edges
  std::vector<int> boundaryParent; ///< boundary loops, through boundary edges
};

/// The faces: which are quads, their edges, corner angles and scaled Jacobians.
void measureFaces(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q, QuadQuality& m, Tally& tally)
{
  const int nQ = static_cast<int>(Q.rows());
  m.faces = nQ;
  tally.angles.reserve(4 * static_cast<std::size_t>(nQ));
  m.scaledJacobian.resize(nQ);
  double jacobianSum = 0.0;
  m.minScaledJacobian = nQ > 0 ? 1.0 : 0.0;
  // every side of every face: (smaller end, larger end, from, to)
  std::vector<std::array<int, 4>> sides;
  sides.reserve(4 * static_cast<std::size_t>(nQ));
  for (int i = 0; i < nQ; ++i)
  {
    std::array<int, 4> q = { Q(i, 0), Q(i, 1), Q(i, 2), Q(i, 3) };
    std::array<int, 4> sorted = q;
    std::sort(sorted.begin(), sorted.end());
    m.quads += std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    for (int k = 0; k < 4; ++k)
    {
      tally.usedVertex[q[k]] = 1;
      const int a = q[k], b = q[(k + 1) % 4];
      sides.push_back({ std::min(a, b), std::max(a, b), a, b });
      const Eigen::Vector3d next = V.row(q[(k + 1) % 4]) - V.row(q[k]);
      const Eigen::Vector3d prev = V.row(q[(k + 3) % 4]) - V.row(q[k]);
      const double ln = next.norm(), lp = prev.norm();
      if (ln > 0 && lp > 0)
      {
        tally.angles.push_back(std::acos(std::clamp(next.dot(prev) / (ln * lp), -1.0, 1.0)));
      }
    }
    const double smallest = quadScaledJacobian(V, Q, i);
    m.scaledJacobian[i] = smallest;
    m.minScaledJacobian = std::min(m.minScaledJacobian, smallest);
    jacobianSum += smallest;
  }
  m.meanScaledJacobian = nQ > 0 ? jacobianSum / nQ : 0.0;
  // the edges in order: the faces on each, and the sides that repeat one in the same direction
  std::sort(sides.begin(), sides.end());
  for (std::size_t j = 0; j < sides.size(); ++j)
  {
    const std::pair<int, int> edge{ sides[j][0], sides[j][1] };
    if (tally.edges.empty() || tally.edges.back().first != edge)
    {
      tally.edges.push_back({ edge, { 0, 0 } });
    }
    auto& count = tally.edges.back().second;
    ++count[0];
    count[1] += j > 0 && sides[j] == sides[j - 1];
  }
}

/// The edges: valences, lengths, non-manifold and boundary edges, components and loops.
void measureEdges(const Eigen::MatrixX3d& V, QuadQuality& m, Tally& tally)
{
  m.valence = Eigen::VectorXi::Zero(V.rows());
  for (const auto& [e, count] : tally.edges)
  {
    ++m.valence[e.first];
    ++m.valence[e.second];
    tally.lengths.push_back((V.row(e.first) - V.row(e.second)).norm());
    unite(tally.parent, e.first, e.second);
    if (count[0] > 2 || count[1] > 0)
    {
      ++m.nonManifoldEdges;
    }
    if (count[0] == 1)
    {
      ++m.boundaryEdges;
      tally.boundary[e.first] = tally.boundary[e.second] = 1;
      unite(tally.boundaryParent, e.first, e.second);
    }
  }
}

/// The vertices the faces use: irregular ones, boundary loops and components.
void measureVertices(QuadQuality& m, Tally& tally)
{
  for (int v = 0; v < static_cast<int>(tally.usedVertex.size()); ++v)
  {
    if (!tally.usedVertex[v])
    {
      continue;
    }
    ++m.vertices;
    if (tally.boundary[v])
    {
      m.irregularBoundary += m.valence[v] != 2 && m.valence[v] != 3;
      m.boundaryLoops += findRoot(tally.boundaryParent, v) == v;
    }
    else
    {
      m.irregularInner += m.valence[v] != 4;
    }
    m.components += findRoot(tally.parent, v) == v;
  }
}

/// The relative standard deviation of x (population), 0 when x is empty or its mean is not
/// positive.
double relativeStandardDeviation(const std::vector<double>& x)
{
  if (x.empty())
  {
    return 0.0;
  }
  double mean = 0.0;
  for (const double v : x)
  {
    mean += v;
  }
  mean /= static_cast<double>(x.size());
  double var = 0.0;
  for (const double v : x)
  {
    var += (v - mean) * (v - mean);
  }
  var /= static_cast<double>(x.size());
  return mean > 0 ? std::sqrt(var) / mean : 0.0;
}
}

std::vector<int> invertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q)
{
  std::vector<int> bad;
  for (int i = 0; i < static_cast<int>(Q.rows()); ++i)
  {
    if (!(quadScaledJacobian(V, Q, i) > 0))
    {
      bad.push_back(i);
    }
  }
  return bad;
}

QuadQuality measureQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q)
{
  QuadQuality m;
  Tally tally(static_cast<int>(V.rows()));
  measureFaces(V, Q, m, tally);
  measureEdges(V, m, tally);
  m.edgeLengthRSD = relativeStandardDeviation(tally.lengths);
  m.angleRSD = relativeStandardDeviation(tally.angles);
  measureVertices(m, tally);
  m.eulerCharacteristic = m.vertices - static_cast<int>(tally.edges.size()) + m.faces;
  return m;
}

int countInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q)
{
  return static_cast<int>(invertedQuads(V, Q).size());
}

}
