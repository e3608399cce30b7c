#include "spira/path/feasibility.h"

#include <algorithm>
#include <limits>

namespace spira {

const char* spiralPhaseName(SpiralPhase phase)
{
  switch (phase) {
    case SpiralPhase::StartUp:
      return "start_up";
    case SpiralPhase::Modulated:
      return "modulated";
    case SpiralPhase::Termination:
      return "termination";
    case SpiralPhase::Closure:
      return "closure";
  }
  return "modulated";
}

SpiralPhase phaseOfRevolution(int revolution, const SpiralReport& report)
{
  if (revolution < report.nStartupRevolutions) return SpiralPhase::StartUp;
  if (revolution < report.nStartupRevolutions + report.nLayers) return SpiralPhase::Modulated;
  return SpiralPhase::Termination;
}

void checkFeasibility(const Trajectory& path, double h, double hMin, double hMax, double tolerance,
                      bool closurePointLast, SpiralReport& report)
{
  const double tol = tolerance * h;
  report.h = h;
  report.hMin = hMin;
  report.hMax = hMax;
  report.heightTolerance = tol;
  report.violations.clear();
  report.modulatedViolations = 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0.0;
  double rampLo = lo, rampHi = hi;
  size_t modulated = 0, ramp = 0;
  const size_t count = path.points.size();
  for (size_t q = 0; q < count; ++q) {
    const TrajectoryPoint& p = path.points[q];
    const SpiralPhase phase =
        closurePointLast && q + 1 == count ? SpiralPhase::Closure : phaseOfRevolution(p.revolution, report);
    if (phase == SpiralPhase::Modulated) {
      lo = std::min(lo, p.height);
      hi = std::max(hi, p.height);
      sum += p.height;
      ++modulated;
    } else if (phase != SpiralPhase::Closure) {
      rampLo = std::min(rampLo, p.height);
      rampHi = std::max(rampHi, p.height);
      ++ramp;
    }
    const bool below = p.height < hMin - tol;
    const bool above = p.height > hMax + tol;
    if (!below && !above) continue;
    report.violations.push_back({q, p.revolution, p.generatrix, p.height, phase, above});
    if (phase == SpiralPhase::Modulated) ++report.modulatedViolations;
  }
  report.heightMin = modulated ? lo : 0.0;
  report.heightMax = modulated ? hi : 0.0;
  report.heightMean = modulated ? sum / modulated : 0.0;
  report.rampHeightMin = ramp ? rampLo : 0.0;
  report.rampHeightMax = ramp ? rampHi : 0.0;
  report.feasible = report.lengthCriterion.ok && report.violations.empty();
}

}  // namespace spira
