#include "SparseCholesky.h"

#include <Eigen/SparseCholesky>
#ifdef MOBIUS_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace mobius
{
namespace
{
#ifdef MOBIUS_HAVE_CHOLMOD
// Below this size Eigen's simplicial factorization is as fast or faster: METIS's ordering
// and CHOLMOD's supernodal bookkeeping cost more than they save (whole map, CPU seconds,
// old / new: 17.5K vertices 1.6 / 2.4 for three maps, 50K vertices 2.96 / 2.86, 200K
// vertices 31 / 12.5).
constexpr Eigen::Index SupernodalMinimumSize = 50000;
#endif
}

struct SparseCholesky::Implementation
{
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::AMDOrdering<int>> Simplicial;
#ifdef MOBIUS_HAVE_CHOLMOD
  Implementation()
  {
    cholmod_common& common = this->Supernodal.cholmod();
    // One ordering, METIS nested dissection, instead of CHOLMOD's default of trying AMD
    // and falling back to METIS only when AMD's fill looks bad: on surface meshes nested
    // dissection gives less fill (200K-vertex mesh, whole map: 14 CPU s with METIS, 21 with
    // AMD), and skipping the AMD trial saves its time.
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_METIS;
    common.postorder = 1;
    // Failures are reported through info(), not printed.
    common.print = 0;
  }
  Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> Supernodal;
#endif
  bool UseSupernodal = false;
};

const char* SparseCholesky::Backend(Eigen::Index size)
{
#ifdef MOBIUS_HAVE_CHOLMOD
  if (size >= SupernodalMinimumSize)
  {
    return "CHOLMOD supernodal (METIS)";
  }
#else
  (void)size;
#endif
  return "Eigen simplicial LDLT (AMD)";
}

SparseCholesky::SparseCholesky()
  : Impl(new Implementation)
{
}

SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::Analyze(const Matrix& matrix)
{
#ifdef MOBIUS_HAVE_CHOLMOD
  this->Impl->UseSupernodal = matrix.rows() >= SupernodalMinimumSize;
  if (this->Impl->UseSupernodal)
  {
    this->Impl->Supernodal.analyzePattern(matrix);
    return this->Impl->Supernodal.info() == Eigen::Success;
  }
#endif
  this->Impl->Simplicial.analyzePattern(matrix);
  return this->Impl->Simplicial.info() == Eigen::Success;
}

bool SparseCholesky::Factorize(const Matrix& matrix)
{
#ifdef MOBIUS_HAVE_CHOLMOD
  if (this->Impl->UseSupernodal)
  {
    this->Impl->Supernodal.factorize(matrix);
    return this->Impl->Supernodal.info() == Eigen::Success;
  }
#endif
  this->Impl->Simplicial.factorize(matrix);
  return this->Impl->Simplicial.info() == Eigen::Success;
}

Eigen::MatrixXd SparseCholesky::Solve(const Eigen::MatrixXd& rightHandSides) const
{
#ifdef MOBIUS_HAVE_CHOLMOD
  if (this->Impl->UseSupernodal)
  {
    return this->Impl->Supernodal.solve(rightHandSides);
  }
#endif
  return this->Impl->Simplicial.solve(rightHandSides);
}
}
