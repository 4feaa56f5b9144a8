// SurfaceRefinement.cxx: refineCoarseComponents.
#include "SurfaceRefinement.h"

#include "MeshTopology.h"

#include <algorithm>
#include <map>
#include <utility>

namespace quadcover
{
namespace
{
/// The points: the input's, then the midpoints added so far.
struct Points
{
  const Eigen::MatrixX3d& V;
  std::vector<Eigen::Vector3d> added;

  Eigen::Vector3d operator[](int i) const
  {
    return i < V.rows() ? Eigen::Vector3d(V.row(i).transpose()) : added[i - V.rows()];
  }
};

/// One 1-to-4 split of the triangles: midpoints shared across edges.
void splitOnce(Points& points, std::vector<Eigen::Vector3i>& triangles, std::vector<int>& parent,
  Refinement& r)
{
  std::map<std::pair<int, int>, int> midpoint;
  auto middle = [&](int a, int b) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    const int next = static_cast<int>(points.V.rows() + points.added.size());
    const auto [it, added] = midpoint.emplace(key, next);
    if (added)
    {
      points.added.push_back(0.5 * (points[key.first] + points[key.second]));
      r.midpoints.push_back({ key.first, key.second });
    }
    return it->second;
  };
  std::vector<Eigen::Vector3i> split;
  std::vector<int> splitParent;
  split.reserve(4 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Eigen::Vector3i& c = triangles[t];
    const int ab = middle(c[0], c[1]), bc = middle(c[1], c[2]), ca = middle(c[2], c[0]);
    for (const Eigen::Vector3i& child : { Eigen::Vector3i(c[0], ab, ca),
           Eigen::Vector3i(ab, c[1], bc), Eigen::Vector3i(ca, bc, c[2]),
           Eigen::Vector3i(ab, bc, ca) })
    {
      split.push_back(child);
      splitParent.push_back(parent[t]);
    }
  }
  triangles.swap(split);
  parent.swap(splitParent);
}
}

Refinement refineCoarseComponents(Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, int minimumTriangles)
{
  Refinement r;
  const int nF = static_cast<int>(F.rows());
  r.parent.resize(nF);
  for (int f = 0; f < nF; ++f)
  {
    r.parent[f] = f;
  }
  if (minimumTriangles <= 0 || nF == 0)
  {
    return r;
  }
  const MeshTopology topo = buildTopology(F, static_cast<int>(V.rows()));
  std::vector<std::vector<int>> components(topo.numComponents());
  for (int f = 0; f < nF; ++f)
  {
    components[topo.faceComponent[f]].push_back(f);
  }
  std::vector<Eigen::Vector3i> all;
  std::vector<int> allParent;
  Points points{ V, {} };
  for (const std::vector<int>& faces : components)
  {
    std::vector<Eigen::Vector3i> triangles;
    std::vector<int> parent = faces;
    for (const int f : faces)
    {
      triangles.push_back(F.row(f).transpose());
    }
    if (static_cast<int>(faces.size()) < minimumTriangles)
    {
      r.refinedTriangles += static_cast<int>(faces.size());
      while (static_cast<int>(triangles.size()) < minimumTriangles)
      {
        splitOnce(points, triangles, parent, r);
      }
    }
    all.insert(all.end(), triangles.begin(), triangles.end());
    allParent.insert(allParent.end(), parent.begin(), parent.end());
  }
  if (r.refinedTriangles == 0)
  {
    return r; // F exactly as it was
  }
  const Eigen::Index nV = V.rows();
  V.conservativeResize(nV + static_cast<Eigen::Index>(points.added.size()), 3);
  for (std::size_t i = 0; i < points.added.size(); ++i)
  {
    V.row(nV + static_cast<Eigen::Index>(i)) = points.added[i].transpose();
  }
  F.resize(static_cast<Eigen::Index>(all.size()), 3);
  for (std::size_t t = 0; t < all.size(); ++t)
  {
    F.row(static_cast<Eigen::Index>(t)) = all[t].transpose();
  }
  r.parent = std::move(allParent);
  return r;
}

}
