#include "spira/planning/plan_advice.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/crotch_flags.h"
#include "spira/planning/level_base.h"
#include "spira/planning/plan_schemas.h"
#include "spira/plugin/settings_section.h"
#include "spira/plugin/strategy_name.h"

namespace spira {
namespace {

struct Window {
  double hMin, hMax;
};

// Wider than h +/- 50 % no WAAM process lays a steady bead: such a window is not advice.
constexpr double kWidestWindow = 0.5;

// The window that holds every measured height, on a 0.05 mm grid; nothing when a point failed for
// another reason than its thickness (a wider window cannot support a bead in mid-air), or when it
// would be wider than a process lays (then `tooWide` says which window it would take).
std::optional<Window> measuredWindow(const PlanOutput& plan, const SpiralSettings& s, std::string& tooWide)
{
  const DepositCheckReport& d = plan.deposits;
  if (d.flags.empty() || d.uncoveredFraction() > 0.005) return std::nullopt;
  Window w{s.hMin, s.hMax};
  for (const DepositFlag& f : d.flags) {
    if (f.kind != DepositDefect::Thin && f.kind != DepositDefect::Thick) return std::nullopt;
    w.hMin = std::min(w.hMin, f.height);
    w.hMax = std::max(w.hMax, f.height);
  }
  w.hMin = std::floor(w.hMin / 0.05) * 0.05;
  w.hMax = std::ceil(w.hMax / 0.05) * 0.05;
  if (w.hMin <= 0.0 || w.hMin >= s.h || w.hMax <= s.h) return std::nullopt;
  if (w.hMin < (1.0 - kWidestWindow) * s.h || w.hMax > (1.0 + kWidestWindow) * s.h) {
    tooWide = "the beads as planned would need a window of " + significantText(w.hMin, 4) + " .. " +
              significantText(w.hMax, 4) + " mm, wider than h +/- 50 %, which no process lays steadily";
    return std::nullopt;
  }
  return w;
}

class Trial {
 public:
  Trial(const PluginRegistry& registry, const PlanRequest& request, Progress& progress, int maxPlans)
      : registry_(registry), request_(request), progress_(progress), left_(maxPlans)
  {
  }
  bool exhausted() const { return left_ <= 0; }
  int planned() const { return planned_; }

  // The request with `strategy` and, when set, `window`.
  PlanRequest with(const std::string& strategy, const std::optional<Window>& window) const
  {
    PlanRequest r = request_;
    r.decomposerId = strategy;
    if (window) {
      r.params[kSpiralSectionName].set("h_min", window->hMin);
      r.params[kSpiralSectionName].set("h_max", window->hMax);
    }
    return r;
  }

  // Plans `r`; true when feasible. Records the failure under `label`.
  bool plans(const PlanRequest& r, const std::string& label)
  {
    --left_;
    ++planned_;
    try {
      SubProgress p(progress_, 0.0, 1.0, "checking: " + label);
      const PlanOutput plan = planPart(registry_, r, p);
      if (plan.feasible()) return true;
      tried.push_back(label + ": " + plan.deposits.summary());
    } catch (const Error& e) {
      tried.push_back(label + ": " + e.what());
    }
    return false;
  }
  std::vector<std::string> tried;

