#include "spira/planning/plan_advice.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "spira/base/error.h"
#include "spira/planning/plan_schemas.h"

namespace spira {
namespace {

struct Window {
  double hMin, hMax;
};

std::string text(double v)
{
  std::ostringstream o;
  o << std::setprecision(4) << v;
  return o.str();
}

std::string shortId(const std::string& id)
{
  const size_t dot = id.find('.');
  return dot == std::string::npos ? id : id.substr(dot + 1);
}

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
    tooWide = "the beads as planned would need a window of " + text(w.hMin) + " .. " + text(w.hMax) +
              " mm, wider than h +/- 50 %, which no process lays steadily";
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

  // Plans with `strategy` and, when set, `window`; true when feasible. Records the failure.
  bool plans(const std::string& strategy, const std::optional<Window>& window, const std::string& label)
  {
    --left_;
    PlanRequest r = request_;
    r.decomposerId = strategy;
    if (window) {
      r.params["spiral"].set("h_min", window->hMin);
      r.params["spiral"].set("h_max", window->hMax);
    }
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
};

}  // namespace

std::string PlanAdvice::text() const
{
  if (found) return change + " (" + flags + "): planned and checked feasible";
  std::string t =
      "cut the part into pieces whose walls rise more evenly, or widen the process window if your process "
      "lays a wider range of beads: no change of window or strategy Spira tried plans it";
  for (size_t i = 0; i < tried.size(); ++i) t += (i ? "; " : " (") + tried[i];
  return tried.empty() ? t : t + ")";
}

PlanAdvice adviseChange(const PluginRegistry& registry, const PlanRequest& request, const PlanOutput* failed,
                        Progress& progress, int maxPlans)
{
  PlanAdvice advice;
  auto it = request.params.find("spiral");
  const SpiralSettings settings = spiralSettingsFrom(it == request.params.end() ? ParamSet() : it->second);
  std::string tooWide;
  const std::optional<Window> window = failed ? measuredWindow(*failed, settings, tooWide) : std::nullopt;
  Trial trial(registry, request, progress, maxPlans);
  if (!tooWide.empty()) trial.tried.push_back(tooWide);
  auto windowText = [](const Window& w) {
    return std::make_pair("widen the process window to " + text(w.hMin) + " .. " + text(w.hMax) + " mm",
                          "--h-min " + text(w.hMin) + " --h-max " + text(w.hMax));
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
    if (trial.plans(request.decomposerId, window, change)) return done(change, flags);
  }
  std::vector<std::string> others;
  for (const Plugin* p : registry.ofKind(PluginKind::Decomposer))
    if (p->id() != request.decomposerId) others.push_back(p->id());
  for (const std::string& id : others) {
    if (trial.exhausted()) break;
    const std::string change = "use the " + shortId(id) + " strategy";
    if (trial.plans(id, std::nullopt, change)) return done(change, "--strategy " + shortId(id));
  }
  if (window)
    for (const std::string& id : others) {
      if (trial.exhausted()) break;
      const auto [widen, flags] = windowText(*window);
      const std::string change = "use the " + shortId(id) + " strategy and " + widen;
      if (trial.plans(id, window, change)) return done(change, "--strategy " + shortId(id) + " " + flags);
    }
  advice.tried = trial.tried;
  return advice;
}

}  // namespace spira
