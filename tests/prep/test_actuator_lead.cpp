#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "prep_shapes.h"
#include "spira/base/error.h"
#include "spira/prep/actuator_lead.h"
#include "spira/prep/path_clock.h"

using namespace spira;
using namespace spira::test;

namespace {

// An independent clock: ds / v(s) integrated by Simpson's rule, v linear in s between points.
struct TestClock {
  std::vector<double> s, t, v;
  explicit TestClock(const Trajectory& tr)
  {
    for (size_t k = 0; k < tr.size(); ++k) {
      v.push_back(tr.points[k].travelSpeed);
      s.push_back(k == 0 ? 0.0 : s.back() + (tr.points[k].position - tr.points[k - 1].position).norm());
      t.push_back(k == 0 ? 0.0 : t.back() + partial(k - 1, s[k] - s[k - 1]));
    }
  }
  // Time to travel d mm into interval k.
  double partial(size_t k, double d) const
  {
    const double len = s.size() > k + 1 ? s[k + 1] - s[k] : d;
    const auto speed = [&](double x) { return len > 0 ? v[k] + (v[k + 1] - v[k]) * x / len : v[k]; };
    const int m = 200;
    double sum = 0.0;
    for (int i = 0; i <= m; ++i) sum += (i == 0 || i == m ? 1 : (i % 2 ? 4 : 2)) / speed(d * i / m);
    return sum * d / (3.0 * m);
  }
  double timeAtArc(double x) const
  {
    size_t k = static_cast<size_t>(std::upper_bound(s.begin(), s.end(), x) - s.begin());
    k = std::clamp<size_t>(k, 1, s.size() - 1) - 1;
    return t[k] + partial(k, x - s[k]);
  }
};

// The actuator integrated with RK4 (1 ms steps, split at every command switch) from rest at y0:
// tau y' + y = u(t - deadTime), u piecewise constant from switch time to switch time. Returns y at
// each of `at` (increasing).
std::vector<double> simulate(const std::vector<double>& switchTime, const std::vector<double>& command,
                             double y0, const LagModel& m, const std::vector<double>& at)
{
  // Output-time pieces: command k from switchTime[k] + deadTime on; before, the settled input y0.
  std::vector<double> start{-1e9}, value{y0};
  for (size_t k = 0; k < command.size(); ++k) {
    start.push_back(switchTime[k] + m.deadTime);
    value.push_back(command[k]);
  }
  std::vector<double> out;
  double y = y0, now = 0.0;
  size_t piece = 0;
  const auto rate = [&](double yy, double u) {
    const double tau = u >= yy ? m.riseTimeConstant : m.fallTimeConstant;
    return (u - yy) / tau;
  };
  for (double target : at) {
    while (now < target) {
      while (piece + 1 < start.size() && start[piece + 1] <= now) ++piece;
      const double end = piece + 1 < start.size() ? std::min(target, start[piece + 1]) : target;
      const double u = value[piece];
      while (now < end) {
        const double h = std::min(1e-3, end - now);
        const double k1 = rate(y, u), k2 = rate(y + 0.5 * h * k1, u), k3 = rate(y + 0.5 * h * k2, u),
                     k4 = rate(y + h * k3, u);
        y += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
        now += h;
      }
      now = end;
    }
    out.push_back(y);
  }
  return out;
}

// Points along x, 0.5 to 1.5 mm apart, with a travel speed of 8 + 3 sin(s / 20) mm/s.
Trajectory variableSpeedPath(int n)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> gap(0.5, 1.5);
  Trajectory tr = straightLine(1.0, n);
  double x = 0.0;
  for (auto& p : tr.points) {
    p.position = Vec3(x, 0, 0);
    p.travelSpeed = 8.0 + 3.0 * std::sin(x / 20.0);
    x += gap(rng);
  }
  return tr;
}

// Planned wire feed: a wave plus a 10 mm/s ramp over 4 mm around s = 200.
std::vector<double> plannedWireFeed(const Trajectory& tr)
{
  std::vector<double> w;
  for (const auto& p : tr.points) {
    const double s = p.position.x();
    w.push_back(100.0 + 20.0 * std::sin(s / 15.0) + 10.0 * std::clamp((s - 198.0) / 4.0, 0.0, 1.0));
  }
  return w;
}

}  // namespace

TEST(PathClock, MatchesQuadratureAndInverts)
{
  const Trajectory tr = variableSpeedPath(300);
  const PathClock clock(tr);
  const TestClock ref(tr);
  for (size_t k = 0; k < tr.size(); ++k) EXPECT_NEAR(clock.times()[k], ref.t[k], 1e-9) << k;
  for (double x : {0.0, 0.3, 17.2, 150.0, ref.s.back()})
    EXPECT_NEAR(clock.arcAtTime(ref.timeAtArc(x)), x, 1e-9) << x;
  Trajectory bad = straightLine(1.0, 3);
  bad.points[1].travelSpeed = 0.0;
  EXPECT_THROW(PathClock{bad}, InputError);
}

