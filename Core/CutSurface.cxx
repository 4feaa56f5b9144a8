// CutSurface.cxx: the surface cut open for the integer-grid map: the singular points, the cut
// graph through them, the frames combed off the cut, the sectors of the points on it.
#include "ParameterizationSteps.h"

#include "CutGraph.h"
#include "FrameField.h"
#include "UnionFind.h"

#include <cmath>
#include <deque>
#include <stdexcept>

namespace quadcover
{
namespace param
{
namespace
{
int mod4(int r)
{
  return ((r % 4) + 4) % 4;
}
}

Field evaluateField(const Inputs& in)
{
  Field field;
  field.topology = evaluateMatchings(in.F, in.topo, in.geometry, in.frameU, in.matching);
  field.branch.assign(in.numVertices(), 0);
  for (int v = 0; v < in.numVertices(); ++v)
  {
    if (!in.topo.boundaryVertex[v])
    {
      field.branch[v] = field.topology.layerShift[v] != 0;
    }
  }
  field.theta = vectorAngles(in.geometry.bases, in.frameU);
  return field;
}

void cutThroughSingularities(const Inputs& in, const Field& field, Parameterization& out)
{
  std::vector<char> terminal(in.numVertices(), 0);
  for (int v = 0; v < in.numVertices(); ++v)
  {
    if (!in.topo.boundaryVertex[v])
    {
      terminal[v] = field.branch[v] || std::abs(field.topology.index[v]) > 1e-6;
      out.branchPoints += field.branch[v];
    }
  }
  out.cut = computeCutGraph(in.topo, terminal);
  out.seamEdges = out.cut.numCutEdges;
}

void combFrames(const Inputs& in, Parameterization& out)
{
  const MeshTopology& topo = in.topo;
  const std::vector<char>& onCut = out.cut.onCut;
  const int nF = in.numFaces();
  out.comb = Eigen::VectorXi::Constant(nF, -1);
  for (int seed = 0; seed < nF; ++seed)
  {
    if (out.comb[seed] >= 0)
    {
      continue;
    }
    out.comb[seed] = 0;
    std::deque<int> queue{ seed };
    while (!queue.empty())
    {
      const int f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k)
      {
        const int g = topo.faceNeighbors(f, k);
        if (g >= 0 && !onCut[topo.faceEdges(f, k)] && out.comb[g] < 0)
        {
          out.comb[g] = mod4(in.matching(f, k) + out.comb[f]);
          queue.push_back(g);
        }
      }
    }
  }
  out.combedMatching.resize(nF, 3);
  out.seam = Eigen::MatrixX3i::Zero(nF, 3);
  for (int f = 0; f < nF; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      const int e = topo.faceEdges(f, k);
      out.combedMatching(f, k) = g < 0 ? -1 : mod4(in.matching(f, k) + out.comb[f] - out.comb[g]);
      out.seam(f, k) = onCut[e] ? 1 : 0;
      if (g >= 0 && !onCut[e] && out.combedMatching(f, k) != 0)
      {
        throw std::logic_error("computeParameterization: the frames cannot be combed off the cut "
                               "(a singular point is not on it)");
      }
    }
  }
}

void cutIntoSectors(const Inputs& in, Parameterization& out)
{
  const MeshTopology& topo = in.topo;
  const Eigen::MatrixX3i& F = in.F;
  const int nF = in.numFaces();
  std::vector<int> parent(3 * nF);
  for (int c = 0; c < 3 * nF; ++c)
  {
    parent[c] = c;
  }
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (topo.edgeFaceCount[e] != 2 || out.cut.onCut[e])
    {
      continue;
    }
    const int c0 = topo.edgeCorners(e, 0);
    const int f = c0 / 3;
    const int g = topo.edgeCorners(e, 1) / 3;
    for (int end = 0; end < 2; ++end)
    {
      const int p = F(f, (c0 % 3 + end) % 3);
      unite(parent, 3 * f + (c0 % 3 + end) % 3, 3 * g + MeshTopology::cornerOf(F, g, p));
    }
  }
  out.cornerSector.assign(3 * nF, -1);
  for (int c = 0; c < 3 * nF; ++c)
  {
    const int root = findRoot(parent, c);
    if (root == c)
    {
      out.cornerSector[c] = static_cast<int>(out.sectorPoint.size());
      out.sectorPoint.push_back(F(c / 3, c % 3));
    }
    out.cornerSector[c] = out.cornerSector[root];
  }
}
}
}