 private:
  const PluginRegistry& registry_;
  const PlanRequest& request_;
  Progress& progress_;
  int left_;
  int planned_ = 0;
};

// The refusal again, with the advice's change when it plans, or what was tried, in its hint.
[[noreturn]] void refuseWithAdvice(const InputError& e, const PlanAdvice& advice)
{
  if (advice.found) throw InputError(e.what(), advice.text());
  std::string hint = e.hint();
  for (const std::string& t : advice.tried) hint += "; tried: " + t;
  throw InputError(e.what(), hint);
}

// A plan laid in constant-distance layers whose flagged points mostly lie in layers that turn by more
// than 90 degrees: the layers fold at their kinks (docs/tubes.md). Empty otherwise.
std::string foldText(const PlanOutput& plan)
{
  constexpr double kFoldDeg = 90.0;
  const std::vector<double>& kinks = plan.layers->kinkDeg;
  size_t atFolds = 0;
  for (const DepositFlag& f : plan.deposits.flags) {
    const size_t k = size_t(std::max(0, plan.spiral.trajectory.points[f.point].revolution));
    const double kink =
        std::max(k < kinks.size() ? kinks[k] : 0.0, k + 1 < kinks.size() ? kinks[k + 1] : 0.0);
    if (kink > kFoldDeg) ++atFolds;
  }
  if (plan.deposits.flags.empty() || 2 * atFolds < plan.deposits.flags.size()) return {};
  std::ostringstream t;
  t << "The layers fold: " << atFolds << " of the " << plan.deposits.flags.size()
    << " flagged points lie where the constant-distance layers turn by more than " << kFoldDeg
    << " degrees (up to " << std::lround(plan.layers->maxKinkDeg)
    << "): the kink the method develops on the outer side of a tight bend folds the layer over itself "
       "there (docs/tubes.md: the kink, and how far --smooth-kink lowers it)";
  return t.str();
}

}  // namespace

std::string PlanAdvice::text(bool withFlags) const
{
  if (found) return change + (withFlags ? " (" + flags + ")" : "") + ": planned and checked feasible";
  std::string t = causeExplainsMost ? cause + ": no change of window or strategy Spira tried plans it"
                                    : "cut the part into pieces whose walls rise more evenly, or widen the "
                                      "process window if your process lays a wider range of beads: no change "
                                      "of window or strategy Spira tried plans it";
  for (size_t i = 0; i < tried.size(); ++i) t += (i ? "; " : " (") + tried[i];
  if (!tried.empty()) t += ")";
  if (!causeExplainsMost && !cause.empty()) t += ". " + cause;
  return t;
}

PlanAdvice adviseChange(const PluginRegistry& registry, const PlanRequest& request, const PlanOutput* failed,
                        Progress& progress, int maxPlans)
{
  PlanAdvice advice;
  const PlanSections sections = readPlanSections(request.params);
  const SpiralSettings& settings = sections.spiral;
  std::string tooWide;
  const std::optional<Window> window = failed ? measuredWindow(*failed, settings, tooWide) : std::nullopt;
  Trial trial(registry, request, progress, maxPlans);
  if (!tooWide.empty()) trial.tried.push_back(tooWide);
  auto windowText = [](const Window& w) {
    return std::make_pair("widen the process window to " + significantText(w.hMin, 4) + " .. " +
                              significantText(w.hMax, 4) + " mm",
                          "--h-min " + significantText(w.hMin, 4) + " --h-max " + significantText(w.hMax, 4));
  };
  auto done = [&](std::string change, std::string flags) {
    advice.found = true;
    advice.change = std::move(change);
    advice.flags = std::move(flags);
    advice.tried = trial.tried;
    return advice;
  };

  if (window) {
    const auto [change, flags] = windowText(*window);
    if (trial.plans(trial.with(request.decomposerId, window), change)) return done(change, flags);
  }
  // The default strategy first: it plans the widest range of parts, and the trials are few.
  std::vector<std::string> others;
  for (const Plugin* p : registry.ofKind(PluginKind::Decomposer))
    if (p->id() != request.decomposerId) others.push_back(p->id());
  std::stable_partition(others.begin(), others.end(),
                        [](const std::string& id) { return id == kDefaultDecomposerId; });
  for (const std::string& id : others) {
    if (trial.exhausted()) break;
    const std::string change = "use the " + strategyName(id) + " strategy";
    if (trial.plans(trial.with(id, std::nullopt), change))
      return done(change, "--strategy " + strategyName(id));
  }
  if (window)
    for (const std::string& id : others) {
      if (trial.exhausted()) break;
      const auto [widen, flags] = windowText(*window);
      const std::string change = "use the " + strategyName(id) + " strategy and " + widen;
      if (trial.plans(trial.with(id, window), change))
        return done(change, "--strategy " + strategyName(id) + " " + flags);
    }
  advice.tried = trial.tried;
  if (failed && failed->layers) {
    const std::string folds = foldText(*failed);
    if (!folds.empty()) {
      // Said after the general advice: cutting the part below the folds is the change that helps.
      advice.cause = folds;
      advice.causeExplainsMost = false;
      return advice;
    }
  }
  if (failed) {
    const std::vector<CrotchFlags> crotches = flagsAtCrotches(*failed, sections.process.beadWidth);
    size_t atCrotches = 0;
    for (const CrotchFlags& c : crotches) atCrotches += c.flagged;
    advice.cause = crotchText(crotches, failed->deposits.flags.size(), settings.hMax);
    advice.causeExplainsMost = !crotches.empty() && 2 * atCrotches >= failed->deposits.flags.size();
  }
  return advice;
}

PlanAdvice adviseSmallerDeposit(const PluginRegistry& registry, const PlanRequest& request,
                                const TooShortError& refusal, Progress& progress)
{
  PlanAdvice advice;
  const auto it = request.params.find(kSpiralSectionName);
  const ParamSet given = it == request.params.end() ? ParamSet() : it->second;
  const SpiralSettings s = readPlanSections(request.params).spiral;
  if (!(refusal.needed() > 0.0) || !(refusal.length() > 0.0)) return advice;
  // At a fixed relative window the ramps' length is proportional to h, and what is left of the
  // wall must be a whole number of layers inside the window. Candidates run down the 0.05 mm grid
  // from the largest h whose ramps and one layer of h_min fit; those whose leftover holds no whole
  // number of layers (within 1 %, the builder's own slack) are skipped, the others planned, at most
  // kMaxPlans of them, and the first feasible one is the advice.
  constexpr int kMaxPlans = 4;
  const double length = refusal.length(), rampsPerH = (refusal.needed() - s.hMin) / s.h;
  const double low = s.hMin / s.h, high = s.hMax / s.h;
  const bool explicitWindow = given.has("h_min") && given.getDouble("h_min") > 0.0;
  Trial trial(registry, request, progress, kMaxPlans);
  for (double h = std::floor(length / (rampsPerH + low) / 0.05) * 0.05;
       h >= kThinnestAdvisedDeposit - 1e-9 && !trial.exhausted(); h -= 0.05) {
    h = std::round(h / 0.05) * 0.05;
    const double rest = length - rampsPerH * h;
    if (rest < 0.99 * low * h || std::ceil(rest / (high * h)) * low * h > 1.01 * rest) continue;
    PlanRequest r = request;
    r.params[kSpiralSectionName].set("h", h);
    std::string flags = "--h " + significantText(h, 4);
    if (explicitWindow) {
      const double f = h / s.h;
      const double lo = std::floor(s.hMin * f / 0.01) * 0.01, hi = std::ceil(s.hMax * f / 0.01) * 0.01;
      r.params[kSpiralSectionName].set("h_min", lo);
      r.params[kSpiralSectionName].set("h_max", hi);
      flags += " --h-min " + significantText(lo, 4) + " --h-max " + significantText(hi, 4);
    }
    const std::string change =
        "lay thinner deposits, h = " + significantText(h, 4) + " mm, so the start-up and closing ramps fit";
    if (trial.plans(r, change)) {
      advice.found = true;
      advice.change = change;
      advice.flags = flags;
      return advice;
    }
  }
  advice.tried = trial.tried;
  if (trial.planned() == 0)
    advice.tried.push_back(
        "the part's walls are too short for the start-up and closing ramps of any deposit of at least " +
        significantText(kThinnestAdvisedDeposit, 4) + " mm, the thinnest a process lays steadily");
  return advice;
}

PlanAdvice adviseLevelBase(const PluginRegistry& registry, const PlanRequest& request,
                           const BaseNotLevelError& refusal, Progress& progress)
{
  PlanAdvice advice;
  LevelledBase levelled;
  try {
    levelled = levelBase(request.mesh, refusal.lower());
  } catch (const InputError& e) {
    advice.tried.push_back(std::string("levelling the base: ") + e.what());
    return advice;
  }
  for (Vec3& v : levelled.mesh.vertices) v.z() += request.substrateZ - levelled.cutZ;
  const MeshReport report = validateMesh(levelled.mesh);
  PlanRequest r(levelled.mesh, report, request);
  r.lowerLoopOverride = -1;
  const std::string change = "cut the part level at z = " + fixedText(levelled.cutZ, 2) +
                             " mm and stand it on the substrate, " + fixedText(levelled.removed, 2) +
                             " mm off its base (Placement > Level Base in Spira)";
  Trial trial(registry, request, progress, 1);
  if (trial.plans(r, change)) {
    advice.found = true;
    advice.change = change;
    advice.flags = "--level-base";
  }
  advice.tried = trial.tried;
  return advice;
}

PlanOutput planOrAdvise(const PluginRegistry& registry, const PlanRequest& request, Progress& progress)
{
  try {
    return planPart(registry, request, progress);
  } catch (const TooShortError& e) {
    refuseWithAdvice(e, adviseSmallerDeposit(registry, request, e, progress));
  } catch (const BaseNotLevelError& e) {
    refuseWithAdvice(e, adviseLevelBase(registry, request, e, progress));
  } catch (const InputError& e) {
    refuseWithAdvice(e, adviseChange(registry, request, nullptr, progress, 2));
  }
}

}  // namespace spira
