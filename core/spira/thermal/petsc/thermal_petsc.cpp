// The one file that includes PETSc and MPI: everything else sees thermal_petsc.h.
#include "spira/thermal/petsc/thermal_petsc.h"

#include <dlfcn.h>
#include <petscksp.h>

#include <algorithm>
#include <string>
#include <vector>

#include "spira/base/error.h"

namespace spira {
namespace {

// PETSc's own message for the error being unwound: its handler sees it where it is raised, the caller
// only gets the code.
thread_local std::string petscMessage;

PetscErrorCode recordError(MPI_Comm, int, const char* function, const char*, PetscErrorCode code,
                           PetscErrorType type, const char* message, void*)
{
  if (type == PETSC_ERROR_INITIAL)
    petscMessage = std::string(function ? function : "PETSc") + ": " + (message ? message : "");
  return code;
}

void check(PetscErrorCode code, const char* call)
{
  if (code == 0) return;
  std::string why = petscMessage;
  petscMessage.clear();
  if (why.empty()) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    why = text ? text : "error " + std::to_string(code);
  }
  throw AlgorithmError(
      "the PETSc thermal solve failed in " + std::string(call) + " (" + why + ")",
      "check the MPI launch, the PETSc installation and PETSC_OPTIONS, or use the in-process solver");
}

bool petscRunning()
{
  PetscBool initialized = PETSC_FALSE, finalized = PETSC_FALSE;
  PetscInitialized(&initialized);
  PetscFinalized(&finalized);
  return initialized && !finalized;
}

// The leading `rows_` unknowns of the system as one distributed matrix, `rows_` >= the window n. Rows
// and columns past n are masked (identity, zero right-hand side and start), so the Krylov vectors stay
// in the window and the residual norm is the window's: the same solve as the in-process one, with the
// pattern fixed between rebuilds. The window grows by whole grains, each rebuild splitting the rows
// evenly again (a split of all nodes would leave the later ranks idle while the build is young).
class PetscPrefixSolver final : public ThermalLinearSolver {
 public:
  explicit PetscPrefixSolver(const ThermalSystem& s) : s_(s), grain_(std::max(1024, (s.size() + 31) / 32))
  {
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
    MPI_Comm_size(PETSC_COMM_WORLD, &size_);
  }
  ~PetscPrefixSolver() override { release(); }
  PetscPrefixSolver(const PetscPrefixSolver&) = delete;
  PetscPrefixSolver& operator=(const PetscPrefixSolver&) = delete;

