#pragma once

#include <algorithm>
#include <chrono>
#include <functional>

// The shortest wall time of `runs` runs of `f`, in seconds: on a shared machine the best run is the
// one least disturbed by the others.
inline double bestOf(int runs, const std::function<void()>& f)
{
  double best = 1e300;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}
