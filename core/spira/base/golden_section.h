#pragma once

#include <cmath>

namespace spira {

// Which part of the bracket a golden-section step keeps when its two inner values are equal. Where
// f is flat (or infinite) over a stretch this picks the end the search drifts to, so callers that
// must reproduce earlier results name it.
enum class GoldenTie { KeepLower, KeepUpper };

struct GoldenSectionOptions {
  int maxSteps = 80;
  double tolerance = 0.0;  // stop once the bracket is no wider than this; 0: take every step
  GoldenTie tie = GoldenTie::KeepLower;
};

// Golden-section search for a minimum of f over [lo, hi]: the middle of the final bracket, which
// holds the minimum when f is unimodal. f is never evaluated at lo or hi themselves; a caller whose
// minimum may sit at an end compares the ends with the result.
template <class F>
double goldenSectionMinimum(F&& f, double lo, double hi, const GoldenSectionOptions& options)
{
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int step = 0; step < options.maxSteps && hi - lo > options.tolerance; ++step) {
    const bool lower = options.tie == GoldenTie::KeepLower ? f1 <= f2 : f1 < f2;
    if (lower) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = f(x2);
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace spira
