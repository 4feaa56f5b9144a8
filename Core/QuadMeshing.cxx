#include "QuadMeshing.h"

#include "CreaseSnapping.h"
#include "FrameField.h"

#include "Parallel.h"
#include "QuadFacing.h"
#include "QuadMeshAdjacency.h"
#include "QuadRelaxation.h"
#include "ScaledJacobian.h"
#include "SurfaceLocator.h"

#include <algorithm>
#include <stdexcept>

namespace quadcover
{

namespace
{
/// The quads still inside out after the repairs: their vertices also try short steps around
/// them (QuadRelaxOptions::unfold); kept only when fewer are inside out and none more faces
/// against the surface (decimated-knight's smoothest field at 3,000 quads: 1 -> 0).
void unfoldLastInverted(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, QuadFacingMemo& facings, QuadMesh& mesh)
{
  const std::vector<int> inverted = invertedQuads(mesh.V, mesh.Q);
  if (inverted.empty())
  {
    return;
  }
  const QuadMesh kept = mesh;
  const std::size_t turned = facings.turned(mesh).size();
  const auto [before, after] = repairQuads(
    V, F, topo, mesh, [](const QuadMesh& m) { return invertedQuads(m.V, m.Q); }, 2, 10, 3,
    Progress(), true);
  if (!(after < before) || facings.turned(mesh).size() > turned)
  {
    mesh = kept;
  }
}

/// Is quad i facing against the surface or inside out?
bool wrongQuad(QuadFacingMemo& facings, const QuadMesh& mesh, int i)
{
  return !(facings.worst(mesh, i) > 0);
}

/// Puts the corners of the quads that the relaxation turned against the surface or inside out
/// back where they were before it, until no quad that was right is wrong: relaxQuads checks each
/// move against the corners' normals only, not against the input's normal at the quad's centre.
/// Only quads with a moved corner are measured, those before the relaxation mostly known to
/// facings already. (Vertices put back: the truck 6 and 10 at 1,000 and 6,500 quads, the teapot
/// 4 at 6,500; none on armadillo, lion, cheburashka, decimated-knight and rocker-arm at either.)
void undoWrongMoves(QuadFacingMemo& facings, const QuadMesh& before, QuadMesh& mesh)
{
  const int nQ = static_cast<int>(mesh.Q.rows());
  auto moved = [&](int q) {
    for (int k = 0; k < 4; ++k)
    {
      if (mesh.V.row(mesh.Q(q, k)) != before.V.row(mesh.Q(q, k)))
      {
        return true;
      }
    }
    return false;
  };
  std::vector<int> watched; // quads with a moved corner that were right before
  for (int q = 0; q < nQ; ++q)
  {
    if (moved(q) && !wrongQuad(facings, before, q))
    {
      watched.push_back(q);
    }
  }
  for (bool again = true; again;)
  {
    again = false;
    for (const int q : watched)
    {
      if (!moved(q) || !wrongQuad(facings, mesh, q))
      {
        continue;
      }
      for (int k = 0; k < 4; ++k)
      {
        const int v = mesh.Q(q, k);
        if (mesh.V.row(v) != before.V.row(v))
        {
          mesh.V.row(v) = before.V.row(v);
          mesh.vertexTriangle[v] = before.vertexTriangle[v];
          mesh.vertexPoint[v] = before.vertexPoint[v];
          again = true;
        }
      }
    }
  }
}
}

QuadMeshResult buildQuadMesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixXd& cornerUV, const QuadMeshOptions& options,
  const Progress& progress)
{
  QuadMeshResult r;
  r.mesh = extractQuads(V, F, topo, cornerUV, options.extraction, progress.part(0.0, 0.5));
  // the holes filled first: their quads are extracted ones too, counted and repaired with the
  // others (counted before the fill, a fill's inverted quad appeared in the output's count only)
  if (options.fillHoles)
  {
    r.patch = patchQuadMesh(V, F, topo, r.mesh);
  }
  if (options.repairInvertedQuads)
  {
    r.invertedExtracted =
      repairInvertedQuads(V, F, topo, r.mesh, 2, 10, 3, progress.part(0.5, 0.7)).first;
  }
  else
  {
    r.invertedExtracted = countInvertedQuads(r.mesh.V, r.mesh.Q);
  }
  SurfaceLocator surface(V, F);
  surface.setComponents(topo.faceComponent);
  QuadFacingMemo facings(surface);
  const std::size_t turned = facings.turned(r.mesh).size();
  // as the evaluator counts them: with the quads measured by their own triangles (quadsToLift)
  const bool components = topo.numComponents() > 1;
  r.turnedExtracted =
    static_cast<int>(turned + (components ? quadsToLift(surface, r.mesh).size() : 0));
  // the quads facing against the surface or turned inside out, in index order
  auto bad = [&](const QuadMesh& m) {
    std::vector<int> list = facings.turned(m), inverted = invertedQuads(m.V, m.Q);
    list.insert(list.end(), inverted.begin(), inverted.end());
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    return list;
  };
  if (options.repairInvertedQuads && turned > 0)
  {
    // their neighbourhoods relaxed
    repairQuads(V, F, topo, r.mesh, bad, 2, 10, 3, progress.part(0.7, 0.73));
  }
  progress.report(0.75);
  if (options.repairInvertedQuads)
  {
    r.facing = repairFacing(V, F, topo, surface, r.mesh, &facings);
    unfoldLastInverted(V, F, topo, facings, r.mesh);
  }
  // the snapping and the relaxation last, so that the repairs above see the quads as the map
  // made them (moved first, a few vertices changed what the repairs did near the map's defects:
  // fandisk with feature lines at 6,500 quads, Hausdorff distance 0.40 -> 0.83%); the snapping
  // before the relaxation, which then evens out the quads beside the creases (the vertices moved
  // onto them stay: its creases are the same edges, at the same angle, and more)
  std::vector<int> steps; // held by the relaxation: beside a crease, not on it
  if (options.snapToCreases)
  {
    const std::vector<char> sharp = sharpEdges(
      topo, computeFaceBases(V, F, topo), options.featureAngle, options.minimumFeatureLength);
    r.snappedVertices = static_cast<int>(snapToCreases(V, F, topo, sharp, surface, r.mesh).size());
    steps = straightenCreaseSteps(V, F, topo, sharp, surface, r.mesh);
    r.snappedVertices += static_cast<int>(steps.size());
  }
  if (options.relaxationIterations > 0)
  {
    QuadRelaxOptions relax;
    if (!steps.empty())
    {
      relax.movable.assign(r.mesh.V.rows(), 1);
      for (const int v : steps)
      {
        relax.movable[v] = 0;
      }
    }
    relax.relaxationIterations = options.relaxationIterations;
    relax.holdAcrossBends = true;
    relax.featureAngle = options.featureAngle;
    const QuadMesh unrelaxed = r.mesh;
    relaxQuads(V, F, topo, r.mesh, relax, progress.part(0.75, 0.95));
    undoWrongMoves(facings, unrelaxed, r.mesh);
  }
  r.fragmentQuads = dropPinchedFragments(r.mesh, topo.faceComponent, PinchedFragmentQuads);
  r.fragmentQuads += dropPiecesAgainstRest(r.mesh, topo.faceComponent, PieceAgainstRestReach);
  if (options.repairInvertedQuads)
  {
    // what no move of the corners mended (the tip of a tube thinner than the quads, a quad
    // squeezed between two others): a change of the connectivity
    r.collapse = removeTurnedQuads(surface, bad(r.mesh), r.mesh);
  }
  // the quads whose centre lies nearer another component's sheet, the last move: the
  // relaxation's projections would put their corners back onto the surface (one more search a
  // quad, so only where there are other components)
  const SheetLift lift = components ? liftOffOtherComponents(surface, r.mesh) : SheetLift();
  r.liftedVertices = lift.liftedVertices;
  r.turnedQuads = static_cast<int>(facings.turned(r.mesh).size()) + lift.remaining;
  r.splitVertices = splitPinchedVertices(r.mesh);
  r.quality = measureQuads(r.mesh.V, r.mesh.Q);
  for (Eigen::Index i = 0; i < r.quality.scaledJacobian.size(); ++i)
  {
    r.invertedFinal += !(r.quality.scaledJacobian[i] > 0);
  }
  r.emptyComponents = componentsWithoutQuads(topo, r.mesh);
  progress.report(1.0);
  return r;
}

