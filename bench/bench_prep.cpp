// Path preparation before export on a 100,000-point spiral plan: a helix on a cylinder of radius 50 mm,
// 2 mm per revolution, points 1 mm apart (318 revolutions), deposit height modulated (2 + 0.3 sin 8
// theta) and travel speed / wire feed modulated (sin 3 theta). Times smoothing + resampling +
// decimation (prepareTrajectory), then the wire-feed lead and deadband on the prepared path. Prints the
// best and median of several runs, wall clock and CPU time (the fairer number on a shared machine).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/prep/actuator_lead.h"
#include "spira/prep/channels.h"
#include "spira/prep/deadband.h"
#include "spira/prep/prepare_trajectory.h"

using namespace spira;

namespace {

Trajectory spiralPlan(size_t n, double spacing)
{
  const double R = 50.0, pitch = 2.0;
  Trajectory tr;
  tr.points.reserve(n);
  const double step = spacing / R;
  const double climb = pitch / (2.0 * kPi);
  for (size_t i = 0; i < n; ++i) {
    const double a = step * static_cast<double>(i);
    TrajectoryPoint p;
    p.position = Vec3(R * std::cos(a), R * std::sin(a), climb * a);
    p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
    p.tangent = Vec3(-R * std::sin(a), R * std::cos(a), climb).normalized();
    p.build = p.normal.cross(p.tangent);
    p.revolution = static_cast<int>(a / (2.0 * kPi));
    p.height = 2.0 + 0.3 * std::sin(8.0 * a);
    p.travelSpeed = 8.0 + std::sin(3.0 * a);
    p.wireFeed = 100.0 + 10.0 * std::sin(3.0 * a);
    tr.points.push_back(p);
  }
  return tr;
}

double seconds(std::chrono::steady_clock::duration d)
{
  return std::chrono::duration<double>(d).count();
}

void run(const char* label, const Trajectory& plan, const PrepParams& params, int repeats)
{
  NullProgress progress;
  std::vector<double> wall, cpu, leadWall;
  PreparedTrajectory prep;
  LeadResult lead;
  DeadbandResult band;
  for (int r = 0; r < repeats; ++r) {
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    prep = prepareTrajectory(plan, params, progress);
    const auto t1 = std::chrono::steady_clock::now();
    cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    wall.push_back(seconds(t1 - t0));
    lead = leadChannel(prep.trajectory, std::string(kWireFeedChannel), LagModel{});
    band = applyDeadband(lead.commandAtPoint, 0.5);
    leadWall.push_back(seconds(std::chrono::steady_clock::now() - t1));
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  std::sort(leadWall.begin(), leadWall.end());
  const PrepReport& rep = prep.report;
  std::printf("%s: %zu points -> %zu samples -> %zu prepared\n", label, rep.pointsIn, rep.samples,
              rep.pointsOut);
  std::printf("  prepare: best %.1f ms, median %.1f ms wall; CPU best %.1f ms\n", 1e3 * wall.front(),
              1e3 * wall[wall.size() / 2], 1e3 * cpu.front());
  std::printf("  lead + deadband (wire feed): best %.2f ms; %zu of %zu setpoints written\n",
              1e3 * leadWall.front(), band.emitted, band.emit.size());
  std::printf(
      "  chord %.4f mm, smoothing offset %.4f mm, height %.4f mm, TS %.3f mm/s, WFS %.3f mm/s, "
      "orientation %.3f deg, segments %.2f..%.2f mm, overrides %zu\n",
      rep.maxChordDeviation, rep.maxSmoothingOffset, rep.maxChannelDeviation.at(kHeightChannel),
      rep.maxChannelDeviation.at(kTravelSpeedChannel), rep.maxChannelDeviation.at(kWireFeedChannel),
      radToDeg(rep.maxOrientationDeviation), rep.minSegment, rep.maxSegment, rep.spacingOverrides);
}

}  // namespace

int main()
{
  const size_t n = 100000;
  PrepParams params;
  run("spiral 1 mm spacing, defaults", spiralPlan(n, 1.0), params, 7);
  run("spiral 3 mm spacing, defaults (smoothing inserts samples)", spiralPlan(n, 3.0), params, 5);
  params.smooth = false;
  run("spiral 1 mm spacing, no smoothing", spiralPlan(n, 1.0), params, 7);
  params.smooth = true;
  params.maxSpacing = 1e6;
  params.heightTolerance = params.travelSpeedTolerance = params.wireFeedTolerance = 1e6;
  run("spiral 1 mm spacing, chord tolerance only, no spacing cap", spiralPlan(n, 1.0), params, 5);
  return 0;
}
