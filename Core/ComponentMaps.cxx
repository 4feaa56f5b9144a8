// ComponentMaps.cxx: the integer-grid map of a surface of several components, one map per
// component with its own edge length, put together.
#include "ParameterizationSteps.h"

#include <algorithm>
#include <cmath>

namespace quadcover
{
namespace param
{
namespace
{
/// One component as a surface of its own.
struct Component
{
  std::vector<int> faces;  ///< its faces, in the surface's order
  std::vector<int> points; ///< its points, in the surface's order
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  Eigen::MatrixX3d frameU;
  Eigen::MatrixX3i matching;
  double area = 0.0;
};

std::vector<Component> splitComponents(const Inputs& in)
{
  const MeshTopology& topo = in.topo;
  std::vector<Component> parts(topo.numComponents());
  std::vector<int> local(in.numVertices(), -1);
  for (int v = 0; v < in.numVertices(); ++v)
  {
    const int c = topo.vertexComponent[v];
    if (c >= 0)
    {
      local[v] = static_cast<int>(parts[c].points.size());
      parts[c].points.push_back(v);
    }
  }
  for (int f = 0; f < in.numFaces(); ++f)
  {
    parts[topo.faceComponent[f]].faces.push_back(f);
  }
  for (Component& part : parts)
  {
    const int nf = static_cast<int>(part.faces.size());
    part.V.resize(static_cast<Eigen::Index>(part.points.size()), 3);
    for (size_t i = 0; i < part.points.size(); ++i)
    {
      part.V.row(static_cast<Eigen::Index>(i)) = in.V.row(part.points[i]);
    }
    part.F.resize(nf, 3);
    part.frameU.resize(nf, 3);
    part.matching.resize(nf, 3);
    for (int i = 0; i < nf; ++i)
    {
      const int f = part.faces[i];
      for (int k = 0; k < 3; ++k)
      {
        part.F(i, k) = local[in.F(f, k)];
      }
      part.frameU.row(i) = in.frameU.row(f);
      part.matching.row(i) = in.matching.row(f);
    }
    part.area = surfaceArea(part.V, part.F);
  }
  return parts;
}

/// The options for one component: at least minimumComponentQuadCount quads on it for each of its
/// holes and handles (2 - its Euler characteristic, at least 1), else its share of the whole
/// surface's target.
ParameterizationOptions componentOptions(
  const ParameterizationOptions& options, double area, double totalArea, const MeshTopology& topo)
{
  ParameterizationOptions own = options;
  // 2 - chi = 2 genus + boundary loops: a grid coarse enough to leave a hole or a handle only a
  // few cells loses it (the truck's wheels of 14 loops on 24 quads came apart)
  const double fewest =
    std::max(1, options.minimumComponentQuadCount) * std::max(1, 2 - topo.eulerCharacteristic());
  if (options.targetEdgeLength > 0)
  {
    own.targetEdgeLength = std::min(options.targetEdgeLength, std::sqrt(area / fewest));
  }
  else
  {
    own.targetQuadCount = std::max(fewest, options.targetQuadCount * area / totalArea);
  }
  return own;
}

/// Adds the map of component `part` to out (per face, per sector but sectorUV, the cut per edge,
/// figures).
void addComponent(const Inputs& in, const Component& part, const MeshTopology& topo,
  const Parameterization& map, Parameterization& out)
{
  const int sectors = static_cast<int>(out.sectorPoint.size());
  for (size_t i = 0; i < part.faces.size(); ++i)
  {
    const int f = part.faces[i], fi = static_cast<int>(i);
    out.cornerUV.row(f) = map.cornerUV.row(fi);
    out.seam.row(f) = map.seam.row(fi);
    out.comb[f] = map.comb[fi];
    out.combedMatching.row(f) = map.combedMatching.row(fi);
    for (int k = 0; k < 3; ++k)
    {
      out.cornerSector[3 * f + k] = sectors + map.cornerSector[3 * fi + k];
      out.cut.onCut[in.topo.faceEdges(f, k)] = map.cut.onCut[topo.faceEdges(fi, k)];
    }
  }
  for (size_t i = 0; i < part.points.size(); ++i)
  {
    out.cut.copies[part.points[i]] = map.cut.copies[i];
  }
  for (const int p : map.sectorPoint)
  {
    out.sectorPoint.push_back(part.points[p]);
  }
  out.cut.numCutEdges += map.cut.numCutEdges;
  out.cut.cutEuler.insert(out.cut.cutEuler.end(), map.cut.cutEuler.begin(), map.cut.cutEuler.end());
  out.cancelledPairs += map.cancelledPairs;
  out.branchPoints += map.branchPoints;
  out.branchPointsOnGrid += map.branchPointsOnGrid;
  out.seamEdges += map.seamEdges;
  out.alignedBoundaryEdges += map.alignedBoundaryEdges;
  out.unknowns += map.unknowns;
  out.integerUnknowns += map.integerUnknowns;
  out.constraints += map.constraints;
  out.nonUnitPivots += map.nonUnitPivots;
  out.separatedBranchPoints += map.separatedBranchPoints;
  out.separatedBoundaryLines += map.separatedBoundaryLines;
  out.flippedContinuous += map.flippedContinuous;
  out.flippedRounded += map.flippedRounded;
  out.flipped += map.flipped;
  out.wrongWindings += map.wrongWindings;
  out.untangleRegions += map.untangleRegions;
  out.regrids += map.regrids;
  out.untangleSeconds += map.untangleSeconds;
  out.untangleBudgetSpent = out.untangleBudgetSpent || map.untangleBudgetSpent;
  out.untangleEvaluations += map.untangleEvaluations;
  out.maxSeamError = std::max(out.maxSeamError, map.maxSeamError);
  out.solveSeconds.insert(out.solveSeconds.end(), map.solveSeconds.begin(), map.solveSeconds.end());
  out.solver = map.solver;
}
}

Parameterization mapEachComponent(const Inputs& in, const Progress& progress)
{
  const std::vector<Component> parts = splitComponents(in);
  double totalArea = 0.0, largest = -1.0;
  for (const Component& part : parts)
  {
    totalArea += part.area;
  }
  Parameterization out;
  out.cornerUV.resize(in.numFaces(), 6);
  out.seam.resize(in.numFaces(), 3);
  out.comb.resize(in.numFaces());
  out.combedMatching.resize(in.numFaces(), 3);
  out.cornerSector.assign(3 * static_cast<size_t>(in.numFaces()), -1);
  out.cut.onCut.assign(in.topo.numEdges(), 0);
  out.cut.copies.assign(in.numVertices(), 0);
  std::vector<Eigen::MatrixX2d> sectorUV; // per component, put together once at the end
  double done = 0.0;
  for (const Component& part : parts)
  {
    const MeshTopology topo = buildTopology(part.F, static_cast<int>(part.V.rows()));
    const FrameGeometry geometry = computeFrameGeometry(part.V, part.F, topo);
    const ParameterizationOptions options =
      componentOptions(in.options, part.area, totalArea, topo);
    const double share = static_cast<double>(part.faces.size()) / in.numFaces();
    const Parameterization map = computeParameterization(part.V, part.F, topo, geometry,
      part.frameU, part.matching, options, progress.part(done, done + share));
    done += share;
    addComponent(in, part, topo, map, out);
    sectorUV.push_back(map.sectorUV);
    // energies are per unit area: the whole surface's is the area-weighted mean
    const double weight = part.area / totalArea;
    out.energyContinuous += weight * map.energyContinuous;
    out.energyRounded += weight * map.energyRounded;
    out.energyFinal += weight * map.energyFinal;
    if (part.area > largest)
    {
      largest = part.area;
      out.edgeLength = map.edgeLength;
    }
  }
  out.sectorUV.resize(static_cast<Eigen::Index>(out.sectorPoint.size()), 2);
  Eigen::Index row = 0;
  for (const Eigen::MatrixX2d& uv : sectorUV)
  {
    out.sectorUV.middleRows(row, uv.rows()) = uv;
    row += uv.rows();
  }
  progress.report(1.0);
  return out;
}
}
}
