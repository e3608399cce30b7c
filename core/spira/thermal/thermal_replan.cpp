#include "spira/thermal/thermal_replan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/path/dwell.h"
#include "spira/path/revolution_thinning.h"

namespace spira {
namespace {

using RevolutionKey = std::pair<int, int>;  // (path, revolution)

RevolutionKey keyOf(const TrajectoryPoint& p)
{
  return {p.path, p.revolution};
}

// Aim a little under the limit: the interpass temperature does not follow a change exactly, and
// landing just over the limit would cost a round for a few degrees.
constexpr double kAim = 0.97;
// No revolution is slowed (nor a band thinned) by more than this in one round: the heat of the
// revolutions below also changes, so a larger step overshoots.
constexpr double kStrongestStep = 0.5;
// A round of a remedy that does not lower the worst interpass temperature by this much ends it.
constexpr double kProgress = 0.5;  // C

// A path with what each remedy did to it.
struct Candidate {
  Trajectory trajectory;
  ThermalStudy study;
  std::map<RevolutionKey, double> hottest;  // interpass per revolution resting on a pass
  double worst = 0.0;
  std::vector<std::string> applied;
  int revolutionsAdded = 0;
  double thinnestRatio = 1.0;
  int revolutionsSlowed = 0;
  double slowestFactor = 1.0;
  int dwells = 0;
  double dwellTime = 0.0;
};

// What a remedy starts from: the current path with its measures, without its study (each round
// simulates its own; the mesh and frames of the starting point are not needed again).
Candidate startingPoint(Candidate& current)
{
  ThermalStudy study = std::move(current.study);
  Candidate base = current;  // all but the study
  current.study = std::move(study);
  return base;
}

std::map<int, int> revolutionSizes(const Trajectory& t, int path)
{
  std::map<int, int> size;
  for (const TrajectoryPoint& p : t.points)
    if (p.path == path) ++size[p.revolution];
  return size;
}

class Replanner {
 public:
  Replanner(const ThermalStudySettings& settings, const ThermalReplanSettings& replan, Progress& progress)
      : settings_(settings),
        replan_(replan),
        progress_(progress),
        ambient_(settings.solver.initialTemperature),
        limit_(replan.interpassMax)
  {
  }

  void start(const Trajectory& planned)
  {
    Candidate c;
    c.trajectory = planned;
    SubProgress first(progress_, 0.0, 1.0 / total(), "thermal history");
    c.study = runThermalStudy(c.trajectory, settings_, first);
    measure(c);
    plannedTime_ = c.study.mesh.buildTime();
    plannedWorst_ = c.worst;
    best_ = c;
    current_ = std::move(c);
  }

  bool met() const { return current_.worst <= limit_; }

  void deposit();
  void heat();
  void dwell();

  ThermalReplanOutcome finish()
  {
    Candidate& c = met() ? current_ : best_;
    ThermalReplanOutcome out;
    out.limitMet = c.worst <= limit_;
    out.rounds = rounds_;
    out.applied = c.applied;
    out.revolutionsAdded = c.revolutionsAdded;
    out.thinnestRatio = c.thinnestRatio;
    out.revolutionsChanged = c.revolutionsSlowed;
    out.slowestFactor = c.slowestFactor;
    out.dwells = c.dwells;
    out.dwellTime = c.dwellTime;
    out.buildTimeAdded = c.study.mesh.buildTime() - plannedTime_;
    out.plannedWorst = plannedWorst_;
    if (!out.limitMet) {
      for (const std::string& note : notes_) out.why += (out.why.empty() ? "" : "; ") + note;
      if (out.why.empty())
        out.why = std::to_string(overLimit(c).size()) + " revolution(s) still above " +
                  significantText(limit_, 4) + " C";
    }
    out.trajectory = std::move(c.trajectory);
    out.study = std::move(c.study);
    progress_.report(1.0, "thermal re-planning");
    return out;
  }

 private:
  int total() const { return replan_.maxRounds + 1; }

  void measure(Candidate& c) const
  {
    c.hottest.clear();
    for (size_t i = 0; i < c.trajectory.size(); ++i) {
      const TrajectoryPoint& p = c.trajectory.points[i];
      if (p.revolution == 0) continue;  // it rests on the substrate, not on a pass of its own
      double& h = c.hottest[keyOf(p)];
      h = std::max(h, c.study.result.interpass[i]);
    }
    c.worst = ambient_;
    for (const auto& [key, t] : c.hottest) c.worst = std::max(c.worst, t);
  }

