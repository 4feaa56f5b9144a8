// QuadsOntoSource.cxx: putQuadsOnto.
#include "QuadsOntoSource.h"

#include "Parallel.h"
#include "QuadCollapse.h"
#include "QuadMeshAdjacency.h"
#include "QuadQuality.h"
#include "ScaledJacobian.h"
#include "SurfaceLocator.h"

#include <algorithm>
#include <atomic>
#include <vector>

namespace quadcover
{
namespace
{
/// How quads face a surface (V, F) whose own triangles may be turned over (a raw input): each
/// triangle's normal is turned as the working surface the quads were made on faces beside it.
class SourceFacing
{
public:
  SourceFacing(const Eigen::MatrixX3d& workV, const Eigen::MatrixX3i& workF,
    const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
    : source(V, F)
    , working_(workV, workF)
    , V_(V)
    , F_(F)
    , turn_(static_cast<std::size_t>(F.rows()))
  {
    for (auto& t : turn_)
    {
      t.store(0, std::memory_order_relaxed);
    }
  }

  /// The cosine between quad q's normal and that of the triangle closest to its centre; -1 for
  /// a quad of zero area.
  double operator()(const QuadMesh& mesh, int q) const
  {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
    {
      centre += mesh.V.row(mesh.Q(q, k)).transpose() / 4.0;
    }
    const int t = source.closest(centre).triangle;
    const Eigen::Vector3d area = quadAreaVector(mesh.V, mesh.Q, q);
    return t < 0 || !(area.norm() > 0.0) ? -1.0 : area.normalized().dot(normal(t));
  }

  const SurfaceLocator source;

private:
  /// Triangle t's normal, turned where the working surface closest to its centre faces the other
  /// way (worked out once a triangle; each thread that asks first gets the same).
  Eigen::Vector3d normal(int t) const
  {
    signed char turn = turn_[t].load(std::memory_order_relaxed);
    const Eigen::Vector3d n = source.normal(t);
    if (turn == 0)
    {
      const Eigen::Vector3d centre = (V_.row(F_(t, 0)) + V_.row(F_(t, 1)) + V_.row(F_(t, 2))) / 3.0;
      const int w = working_.closest(centre.transpose()).triangle;
      turn = w >= 0 && n.dot(working_.normal(w)) < 0.0 ? -1 : 1;
      turn_[t].store(turn, std::memory_order_relaxed);
    }
    return turn * n;
  }

  const SurfaceLocator working_;
  const Eigen::MatrixX3d& V_;
  const Eigen::MatrixX3i& F_;
  mutable std::vector<std::atomic<signed char>> turn_;
};

/// Calls body(i) for i in [0, n) on the threads.
template<typename Body>
void forEach(int n, Body&& body)
{
  parallelFor(n, 0, [&](int begin, int end, int) {
    for (int i = begin; i < end; ++i)
    {
      body(i);
    }
  });
}
}

void putQuadsOnto(QuadMeshResult& r, const Eigen::MatrixX3d& workV, const Eigen::MatrixX3i& workF,
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, bool removeTurned)
{
  QuadMesh& quads = r.mesh;
  const int nQ = static_cast<int>(quads.Q.rows());
  const SourceFacing facing(workV, workF, V, F);
  std::vector<double> cosine(nQ);
  std::vector<char> faced(nQ), wasInverted(nQ);
  forEach(nQ, [&](int q) {
    faced[q] = facing(quads, q) > 0.0;
    wasInverted[q] = quadScaledJacobian(quads.V, quads.Q, q) <= 0.0;
  });
  const Eigen::MatrixX3d before = quads.V;
  forEach(static_cast<int>(quads.V.rows()), [&](int v) {
    const SurfaceLocator::Hit hit = facing.source.closest(quads.V.row(v).transpose());
    if (hit.triangle >= 0)
    {
      quads.V.row(v) = hit.point.transpose();
    }
  });
  // every quad first, then those beside a vertex put back
  const VertexQuads around = vertexQuads(quads);
  std::vector<int> check(nQ);
  for (int q = 0; q < nQ; ++q)
  {
    check[q] = q;
  }
  while (!check.empty())
  {
    std::vector<char> wrong(check.size());
    forEach(static_cast<int>(check.size()), [&](int i) {
      const int q = check[i];
      cosine[q] = facing(quads, q);
      wrong[i] =
        quadAreaVector(quads.V, quads.Q, q).dot(quadAreaVector(before, quads.Q, q)) <= 0.0 ||
        (!wasInverted[q] && quadScaledJacobian(quads.V, quads.Q, q) <= 0.0) ||
        (faced[q] && !(cosine[q] > 0.0));
    });
    std::vector<int> next;
    for (std::size_t i = 0; i < check.size(); ++i)
    {
      for (int k = 0; wrong[i] && k < 4; ++k)
      {
        const int v = quads.Q(check[i], k);
        if (quads.V.row(v) != before.row(v))
        {
          quads.V.row(v) = before.row(v);
          next.insert(next.end(), around.quads.begin() + around.offsets[v],
            around.quads.begin() + around.offsets[v + 1]);
        }
      }
    }
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    check = std::move(next);
  }
  // quads that face against (V, F) or are inside out as they are: a thin part whose working
  // surface lies farther from its other side than the quads bulge
  std::vector<int> bad;
  for (int q = 0; removeTurned && q < nQ; ++q)
  {
    if (!(cosine[q] > 0.0) || !(quadScaledJacobian(quads.V, quads.Q, q) > 0.0))
    {
      bad.push_back(q);
    }
  }
  const QuadJudge judge{ [&](const QuadMesh& mesh, int q) {
                          return std::min(facing(mesh, q), quadScaledJacobian(mesh.V, mesh.Q, q));
                        },
    [&](const Eigen::Vector3d& p) { return facing.source.closest(p); } };
  const QuadCollapseResult collapse = removeTurnedQuads(judge, bad, quads);
  r.collapse.ears += collapse.ears;
  r.collapse.collapsed += collapse.collapsed;
  r.quality = measureQuads(quads.V, quads.Q);
  r.invertedFinal = countInvertedQuads(quads.V, quads.Q);
}

}
