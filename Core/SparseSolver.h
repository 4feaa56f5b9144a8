// SparseSolver.h: the sparse symmetric (Hermitian) positive definite solver of the core.
// CHOLMOD's Cholesky (SuiteSparse; supernodal, or simplicial where asked) when the build found
// it, else Eigen's SimplicialLDLT (CMake reports which at configure time). At a million
// triangles CHOLMOD factors the smoother's complex system about seven times faster
// (Benchmarks/README.md).
#ifndef quadcover_SparseSolver_h
#define quadcover_SparseSolver_h

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <new>
#include <type_traits>
#include <vector>

#ifdef QUADCOVER_HAVE_CHOLMOD
#include "CholmodThreads.h"

#include <Eigen/CholmodSupport>
#include <cholmod_camd.h>
#endif

namespace quadcover
{
/// How the factor is stored. Supernodal: in dense blocks factored and applied by the BLAS, the
/// fastest to factor a system with much fill. Simplicial: a column at a time, without the BLAS;
/// on surface meshes the supernodes are small, a BLAS call each, and its solves take half the
/// time (Benchmarks/README.md): for a system solved many times.
enum class Factorization
{
  Supernodal,
  Simplicial,
  /// Simplicial where the factor costs fewer than 100 flops per entry, else supernodal: a
  /// triangle's three neighbours leave little fill on a mesh of 100k triangles (armadillo's
  /// frame systems: 61 flops per entry, simplicial factored in 0.2 s against 0.35 s), and
  /// more on finer ones (four times as many triangles: a tie).
  Automatic
};

#ifdef QUADCOVER_HAVE_CHOLMOD
/**
 * Eigen's CholmodSupernodalLLT (or, with Factorization::Simplicial, CHOLMOD's simplicial
 * factor, which calls no BLAS) with the BLAS on one thread and CHOLMOD's OpenMP loops under
 * OpenMP's dynamic adjustment wherever CHOLMOD runs (CholmodThreads.h), so that the result does
 * not depend on the BLAS thread count and CHOLMOD's threads need not outnumber the cores.
 * compute() and solve() are used as Eigen's; the solves run when the solve() expression is
 * assigned, which calls _solve_impl below.
 */
template<typename MatrixType>
class CholmodLLT : public Eigen::CholmodBase<MatrixType, Eigen::Lower, CholmodLLT<MatrixType>>
{
  using Base = Eigen::CholmodBase<MatrixType, Eigen::Lower, CholmodLLT<MatrixType>>;

public:
  explicit CholmodLLT(Factorization storage = Factorization::Supernodal)
  {
    this->m_cholmod.final_asis = 1;
    this->m_cholmod.supernodal = storage == Factorization::Supernodal ? CHOLMOD_SUPERNODAL
      : storage == Factorization::Simplicial                          ? CHOLMOD_SIMPLICIAL
                                                                      : CHOLMOD_AUTO;
    this->m_cholmod.supernodal_switch = 100.0;
  }

  CholmodLLT& compute(const MatrixType& matrix)
  {
    this->analyzePattern(matrix);
    this->factorize(matrix);
    return *this;
  }

  void analyzePattern(const MatrixType& matrix)
  {
    const CholmodThreads threads;
    Base::analyzePattern(matrix);
  }

  /// analyzePattern, with the last `last` unknowns ordered after all others (CAMD, the
  /// constrained minimum degree), so that inverseOfLast can read their block of the inverse off
  /// the factor. Plain analyzePattern when last <= 0 or CAMD or the analysis fails.
  void analyzePatternWithLast(const MatrixType& matrix, int last)
  {
    const int n = static_cast<int>(matrix.rows());
    if (last <= 0 || last > n)
    {
      this->analyzePattern(matrix);
      return;
    }
    if (this->m_cholmodFactor)
    {
      cholmod_free_factor(&this->m_cholmodFactor, &this->m_cholmod);
      this->m_cholmodFactor = nullptr;
    }
    cholmod_sparse A = Eigen::viewAsCholmod(matrix.template selfadjointView<Eigen::Lower>());
    std::vector<int> member(n, 0), perm(n);
    std::fill(member.end() - last, member.end(), 1);
    const CholmodThreads threads;
    cholmod_common& c = this->m_cholmod;
    // rows denser than 5 sqrt(n) ordered last without elimination (CAMD's default is 10): the
    // integers of long seams reach a few thousand entries in the map's system and took CAMD
    // 0.25 s at 86k unknowns, 0.07 s at 5 (Benchmarks/README.md)
    const int current = c.current; // cholmod_camd reads the current method's controls
    const double dense = c.method[0].prune_dense;
    c.current = 0;
    c.method[0].prune_dense = 5.0;
    const int ordered = cholmod_camd(&A, nullptr, 0, member.data(), perm.data(), &c);
    c.method[0].prune_dense = dense;
    c.current = current;
    if (!ordered)
    {
      this->analyzePattern(matrix);
      return;
    }
    const int methods = c.nmethods, ordering = c.method[0].ordering;
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
    this->m_cholmodFactor = cholmod_analyze_p(&A, perm.data(), nullptr, 0, &c);
    c.nmethods = methods;
    c.method[0].ordering = ordering;
    if (!this->m_cholmodFactor)
    {
      this->analyzePattern(matrix);
      return;
    }
    this->m_isInitialized = true;
    this->m_info = Eigen::Success;
    this->m_analysisIsOk = true;
    this->m_factorizationIsOk = false;
  }

