// spira-cli thermal --backend: an unknown backend is a usage error (exit 2). In a build with PETSc, the
// in-process backend is refused under an MPI launch of several processes (each would simulate the
// whole build alone; the runs themselves are tests/cli/mpi). In a build without PETSc, --backend petsc
// and an MPI launch exit 3 saying what to install. Nothing is written in any of these cases.
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

class CliThermalBackend : public ::testing::Test {
 protected:
  static void SetUpTestSuite()
  {
    dir_ = new TempDir;
    const CliRun r = runCli({"plan", (sourceDir() / "resources/samples/open_cylinder.stl").string(), "-o",
                             (*dir_ / "plan").string(), "--points-per-rev", "36"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  static void TearDownTestSuite()
  {
    delete dir_;
    dir_ = nullptr;
  }
  CliRun thermal(const std::vector<std::string>& extra, const std::vector<std::string>& env = {})
  {
    std::vector<std::string> args = {"thermal", (*dir_ / "plan").string(), "-o", out().string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runCli(args, env);
  }
  fs::path out() const { return tmp_ / "out"; }
  TempDir tmp_;
  static TempDir* dir_;
};
TempDir* CliThermalBackend::dir_ = nullptr;

TEST_F(CliThermalBackend, AnUnknownBackendIsAUsageError)
{
  const CliRun r = thermal({"--backend", "cuda"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--backend cuda is not a thermal backend"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out() / "thermal.json"));
}

// The launcher's environment as OpenMPI's mpirun sets it for the first of two ranks; nothing here
// starts MPI, the command is refused first.
const std::vector<std::string> kFirstOfTwoRanks = {"OMPI_COMM_WORLD_SIZE=2", "OMPI_COMM_WORLD_RANK=0"};

#if SPIRA_WITH_PETSC
TEST_F(CliThermalBackend, TheInProcessBackendIsRefusedUnderAnMpiLaunch)
{
  CliRun r = thermal({"--backend", "eigen"}, kFirstOfTwoRanks);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("one of 2 processes of an MPI launch"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out() / "thermal.json"));
  // The same with a PMI launcher (MPICH's Hydra, Slurm); the second rank says nothing.
  r = thermal({"--backend", "eigen"}, {"PMI_SIZE=3", "PMI_RANK=1"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "");
}
#else
TEST_F(CliThermalBackend, PetscAndMpiLaunchesExitThreeInABuildWithoutPetsc)
{
  CliRun r = thermal({"--backend", "petsc"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("built without PETSc, so it cannot run the thermal model with --backend petsc"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("install libpetsc-real-dev"), std::string::npos) << r.err;
  r = thermal({}, kFirstOfTwoRanks);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("cannot run the thermal model on 2 processes of an MPI launch"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out() / "thermal.json"));
  // Without a launch the in-process backend runs, as before.
  r = thermal({});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(out() / "thermal.json"));
}
#endif

}  // namespace
}  // namespace spira::test