  int solve(int n, double thetaDt, const std::vector<double>& b, std::vector<double>& x,
            double tolerance) override
  {
    if (n > rows_) build(std::min(s_.size(), (n + grain_ - 1) / grain_ * grain_));
    for (PetscInt i = lo_; i < hi_; ++i)
      for (PetscInt q = rowStart_[size_t(i - lo_)]; q < rowStart_[size_t(i - lo_) + 1]; ++q) {
        const PetscInt j = column_[size_t(q)];
        const size_t p = size_t(source_[size_t(q)]);
        value_[size_t(q)] =
            i < n && j < n ? s_.capacity[p] + thetaDt * s_.conductance[p] : (i == j ? 1.0 : 0.0);
      }
    check(MatUpdateMPIAIJWithArray(a_, value_.data()), "MatUpdateMPIAIJWithArray");
    copyIn(b, n, b_);
    copyIn(x, n, x_);
    check(KSPSetOperators(ksp_, a_, a_), "KSPSetOperators");
    // No absolute floor, as in process: the relative residual alone decides.
    check(KSPSetTolerances(ksp_, tolerance, 0.0, PETSC_DEFAULT, 10 * PetscInt(n) + 100), "KSPSetTolerances");
    check(KSPSolve(ksp_, b_, x_), "KSPSolve");
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
    if (reason < 0)
      throw AlgorithmError(
          "the thermal solve did not converge (PETSc: " + std::string(KSPConvergedReasons[reason]) + ")",
          "use a smaller time step");
    PetscInt iterations = 0;
    check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
    check(VecScatterBegin(gather_, x_, all_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    check(VecScatterEnd(gather_, x_, all_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    const PetscScalar* all = nullptr;
    check(VecGetArrayRead(all_, &all), "VecGetArrayRead");
    std::copy(all, all + n, x.begin());
    check(VecRestoreArrayRead(all_, &all), "VecRestoreArrayRead");
    return int(iterations);
  }

 private:
  void build(int rows)
  {
    release();
    rows_ = rows;
    lo_ = PetscInt(static_cast<long long>(rows) * rank_ / size_);
    hi_ = PetscInt(static_cast<long long>(rows) * (rank_ + 1) / size_);
    rowStart_.assign(1, 0);
    column_.clear();
    source_.clear();
    for (PetscInt i = lo_; i < hi_; ++i) {
      for (int p = s_.rowStart[size_t(i)]; p < s_.rowStart[size_t(i) + 1]; ++p)
        if (s_.column[size_t(p)] < rows) {
          column_.push_back(s_.column[size_t(p)]);
          source_.push_back(p);
        }
      rowStart_.push_back(PetscInt(column_.size()));
    }
    value_.assign(column_.size(), 0.0);
    for (PetscInt i = lo_; i < hi_; ++i)
      for (PetscInt q = rowStart_[size_t(i - lo_)]; q < rowStart_[size_t(i - lo_) + 1]; ++q)
        if (column_[size_t(q)] == i) value_[size_t(q)] = 1.0;
    check(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, hi_ - lo_, hi_ - lo_, rows, rows, rowStart_.data(),
                                    column_.data(), value_.data(), &a_),
          "MatCreateMPIAIJWithArrays");
    check(MatCreateVecs(a_, &x_, &b_), "MatCreateVecs");
    check(VecScatterCreateToAll(x_, &gather_, &all_), "VecScatterCreateToAll");
    check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
    check(KSPSetType(ksp_, KSPCG), "KSPSetType");
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "KSPGetPC");
    check(PCSetType(pc, PCJACOBI), "PCSetType");
    // The in-process solver's test: |b - A x| <= tolerance |b|, from the warm start.
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    check(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE), "KSPSetInitialGuessNonzero");
    check(KSPSetOptionsPrefix(ksp_, "thermal_"), "KSPSetOptionsPrefix");
    check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
  }

  // The owned rows of `v`, zero past the window.
  void copyIn(const std::vector<double>& v, int n, Vec target)
  {
    PetscScalar* out = nullptr;
    check(VecGetArray(target, &out), "VecGetArray");
    for (PetscInt i = lo_; i < hi_; ++i) out[i - lo_] = i < n ? v[size_t(i)] : 0.0;
    check(VecRestoreArray(target, &out), "VecRestoreArray");
  }

  void release()
  {
    if (!petscRunning()) return;
    KSPDestroy(&ksp_);
    VecScatterDestroy(&gather_);
    VecDestroy(&all_);
    VecDestroy(&x_);
    VecDestroy(&b_);
    MatDestroy(&a_);
    rows_ = 0;
  }

  const ThermalSystem& s_;
  const int grain_;
  int rank_ = 0, size_ = 1;
  int rows_ = 0;              // unknowns in the PETSc system (0: not built)
  PetscInt lo_ = 0, hi_ = 0;  // this rank's rows
  std::vector<PetscInt> rowStart_, column_;
  std::vector<int> source_;  // of each local entry, its index in the system's pattern
  std::vector<PetscScalar> value_;
  Mat a_ = nullptr;
  Vec b_ = nullptr, x_ = nullptr, all_ = nullptr;
  VecScatter gather_ = nullptr;
  KSP ksp_ = nullptr;
};

}  // namespace

PetscSession::PetscSession()
{
  PetscBool initialized = PETSC_FALSE;
  PetscInitialized(&initialized);
  if (initialized) throw InternalError("PETSc was started twice in one process");
  // No signal handlers: a crash stays the program's own, not a PETSc trace.
  static char program[] = "spira", noSignals[] = "-no_signal_handler";
  static char* arguments[] = {program, noSignals, nullptr};
  int argc = 2;
  char** argv = arguments;
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0)
    throw InputError("PETSc could not start MPI", "run under mpirun, or check the MPI installation");
  PetscPushErrorHandler(recordError, nullptr);
  // PETSc's vector operations call BLAS. Debian's OpenBLAS starts a thread per core for vectors of
  // some 10,000 entries and they spin (sched_yield) against the ranks: on the dome's 16,562 nodes that
  // took 33 s of system time for 25 s of work. One BLAS thread per rank; MPI gives the parallelism.
  using SetThreads = void (*)(int);
  if (void* set = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) reinterpret_cast<SetThreads>(set)(1);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
}

PetscSession::~PetscSession()
{
  PetscPopErrorHandler();
  PetscFinalize();
}

ThermalSolverFactory petscThermalSolver()
{
  return [](const ThermalSystem& system) -> std::unique_ptr<ThermalLinearSolver> {
    if (!petscRunning()) throw InternalError("the PETSc thermal solver needs a PetscSession");
    return std::make_unique<PetscPrefixSolver>(system);
  };
}

}  // namespace spira
