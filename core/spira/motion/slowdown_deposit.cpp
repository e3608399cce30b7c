#include "spira/motion/slowdown_deposit.h"

#include <cmath>

#include "spira/base/error.h"

namespace spira {

SlowdownReport slowdownDeposit(const Trajectory& path, const std::vector<double>& speedRatio,
                               const ProcessSettings& process, const DepositWindow& window)
{
  if (speedRatio.size() != path.size())
    throw InternalError("slowdown: " + std::to_string(speedRatio.size()) + " speed ratios for " +
                        std::to_string(path.size()) + " points");
  const bool calibrated = process.model == HeightModel::Calibration && !process.calibration.empty();
  SlowdownReport out;
  out.model = calibrated ? "calibration" : "mass_conservation";
  for (size_t i = 0; i < path.size(); ++i) {
    const double factor = speedRatio[i];
    if (!(factor > 1.0)) continue;
    const TrajectoryPoint& p = path.points[i];
    SlowedPoint s;
    s.point = i;
    s.factor = factor;
    s.plannedHeight = p.height;
    if (calibrated && p.wireFeed > 0.0 && p.travelSpeed > 0.0) {
      // The table was measured at process.wireFeed; the bead depends on WFS / TS only.
      const double tableSpeed = p.travelSpeed * process.wireFeed / p.wireFeed;
      s.slowedHeight = std::isfinite(factor) ? process.calibration.height(tableSpeed / factor)
                                             : std::numeric_limits<double>::infinity();
      // Slower than the slowest measured bead: thicker than anything measured.
      if (tableSpeed / factor < process.calibration.travelSpeeds().back())
        s.slowedHeight = std::numeric_limits<double>::infinity();
    } else {
      s.slowedHeight = p.height * factor;
    }
    s.fits = window.fits(s.slowedHeight);
    out.outsideWindow += !s.fits;
    if (out.points.empty() || factor > out.maxFactor) {
      out.maxFactor = factor;
      out.maxFactorPoint = i;
    }
    if (out.points.empty() || s.slowedHeight > out.maxSlowedHeight) {
      out.maxSlowedHeight = s.slowedHeight;
      out.maxSlowedHeightPoint = i;
    }
    out.points.push_back(s);
  }
  return out;
}

}  // namespace spira
