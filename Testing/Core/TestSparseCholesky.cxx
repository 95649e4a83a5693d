// SparseCholesky on shifted grid Laplacians small and large enough for each backend: the
// solutions must satisfy the systems, and a refactorization with new values (same pattern)
// must solve the new system, not the old one; so for a factorization made for many solves,
// whose backend differs below the supernodal size.
#include "SparseCholesky.h"
#include "CoreTest.h"

#include <Eigen/Dense>

#include <cmath>
#include <cstring>
#include <vector>

namespace
{
using mobius::SparseCholesky;

// The 5-point Laplacian of a side x side grid plus shift * I (both triangles stored).
SparseCholesky::Matrix ShiftedGridLaplacian(int side, double shift)
{
  std::vector<Eigen::Triplet<double>> entries;
  auto id = [side](int i, int j) { return i * side + j; };
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      double degree = 0;
      const int neighbours[4][2] = { { i - 1, j }, { i + 1, j }, { i, j - 1 }, { i, j + 1 } };
      for (const auto& n : neighbours)
      {
        if (n[0] >= 0 && n[0] < side && n[1] >= 0 && n[1] < side)
        {
          entries.emplace_back(id(i, j), id(n[0], n[1]), -1.0);
          degree += 1;
        }
      }
      entries.emplace_back(id(i, j), id(i, j), degree + shift);
    }
  }
  SparseCholesky::Matrix matrix(side * side, side * side);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

void TestSolves(int side, SparseCholesky::Use use = SparseCholesky::Use::FewSolves)
{
  SparseCholesky::Matrix matrix = ShiftedGridLaplacian(side, 0.01);
  SparseCholesky solver(use);
  MOBIUS_CHECK(solver.Analyze(matrix));
  MOBIUS_CHECK(solver.Factorize(matrix));
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(matrix.rows(), 3);
  Eigen::MatrixXd x = solver.Solve(b);
  MOBIUS_CHECK(x.rows() == matrix.rows() && x.cols() == 3);
  MOBIUS_CHECK((matrix * x - b).norm() <= 1e-9 * b.norm());

  // New values on the same pattern (the flow's changing mass): the analysis is reused.
  SparseCholesky::Matrix shifted = ShiftedGridLaplacian(side, 0.5);
  MOBIUS_CHECK(solver.Factorize(shifted));
  x = solver.Solve(b);
  MOBIUS_CHECK((shifted * x - b).norm() <= 1e-9 * b.norm());
  MOBIUS_CHECK((matrix * x - b).norm() > 1e-3 * b.norm()); // really the new system
}
}

int main()
{
  TestSolves(20); // 400 rows: simplicial
  TestSolves(250); // 62,500 rows: supernodal when built with CHOLMOD
  TestSolves(20, SparseCholesky::Use::ManySolves); // CHOLMOD's simplicial when built with it
  TestSolves(250, SparseCholesky::Use::ManySolves);
  MOBIUS_CHECK(std::strlen(SparseCholesky::Backend(400)) > 0);
#ifdef MOBIUS_HAVE_CHOLMOD
  MOBIUS_CHECK(std::strstr(SparseCholesky::Backend(62500), "CHOLMOD") != nullptr);
  MOBIUS_CHECK(std::strstr(SparseCholesky::Backend(400), "Eigen") != nullptr);
  MOBIUS_CHECK(std::strstr(
                 SparseCholesky::Backend(400, SparseCholesky::Use::ManySolves), "CHOLMOD") != nullptr);
#endif
  return MOBIUS_TEST_RESULT();
}
