// The PETSc backend of the thermal model's linear solves, in this one process (PETSC_COMM_WORLD of size
// 1; spira-cli on two MPI ranks is tests/cli/mpi): the same temperatures as the in-process conjugate
// gradient to the solver's tolerance and the same iterations (same method, same convergence test). PETSc
// failures becoming errors with PETSc's message: tests/cli/mpi.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "spira/base/progress.h"
#include "spira/thermal/petsc/thermal_petsc.h"
#include "spira/thermal/thermal_solver.h"
#include "thermal/thermal_cases.h"

namespace spira {
namespace {

// MPI starts once per process: one session for all the tests of the program.
class PetscEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { session_ = std::make_unique<PetscSession>(); }
  void TearDown() override { session_.reset(); }

 private:
  std::unique_ptr<PetscSession> session_;
};
const auto* const environment = ::testing::AddGlobalTestEnvironment(new PetscEnvironment);

// The 1e-6 relative residual moved the dome's temperatures by < 0.01 C against 1e-10 (docs/thermal.md):
// two solves that both meet the tolerance differ by no more than that, per unit of tolerance.
double allowedDifference(const ThermalSettings& s)
{
  return 1e4 * s.tolerance;
}

double largestDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

struct Runs {
  ThermalResult inProcess, petsc;
};

Runs runBoth(const ThermalMesh& mesh, ThermalSettings s)
{
  NullProgress progress;
  Runs r;
  r.inProcess = simulateThermal(mesh, s, progress);
  s.linearSolver = petscThermalSolver();
  r.petsc = simulateThermal(mesh, s, progress);
  return r;
}

void expectSameTemperatures(const Runs& r, double allowed)
{
  const ThermalResult &a = r.inProcess, &b = r.petsc;
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_LE(largestDifference(a.peak, b.peak), allowed);
  EXPECT_LE(largestDifference(a.interpass, b.interpass), allowed);
  EXPECT_LE(largestDifference(a.belowAtArrival, b.belowAtArrival), allowed);
  EXPECT_LE(largestDifference(a.nodePeak, b.nodePeak), allowed);
  EXPECT_LE(largestDifference(a.finalTemperature, b.finalTemperature), allowed);
  ASSERT_EQ(a.probeTemperatures.size(), b.probeTemperatures.size());
  for (size_t p = 0; p < a.probeTemperatures.size(); ++p)
    EXPECT_LE(largestDifference(a.probeTemperatures[p], b.probeTemperatures[p]), allowed) << "probe " << p;
  EXPECT_NEAR(a.energy.stored, b.energy.stored, 1e-6 * a.energy.in);
  EXPECT_NEAR(a.energy.lost, b.energy.lost, 1e-6 * a.energy.in);
  EXPECT_DOUBLE_EQ(a.meanWindow, b.meanWindow);
}

TEST(ThermalPetsc, WallGivesTheInProcessTemperaturesAndIterations)
{
  const Trajectory t = test::cylinderWall(30.0, 6, 120, 2.0, 6.0);
  const ThermalMesh mesh = buildThermalMesh(t, {});
  ThermalSettings s;
  s.probeNodes = {mesh.heatNode[size_t(mesh.pointHeatIndex[180])], 0};
  s.probePositions = {Vec3(30.0, 0.0, 8.0)};
  s.coolingTime = 60.0;
  const Runs r = runBoth(mesh, s);
  expectSameTemperatures(r, allowedDifference(s));
  EXPECT_GT(*std::max_element(r.petsc.peak.begin(), r.petsc.peak.end()), 1500.0);
  // The same method and convergence test: the same iterations, up to rounding at the threshold.
  EXPECT_NEAR(r.inProcess.solverIterations, r.petsc.solverIterations, 0.05);
  EXPECT_GT(r.petsc.solverIterations, 2.0);
}

// Implicit Euler on a dome closed by an apex fan, its hot closure and its fringe of inactive elements.
TEST(ThermalPetsc, DomeUnderImplicitEulerGivesTheInProcessTemperatures)
{
  const ThermalMesh mesh = buildThermalMesh(test::hemisphereDome(20.0, 2.0, 60, 6.0), {});
  ThermalSettings s;
  s.scheme = ThermalScheme::ImplicitEuler;
  s.tolerance = 1e-8;
  const Runs r = runBoth(mesh, s);
  expectSameTemperatures(r, allowedDifference(s));
  EXPECT_GT(*std::max_element(r.petsc.interpass.begin(), r.petsc.interpass.end()), 100.0);
}

// The bound is not loose: at a hundredth of relative residual the temperatures move well past it.
TEST(ThermalPetsc, ALooseToleranceMovesTemperaturesPastTheBound)
{
  const ThermalMesh mesh = buildThermalMesh(test::cylinderWall(30.0, 4, 120, 2.0, 6.0), {});
  ThermalSettings tight, loose;
  loose.tolerance = 1e-2;
  loose.linearSolver = petscThermalSolver();
  NullProgress progress;
  const ThermalResult a = simulateThermal(mesh, tight, progress), b = simulateThermal(mesh, loose, progress);
  EXPECT_GT(largestDifference(a.finalTemperature, b.finalTemperature), allowedDifference(tight));
}

}  // namespace
}  // namespace spira