// The round trip: commands written at the lead distances before each point, fed through the lag model
// (integrated independently), reproduce the planned wire feed at every point the lead can reach.
TEST(ActuatorLead, LedCommandReproducesThePlannedChannel)
{
  const Trajectory tr = variableSpeedPath(400);
  const std::vector<double> planned = plannedWireFeed(tr);
  LagModel model;
  model.deadTime = 0.15;
  model.riseTimeConstant = 0.08;
  model.fallTimeConstant = 0.12;
  const LeadResult lead = leadChannel(tr, planned, model);
  const TestClock clock(tr);

  size_t firstExact = 0;
  while (clock.t[firstExact] <= model.deadTime) ++firstExact;
  EXPECT_EQ(lead.firstExactIndex, firstExact);
  EXPECT_EQ(lead.clampedCommands, 0u);

  std::vector<double> trigger;
  for (size_t k = 0; k < tr.size(); ++k) {
    EXPECT_GE(lead.leadDistance[k], 0.0);
    trigger.push_back(clock.timeAtArc(clock.s[k] - lead.leadDistance[k]));
    EXPECT_NEAR(trigger[k], std::max(0.0, clock.t[k] - model.deadTime), 1e-9) << k;
  }
  const std::vector<double> y = simulate(trigger, lead.command, planned[0], model, clock.t);
  double worst = 0.0, unledWorst = 0.0;
  for (size_t k = firstExact; k < tr.size(); ++k) {
    worst = std::max(worst, std::abs(y[k] - planned[k]));
    EXPECT_NEAR(lead.predicted[k], planned[k], 1e-9);
  }
  // Stated tolerance: 1e-6 mm/s of wire feed (the RK4 integration error is far below).
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(lead.maxError, 1e-9);

  // Without the lead (the planned value written at each point) the same actuator misses by mm/s.
  const std::vector<double> unled = simulate(clock.t, planned, planned[0], model, clock.t);
  for (size_t k = firstExact; k < tr.size(); ++k)
    unledWorst = std::max(unledWorst, std::abs(unled[k] - planned[k]));
  std::printf("wire feed tracking error: led %.2e mm/s, unled %.2f mm/s\n", worst, unledWorst);
  EXPECT_GT(unledWorst, 1.0);
}

// At constant speed the lead is a fixed distance: dead time x speed, and the setpoint in force at a
// point is the one planned for a point that many millimetres ahead.
TEST(ActuatorLead, ConstantSpeedLeadsByDeadTimeTimesSpeed)
{
  const Trajectory tr = straightLine(100.0, 101);  // 1 mm apart, 10 mm/s
  std::vector<double> planned;
  for (size_t k = 0; k < tr.size(); ++k) planned.push_back(100.0 + 5.0 * std::sin(0.1 * k));
  LagModel model;
  model.deadTime = 0.2;
  const LeadResult lead = leadChannel(tr, planned, model);
  for (size_t k = 0; k < tr.size(); ++k) {
    EXPECT_NEAR(lead.time[k], 0.1 * k, 1e-12);
    EXPECT_NEAR(lead.leadDistance[k], std::min(2.0, 1.0 * k), 1e-9) << k;
    if (k + 2 < tr.size()) {
      EXPECT_EQ(lead.commandAtPoint[k], lead.command[k + 2]) << k;
    }
  }
  // Dead time only: the command is the planned value of the next point, written 2 mm early.
  model.riseTimeConstant = model.fallTimeConstant = 0.0;
  const LeadResult pure = leadChannel(tr, planned, model);
  for (size_t k = 2; k + 1 < tr.size(); ++k) EXPECT_DOUBLE_EQ(pure.command[k], planned[k + 1]);
}

// A step the feeder cannot follow: commands are clamped, the prediction stays honest (it matches the
// independent simulation) and the output is exact again once the step is caught up.
TEST(ActuatorLead, ClampedCommandsArePredictedHonestly)
{
  const Trajectory tr = straightLine(100.0, 101);
  std::vector<double> planned(tr.size(), 100.0);
  for (size_t k = 50; k < tr.size(); ++k) planned[k] = 150.0;
  LagModel model;
  model.deadTime = 0.1;
  model.riseTimeConstant = model.fallTimeConstant = 0.2;
  model.maxCommand = 160.0;
  const LeadResult lead = leadChannel(tr, planned, model);
  EXPECT_GT(lead.clampedCommands, 0u);
  EXPECT_GT(lead.maxError, 1.0);
  for (double c : lead.command) EXPECT_LE(c, 160.0);
  const TestClock clock(tr);
  const std::vector<double> y = simulate(lead.triggerTime, lead.command, planned[0], model, clock.t);
  for (size_t k = 0; k < tr.size(); ++k) EXPECT_NEAR(lead.predicted[k], y[k], 1e-6) << k;
  EXPECT_NEAR(lead.predicted.back(), 150.0, 1e-9);
}

TEST(ActuatorLead, RejectsBadInput)
{
  const Trajectory tr = straightLine(10.0, 11);
  LagModel model;
  model.deadTime = -1.0;
  EXPECT_THROW(leadChannel(tr, std::vector<double>(11, 1.0), model), InputError);
  model = LagModel{};
  EXPECT_THROW(leadChannel(tr, std::vector<double>(3, 1.0), model), InputError);
  EXPECT_THROW(leadChannel(tr, std::string("nozzle"), model), InputError);
  EXPECT_EQ(leadChannel(tr, std::string("wireFeed"), model).command.size(), 11u);
}
