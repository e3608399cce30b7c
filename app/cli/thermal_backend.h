#pragma once

#include <memory>
#include <string>

#include "cli_common.h"
#include "spira/thermal/thermal_solver.h"

namespace spira {
class PetscSession;
}

namespace spira::cli {

// The backend of 'spira-cli thermal''s linear solves, --backend eigen|petsc, and for petsc this process's
// share of the MPI run. Under mpirun -n N (N > 1) each rank runs the same model, the solves are
// distributed, and only rank 0 prints and writes.
class ThermalBackend {
 public:
  // Takes --backend from `args` (default: eigen, or petsc under an MPI launch of more than one
  // process). UsageError for an unknown name, or eigen under such a launch (each process would simulate
  // the whole build alone); InputError (exit 3) for petsc or a multi-process launch in a build without
  // PETSc. Under a launch, the ranks other than 0 (by the launcher's environment) fall silent here, so
  // the errors every rank meets are printed once. Nothing starts yet.
  explicit ThermalBackend(Args& args);
  ThermalBackend(const ThermalBackend&) = delete;
  ThermalBackend& operator=(const ThermalBackend&) = delete;

  // Starts PETSc (MPI) for petsc, says so and sets the settings' solver.
  void start(ThermalSettings& settings);
  // Whether this process writes the results: false on the ranks other than 0.
  bool writes() const { return rank_ == 0; }

 private:
  // Drops this process's output for the rest of its life (rank > 0).
  static void silence();

  std::string name_;
  std::shared_ptr<PetscSession> session_;  // shared_ptr: PetscSession is incomplete without PETSc
  int rank_ = 0;
};

}  // namespace spira::cli
