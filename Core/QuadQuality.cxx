// QuadQuality.cxx: measureQuads and the count of inverted quads.
#include "QuadQuality.h"

#include "ScaledJacobian.h"
#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace quadcover
{

QuadQuality measureQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q)
{
  QuadQuality m;
  const int nV = static_cast<int>(V.rows());
  const int nQ = static_cast<int>(Q.rows());
  m.faces = nQ;
  std::map<std::pair<int, int>, std::array<int, 2>> edges; // (faces, same-direction clashes)
  std::vector<char> usedVertex(nV, 0);
  std::vector<double> angles;
  angles.reserve(4 * static_cast<std::size_t>(nQ));
  m.scaledJacobian.resize(nQ);
  double jacobianSum = 0.0;
  m.minScaledJacobian = nQ > 0 ? 1.0 : 0.0;
  std::map<std::pair<int, int>, int> directed;
  for (int i = 0; i < nQ; ++i)
  {
    std::array<int, 4> q = { Q(i, 0), Q(i, 1), Q(i, 2), Q(i, 3) };
    std::array<int, 4> sorted = q;
    std::sort(sorted.begin(), sorted.end());
    m.quads += std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    for (int k = 0; k < 4; ++k)
    {
      usedVertex[q[k]] = 1;
      const int a = q[k], b = q[(k + 1) % 4];
      auto& e = edges[{ std::min(a, b), std::max(a, b) }];
      ++e[0];
      if (++directed[{ a, b }] > 1)
      {
        ++e[1];
      }
      const Eigen::Vector3d next = V.row(q[(k + 1) % 4]) - V.row(q[k]);
      const Eigen::Vector3d prev = V.row(q[(k + 3) % 4]) - V.row(q[k]);
      const double ln = next.norm(), lp = prev.norm();
      if (ln > 0 && lp > 0)
      {
        angles.push_back(std::acos(std::clamp(next.dot(prev) / (ln * lp), -1.0, 1.0)));
      }
    }
    const double smallest = quadScaledJacobian(V, Q, i);
    m.scaledJacobian[i] = smallest;
    m.minScaledJacobian = std::min(m.minScaledJacobian, smallest);
    jacobianSum += smallest;
  }
  m.meanScaledJacobian = nQ > 0 ? jacobianSum / nQ : 0.0;
  m.valence = Eigen::VectorXi::Zero(nV);
  std::vector<char> boundary(nV, 0);
  std::vector<double> lengths;
  std::vector<int> parent(nV);
  for (int v = 0; v < nV; ++v)
  {
    parent[v] = v;
  }
  std::vector<int> boundaryParent(nV);
  for (int v = 0; v < nV; ++v)
  {
    boundaryParent[v] = v;
  }
  for (const auto& [e, count] : edges)
  {
    ++m.valence[e.first];
    ++m.valence[e.second];
    lengths.push_back((V.row(e.first) - V.row(e.second)).norm());
    unite(parent, e.first, e.second);
    if (count[0] > 2 || count[1] > 0)
    {
      ++m.nonManifoldEdges;
    }
    if (count[0] == 1)
    {
      ++m.boundaryEdges;
      boundary[e.first] = boundary[e.second] = 1;
      unite(boundaryParent, e.first, e.second);
    }
  }
  auto rsd = [](const std::vector<double>& x) {
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
  };
  m.edgeLengthRSD = rsd(lengths);
  m.angleRSD = rsd(angles);
  for (int v = 0; v < nV; ++v)
  {
    if (!usedVertex[v])
    {
      continue;
    }
    ++m.vertices;
    if (boundary[v])
    {
      m.irregularBoundary += m.valence[v] != 2 && m.valence[v] != 3;
      m.boundaryLoops += findRoot(boundaryParent, v) == v;
    }
    else
    {
      m.irregularInner += m.valence[v] != 4;
    }
    m.components += findRoot(parent, v) == v;
  }
  m.eulerCharacteristic = m.vertices - static_cast<int>(edges.size()) + m.faces;
  return m;
}

int countInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q)
{
  int count = 0;
  for (int i = 0; i < static_cast<int>(Q.rows()); ++i)
  {
    count += !(quadScaledJacobian(V, Q, i) > 0);
  }
  return count;
}

}
