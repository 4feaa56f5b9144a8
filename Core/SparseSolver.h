// SparseSolver.h: the sparse symmetric (Hermitian) positive definite solver of the core.
// CHOLMOD's supernodal Cholesky (SuiteSparse) when the build found it, else Eigen's
// SimplicialLDLT (CMake reports which at configure time). At a million triangles CHOLMOD factors
// the smoother's complex system about seven times faster (Benchmarks/README.md).
#ifndef quadcover_SparseSolver_h
#define quadcover_SparseSolver_h

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#ifdef QUADCOVER_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace quadcover
{
#ifdef QUADCOVER_HAVE_CHOLMOD
template<typename Scalar>
using SpdSolver = Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<Scalar>>;
#else
template<typename Scalar>
using SpdSolver = Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>>;
#endif
}

#endif
