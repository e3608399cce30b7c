// The source's qualitative results (000_dbb97c2716e10cc3.txt §5.6, Fig. 5.15-5.17) on its base case,
// G3Si1 at 1000 W and 6 mm/s, and the bad settings the solver refuses.
#include <gtest/gtest.h>

#include <algorithm>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/path/dwell.h"
#include "spira/thermal/thermal_solver.h"
#include "thermal/thermal_cases.h"

namespace spira {
namespace {

// A node stays at ambient until it is deposited, then jumps above melting within a fraction of a
// second; the valley (interpass) temperatures under one generatrix rise over the first revolutions.
TEST(ThermalModel, NodeWaitsAtAmbientJumpsAboveMeltingAndValleysRise)
{
  const Trajectory t = test::cylinderWall(30.0, 10, 120, 2.0, 6.0);
  const ThermalMesh mesh = buildThermalMesh(t, {});
  ThermalSettings s;
  const size_t point = 120 + 60;  // revolution 1, half-way round
  const int h = mesh.pointHeatIndex[point];
  s.probeNodes = {mesh.heatNode[size_t(h)]};
  NullProgress progress;
  const ThermalResult r = simulateThermal(mesh, s, progress);
  const double arrival = mesh.heatTime[size_t(h)], started = mesh.heatTime[size_t(h - 1)];
  double before = 0.0, after = 0.0;
  for (size_t i = 0; i < r.probeTimes.size(); ++i) {
    const double T = r.probeTemperatures[0][i];
    if (r.probeTimes[i] <= started) before = std::max(before, T);
    if (r.probeTimes[i] >= arrival && r.probeTimes[i] <= arrival + 0.5) after = std::max(after, T);
  }
  EXPECT_EQ(before, 20.0);
  EXPECT_GT(after, 1500.0);
  EXPECT_GT(r.peak[point], 1500.0);
  EXPECT_GT(r.timeAboveMelt[point], 0.0);
  std::printf("node of revolution 1: 20 C until %.1f s, %.0f C within 0.5 s of the torch; valleys:", started,
              after);
  for (int rev = 1; rev <= 6; ++rev) {
    const double valley = r.interpass[size_t(rev * 120 + 60)],
                 next = r.interpass[size_t((rev + 1) * 120 + 60)];
    std::printf(" %.0f", valley);
    if (rev < 6) {
      EXPECT_GT(next, valley + 5.0) << "revolution " << rev;
    }
    EXPECT_LE(valley, r.belowAtArrival[size_t(rev * 120 + 60)]);
  }
  std::printf("\n");
  // The first revolution sits on the substrate, still at ambient before the torch.
  EXPECT_NEAR(r.interpass[60], 20.0, 1.0);
}

// A dwell at the end of revolution 2: everything after it happens 60 s later, no heat goes in
// during the wait, the energy still balances, and the revolution laid after it finds the wall
// below cooler than without the wait.
TEST(ThermalModel, ADwellDelaysTheRestWithoutHeatAndCoolsTheWallBelow)
{
  const Trajectory plain = test::cylinderWall(30.0, 6, 120, 2.0, 6.0);
  Trajectory waiting = plain;
  const size_t at = 3 * 120 - 1;  // the last point of revolution 2
  waiting.extra[kDwellChannel].assign(plain.size(), 0.0);
  waiting.extra[kDwellChannel][at] = 60.0;
  const ThermalMesh a = buildThermalMesh(plain, {}), b = buildThermalMesh(waiting, {});
  ASSERT_EQ(a.nodeCount(), b.nodeCount());
  ASSERT_EQ(b.heatTime.size(), a.heatTime.size() + 1);
  for (size_t i = 0; i < plain.size(); ++i) {
    const double ta = a.heatTime[size_t(a.pointHeatIndex[i])], tb = b.heatTime[size_t(b.pointHeatIndex[i])];
    EXPECT_NEAR(tb, i <= at ? ta : ta + 60.0, 1e-9) << "point " << i;
  }
  EXPECT_FALSE(b.heatArcOn[size_t(b.pointHeatIndex[at])]);
  EXPECT_NEAR(b.buildTime(), a.buildTime() + 60.0, 1e-9);

  ThermalSettings s;
  NullProgress progress;
  const ThermalResult ra = simulateThermal(a, s, progress), rb = simulateThermal(b, s, progress);
  EXPECT_NEAR(rb.energy.in, ra.energy.in, 1e-9 * ra.energy.in);
  EXPECT_LT(std::abs(rb.energy.imbalance()), 1e-3 * rb.energy.in);
  for (size_t i = 0; i <= at; ++i) ASSERT_NEAR(rb.interpass[i], ra.interpass[i], 1e-6) << "point " << i;
  const size_t over = at + 61;  // revolution 3, half-way round
  std::printf("interpass half-way round revolution 3: %.0f C without the dwell, %.0f C after 60 s\n",
              ra.interpass[over], rb.interpass[over]);
  EXPECT_LT(rb.interpass[over], ra.interpass[over] - 50.0);
}

// Faster travel: lower peaks at the same power, higher valleys (more frequent passes) (Fig. 5.16).
TEST(ThermalModel, FasterTravelGivesLowerPeaksAndHigherValleys)
{
  const auto run = [](double speed) {
    const Trajectory t = test::cylinderWall(30.0, 8, 120, 2.0, speed);
    NullProgress progress;
    return simulateThermal(buildThermalMesh(t, {}), ThermalSettings{}, progress);
  };
  const ThermalResult slow = run(4.0), fast = run(9.0);
  const size_t p = 5 * 120 + 60;
  EXPECT_GT(slow.peak[p], fast.peak[p]);
  EXPECT_LT(slow.interpass[p], fast.interpass[p]);
  std::printf("4 mm/s: peak %.0f C, interpass %.0f C; 9 mm/s: peak %.0f C, interpass %.0f C\n", slow.peak[p],
              slow.interpass[p], fast.peak[p], fast.interpass[p]);
}

// On a closed dome the revolutions shorten towards the closure and the interpass temperature climbs there.
TEST(ThermalModel, InterpassIsHighestNearTheClosureOfADome)
{
  const Trajectory t = test::hemisphereDome(30.0, 2.0, 120, 6.0);
  NullProgress progress;
  const ThermalResult r = simulateThermal(buildThermalMesh(t, {}), ThermalSettings{}, progress);
  const int last = t.points.back().revolution;
  const auto worstOf = [&](int rev) {
    double m = 0.0;
    for (size_t i = 0; i < t.size(); ++i)
      if (t.points[i].revolution == rev) m = std::max(m, r.interpass[i]);
    return m;
  };
  const double middle = worstOf(last / 2), closing = worstOf(last - 1);
  EXPECT_GT(closing, middle + 100.0);
  EXPECT_LT(std::abs(r.energy.imbalance()), 1e-3 * r.energy.in);
  std::printf("dome R 30: worst interpass %.0f C half-way up, %.0f C on the last ring\n", middle, closing);
}

TEST(ThermalModel, RefusesBadSettingsAndStopsWhenCancelled)
{
  const ThermalMesh mesh = buildThermalMesh(test::cylinderWall(20.0, 3, 40, 2.0, 6.0), {});
  NullProgress progress;
  ThermalSettings s;
  s.power = -1.0;
  EXPECT_THROW(simulateThermal(mesh, s, progress), InputError);
  s = {};
  s.material.specificHeat = 0.0;
  EXPECT_THROW(simulateThermal(mesh, s, progress), InputError);
  s = {};
  s.timeStep = 2.0;  // the torch crosses 12 mm of a 5 mm shell
  try {
    simulateThermal(mesh, s, progress);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(e.hint().find("at most 0.416"), std::string::npos) << e.hint();  // half the shell at 6 mm/s
  }
  s.timeStep = 0.4;
  EXPECT_NO_THROW(simulateThermal(mesh, s, progress));
  s.scheme = ThermalScheme::ImplicitEuler;  // the whole shell
  s.timeStep = 0.8;
  EXPECT_NO_THROW(simulateThermal(mesh, s, progress));
  CallbackProgress cancelled;
  cancelled.cancel();
  EXPECT_THROW(simulateThermal(mesh, ThermalSettings{}, cancelled), Cancelled);
}

}  // namespace
}  // namespace spira
