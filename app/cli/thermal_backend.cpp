#include "thermal_backend.h"

#include <cstdlib>
#include <iostream>
#include <streambuf>
#include <utility>

#include "spira/base/error.h"

#if SPIRA_WITH_PETSC
#include "spira/thermal/petsc/thermal_petsc.h"
#endif

namespace spira::cli {
namespace {

// This process's place in the MPI launch it belongs to, from the launcher's environment (OpenMPI's
// mpirun, or a PMI launcher: MPICH's Hydra, Slurm); one process of one outside a launch.
struct Launch {
  long size = 1, rank = 0;
};

long environmentNumber(const char* name, long fallback)
{
  const char* value = std::getenv(name);
  if (!value) return fallback;
  char* end = nullptr;
  const long n = std::strtol(value, &end, 10);
  return end != value && *end == '\0' && n >= 0 ? n : fallback;
}

Launch mpiLaunch()
{
  for (const auto& [size, rank] :
       {std::pair{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"}, {"PMI_SIZE", "PMI_RANK"}})
    if (const long n = environmentNumber(size, 1); n > 1) return {n, environmentNumber(rank, 0)};
  return {};
}

class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
};

}  // namespace

ThermalBackend::ThermalBackend(Args& args)
{
  const Launch launch = mpiLaunch();
  // Every rank meets the same errors: rank 0 says so.
  if (launch.rank != 0) silence();
  name_ = args.takeOption("--backend");
  if (name_.empty()) name_ = launch.size > 1 ? "petsc" : "eigen";
  if (name_ != "eigen" && name_ != "petsc")
    throw UsageError("--backend " + name_ + " is not a thermal backend",
                     "write --backend eigen (in-process) or --backend petsc (PETSc, MPI)");
  const std::string processes = std::to_string(launch.size) + " processes of an MPI launch";
  if (!SPIRA_WITH_PETSC && (name_ == "petsc" || launch.size > 1))
    throw InputError(
        "this spira-cli was built without PETSc, so it cannot run the thermal model " +
            (launch.size > 1 ? "on " + processes : std::string("with --backend petsc")),
        "install libpetsc-real-dev (packaging/install-deps.sh does) and rebuild: CMake then builds the "
        "backend (SPIRA_WITH_PETSC); or run without mpirun and --backend petsc");
  if (name_ == "eigen" && launch.size > 1)
    throw UsageError("--backend eigen solves in one process, but this is one of " + processes +
                         ": each would simulate the whole build alone",
                     "use --backend petsc under mpirun, or run without mpirun");
}

void ThermalBackend::silence()
{
  // Never destroyed: the standard streams are flushed after function statics are gone.
  static NullBuffer* const nothing = new NullBuffer;
  std::cout.rdbuf(nothing);
  std::cerr.rdbuf(nothing);
}

void ThermalBackend::start(ThermalSettings& settings)
{
#if SPIRA_WITH_PETSC
  if (name_ != "petsc") return;
  session_ = std::make_shared<PetscSession>();
  rank_ = session_->rank();
  settings.linearSolver = petscThermalSolver();
  if (rank_ != 0) silence();
  std::cout << "backend: PETSc on " << session_->size() << " MPI process"
            << (session_->size() > 1 ? "es" : "") << "\n";
#else
  static_cast<void>(settings);
#endif
}

}  // namespace spira::cli
