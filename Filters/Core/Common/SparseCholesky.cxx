#include "SparseCholesky.h"

#include <Eigen/SparseCholesky>
#ifdef MOBIUS_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>

#include <dlfcn.h>

#include <mutex>
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

// While a supernodal factorization or solve runs, the linear algebra libraries under CHOLMOD
// run on the calling thread only. Debian's CHOLMOD opens an OpenMP region of 4 threads for
// each supernode's small copy loops (~250,000 regions per factorization of a 200K-vertex
// Laplacian), and OpenBLAS (when it is the libblas.so.3 alternative) starts its own
// threads for each dense kernel: on a 2-core machine, with the other mesh's map running
// beside this one, the threads mostly wait for each other. Measured on the 200K-vertex map,
// one run alone: 11.8 s wall with both libraries' threads, 8.1 s with one thread each.
// The settings are process-wide, so they are made by the first factorization that starts
// and restored by the last one to end.
class CallingThreadLinearAlgebra
{
public:
  CallingThreadLinearAlgebra()
  {
    std::lock_guard<std::mutex> lock(Mutex());
    State& state = Shared();
    if (state.Users++ == 0)
    {
      state.Load();
      if (state.GetMaxActiveLevels && state.SetMaxActiveLevels)
      {
        state.SavedActiveLevels = state.GetMaxActiveLevels();
        state.SetMaxActiveLevels(0); // every OpenMP region runs on its calling thread
      }
      if (state.GetBlasThreads && state.SetBlasThreads)
      {
        state.SavedBlasThreads = state.GetBlasThreads();
        state.SetBlasThreads(1);
      }
    }
  }
  ~CallingThreadLinearAlgebra()
  {
    std::lock_guard<std::mutex> lock(Mutex());
    State& state = Shared();
    if (--state.Users == 0)
    {
      if (state.SetMaxActiveLevels && state.SavedActiveLevels >= 0)
      {
        state.SetMaxActiveLevels(state.SavedActiveLevels);
      }
      if (state.SetBlasThreads && state.SavedBlasThreads > 0)
      {
        state.SetBlasThreads(state.SavedBlasThreads);
      }
    }
  }
  CallingThreadLinearAlgebra(const CallingThreadLinearAlgebra&) = delete;
  CallingThreadLinearAlgebra& operator=(const CallingThreadLinearAlgebra&) = delete;

private:
  using GetInt = int (*)();
  using SetInt = void (*)(int);
  struct State
  {
    int Users = 0;
    bool Loaded = false;
    GetInt GetMaxActiveLevels = nullptr;
    SetInt SetMaxActiveLevels = nullptr;
    GetInt GetBlasThreads = nullptr;
    SetInt SetBlasThreads = nullptr;
    int SavedActiveLevels = -1;
    int SavedBlasThreads = 0;

    // Looked up in the libraries CHOLMOD already loaded (RTLD_NOLOAD: nothing new is
    // loaded): libgomp when CHOLMOD was built with OpenMP, and the BLAS, whose thread
    // setter exists only when it is OpenBLAS. Missing ones are left alone.
    void Load()
    {
      if (this->Loaded)
      {
        return;
      }
      this->Loaded = true;
      if (void* openmp = dlopen("libgomp.so.1", RTLD_NOW | RTLD_NOLOAD))
      {
        this->GetMaxActiveLevels =
          reinterpret_cast<GetInt>(dlsym(openmp, "omp_get_max_active_levels"));
        this->SetMaxActiveLevels =
          reinterpret_cast<SetInt>(dlsym(openmp, "omp_set_max_active_levels"));
      }
      if (void* blas = dlopen("libblas.so.3", RTLD_NOW | RTLD_NOLOAD))
      {
        this->GetBlasThreads =
          reinterpret_cast<GetInt>(dlsym(blas, "openblas_get_num_threads"));
        this->SetBlasThreads =
          reinterpret_cast<SetInt>(dlsym(blas, "openblas_set_num_threads"));
      }
    }
  };
  static std::mutex& Mutex()
  {
    static std::mutex mutex;
    return mutex;
  }
  static State& Shared()
  {
    static State state;
    return state;
  }
};
#endif
}

