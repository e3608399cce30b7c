#include "spira/collision/tilt_ramp.h"

#include <algorithm>

namespace spira {

std::vector<double> rampEnvelope(const std::vector<double>& magnitude, double maxStep)
{
  std::vector<double> e(magnitude.size(), 0.0);
  double carried = 0.0;
  for (size_t i = 0; i < e.size(); ++i) {
    carried = std::max({magnitude[i], carried - maxStep, 0.0});
    e[i] = carried;
  }
  carried = 0.0;
  for (size_t i = e.size(); i-- > 0;) {
    carried = std::max(e[i], carried - maxStep);
    e[i] = carried;
  }
  return e;
}

}  // namespace spira
