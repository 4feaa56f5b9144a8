// ComponentMaps.cxx: the integer-grid map of a surface of several components, one map per
// component with its own edge length, put together.
#include "ParameterizationSteps.h"

#include "Parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>

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
  // a grid coarse enough to leave a hole or a handle only a few cells loses it (the truck's
  // wheels of 14 loops on 24 quads came apart)
  const double fewest =
    std::max(1, options.minimumComponentQuadCount) * holesAndHandles(topo.eulerCharacteristic());
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
    out.layerShift[part.points[i]] = map.layerShift[static_cast<Eigen::Index>(i)];
    out.singularityIndex[part.points[i]] = map.singularityIndex[static_cast<Eigen::Index>(i)];
  }
  for (const int p : map.sectorPoint)
  {
    out.sectorPoint.push_back(part.points[p]);
  }
  out.cut.numCutEdges += map.cut.numCutEdges;
  out.cut.cutEuler.insert(out.cut.cutEuler.end(), map.cut.cutEuler.begin(), map.cut.cutEuler.end());
  out.cancelledPairs += map.cancelledPairs;
  out.movedSingularities += map.movedSingularities;
  out.addedConePairs += map.addedConePairs;
  out.droppedConePairs += map.droppedConePairs;
  out.finerGridRetries += map.finerGridRetries;
  out.finerGridTriangles += map.finerGridTriangles;
  out.branchPoints += map.branchPoints;
  out.branchPointsOnGrid += map.branchPointsOnGrid;
  out.seamEdges += map.seamEdges;
  out.alignedBoundaryEdges += map.alignedBoundaryEdges;
  out.alignedFeatureEdges += map.alignedFeatureEdges;
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
  out.finerForSingularities = out.finerForSingularities || map.finerForSingularities;
  out.untangleEvaluations += map.untangleEvaluations;
  out.maxSeamError = std::max(out.maxSeamError, map.maxSeamError);
  out.solveSeconds.insert(out.solveSeconds.end(), map.solveSeconds.begin(), map.solveSeconds.end());
  out.solver = map.solver;
}

/// A component's topology and map.
struct ComponentMap
{
  MeshTopology topo;
  Parameterization map;
};

/// Joins the worker threads however the scope is left; left by an exception (a cancel, a thread
/// that could not start), it first asks them to stop.
struct Joiner
{
  std::vector<std::thread>& threads;
  std::atomic<bool>& stop;
  bool finished = false;

  ~Joiner()
  {
    if (!finished)
    {
      stop = true;
    }
    for (std::thread& t : threads)
    {
      t.join();
    }
  }
};

/**
 * The maps of the components, on several threads (options.numberOfThreads, shared out between
 * the components mapped at once and their untangling): the components are independent, so each
 * map is what it would be on one thread. The largest components go first (no thread is left
 * with a large one at the end), the calling thread taking the largest. It reports progress by
 * the share of triangles mapped, while it maps and then while it waits for the others; when it
 * is cancelled, the other threads stop at their next report. A component whose map fails does
 * not stop the others: the failure of the first such component is thrown, as on one thread.
 */
std::vector<ComponentMap> mapComponents(
  const Inputs& in, const std::vector<Component>& parts, double totalArea, const Progress& progress)
{
  std::vector<int> order(parts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](int a, int b) { return parts[a].faces.size() > parts[b].faces.size(); });
  const int wanted = threadCount(in.options.numberOfThreads);
  const int threads = std::max(1, std::min(wanted, static_cast<int>(parts.size())));
  std::vector<ComponentMap> maps(parts.size());
  std::vector<std::exception_ptr> failed(parts.size());
  std::atomic<std::size_t> next{ 1 }; // the calling thread starts with the first
  std::atomic<long long> facesDone{ 0 };
  std::atomic<bool> stop{ false };
  std::mutex mutex;
  std::condition_variable changed;
  int running = threads - 1; // worker threads not done (under mutex)
  const Progress stoppable([&stop](double) { return !stop.load(); });
  double reported = 0.0; // the calling thread's last fraction: it only grows
  auto work = [&](std::size_t n, bool calling) {
    for (; n < order.size() && !stop; n = next++)
    {
      const int c = order[n];
      const Component& part = parts[c];
      const double share = static_cast<double>(part.faces.size()) / in.numFaces();
      try
      {
        const MeshTopology& topo = maps[c].topo =
          buildTopology(part.F, static_cast<int>(part.V.rows()));
        const FrameGeometry geometry = computeFrameGeometry(part.V, part.F, topo);
        ParameterizationOptions options = componentOptions(in.options, part.area, totalArea, topo);
        options.numberOfThreads = std::max(1, wanted / threads); // its untangling's
        maps[c].map = computeParameterization(part.V, part.F, topo, geometry, part.frameU,
          part.matching, options, calling ? progress.part(reported, reported + share) : stoppable);
      }
      catch (const Cancelled&)
      {
        if (calling)
        {
          throw; // cancelled by the caller: the other threads stop too (Joiner)
        }
        return; // stopped because the calling thread was cancelled
      }
      catch (...)
      {
        // the others go on, so that the failure thrown is the first in component order, as on
        // one thread
        failed[c] = std::current_exception();
      }
      facesDone += static_cast<long long>(part.faces.size());
      changed.notify_all();
      if (calling)
      {
        // what the other threads finished meanwhile counts too
        reported = std::max(reported + share, static_cast<double>(facesDone) / in.numFaces());
        progress.report(reported);
      }
    }
  };
  std::vector<std::thread> workers;
  Joiner joiner{ workers, stop };
  for (int t = 1; t < threads; ++t)
  {
    workers.emplace_back([&]() {
      work(next++, false);
      std::lock_guard<std::mutex> lock(mutex);
      --running;
      changed.notify_all();
    });
  }
  work(0, true);
  // the others' components: report them as they finish (and hear a cancel meanwhile)
  std::unique_lock<std::mutex> lock(mutex);
  while (running > 0)
  {
    changed.wait_for(lock, std::chrono::milliseconds(100));
    lock.unlock();
    reported = std::max(reported, static_cast<double>(facesDone) / in.numFaces());
    progress.report(reported);
    lock.lock();
  }
  lock.unlock();
  joiner.finished = true;
  for (const std::exception_ptr& e : failed)
  {
    if (e)
    {
      std::rethrow_exception(e);
    }
  }
  return maps;
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
  const std::vector<ComponentMap> maps = mapComponents(in, parts, totalArea, progress);
  Parameterization out;
  out.cornerUV.resize(in.numFaces(), 6);
  out.seam.resize(in.numFaces(), 3);
  out.comb.resize(in.numFaces());
  out.combedMatching.resize(in.numFaces(), 3);
  out.layerShift = Eigen::VectorXi::Zero(in.numVertices());
  out.singularityIndex = Eigen::VectorXd::Zero(in.numVertices());
  out.cornerSector.assign(3 * static_cast<size_t>(in.numFaces()), -1);
  out.cut.onCut.assign(in.topo.numEdges(), 0);
  out.cut.copies.assign(in.numVertices(), 0);
  for (std::size_t c = 0; c < parts.size(); ++c)
  {
    const Component& part = parts[c];
    const Parameterization& map = maps[c].map;
    addComponent(in, part, maps[c].topo, map, out);
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
  for (const ComponentMap& m : maps)
  {
    out.sectorUV.middleRows(row, m.map.sectorUV.rows()) = m.map.sectorUV;
    row += m.map.sectorUV.rows();
  }
  progress.report(1.0);
  return out;
}
}
}