  std::vector<RevolutionKey> overLimit(const Candidate& c) const
  {
    std::vector<RevolutionKey> over;
    for (const auto& [key, t] : c.hottest)
      if (t > limit_) over.push_back(key);
    return over;
  }

  // The next round, or false (with a note) when the budget is spent.
  bool roundLeft()
  {
    if (rounds_ < replan_.maxRounds) return true;
    note(std::to_string(overLimit(current_).size()) + " revolution(s) still above " +
         significantText(limit_, 4) + " C after " + std::to_string(rounds_) + " re-simulations");
    return false;
  }

  void simulate(Candidate next, const char* remedy)
  {
    ++rounds_;
    SubProgress round(progress_, double(rounds_) / total(), double(rounds_ + 1) / total(),
                      "thermal re-planning");
    next.study = runThermalStudy(next.trajectory, settings_, round);
    measure(next);
    if (next.applied.empty() || next.applied.back() != remedy) next.applied.push_back(remedy);
    if (next.worst < best_.worst) best_ = next;
    current_ = std::move(next);
  }

  // Back to the best path simulated, for the next remedy to start from.
  void settle()
  {
    if (best_.worst < current_.worst) current_ = best_;
  }

  void note(const std::string& text)
  {
    if (std::find(notes_.begin(), notes_.end(), text) == notes_.end()) notes_.push_back(text);
  }

  double stepFor(double hottest) const
  {
    return std::clamp((kAim * limit_ - ambient_) / (hottest - ambient_), kStrongestStep, 1.0);
  }

