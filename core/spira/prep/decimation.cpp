#include "spira/prep/decimation.h"

#include <algorithm>

namespace spira {

namespace {

// The farthest a in (i, limit] that fits, found by doubling then bisection; i + 1 always fits.
size_t reach(const SampleSet& s, size_t i, size_t limit)
{
  size_t good = i + 1, step = 1;
  size_t bad = 0;
  while (good < limit) {
    const size_t candidate = std::min(good + step, limit);
    if (!s.fits(i, candidate)) {
      bad = candidate;
      break;
    }
    good = candidate;
    step *= 2;
  }
  if (bad == 0) return good;
  while (bad - good > 1) {
    const size_t mid = good + (bad - good) / 2;
    if (s.fits(i, mid))
      good = mid;
    else
      bad = mid;
  }
  return good;
}

// Index of the last sample whose arc length is <= value (at least `floor`).
size_t lastAtOrBefore(const std::vector<double>& arc, double value, size_t floor)
{
  const size_t k = static_cast<size_t>(std::upper_bound(arc.begin(), arc.end(), value) - arc.begin());
  return std::max(floor, k == 0 ? 0 : k - 1);
}

}  // namespace

Selection selectSamples(const SampleSet& samples, const PrepParams& params, Progress& progress)
{
  Selection out;
  const size_t n = samples.size();
  if (n == 0) return out;
  std::vector<double> arc(n);
  std::vector<size_t> protectedIdx;
  for (size_t j = 0; j < n; ++j) {
    arc[j] = samples.arc(j);
    if (samples.isProtected(j)) protectedIdx.push_back(j);
  }
  out.kept.push_back(0);
  size_t i = 0, p = 0, steps = 0;
  while (i + 1 < n) {
    if ((++steps & 1023) == 0) {
      progress.checkCancel();
      progress.report(static_cast<double>(i) / static_cast<double>(n), "decimating");
    }
    while (protectedIdx[p] <= i) ++p;
    const size_t next = protectedIdx[p];
    const size_t spacingLimit = lastAtOrBefore(arc, arc[i] + params.maxSpacing, i + 1);
    const size_t limit = std::min(next, spacingLimit);
    size_t best = reach(samples, i, limit);
    if (best < next && arc[best] - arc[i] < params.minSpacing) {
      const auto far = std::lower_bound(arc.begin(), arc.end(), arc[i] + params.minSpacing) - arc.begin();
      const size_t stretched = std::min({static_cast<size_t>(far), next, spacingLimit});
      if (stretched > best) {
        best = stretched;
        if (!samples.fits(i, best)) ++out.spacingOverrides;
      }
    } else if (best < next && arc[next] - arc[best] < params.minSpacing) {
      if (next <= spacingLimit && samples.fits(i, next)) {
        best = next;
      } else {
        const size_t back = lastAtOrBefore(arc, arc[next] - params.minSpacing, i);
        if (back > i && arc[back] - arc[i] >= params.minSpacing &&
            arc[next] - arc[back] <= params.maxSpacing && samples.fits(i, back) && samples.fits(back, next))
          best = back;
      }
    }
    out.kept.push_back(best);
    i = best;
  }
  return out;
}

}  // namespace spira
