#include "spira/scan/scan_resume.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {

std::string ResumeReport::summary() const
{
  const auto side = [](double v) {
    return significantText(std::abs(v), 3) + (v < 0.0 ? " mm above" : " mm below");
  };
  std::string s = "the wall's top measured at " + std::to_string(edgePoints) + " points lies from " +
                  side(shortfallMin) + " to " + side(shortfallMax) + " the plan (mean " +
                  side(shortfallMean) + ")";
  if (unmeasured > 0) s += ", " + std::to_string(unmeasured) + " of them out of the scan and interpolated";
  if (reachesTop())
    return s + "; made up within " + std::to_string(revolutionsMax) + " revolution(s), deposits " +
           significantText(heightMin, 4) + " to " + significantText(heightMax, 4) + " mm";
  return s + "; the window cannot make it all up: the top ends " + significantText(leftoverMax, 3) +
         " mm short at point " + std::to_string(leftoverPoint);
}

Resumed resumeFromEdge(const Trajectory& plan, size_t at, const MeasuredEdge& edge,
                       const ResumeSettings& settings)
{
  if (at == 0 || at >= plan.size())
    throw InputError("index " + std::to_string(at) + " leaves nothing of the plan's " +
                         std::to_string(plan.size()) + " points to resume",
                     "give the number of points deposited, from 1 to " + std::to_string(plan.size() - 1));
  if (!(settings.hMin > 0.0) || !(settings.hMax > settings.hMin))
    throw InputError("the window " + significantText(settings.hMin, 4) + " .. " +
                         significantText(settings.hMax, 4) + " mm",
                     "give h_min above 0 and below h_max");
  std::map<std::pair<int, int>, double> missing;  // (sub-path, generatrix) -> shortfall still to make up
  Resumed out;
  ResumeReport& r = out.report;
  r.at = at;
  r.edgePoints = edge.points.size();
  r.unmeasured = edge.unmeasured;
  r.shortfallMin = *std::min_element(edge.shortfall.begin(), edge.shortfall.end());
  r.shortfallMax = *std::max_element(edge.shortfall.begin(), edge.shortfall.end());
  double sum = 0.0;
  for (size_t e = 0; e < edge.points.size(); ++e) {
    const TrajectoryPoint& p = plan.points[edge.points[e]];
    missing[{p.path, p.generatrix}] = edge.shortfall[e];
    sum += edge.shortfall[e];
  }
  r.shortfallMean = sum / double(edge.points.size());

  // The continuation's points per generatrix, in order.
  std::map<std::pair<int, int>, std::vector<size_t>> column;
  for (size_t i = at; i < plan.size(); ++i)
    column[{plan.points[i].path, plan.points[i].generatrix}].push_back(i);
  out.continuation.points.assign(plan.points.begin() + std::ptrdiff_t(at), plan.points.end());
  for (const auto& [name, values] : plan.extra)
    out.continuation.extra[name].assign(values.begin() + std::ptrdiff_t(at), values.end());
  std::vector<double> added(plan.size() - at, 0.0), still(plan.size() - at, 0.0);
  for (const auto& [key, points] : column) {
    const auto found = missing.find(key);
    if (found == missing.end())
      throw InputError("generatrix " + std::to_string(key.second) + " of the plan has no bead before point " +
                           std::to_string(at) + " to resume on",
                       "resume after the first revolution is complete");
    const double d = found->second;
    // The fewest revolutions n that lay d / n more on each inside the window.
    const auto fits = [&](size_t n) {
      for (size_t k = 0; k < n; ++k) {
        const double h = plan.points[points[k]].height + d / double(n);
        if (h > settings.hMax + 1e-12 || h < std::min(settings.hMin, plan.points[points[k]].height) - 1e-12)
          return false;
      }
      return true;
    };
    size_t n = 1;
    while (n < points.size() && !fits(n)) ++n;
    double left = d;
    if (fits(n)) {
      for (size_t k = 0; k < n; ++k) added[points[k] - at] = d / double(n);
    } else {
      // Each revolution as much as the window allows, to the end.
      for (size_t k = 0; k < points.size() && std::abs(left) > 1e-12; ++k) {
        const double h = plan.points[points[k]].height;
        const double room =
            d > 0.0 ? std::max(0.0, settings.hMax - h) : std::min(0.0, std::min(settings.hMin, h) - h);
        const double e = d > 0.0 ? std::min(left, room) : std::max(left, room);
        added[points[k] - at] = e;
        left -= e;
      }
    }
    r.revolutionsMax = std::max(r.revolutionsMax, int(n));
    left = d;
    for (size_t k = 0; k < points.size(); ++k) {
      left -= added[points[k] - at];
      still[points[k] - at] = left;
    }
    if (std::abs(left) > r.leftoverMax) r.leftoverMax = std::abs(left), r.leftoverPoint = points.back();
  }
  r.heightMin = 1e300, r.heightMax = 0.0;
  for (size_t k = 0; k < out.continuation.size(); ++k) {
    TrajectoryPoint& p = out.continuation.points[k];
    p.height += added[k];
    p.position -= p.build.normalized() * still[k];
    if (p.arcOn) r.heightMin = std::min(r.heightMin, p.height), r.heightMax = std::max(r.heightMax, p.height);
  }
  applyProcess(out.continuation, settings.process);
  return out;
}

ProcessSettings processOfPlan(const Trajectory& plan, double beadWidth)
{
  ProcessSettings s;
  s.beadWidth = beadWidth;
  double wfsMin = 1e300, wfsMax = 0.0, tsMax = 0.0;
  for (const TrajectoryPoint& p : plan.points) {
    if (!p.arcOn) continue;
    wfsMin = std::min(wfsMin, p.wireFeed), wfsMax = std::max(wfsMax, p.wireFeed);
    tsMax = std::max(tsMax, p.travelSpeed);
  }
  if (wfsMax > 0.0 && wfsMax - wfsMin <= 1e-9 * wfsMax) {
    s.mode = ProcessMode::Synergic;
    s.wireFeed = wfsMax;
  } else if (tsMax > 0.0) {
    s.mode = ProcessMode::ConstantTravelSpeed;
    s.travelSpeed = tsMax;
  }
  return s;
}

}  // namespace spira