int componentsWithoutQuads(const MeshTopology& topo, const QuadMesh& mesh)
{
  const int nQ = static_cast<int>(mesh.Q.rows());
  const int nF = static_cast<int>(topo.faceComponent.size());
  const bool perQuad = mesh.quadTriangle.size() == static_cast<std::size_t>(nQ);
  std::vector<char> meshed(topo.numComponents(), 0);
  for (int q = 0; q < nQ; ++q)
  {
    const int corner = mesh.Q(q, 0);
    const int t = perQuad ? mesh.quadTriangle[q]
                          : (corner >= 0 && corner < static_cast<int>(mesh.vertexTriangle.size())
                                ? mesh.vertexTriangle[corner]
                                : -1);
    if (t >= 0 && t < nF && topo.faceComponent[t] >= 0)
    {
      meshed[topo.faceComponent[t]] = 1;
    }
  }
  // (every component has a triangle: they are the triangles' components)
  return static_cast<int>(std::count(meshed.begin(), meshed.end(), 0));
}

Eigen::MatrixX3d joinSplitPoints(
  const Eigen::MatrixX3d& V, Eigen::MatrixX3i& F, const std::vector<int>& pointId)
{
  const int n = static_cast<int>(V.rows());
  if (static_cast<int>(pointId.size()) != n)
  {
    throw std::invalid_argument("joinSplitPoints: one id per point is needed");
  }
  int top = -1;
  for (const int id : pointId)
  {
    if (id < 0 || id >= n)
    {
      throw std::invalid_argument("joinSplitPoints: a point id is out of range");
    }
    top = std::max(top, id);
  }
  Eigen::MatrixX3d joined = Eigen::MatrixX3d::Zero(top + 1, 3);
  for (int p = 0; p < n; ++p)
  {
    joined.row(pointId[p]) = V.row(p);
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (F(f, k) < 0 || F(f, k) >= n)
      {
        throw std::invalid_argument("joinSplitPoints: a triangle refers to a point that does not "
                                    "exist");
      }
      F(f, k) = pointId[F(f, k)];
    }
  }
  return joined;
}

