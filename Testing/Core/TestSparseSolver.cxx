// The core's sparse solver: solves in both storages, and the block of the inverse at the last
// unknowns read off the factor, against dense linear algebra.
#include "SparseSolver.h"

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include <thread>
#include <vector>

using namespace quadcover;

namespace
{
/// A grid Laplacian (side x side) plus a small mass, and `last` unknowns after it, each coupled
/// to a dozen grid points spread over the grid (as the map's integer translations are to the
/// points along their seam) and to the next: symmetric positive definite.
Eigen::SparseMatrix<double> seamLikeSystem(int side, int last)
{
  const int grid = side * side, n = grid + last;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(n, 0.01);
  auto link = [&](int a, int b, double w) {
    t.emplace_back(a, b, -w);
    t.emplace_back(b, a, -w);
    diagonal[a] += w;
    diagonal[b] += w;
  };
  for (int r = 0; r < side; ++r)
  {
    for (int c = 0; c < side; ++c)
    {
      const int i = r * side + c;
      if (c + 1 < side)
        link(i, i + 1, 1.0);
      if (r + 1 < side)
        link(i, i + side, 1.0 + 0.1 * (r % 3));
    }
  }
  for (int k = 0; k < last; ++k)
  {
    for (int j = 0; j < 12; ++j)
    {
      link(grid + k, (37 * k + 53 * j) % grid, 0.3);
    }
    if (k + 1 < last)
      link(grid + k, grid + k + 1, 0.5);
  }
  for (int i = 0; i < n; ++i)
  {
    t.emplace_back(i, i, diagonal[i]);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}
}

TEST(SparseSolver, SolvesMatchDenseInBothStorages)
{
  const Eigen::SparseMatrix<double> A = seamLikeSystem(20, 8);
  const Eigen::MatrixXd dense(A);
  Eigen::VectorXd b(A.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i)
  {
    b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.1;
  }
  const Eigen::VectorXd expected = dense.llt().solve(b);
  for (const Factorization storage :
    { Factorization::Supernodal, Factorization::Simplicial, Factorization::Automatic })
  {
    SpdSolver<double> solver(storage);
    solver.compute(A);
    ASSERT_EQ(solver.info(), Eigen::Success);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-10 * expected.cwiseAbs().maxCoeff());
    // the same bits from solves on several threads at once, each with its own workspace
    std::vector<Eigen::VectorXd> concurrent(4);
    std::vector<std::thread> threads;
    for (auto& y : concurrent)
    {
      threads.emplace_back([&solver, &b, &y]() {
        for (int repeat = 0; repeat < 50; ++repeat)
        {
          y = solver.solveConcurrently(b);
        }
      });
    }
    for (auto& thread : threads)
    {
      thread.join();
    }
    for (const auto& y : concurrent)
    {
      EXPECT_EQ(y, x);
    }
    // and of several columns at once, as solve(B) gives them
    Eigen::MatrixXd B(A.rows(), 3);
    B << b, b.reverse(), b.cwiseAbs2();
    const Eigen::MatrixXd X = solver.solve(B);
    std::vector<Eigen::MatrixXd> columns(2);
    threads.clear();
    for (auto& Y : columns)
    {
      threads.emplace_back([&solver, &B, &Y]() {
        for (int repeat = 0; repeat < 50; ++repeat)
        {
          Y = solver.solveColumnsConcurrently(B);
        }
      });
    }
    for (auto& thread : threads)
    {
      thread.join();
    }
    for (const auto& Y : columns)
    {
      EXPECT_EQ(Y, X);
    }
    // (not bit for bit each column's own solve: the BLAS sums a block of columns otherwise)
    EXPECT_LT((X.col(0) - x).cwiseAbs().maxCoeff(), 1e-12 * x.cwiseAbs().maxCoeff());
  }
}

TEST(SparseSolver, InverseOfTheLastUnknownsComesOffTheFactor)
{
  const int last = 10;
  const Eigen::SparseMatrix<double> A = seamLikeSystem(24, last);
  const Eigen::Index n = A.rows();
  const Eigen::MatrixXd inverse = Eigen::MatrixXd(A).llt().solve(Eigen::MatrixXd::Identity(n, n));
  const Eigen::MatrixXd expected = inverse.bottomRightCorner(last, last);

  SpdSolver<double> solver;
  solver.analyzePatternWithLast(A, last);
  solver.factorize(A);
  ASSERT_EQ(solver.info(), Eigen::Success);
  Eigen::MatrixXd S;
  const bool read = solver.inverseOfLast(last, S);
#ifdef QUADCOVER_HAVE_CHOLMOD
  ASSERT_TRUE(read) << "the last unknowns did not end the supernodal factor";
  ASSERT_EQ(S.rows(), last);
  ASSERT_EQ(S.cols(), last);
  EXPECT_LT((S - expected).cwiseAbs().maxCoeff(), 1e-10 * expected.cwiseAbs().maxCoeff());
  EXPECT_LT((S - S.transpose()).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
#else
  EXPECT_FALSE(read); // Eigen's fallback: the caller solves for the block instead
#endif
  // the constrained ordering changes nothing in the solves
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const Eigen::VectorXd x = solver.solve(b);
  EXPECT_LT((A * x - b).cwiseAbs().maxCoeff(), 1e-10);

  // a simplicial factor is not read
  SpdSolver<double> simplicial(Factorization::Simplicial);
  simplicial.analyzePatternWithLast(A, last);
  simplicial.factorize(A);
  ASSERT_EQ(simplicial.info(), Eigen::Success);
  Eigen::MatrixXd untouched(1, 1);
  EXPECT_FALSE(simplicial.inverseOfLast(last, untouched));
  EXPECT_EQ(untouched.rows(), 1);
}

#ifdef QUADCOVER_HAVE_CHOLMOD
TEST(SparseSolver, CholmodCallsRunOnOneBlasThreadWithDynamicOpenMP)
{
  const auto& control = detail::CholmodThreadControl::instance();
  if (!CholmodThreads::controlsOpenMP() || !CholmodThreads::controlsBlas())
  {
    GTEST_SKIP() << "CHOLMOD is loaded without OpenMP or without OpenBLAS";
  }
  const int dynamic = control.getDynamic(), blas = control.get();
  {
    const CholmodThreads outer;
    EXPECT_EQ(control.getDynamic(), 1);
    EXPECT_EQ(control.get(), 1);
    // the dynamic adjustment is the calling thread's own: another thread does not see it
    int other = -1;
    std::thread([&]() { other = control.getDynamic(); }).join();
    EXPECT_EQ(other, dynamic);
    {
      const CholmodThreads inner; // nested: the outer one's settings stay
      EXPECT_EQ(control.getDynamic(), 1);
    }
    EXPECT_EQ(control.getDynamic(), 1);
    EXPECT_EQ(control.get(), 1);
  }
  // both back as they were
  EXPECT_EQ(control.getDynamic(), dynamic);
  EXPECT_EQ(control.get(), blas);
}
#endif
