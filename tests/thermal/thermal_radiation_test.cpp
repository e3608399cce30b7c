// Radiation (an option; the source leaves it out): against the closed-form cooling of a uniform
// wall radiating from both faces to 0 K, and in the energy balance of a whole build.
#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/progress.h"
#include "spira/thermal/thermal_solver.h"
#include "thermal/thermal_cases.h"

namespace spira {
namespace {

// rho c tau dT/dt = -2 sigma eps T^4 (T in K, surroundings at 0 K): T(t) = (T0^-3 + 3 k t)^(-1/3),
// k = 2 sigma eps / (rho c tau).
TEST(ThermalRadiation, UniformWallCoolsAsTheClosedForm)
{
  ThermalMeshSettings ms;
  ms.thickness = 5.0;
  const ThermalMesh mesh = buildThermalMesh(test::cylinderWall(20.0, 5, 60, 2.0, 1e6), ms);
  ThermalSettings s;
  s.power = 0.0;
  s.films.air = 0.0;
  s.films.substrate = 0.0;
  s.films.airTemperature = -273.15;
  s.material.emissivity = 0.8;
  s.activateAll = true;
  s.initialTemperature = 1000.0;
  s.coolingTime = 600.0;
  s.timeStep = 0.25;
  s.tolerance = 1e-10;
  s.probeNodes = {0, int(mesh.nodeCount()) / 2, int(mesh.nodeCount()) - 1};
  NullProgress progress;
  const ThermalResult r = simulateThermal(mesh, s, progress);
  const double k = 2.0 * 5.670374419e-8 * 0.8 / (7800.0 * 470.0 * 0.005);
  double worst = 0.0;
  for (size_t i = 0; i < r.probeTimes.size(); ++i)
    for (const auto& probe : r.probeTemperatures) {
      const double exact = std::pow(std::pow(1273.15, -3.0) + 3.0 * k * r.probeTimes[i], -1.0 / 3.0) - 273.15;
      worst = std::max(worst, std::abs(probe[i] - exact) / (exact + 273.15));
    }
  EXPECT_LT(worst, 2e-3);
  const double end = std::pow(std::pow(1273.15, -3.0) + 3.0 * k * 600.0, -1.0 / 3.0) - 273.15;
  EXPECT_LT(end, 400.0);  // it cools a lot: the check is not of a wall that barely moved
  EXPECT_NEAR(r.energy.imbalance(), 0.0, 1e-6 * r.energy.lost);
  std::printf("radiative cooling: T(600 s) = %.2f C (exact %.2f), max relative error %.3g\n",
              r.probeTemperatures[0].back(), end, worst);
}

// With radiation the energy still balances over a build, and it only ever takes heat away.
TEST(ThermalRadiation, KeepsTheEnergyBalanceAndCools)
{
  const Trajectory t = test::cylinderWall(20.0, 8, 72, 2.0, 6.0);
  const ThermalMesh mesh = buildThermalMesh(t, {});
  ThermalSettings s;
  s.coolingTime = 60.0;
  NullProgress progress;
  const ThermalResult plain = simulateThermal(mesh, s, progress);
  s.material.emissivity = 0.8;
  const ThermalResult radiating = simulateThermal(mesh, s, progress);
  EXPECT_NEAR(radiating.energy.in, plain.energy.in, 1e-9 * plain.energy.in);
  EXPECT_LT(std::abs(radiating.energy.imbalance()), 1e-3 * radiating.energy.in);
  EXPECT_LT(radiating.energy.stored, plain.energy.stored);
  for (size_t p = 0; p < t.size(); ++p) EXPECT_LE(radiating.peak[p], plain.peak[p] + 1e-9) << p;
  double meanDrop = 0.0;
  for (size_t p = 0; p < t.size(); ++p) meanDrop += (plain.peak[p] - radiating.peak[p]) / double(t.size());
  EXPECT_GT(meanDrop, 10.0);
  std::printf("radiation at eps 0.8: stored %.0f J instead of %.0f J, peaks lower by %.0f C on average\n",
              radiating.energy.stored, plain.energy.stored, meanDrop);
}

}  // namespace
}  // namespace spira
