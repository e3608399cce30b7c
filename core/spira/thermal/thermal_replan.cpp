#include "spira/thermal/thermal_replan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {
namespace {

using RevolutionKey = std::pair<int, int>;  // (path, revolution)

RevolutionKey keyOf(const TrajectoryPoint& p)
{
  return {p.path, p.revolution};
}

// Aim a little under the limit: the interpass temperature does not follow the speed factor exactly,
// and landing just over the limit would cost a round for a few degrees.
constexpr double kAim = 0.97;
// No revolution is slowed by more than this in one round: the heat of the revolutions below also
// changes, so a larger step overshoots.
constexpr double kStrongestStep = 0.5;

}  // namespace

double powerPerWireFeedOf(const Trajectory& trajectory, double power)
{
  std::vector<double> feeds;
  for (const TrajectoryPoint& p : trajectory.points)
    if (p.arcOn && p.wireFeed > 0.0) feeds.push_back(p.wireFeed);
  if (feeds.empty())
    throw InputError("the path has no wire feed to scale the arc power with",
                     "plan it with the process stage (synergic or constant travel speed)");
  std::nth_element(feeds.begin(), feeds.begin() + long(feeds.size() / 2), feeds.end());
  return power / feeds[feeds.size() / 2];
}

ThermalReplanOutcome replanForInterpass(const Trajectory& planned, const ThermalStudySettings& settings,
                                        const ThermalReplanSettings& replan, Progress& progress)
{
  const double ambient = settings.solver.initialTemperature, limit = replan.interpassMax;
  if (!(limit > ambient) || !std::isfinite(limit))
    throw InputError("an interpass limit of " + significantText(limit, 6) + " C is not above the initial " +
                         significantText(ambient, 6) + " C",
                     "give a limit such as 250 C (G3Si1's suggested interpass temperature)");
  if (!(settings.solver.powerPerWireFeed > 0.0) && settings.solver.powerTable.empty())
    throw InputError("re-planning needs the arc power to follow the wire feed",
                     "set the power per unit wire feed (powerPerWireFeedOf)");

  // The lowest factor each revolution may be slowed to: no point below the process's slowest wire
  // feed or travel speed.
  std::map<RevolutionKey, double> floorOf, factorOf;
  for (const TrajectoryPoint& p : planned.points) {
    double lowest = 0.0;
    if (p.wireFeed > 0.0) lowest = std::max(lowest, replan.limits.wireFeedMin / p.wireFeed);
    if (p.travelSpeed > 0.0) lowest = std::max(lowest, replan.limits.travelSpeedMin / p.travelSpeed);
    double& f = floorOf[keyOf(p)];
    f = std::max(f, std::min(1.0, lowest));
    factorOf[keyOf(p)] = 1.0;
  }

  ThermalReplanOutcome out;
  out.trajectory = planned;
  const int total = replan.maxRounds + 1;
  SubProgress first(progress, 0.0, 1.0 / total, "thermal history");
  out.study = runThermalStudy(out.trajectory, settings, first);
  const double plannedTime = out.study.mesh.buildTime();
  for (;;) {
    std::map<RevolutionKey, double> hottest;
    for (size_t i = 0; i < planned.points.size(); ++i) {
      const TrajectoryPoint& p = planned.points[i];
      if (p.revolution == 0) continue;  // it rests on the substrate, not on a pass of its own
      double& h = hottest[keyOf(p)];
      h = std::max(h, out.study.result.interpass[i]);
    }
    std::vector<RevolutionKey> over;
    for (const auto& [key, t] : hottest)
      if (t > limit) over.push_back(key);
    if (over.empty()) {
      out.limitMet = true;
      break;
    }
    if (out.rounds >= replan.maxRounds) {
      out.why = std::to_string(over.size()) + " revolution(s) still above " + significantText(limit, 4) +
                " C after " + std::to_string(out.rounds) + " re-simulations";
      break;
    }
    bool changed = false;
    for (const RevolutionKey& key : over) {
      const double ratio = (kAim * limit - ambient) / (hottest[key] - ambient);
      const double step = std::clamp(ratio, kStrongestStep, 1.0);
      // The revolution itself and the one it rests on: together they make the time the deposit
      // below has to cool, and the heat put in over it.
      for (const RevolutionKey& k : {key, RevolutionKey{key.first, key.second - 1}}) {
        if (!factorOf.count(k)) continue;
        const double next = std::max(floorOf[k], factorOf[k] * step);
        if (next < factorOf[k] - 1e-12) {
          factorOf[k] = next;
          changed = true;
        }
      }
    }
    if (!changed) {
      out.why = "the revolutions above " + significantText(limit, 4) +
                " C already run at the slowest wire feed or travel speed the process allows (" +
                significantText(replan.limits.wireFeedMin, 4) + " mm/s, " +
                significantText(replan.limits.travelSpeedMin, 4) + " mm/s)";
      break;
    }
    for (TrajectoryPoint& p : out.trajectory.points) {
      const size_t i = size_t(&p - out.trajectory.points.data());
      const double f = factorOf[keyOf(p)];
      p.travelSpeed = planned.points[i].travelSpeed * f;
      p.wireFeed = planned.points[i].wireFeed * f;
    }
    ++out.rounds;
    SubProgress round(progress, double(out.rounds) / total, double(out.rounds + 1) / total,
                      "thermal re-planning");
    out.study = runThermalStudy(out.trajectory, settings, round);
  }
  for (const auto& [key, f] : factorOf) {
    out.revolutionsChanged += f < 1.0;
    out.slowestFactor = std::min(out.slowestFactor, f);
  }
  out.buildTimeAdded = out.study.mesh.buildTime() - plannedTime;
  progress.report(1.0, "thermal re-planning");
  return out;
}

}  // namespace spira
