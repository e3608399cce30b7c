#include "spira/path/process_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/path/dwell.h"

namespace spira {

namespace {

void requirePositive(double v, const char* what, const char* hint)
{
  if (!std::isfinite(v) || v <= 0.0) {
    std::ostringstream m;
    m << "the " << what << " must be a positive number, not " << v;
    throw InputError(m.str(), hint);
  }
}

void requireRange(double lo, double hi, const char* what)
{
  if (std::isnan(lo) || std::isnan(hi) || lo < 0.0 || lo > hi) {
    std::ostringstream m;
    m << "the " << what << " limits [" << lo << ", " << hi
      << "] mm/s are not an interval of non-negative speeds";
    throw InputError(m.str(), "set 0 <= minimum <= maximum, or leave the defaults (no limit)");
  }
}

void validate(const ProcessSettings& s)
{
  requirePositive(s.wireDiameter, "wire diameter (mm)", "enter the wire diameter, e.g. 1.0 mm");
  requirePositive(s.beadWidth, "bead width (mm)", "enter the measured wall width, e.g. 5.2 mm");
  if (s.mode == ProcessMode::Synergic || s.model == HeightModel::Calibration)
    requirePositive(s.wireFeed, "wire-feed speed (mm/s)",
                    "enter the wire-feed speed, e.g. 2.3 m/min = 38.3 mm/s");
  if (s.mode == ProcessMode::ConstantTravelSpeed)
    requirePositive(s.travelSpeed, "travel speed (mm/s)", "enter the travel speed to hold, e.g. 5 mm/s");
  if (s.model == HeightModel::Calibration && s.calibration.empty())
    throw InputError("the calibration height model has no table",
                     "load a height_mm,travel_speed_mm_s table or use the mass-conservation model");
  requireRange(s.limits.travelSpeedMin, s.limits.travelSpeedMax, "travel-speed");
  requireRange(s.limits.wireFeedMin, s.limits.wireFeedMax, "wire-feed");
}

// Records a speed beyond [lo, hi] and, when `clamp`, brings it back to the bound it crossed.
void checkLimit(std::vector<ProcessViolation>& out, size_t q, double& v, double lo, double hi,
                ProcessViolationKind below, ProcessViolationKind above, bool clamp)
{
  if (v < lo) out.push_back({q, below, v, lo});
  if (v > hi) out.push_back({q, above, v, hi});
  if (clamp) v = std::clamp(v, lo, hi);
}

}  // namespace

const char* processViolationName(ProcessViolationKind kind)
{
  switch (kind) {
    case ProcessViolationKind::TravelSpeedBelowMin:
      return "travel_speed_below_min";
    case ProcessViolationKind::TravelSpeedAboveMax:
      return "travel_speed_above_max";
    case ProcessViolationKind::WireFeedBelowMin:
      return "wire_feed_below_min";
    case ProcessViolationKind::WireFeedAboveMax:
      return "wire_feed_above_max";
    case ProcessViolationKind::HeightOutsideCalibration:
      return "height_outside_calibration";
    case ProcessViolationKind::HeightNotPositive:
      return "height_not_positive";
  }
  return "travel_speed_above_max";
}

double massConservationHeight(double wireDiameter, double beadWidth, double wireFeed, double travelSpeed)
{
  return kPi * wireDiameter * wireDiameter * wireFeed / (4.0 * beadWidth * travelSpeed);
}

double massConservationTravelSpeed(double wireDiameter, double beadWidth, double wireFeed, double height)
{
  return kPi * wireDiameter * wireDiameter * wireFeed / (4.0 * beadWidth * height);
}

double massConservationWireFeed(double wireDiameter, double beadWidth, double travelSpeed, double height)
{
  return 4.0 * beadWidth * travelSpeed * height / (kPi * wireDiameter * wireDiameter);
}

ProcessReport applyProcess(Trajectory& path, const ProcessSettings& s)
{
  validate(s);
  ProcessReport report;
  auto& pts = path.points;
  const bool synergic = s.mode == ProcessMode::Synergic;
  std::vector<bool> mapped(pts.size(), false);
  for (size_t q = 0; q < pts.size(); ++q) {
    TrajectoryPoint& p = pts[q];
    p.arcOn = true;
    const double h = p.height;
    if (!(h > 0.0) || !std::isfinite(h)) {
      report.violations.push_back({q, ProcessViolationKind::HeightNotPositive, h, 0.0});
      continue;
    }
    if (s.model == HeightModel::Calibration) {
      const CalibrationTable& table = s.calibration;
      if (!table.covers(h))
        report.violations.push_back({q, ProcessViolationKind::HeightOutsideCalibration, h,
                                     h < table.heightMin() ? table.heightMin() : table.heightMax()});
      const double tableTs = table.travelSpeed(h);
      p.travelSpeed = synergic ? tableTs : s.travelSpeed;
      p.wireFeed = synergic ? s.wireFeed : s.wireFeed * s.travelSpeed / tableTs;
    } else {
      p.travelSpeed =
          synergic ? massConservationTravelSpeed(s.wireDiameter, s.beadWidth, s.wireFeed, h) : s.travelSpeed;
      p.wireFeed =
          synergic ? s.wireFeed : massConservationWireFeed(s.wireDiameter, s.beadWidth, s.travelSpeed, h);
    }
    mapped[q] = true;
  }
  // Points without a usable height keep the speeds of the point before them (after them at the
  // start); with none mapped at all, the held speeds.
  const auto firstMapped = std::find(mapped.begin(), mapped.end(), true);
  for (size_t q = 0; q < pts.size(); ++q) {
    if (mapped[q]) continue;
    if (firstMapped == mapped.end()) {
      pts[q].travelSpeed = s.travelSpeed;
      pts[q].wireFeed = s.wireFeed;
    } else {
      const TrajectoryPoint& from = q > 0 && q > static_cast<size_t>(firstMapped - mapped.begin())
                                        ? pts[q - 1]
                                        : pts[static_cast<size_t>(firstMapped - mapped.begin())];
      pts[q].travelSpeed = from.travelSpeed;
      pts[q].wireFeed = from.wireFeed;
    }
  }

  const ProcessLimits& lim = s.limits;
  for (size_t q = 0; q < pts.size(); ++q) {
    TrajectoryPoint& p = pts[q];
    checkLimit(report.violations, q, p.travelSpeed, lim.travelSpeedMin, lim.travelSpeedMax,
               ProcessViolationKind::TravelSpeedBelowMin, ProcessViolationKind::TravelSpeedAboveMax,
               s.clampToLimits);
    checkLimit(report.violations, q, p.wireFeed, lim.wireFeedMin, lim.wireFeedMax,
               ProcessViolationKind::WireFeedBelowMin, ProcessViolationKind::WireFeedAboveMax,
               s.clampToLimits);
    if (q + 1 < pts.size()) {
      const double dt = (pts[q + 1].position - p.position).norm() / p.travelSpeed;
      report.buildTime += dt;
      report.wireLength += p.wireFeed * dt;
    }
  }
  const DwellTotals dwell = dwellTotals(path);
  report.dwells = dwell.count;
  report.dwellTime = dwell.seconds;
  report.buildTime += dwell.seconds;
  std::stable_sort(report.violations.begin(), report.violations.end(),
                   [](const ProcessViolation& a, const ProcessViolation& b) { return a.point < b.point; });
  report.depositVolume = report.wireLength * kPi * s.wireDiameter * s.wireDiameter / 4.0;
  if (!pts.empty()) {
    const auto [tsLo, tsHi] = std::minmax_element(
        pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.travelSpeed < b.travelSpeed; });
    const auto [wfLo, wfHi] = std::minmax_element(
        pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.wireFeed < b.wireFeed; });
    report.travelSpeedMin = tsLo->travelSpeed;
    report.travelSpeedMax = tsHi->travelSpeed;
    report.wireFeedMin = wfLo->wireFeed;
    report.wireFeedMax = wfHi->wireFeed;
  }
  report.withinLimits = report.violations.empty();
  return report;
}

}  // namespace spira