  const ThermalStudySettings& settings_;
  const ThermalReplanSettings& replan_;
  Progress& progress_;
  const double ambient_, limit_;
  Candidate current_, best_;
  int rounds_ = 0;
  double plannedTime_ = 0.0, plannedWorst_ = 0.0;
  std::vector<std::string> notes_;
};

void Replanner::deposit()
{
  if (met() || !replan_.deposit) return;
  if (!(replan_.hMin > 0.0)) {
    note("the deposit remedy needs the process window's h_min");
    return;
  }
  const Candidate base = startingPoint(current_);
  // Per path the band from two revolutions under the first one above the limit to the last one
  // above it, within the revolutions that visit every generatrix.
  std::map<int, ThinningZone> zones;
  for (const auto& [path, rev] : overLimit(base)) {
    auto [it, fresh] = zones.try_emplace(path, ThinningZone{path, std::max(0, rev - 2), rev, 1.0});
    if (!fresh) it->second.last = std::max(it->second.last, rev);
  }
  // A path fed at one wire speed thins by travelling faster, any other by feeding less wire.
  double feedLow = 1e300, feedHigh = 0.0;
  for (const TrajectoryPoint& p : base.trajectory.points)
    if (p.arcOn) feedLow = std::min(feedLow, p.wireFeed), feedHigh = std::max(feedHigh, p.wireFeed);
  const bool synergic = feedHigh <= feedLow * (1.0 + 1e-9);
  double floor = 0.0;
  for (auto it = zones.begin(); it != zones.end();) {
    ThinningZone& z = it->second;
    const std::map<int, int> size = revolutionSizes(base.trajectory, z.path);
    int last = z.first;
    while (last < z.last && size.count(last + 1) && size.at(last + 1) == size.at(z.first)) ++last;
    z.last = last;
    if (z.last <= z.first) {
      it = zones.erase(it);
      continue;
    }
    // Each generatrix lays the band in equal layers (revolution_thinning.h): its mean height may
    // thin down to h_min.
    std::map<int, double> band;  // per generatrix: the band's deposit
    for (const TrajectoryPoint& p : base.trajectory.points) {
      if (p.path != z.path || p.revolution <= z.first || p.revolution > z.last) continue;
      band[p.generatrix] += p.height;
      floor = std::max(floor, synergic ? p.travelSpeed / replan_.limits.travelSpeedMax
                                       : replan_.limits.wireFeedMin / p.wireFeed);
    }
    for (const auto& [generatrix, height] : band)
      floor = std::max(floor, height > 0.0 ? replan_.hMin * (z.last - z.first) / height : 1.0);
    ++it;
  }
  if (zones.empty()) {
    note("the revolutions above the limit cannot be thinned (they do not visit every generatrix)");
    return;
  }
  if (floor >= 1.0 - 1e-9) {
    note("the deposit there is already at the window's h_min (" + significantText(replan_.hMin, 4) +
         " mm) or the process's speed limits");
    return;
  }
  int widest = 0;
  for (const auto& [path, zone] : zones) widest = std::max(widest, zone.last - zone.first);
  double ratio = 1.0;
  while (!met() && roundLeft()) {
    double hot = ambient_;
    for (const auto& [key, t] : current_.hottest)
      if (zones.count(key.first)) hot = std::max(hot, t);
    // A whole number of revolutions fills each band: at least one more in the widest one, or the
    // round would simulate the same path again.
    const int laid = int(std::ceil(widest / ratio - 1e-9));
    const double next = std::min(std::max(floor, ratio * stepFor(hot)), double(widest) / (laid + 1));
    if (next < floor - 1e-12) {
      note("the thinned band is at the window's h_min (" + significantText(replan_.hMin, 4) +
           " mm) or the process's speed limits");
      break;
    }
    Candidate c = base;
    double thinnest = 1.0;
    for (const auto& [path, zone] : zones) {
      ThinningZone z = zone;
      z.ratio = next;
      ThinningResult thin = thinRevolutions(c.trajectory, z);
      c.trajectory = std::move(thin.trajectory);
      c.revolutionsAdded += thin.revolutionsAdded;
      thinnest = std::min(thinnest, thin.ratio);
    }
    c.thinnestRatio = thinnest;
    const double before = current_.worst;
    simulate(std::move(c), "deposit");
    ratio = next;
    if (current_.worst > before - kProgress) {
      note(std::string(synergic ? "thinner, faster revolutions" : "thinner revolutions fed less wire") +
           " did not lower the interpass temperature (" + significantText(before, 4) + " C before, " +
           significantText(current_.worst, 4) + " C after)");
      break;
    }
  }
  settle();
}

void Replanner::heat()
{
  if (met() || !replan_.heat) return;
  const Candidate base = startingPoint(current_);
  // The lowest factor each revolution may be slowed to: no point below the process's slowest wire
  // feed or travel speed.
  std::map<RevolutionKey, double> floorOf, factorOf;
  for (const TrajectoryPoint& p : base.trajectory.points) {
    double lowest = 0.0;
    if (p.wireFeed > 0.0) lowest = std::max(lowest, replan_.limits.wireFeedMin / p.wireFeed);
    if (p.travelSpeed > 0.0) lowest = std::max(lowest, replan_.limits.travelSpeedMin / p.travelSpeed);
    double& f = floorOf[keyOf(p)];
    f = std::max(f, std::min(1.0, lowest));
    factorOf[keyOf(p)] = 1.0;
  }
  while (!met() && roundLeft()) {
    bool changed = false;
    for (const RevolutionKey& key : overLimit(current_)) {
      const double step = stepFor(current_.hottest.at(key));
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
      note("the revolutions above " + significantText(limit_, 4) +
           " C already run at the slowest wire feed or travel speed the process allows (" +
           significantText(replan_.limits.wireFeedMin, 4) + " mm/s, " +
           significantText(replan_.limits.travelSpeedMin, 4) + " mm/s)");
      break;
    }
    Candidate c = base;
    for (size_t i = 0; i < c.trajectory.size(); ++i) {
      TrajectoryPoint& p = c.trajectory.points[i];
      const double f = factorOf[keyOf(p)];
      p.travelSpeed = base.trajectory.points[i].travelSpeed * f;
      p.wireFeed = base.trajectory.points[i].wireFeed * f;
    }
    for (const auto& [key, f] : factorOf) {
      c.revolutionsSlowed += f < 1.0;
      c.slowestFactor = std::min(c.slowestFactor, f);
    }
    simulate(std::move(c), "heat");
  }
  settle();
}

void Replanner::dwell()
{
  if (met() || !replan_.dwell) return;
  const Candidate base = startingPoint(current_);
  // Where each revolution's dwell goes: the last point of the revolution under it.
  std::map<RevolutionKey, size_t> lastOf;
  for (size_t i = 0; i < base.trajectory.size(); ++i) lastOf[keyOf(base.trajectory.points[i])] = i;
  struct Wait {
    double seconds = 0.0;
    double unchanged = 0.0;  // the interpass temperature without this dwell
  };
  std::map<RevolutionKey, Wait> waits;
  // The starting point's timing: current_ changes with each round.
  const std::vector<double> heatTime = current_.study.mesh.heatTime;
  const std::vector<int> heatIndex = current_.study.mesh.pointHeatIndex;
  while (!met() && roundLeft()) {
    bool changed = false;
    for (const RevolutionKey& key : overLimit(current_)) {
      const auto below = lastOf.find({key.first, key.second - 1});
      if (below == lastOf.end() || !base.trajectory.points[below->second].arcOn) continue;
      Wait& w = waits[key];
      const double now = current_.hottest.at(key);
      const double goal = std::log((now - ambient_) / (kAim * limit_ - ambient_));
      double next;
      if (w.seconds == 0.0) {
        w.unchanged = now;
        // Until a dwell has been measured, the part is taken to cool over about one revolution.
        const size_t first =
            lastOf.count({key.first, key.second - 2}) ? lastOf.at({key.first, key.second - 2}) : 0;
        const double revolution =
            heatTime[size_t(heatIndex[below->second])] - heatTime[size_t(heatIndex[first])];
        next = std::max(10.0, revolution) * goal;
      } else {
        // Exponential cooling through the two measures: no dwell, and this one.
        const double cooled = std::log((w.unchanged - ambient_) / (now - ambient_));
        next = cooled > 1e-3
                   ? w.seconds * std::log((w.unchanged - ambient_) / (kAim * limit_ - ambient_)) / cooled
                   : 2.0 * w.seconds;
      }
      next = std::min(std::max(next, w.seconds * 1.1), replan_.maxDwell);
      if (next > w.seconds + 1e-9) {
        w.seconds = next;
        changed = true;
      }
    }
    if (!changed) {
      note("the dwells have reached the longest wait allowed (" + significantText(replan_.maxDwell, 4) +
           " s)");
      break;
    }
    Candidate c = base;
    std::vector<double> channel(c.trajectory.size(), 0.0);
    for (const auto& [key, w] : waits) {
      channel[lastOf.at({key.first, key.second - 1})] = w.seconds;
      ++c.dwells;
      c.dwellTime += w.seconds;
    }
    c.trajectory.extra[kDwellChannel] = std::move(channel);
    simulate(std::move(c), "dwell");
  }
  settle();
}

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

std::string remediesText(const ThermalReplanSettings& s)
{
  std::string text;
  for (const auto& [on, name] : {std::pair{s.deposit, "deposit"}, {s.heat, "heat"}, {s.dwell, "dwell"}})
    if (on) text += (text.empty() ? "" : ",") + std::string(name);
  return text;
}

ThermalReplanOutcome replanForInterpass(const Trajectory& planned, const ThermalStudySettings& settings,
                                        const ThermalReplanSettings& replan, Progress& progress)
{
  const double ambient = settings.solver.initialTemperature, limit = replan.interpassMax;
  if (!(limit > ambient) || !std::isfinite(limit))
    throw InputError("an interpass limit of " + significantText(limit, 6) + " C is not above the initial " +
                         significantText(ambient, 6) + " C",
                     "give a limit such as 250 C (G3Si1's suggested interpass temperature)");
  if (!replan.deposit && !replan.heat && !replan.dwell)
    throw InputError("no re-planning remedy is chosen", "choose deposit, heat or dwell (or several)");
  if (!(settings.solver.powerPerWireFeed > 0.0) && settings.solver.powerTable.empty())
    throw InputError("re-planning needs the arc power to follow the wire feed",
                     "set the power per unit wire feed (powerPerWireFeedOf)");
  if (replan.dwell && !(replan.maxDwell > 0.0))
    throw InputError("the longest dwell must be positive", "allow a wait of a few minutes, e.g. 600 s");

  Replanner run(settings, replan, progress);
  run.start(planned);
  run.deposit();
  run.heat();
  run.dwell();
  return run.finish();
}

}  // namespace spira
