#include "spira/path/layer_count.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace spira {

namespace {

// Quotients within 1e-9 of an integer count as that integer, so 89.1 / 0.9 gives 99, not 98.
constexpr double kSnap = 1e-9;

int floorCount(double x)
{
  return static_cast<int>(std::floor(x * (1.0 + kSnap)));
}
int ceilCount(double x)
{
  return static_cast<int>(std::ceil(x * (1.0 - kSnap)));
}

}  // namespace

int countLayers(const std::vector<double>& lengths, double h, double hMin, double hMax, LayerMode mode)
{
  if (lengths.empty()) return 0;
  const auto [minIt, maxIt] = std::minmax_element(lengths.begin(), lengths.end());
  const int nHigh = std::max(0, floorCount(*minIt / hMin));  // every d_i >= h_min
  if (mode == LayerMode::Floor) return nHigh;

  const double mean = std::accumulate(lengths.begin(), lengths.end(), 0.0) / lengths.size();
  const double x = mean / h;
  const int lo = std::max(1, static_cast<int>(std::floor(x)));
  const int hi = std::max(1, static_cast<int>(std::ceil(x)));
  int n = std::abs(mean / lo - h) < std::abs(mean / hi - h) ? lo : hi;
  const int nLow = std::max(1, ceilCount(*maxIt / hMax));  // every d_i <= h_max
  if (nLow <= nHigh) n = std::clamp(n, nLow, nHigh);
  return *minIt < hMin * (1.0 - kSnap) ? 0 : n;
}

LengthCriterion lengthCriterion(const std::vector<double>& lengths, int nLayers, double hMin, double hMax)
{
  LengthCriterion c;
  if (lengths.empty()) return c;
  const auto [minIt, maxIt] = std::minmax_element(lengths.begin(), lengths.end());
  c.lengthMin = *minIt;
  c.lengthMax = *maxIt;
  c.nLayers = nLayers;
  c.window = hMax - hMin;
  if (nLayers <= 0) return c;
  c.stepSpread = (c.lengthMax - c.lengthMin) / nLayers;
  c.ok = c.stepSpread <= c.window * (1.0 + kSnap);
  return c;
}

LengthCriterion thesisLengthCriterion(const std::vector<double>& lengths, double hMin, double hMax)
{
  if (lengths.empty()) return {};
  const double shortest = *std::min_element(lengths.begin(), lengths.end());
  return lengthCriterion(lengths, std::max(0, floorCount(shortest / hMin)), hMin, hMax);
}

}  // namespace spira