bool splitPointsCoincide(const Eigen::MatrixX3d& V, const std::vector<int>& pointId)
{
  std::vector<int> first(V.rows(), -1); // the first point of each id
  for (int p = 0; p < static_cast<int>(pointId.size()); ++p)
  {
    int& f = first[pointId[p]];
    if (f < 0)
    {
      f = p;
    }
    else if (V.row(f) != V.row(p))
    {
      return false;
    }
  }
  return true;
}

Eigen::MatrixX3i quadTriangles(const Eigen::MatrixX4i& Q)
{
  Eigen::MatrixX3i T(2 * Q.rows(), 3);
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
  {
    T.row(2 * i) << Q(i, 0), Q(i, 1), Q(i, 2);
    T.row(2 * i + 1) << Q(i, 0), Q(i, 2), Q(i, 3);
  }
  return T;
}

HausdorffSamples hausdorffSamples(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const Eigen::MatrixX3d& quadV, const Eigen::MatrixX4i& Q)
{
  HausdorffSamples s;
  s.quadTriangles = quadTriangles(Q);
  s.quadPoints.resize(quadV.rows() + 5 * Q.rows(), 3);
  s.quadPoints.topRows(quadV.rows()) = quadV;
  Eigen::Index next = quadV.rows();
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
  {
    const auto q = Q.row(i);
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k)
    {
      s.quadPoints.row(next++) = 0.5 * (quadV.row(q[k]) + quadV.row(q[(k + 1) % 4]));
      centre += 0.25 * quadV.row(q[k]);
    }
    s.quadPoints.row(next++) = centre;
  }
  // only the points triangles use: a joined or messy surface may have others
  std::vector<char> used(V.rows(), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    used[F(f, 0)] = used[F(f, 1)] = used[F(f, 2)] = 1;
  }
  s.surfacePoints.resize(std::count(used.begin(), used.end(), 1), 3);
  for (Eigen::Index v = 0, i = 0; v < V.rows(); ++v)
  {
    if (used[v])
    {
      s.surfacePoints.row(i++) = V.row(v);
    }
  }
  if (s.surfacePoints.rows() > 0)
  {
    s.diagonal =
      (s.surfacePoints.colwise().maxCoeff() - s.surfacePoints.colwise().minCoeff()).norm();
  }
  return s;
}

double largestDistance(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& V,
  const Eigen::MatrixX3i& F, int threads)
{
  const SurfaceLocator locator(V, F);
  const int n = static_cast<int>(points.rows());
  std::vector<double> largest(std::max(1, threadCount(threads)), 0.0);
  // each thread keeps its own largest: a maximum does not depend on how the points are shared
  parallelFor(n, threads, [&](int begin, int end, int thread) {
    for (int i = begin; i < end; ++i)
    {
      largest[thread] = std::max(largest[thread], locator.closest(points.row(i).transpose()).distance);
    }
  });
  return *std::max_element(largest.begin(), largest.end());
}

}
