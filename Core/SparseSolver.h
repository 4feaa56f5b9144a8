// SparseSolver.h: the sparse symmetric (Hermitian) positive definite solver of the core.
// CHOLMOD's Cholesky (SuiteSparse; supernodal, or simplicial where asked) when the build found
// it, else Eigen's SimplicialLDLT (CMake reports which at configure time). At a million
// triangles CHOLMOD factors the smoother's complex system about seven times faster
// (Benchmarks/README.md).
#ifndef quadcover_SparseSolver_h
#define quadcover_SparseSolver_h

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#ifdef QUADCOVER_HAVE_CHOLMOD
#include "BlasThreads.h"

#include <Eigen/CholmodSupport>
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
  Simplicial
};

#ifdef QUADCOVER_HAVE_CHOLMOD
/**
 * Eigen's CholmodSupernodalLLT with the BLAS on one thread wherever CHOLMOD calls it (the
 * numeric factorization and the solves; the analysis uses no BLAS), so that the result does not
 * depend on the BLAS thread count (BlasThreads.h). compute() and solve() are used as Eigen's;
 * the solves run when the solve() expression is assigned, which calls _solve_impl below.
 */
template<typename MatrixType>
class CholmodLLT : public Eigen::CholmodBase<MatrixType, Eigen::Lower, CholmodLLT<MatrixType>>
{
  using Base = Eigen::CholmodBase<MatrixType, Eigen::Lower, CholmodLLT<MatrixType>>;

public:
  explicit CholmodLLT(Factorization storage = Factorization::Supernodal)
  {
    this->m_cholmod.final_asis = 1;
    this->m_cholmod.supernodal =
      storage == Factorization::Supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  }

  CholmodLLT& compute(const MatrixType& matrix)
  {
    this->analyzePattern(matrix);
    this->factorize(matrix);
    return *this;
  }

  void factorize(const MatrixType& matrix)
  {
    const OneBlasThread one;
    Base::factorize(matrix);
  }

  template<typename Rhs, typename Dest>
  void _solve_impl(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dest>& dest) const
  {
    const OneBlasThread one;
    Base::_solve_impl(b, dest);
  }

  template<typename Rhs, typename Dest>
  void _solve_impl(const Eigen::SparseMatrixBase<Rhs>& b, Eigen::SparseMatrixBase<Dest>& dest) const
  {
    const OneBlasThread one;
    Base::_solve_impl(b, dest);
  }
};

template<typename Scalar>
using SpdSolver = CholmodLLT<Eigen::SparseMatrix<Scalar>>;
#else
/// Eigen's SimplicialLDLT (simplicial whatever the storage asked).
template<typename Scalar>
class SpdSolver : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>>
{
public:
  explicit SpdSolver(Factorization = Factorization::Supernodal) {}
};
#endif
}

#endif