  /**
   * The block of the inverse of the factored (real) matrix at its last `last` unknowns, from
   * the factor: when they are the factor's last columns (analyzePatternWithLast; the elimination
   * tree's postorder may move them), with L22 the factor's trailing block that block is
   * (L22 L22^T)^-1, a dense last x last computation instead of `last` solves. False (S
   * untouched) when the factor does not end with them or is not supernodal.
   */
  bool inverseOfLast(int last, Eigen::MatrixXd& S) const
  {
    static_assert(std::is_same<typename MatrixType::Scalar, double>::value, "real only");
    const cholmod_factor* L = this->m_cholmodFactor;
    if (!L || !this->m_factorizationIsOk || this->m_info != Eigen::Success || !L->is_super ||
      last <= 0 || static_cast<std::size_t>(last) > L->n)
    {
      return false;
    }
    const int n = static_cast<int>(L->n), first = n - last;
    const int* perm = static_cast<const int*>(L->Perm);
    for (int p = first; p < n; ++p)
    {
      if (perm[p] < first)
      {
        return false;
      }
    }
    const int* super = static_cast<const int*>(L->super);
    const int* pi = static_cast<const int*>(L->pi);
    const int* px = static_cast<const int*>(L->px);
    const int* rows = static_cast<const int*>(L->s);
    const double* x = static_cast<const double*>(L->x);
    Eigen::MatrixXd L22 = Eigen::MatrixXd::Zero(last, last);
    for (std::size_t s = 0; s < L->nsuper; ++s)
    {
      const int k1 = super[s], k2 = super[s + 1], nsrow = pi[s + 1] - pi[s];
      for (int j = std::max(k1, first); j < k2; ++j)
      {
        // rows of a supernode: its own columns first, then the rest, ascending
        for (int i = j - k1; i < nsrow; ++i)
        {
          L22(rows[pi[s] + i] - first, j - first) = x[px[s] + i + (j - k1) * nsrow];
        }
      }
    }
    const Eigen::MatrixXd W =
      L22.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(last, last));
    const Eigen::MatrixXd inverse = W.transpose() * W;
    S.resize(last, last);
    for (int p = 0; p < last; ++p)
    {
      for (int q = 0; q < last; ++q)
      {
        S(perm[first + p] - first, perm[first + q] - first) = inverse(p, q);
      }
    }
    return true;
  }

  void factorize(const MatrixType& matrix)
  {
    const CholmodThreads threads;
    Base::factorize(matrix);
  }

  /// solve(b) that several threads may call at once on one factor: CHOLMOD's workspace and
  /// counters are then a cholmod_common of the call's own, not the solver's. The same call to
  /// cholmod_solve as solve(b), so the same numbers; std::bad_alloc where CHOLMOD fails.
  Eigen::Matrix<typename MatrixType::Scalar, Eigen::Dynamic, 1> solveConcurrently(
    const Eigen::Matrix<typename MatrixType::Scalar, Eigen::Dynamic, 1>& b) const
  {
    return this->solveOwnCommon(b);
  }

  /// solve(b) of the columns of b, in one pass over the factor, that several threads may call
  /// at once: the same numbers as solve(b) (not bit for bit those of each column solved alone).
  Eigen::Matrix<typename MatrixType::Scalar, Eigen::Dynamic, Eigen::Dynamic>
  solveColumnsConcurrently(
    const Eigen::Matrix<typename MatrixType::Scalar, Eigen::Dynamic, Eigen::Dynamic>& b) const
  {
    return this->solveOwnCommon(b);
  }

private:
  template<typename Dense>
  Dense solveOwnCommon(const Dense& b) const
  {
    eigen_assert(this->m_factorizationIsOk && "solveConcurrently() needs a factorization");
    if (!this->m_factorizationIsOk || b.rows() != static_cast<Eigen::Index>(this->rows()))
    {
      return Dense();
    }
    const CholmodThreads threads;
    // freed on every way out, the copy's bad_alloc included
    struct Workspace
    {
      cholmod_common c;
      cholmod_dense* X = nullptr;
      Workspace() { cholmod_start(&c); }
      ~Workspace()
      {
        cholmod_free_dense(&X, &c);
        cholmod_finish(&c);
      }
    } w;
    Dense rhs = b;
    cholmod_dense B = Eigen::viewAsCholmod(rhs);
    w.X = cholmod_solve(CHOLMOD_A, this->m_cholmodFactor, &B, &w.c);
    if (!w.X)
    {
      throw std::bad_alloc(); // what cholmod_solve fails on with a factor: its workspace
    }
    return Dense(Eigen::Map<const Dense>(
      static_cast<const typename MatrixType::Scalar*>(w.X->x), b.rows(), b.cols()));
  }

public:
  template<typename Rhs, typename Dest>
  void _solve_impl(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest) const
  {
    const CholmodThreads threads;
    Base::_solve_impl(b, dest);
  }

  template<typename Rhs, typename Dest>
  void _solve_impl(const Eigen::SparseMatrixBase<Rhs>& b, Eigen::SparseMatrixBase<Dest>& dest) const
  {
    const CholmodThreads threads;
    Base::_solve_impl(b, dest);
  }
};

template<typename Scalar>
using SpdSolver = CholmodLLT<Eigen::SparseMatrix<Scalar>>;
#else
/// Eigen's SimplicialLDLT (simplicial whatever the storage asked; no block of the inverse
/// from its factor).
template<typename Scalar>
class SpdSolver : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>>
{
public:
  explicit SpdSolver(Factorization = Factorization::Supernodal) {}
  void analyzePatternWithLast(const Eigen::SparseMatrix<Scalar>& matrix, int)
  {
    this->analyzePattern(matrix);
  }
  bool inverseOfLast(int, Eigen::MatrixXd&) const { return false; }
  /// solve(b); Eigen's solves keep no state in the solver.
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> solveConcurrently(
    const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& b) const
  {
    return this->solve(b);
  }
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> solveColumnsConcurrently(
    const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& b) const
  {
    return this->solve(b);
  }
};
#endif
}

#endif
