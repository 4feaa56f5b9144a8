// Untangler.h: internal to Core: foldover-free untangling of the flipped triangles of the
// integer-grid map (Garanzha et al. 2021), moving only real unknowns near them.
#ifndef quadcover_Untangler_h
#define quadcover_Untangler_h

#include "MeshTopology.h"
#include "Progress.h"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <utility>
#include <vector>

namespace quadcover
{
namespace param
{
/// One triangle's untangling energy at its Jacobian J (relative to the grid), with its gradient
/// and Hessian in J's entries (J00, J01, J10, J11) where asked.
double triangleEnergy(const Eigen::Matrix2d& J, double eps, double theta,
  Eigen::Matrix2d* gradient = nullptr, Eigen::Matrix4d* hessian = nullptr);

/// triangleEnergy's Hessian at J with each eigenvalue replaced by its absolute value, from its
/// eigenvectors in closed form: semidefinite, and where the Hessian curves down (folds, saddles)
/// as steep upwards, so that Newton steps leave a saddle instead of crawling along it.
Eigen::Matrix4d absoluteHessian(const Eigen::Matrix2d& J, double eps, double theta);

/**
 * Removes flipped triangles from a map x = (real unknowns, integer unknowns) by moving only real
 * unknowns near them: the foldover-free untangling of Garanzha et al. (2021). Each triangle's
 * Jacobian J (relative to the grid, so 1 is a perfect unit cell) pays
 *   (1 - theta) tr(J^T J) / chi(det J) + theta (det^2 J + 1) / chi(det J),
 *   chi(d) = (d + sqrt(eps^2 + d^2)) / 2,
 * a smooth stand-in for a barrier against det J <= 0 that stays finite on flipped triangles; eps
 * shrinks with the most negative determinant, so the minimizer becomes foldover-free. Each eps is
 * minimized by Newton steps on the sum of the triangles' Hessians with their negative eigenvalues
 * made positive (absoluteHessian), a sparse Cholesky factorization each.
 * The unknowns moved are those of the triangles within `rings` rings of a flipped one; every
 * triangle they touch is in the energy.
 */
struct Untangler
{
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& Dr; // rows of D: 4 per triangle
  const Eigen::SparseMatrix<double>& Dc;                  // the same, by column
  const Eigen::VectorXd& sqrtArea;                        // per triangle, 0 if skipped
  double edgeLength;                                      // h: J relative to the unit cell
  /// per triangle, its grid edge over h (SeamlessSystem::cellScale; empty: 1 everywhere)
  const Eigen::VectorXd& cellScale;
  int numReal;
  /// Work left, in triangle energy evaluations, shared by every run of one repair: runs stop
  /// when it is spent (nullptr: no limit); a Newton step's Hessian and its factorization count
  /// as LocalEnergy::HessianCost evaluations a face, about what they take in time on a
  /// neighbourhood of a few rings; a pass on a wide one (16 rings around a hundred flips) took
  /// about four times as long per evaluation counted, its larger factorizations the likely
  /// cause (Benchmarks/README.md, 2026-12-06 (5)). Counting work, not seconds, keeps the result
  /// the same on every machine.
  long long* work = nullptr;
  static constexpr double DefaultTheta = 0.25;
  double theta = DefaultTheta;
  /// Worker threads (0: defaultThreadCount()); the result does not depend on it.
  int numberOfThreads = 0;

  bool spent() const { return work && *work <= 0; }

  /// Untangles around `flipped` (faces), moving real unknowns not `frozen` (empty: none is);
  /// callers recount the flips. Reports once per Newton step (approaching 1, as the number of
  /// steps is not known beforehand).
  void run(const MeshTopology& topo, const Eigen::MatrixX3i& F, const std::vector<int>& flipped,
    int rings, int maxRounds, Eigen::VectorXd& x, const std::vector<char>& frozen,
    const Progress& progress) const;

private:
  /// The real unknowns (not frozen) that the rows of the faces in the region use, in order.
  std::vector<int> freeColumns(
    const std::vector<char>& inRegion, const std::vector<char>& frozen) const;
  /// The faces (with area) whose rows use any of the columns.
  std::vector<int> facesUsing(const std::vector<int>& columns) const;
  /// The columns split into pieces that no face's rows join, each with the faces using it.
  std::vector<std::pair<std::vector<int>, std::vector<int>>> pieces(
    const std::vector<int>& columns, const std::vector<int>& faces) const;
};
}
}

#endif