struct SparseCholesky::Implementation
{
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::AMDOrdering<int>> Simplicial;
#ifdef MOBIUS_HAVE_CHOLMOD
  explicit Implementation(Use use)
    : ManySolves(use == Use::ManySolves)
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
    // Larger relaxed supernodes than CHOLMOD's defaults (4, 16, 48 columns; 0.8, 0.1, 0.05
    // of explicit zeros allowed): a surface mesh's factor otherwise has many small
    // supernodes, each with its own bookkeeping and small dense kernels. 200K-vertex map,
    // CPU seconds, median of 3: 11.5 with the defaults, 9.2 with these.
    common.nrelax[0] = 16;
    common.nrelax[1] = 64;
    common.nrelax[2] = 256;
    common.zrelax[0] = 0.8;
    common.zrelax[1] = 0.3;
    common.zrelax[2] = 0.1;
    cholmod_common& simplicial = this->SimplicialForSolves.cholmod();
    simplicial.nmethods = 1;
    simplicial.method[0].ordering = CHOLMOD_AMD; // less fill than METIS at these sizes
    simplicial.postorder = 1;
    simplicial.print = 0;
  }
  Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> Supernodal;
  Eigen::CholmodSimplicialLDLT<Matrix, Eigen::Lower> SimplicialForSolves;
  const bool ManySolves;
  bool UseSimplicialForSolves = false;
#else
  explicit Implementation(Use) {}
#endif
  bool UseSupernodal = false;
};

const char* SparseCholesky::Backend(Eigen::Index size, Use use)
{
#ifdef MOBIUS_HAVE_CHOLMOD
  if (size >= SupernodalMinimumSize)
  {
    return "CHOLMOD supernodal (METIS)";
  }
  if (use == Use::ManySolves)
  {
    return "CHOLMOD simplicial LDLT (AMD)";
  }
#else
  (void)size;
  (void)use;
#endif
  return "Eigen simplicial LDLT (AMD)";
}

SparseCholesky::SparseCholesky(Use use)
  : Impl(new Implementation(use))
{
}

SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::Analyze(const Matrix& matrix)
{
#ifdef MOBIUS_HAVE_CHOLMOD
  this->Impl->UseSupernodal = matrix.rows() >= SupernodalMinimumSize;
  this->Impl->UseSimplicialForSolves = !this->Impl->UseSupernodal && this->Impl->ManySolves;
  if (this->Impl->UseSupernodal)
  {
    CallingThreadLinearAlgebra oneThread;
    this->Impl->Supernodal.analyzePattern(matrix);
    return this->Impl->Supernodal.info() == Eigen::Success;
  }
  if (this->Impl->UseSimplicialForSolves)
  {
    this->Impl->SimplicialForSolves.analyzePattern(matrix);
    return this->Impl->SimplicialForSolves.info() == Eigen::Success;
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
    CallingThreadLinearAlgebra oneThread;
    this->Impl->Supernodal.factorize(matrix);
    return this->Impl->Supernodal.info() == Eigen::Success;
  }
  if (this->Impl->UseSimplicialForSolves)
  {
    this->Impl->SimplicialForSolves.factorize(matrix);
    return this->Impl->SimplicialForSolves.info() == Eigen::Success;
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
    CallingThreadLinearAlgebra oneThread;
    return this->Impl->Supernodal.solve(rightHandSides);
  }
  if (this->Impl->UseSimplicialForSolves)
  {
    return this->Impl->SimplicialForSolves.solve(rightHandSides);
  }
#endif
  return this->Impl->Simplicial.solve(rightHandSides);
}
}
