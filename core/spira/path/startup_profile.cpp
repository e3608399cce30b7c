#include "spira/path/startup_profile.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "spira/base/error.h"

namespace spira {

namespace {

std::string windowText(double h, double hMin, double hMax)
{
  std::ostringstream s;
  s << "h = " << h << " mm, h_min = " << hMin << " mm, h_max = " << hMax << " mm";
  return s.str();
}

}  // namespace

StartupProfile::StartupProfile(double h, double hMin, double hMax, StartupTransition transition,
                               int pointsPerRevolution, double layerStep)
    : h_(h), hMin_(hMin), hMax_(hMax), hT_(h), c_(h)
{
  const std::string w = windowText(h, hMin, hMax);
  if (!std::isfinite(h) || !std::isfinite(hMin) || !std::isfinite(hMax))
    throw InputError("deposit heights are not finite numbers (" + w + ")", "enter finite heights in mm");
  if (hMin <= 0.0)
    throw InputError("the minimum deposit height must be positive (" + w + ")",
                     "set h_min to the thinnest bead the process can lay, e.g. 0.9 h");
  if (hMin >= hMax)
    throw InputError("the modulation window is empty: h_min must be smaller than h_max (" + w + ")",
                     "widen the window, e.g. h_min = 0.9 h and h_max = 1.1 h");
  if (h < hMin || h > hMax)
    throw InputError("the nominal deposit height lies outside the modulation window (" + w + ")",
                     "choose h between h_min and h_max");

  const double delta = hMax - hMin;
  const double reach = h * (1.0 - 1e-9);
  if (reach / delta > 1e6)
    throw InputError(
        "the modulation window is too narrow: the start-up would need more than a million "
        "revolutions (" +
            w + ")",
        "widen the window between h_min and h_max");
  int j = static_cast<int>(std::floor(reach / delta));
  while (j > 0 && j * delta >= reach) --j;
  while ((j + 1) * delta < reach) ++j;
  fullRamps_ = j;

  if (transition == StartupTransition::UniformHelix) {
    if (pointsPerRevolution < 2)
      throw InputError("a uniform-helix start-up needs the number of points per revolution",
                       "decompose the part into generatrices first");
    const double n = pointsPerRevolution;
    if (std::isfinite(layerStep) && layerStep > 0.0) c_ = std::clamp(layerStep, hMin, hMax);
    hT_ = std::clamp(hMin + c_ * (n - 1.0) / n - j * delta, hMin, hMax);
  }
}

double StartupProfile::startStep(int r, double u) const
{
  if (r < fullRamps_) return hMin_ + (hMax_ - hMin_) * u;
  if (r == fullRamps_) return hMin_ + (hT_ - hMin_) * u;
  return c_;
}

double StartupProfile::endStep(int r, double u) const
{
  if (r == 0) return c_;
  if (r == 1) return hT_ - (hT_ - hMin_) * u;
  return hMax_ - (hMax_ - hMin_) * u;
}

double StartupProfile::startLength(double u) const
{
  return fullRamps_ * (hMin_ + (hMax_ - hMin_) * u) + hMin_ + (hT_ - hMin_) * u + c_;
}

double StartupProfile::endLength(double u) const
{
  return c_ + hT_ - (hT_ - hMin_) * u + fullRamps_ * (hMax_ - (hMax_ - hMin_) * u);
}

}  // namespace spira
