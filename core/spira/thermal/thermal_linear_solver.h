#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "spira/thermal/thermal_system.h"

namespace spira {

// The linear solve of one time step: (C + thetaDt K) x = b on the leading `n` unknowns of a
// ThermalSystem (the deposited prefix and its fringe), the nodes past `n` held fixed (their coupling is
// already in b). x holds the warm start on entry and the solution on return, to a relative residual
// |b - A x| <= tolerance |b| on those n unknowns; entries past n are left alone. Returns the iterations
// taken; throws AlgorithmError when it does not converge. The system's values change between calls
// (element birth) but never its pattern or size.
class ThermalLinearSolver {
 public:
  virtual ~ThermalLinearSolver() = default;
  virtual int solve(int n, double thetaDt, const std::vector<double>& b, std::vector<double>& x,
                    double tolerance) = 0;
};

// Makes the solver for one simulation's system, which outlives it. An empty factory is the
// in-process conjugate gradient; the PETSc (MPI) one is in spira/thermal/petsc/thermal_petsc.h.
using ThermalSolverFactory = std::function<std::unique_ptr<ThermalLinearSolver>(const ThermalSystem&)>;

}  // namespace spira
