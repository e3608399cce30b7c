// The led wire feed, read back from the written programs: a step of the planned wire feed, a
// feeder modelled as dead time plus first-order lag, and the setpoints at the times the files
// make the controller write them. The modelled feed must reach the new value at the planned
// point of the step (and without the lead it does not).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "builtin_plugins.h"
#include "export_test_data.h"
#include "krl_reader.h"
#include "spira/base/progress.h"
#include "spira/pipeline/export_job.h"
#include "spira/plugin/plugin_registry.h"
#include "support/test_support.h"
#include "tp_reader.h"

namespace spira {
namespace {

constexpr double kLow = 3.0, kHigh = 5.0;  // m/min
constexpr size_t kStep = 80;               // first planned point at kHigh
constexpr double kMmPerS = 1000.0 / 60.0;  // per m/min

LagModel feeder()
{
  LagModel m;
  m.deadTime = 0.2;
  m.riseTimeConstant = 0.1;
  m.fallTimeConstant = 0.15;
  return m;
}

Trajectory stepPlan()
{
  Trajectory plan = test::cylinderPlan(2, 72, 30.0, 2.0);
  for (size_t i = 0; i < plan.size(); ++i) {
    plan.points[i].travelSpeed = 10.0;
    plan.points[i].wireFeed = (i < kStep ? kLow : kHigh) * kMmPerS;
  }
  return plan;
}

// A setpoint (m/min) and the time (s, 0 at the first path point) the controller writes it.
struct Setpoint {
  double time;
  double wfs;
};

// Time of each path target (0 at the first) and the setpoints read back.
struct ReadBack {
  std::vector<Vec3> targets;
  std::vector<double> times;
  std::vector<Setpoint> setpoints;
};

// The modelled feed at time t: the feeder sees each setpoint deadTime after it is written and
// follows it with the first-order lag; settled at kLow before the motion.
double feedAt(const std::vector<Setpoint>& setpoints, double t, const LagModel& m)
{
  double y = kLow, u = kLow, now = -1.0;
  std::vector<Setpoint> seen = setpoints;
  std::sort(seen.begin(), seen.end(), [](const Setpoint& a, const Setpoint& b) { return a.time < b.time; });
  auto advance = [&](double to) {
    const double tau = u >= y ? m.riseTimeConstant : m.fallTimeConstant;
    y = u + (y - u) * std::exp(-(to - now) / tau);
    now = to;
  };
  for (const Setpoint& s : seen) {
    const double acts = s.time + m.deadTime;
    if (acts >= t) break;
    if (acts > now) advance(acts);
    u = s.wfs;
  }
  advance(t);
  return y;
}

ReadBack readKrl(const std::filesystem::path& dir)
{
  const test::KrlRun run = test::runKrl(dir, "spira_part");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ReadBack r;
  double t = 0.0;
  for (const test::KrlMove& m : run.moves) {
    if (m.target.rfind("XP", 0) != 0) continue;
    const double start = t;
    if (!r.targets.empty()) t += (m.pose.xyz - r.targets.back()).norm() / (1000.0 * m.velCp);
    for (const auto& text : m.triggers) {
      const size_t at = text.find("TRIGGER WHEN DISTANCE=");
      int distance = 0, delayMs = 0;
      double volts = 0.0;
      if (at == std::string::npos ||
          std::sscanf(text.c_str() + at, "TRIGGER WHEN DISTANCE=%d DELAY=%d DO $ANOUT[1]=%lf", &distance,
                      &delayMs, &volts) != 3)
        continue;
      r.setpoints.push_back({(distance == 0 ? start : t) + delayMs / 1000.0, volts / 0.1});
    }
    r.targets.push_back(m.pose.xyz);
    r.times.push_back(t);
  }
  return r;
}

ReadBack readTp(const std::filesystem::path& dir)
{
  const test::TpRun run = test::runTp(dir, "SPIRA_PART");
  for (const auto& p : run.problems) ADD_FAILURE() << p;
  ReadBack r;
  double t = 0.0;
  bool started = false;
  for (size_t i = 1; i < run.moves.size(); ++i) {  // moves[0] is the joint move to the approach
    const test::TpMove& m = run.moves[i];
    const Vec3 xyz = test::tpPose(m.pos).translation();
    if (started) t += (xyz - r.targets.back()).norm() / std::stod(m.speed);
    for (const char* tag : {"TA ", "TB "}) {
      const size_t at = m.options.find(tag);
      double offset = 0.0;
      int value = 0;
      if (at != std::string::npos &&
          std::sscanf(m.options.c_str() + at + 3, "%lfsec,AO[1]=%d", &offset, &value) == 2)
        r.setpoints.push_back({tag[1] == 'A' ? t + offset : t - offset, value / 100.0});
    }
    if (m.speed.find("mm/sec") == std::string::npos) ADD_FAILURE() << m.speed;
    if (i == 1) started = true;  // the approach ends on the first path point: time 0
    if (started) {
      r.targets.push_back(xyz);
      r.times.push_back(t);
    }
  }
  return r;
}

ReadBack exportStep(const std::string& id, bool lead, const std::filesystem::path& dir)
{
  ExportJob job;
  job.exporterId = id;
  job.exporterParams.set("process_command", std::string("speed_analog"));
  job.exporterParams.set("wfs_deadband", 0.0);
  job.prep.leadWireFeed = lead;
  job.prep.wireFeedLag = feeder();
  job.header = test::testHeader();
  NullProgress progress;
  exportTrajectory(builtinRegistry(), stepPlan(), job, dir, progress);
  return id == "export.krl" ? readKrl(dir) : readTp(dir);
}

// Index of the read-back target at the planned point `i`.
size_t targetAt(const ReadBack& r, const Vec3& planned)
{
  size_t best = 0;
  for (size_t k = 0; k < r.targets.size(); ++k)
    if ((r.targets[k] - planned).norm() < (r.targets[best] - planned).norm()) best = k;
  EXPECT_LT((r.targets[best] - planned).norm(), 0.05);
  return best;
}

void checkStepIsMet(const std::string& id)
{
  const Trajectory plan = stepPlan();
  test::TempDir led, plain;
  const ReadBack r = exportStep(id, true, led.path());
  ASSERT_FALSE(r.setpoints.empty());
  const size_t step = targetAt(r, plan.points[kStep].position);
  const size_t before = targetAt(r, plan.points[kStep - 1].position);
  ASSERT_EQ(before + 1, step);
  // Before the step the feed holds the low value; from the planned step point on it is the high one.
  for (size_t k = 0; k <= before; ++k)
    EXPECT_NEAR(feedAt(r.setpoints, r.times[k], feeder()), kLow, 0.05) << id << " target " << k;
  for (size_t k = step; k < r.targets.size(); ++k)
    EXPECT_NEAR(feedAt(r.setpoints, r.times[k], feeder()), kHigh, 0.05) << id << " target " << k;
  // The step's first setpoint is written ahead of the step by about the dead time.
  double first = 1e9;
  for (const Setpoint& s : r.setpoints)
    if (s.wfs > kLow + 0.1) first = std::min(first, s.time);
  EXPECT_NEAR(first, r.times[before] - feeder().deadTime, 0.011) << id;

  // Without the lead the setpoint is written as the last move before the step starts: the dead
  // time eats most of that move and the feed is still about 1 m/min short at the step.
  const ReadBack p = exportStep(id, false, plain.path());
  const size_t plainStep = targetAt(p, plan.points[kStep].position);
  EXPECT_LT(feedAt(p.setpoints, p.times[plainStep], feeder()), kHigh - 0.5) << id;
}

TEST(WfsLeadExport, KrlTriggersMakeTheFeedReachTheStepAtItsPoint)
{
  checkStepIsMet("export.krl");
}

TEST(WfsLeadExport, TpPointLogicMakesTheFeedReachTheStepAtItsPoint)
{
  checkStepIsMet("export.fanuc_tp");
}

}  // namespace
}  // namespace spira
