#pragma once

#include "spira/thermal/thermal_linear_solver.h"

namespace spira {

// The thermal model's linear solves on PETSc over MPI, for models that outgrow one process. Its own
// library (spira_thermal_petsc, built when CMake finds PETSc: SPIRA_WITH_PETSC), so only the programs
// that offer it link PETSc and MPI; this header carries no PETSc type.

// PETSc and MPI in this process: PetscInitialize on construction, PetscFinalize on destruction. MPI
// starts once per process and cannot start again after it stops, so a process makes one session,
// before its first PETSc solve and alive until its last. Under mpirun every rank makes its own.
// InputError when MPI cannot start; InternalError for a second session.
class PetscSession {
 public:
  PetscSession();
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;

  int rank() const { return rank_; }  // in PETSC_COMM_WORLD
  int size() const { return size_; }  // ranks in PETSC_COMM_WORLD

 private:
  int rank_ = 0, size_ = 1;
};

// The PETSc backend for ThermalSettings::linearSolver: conjugate gradient with a Jacobi preconditioner on
// a distributed matrix, each rank owning a contiguous block of rows, the solution gathered back to
// every rank. Every rank of PETSC_COMM_WORLD must run the same simulation (same mesh, settings and
// steps: the solves are collective). Needs a live PetscSession. The solver's type and preconditioner
// can be changed through PETSc's options with the prefix "thermal_" (PETSC_OPTIONS="-thermal_pc_type
// bjacobi"). A PETSc error becomes an AlgorithmError carrying PETSc's message.
ThermalSolverFactory petscThermalSolver();

}  // namespace spira
