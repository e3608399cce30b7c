#include "spira/contour/generatrix_chain.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <tbb/parallel_for.h>

#include "spira/base/error.h"
#include "spira/contour/point_grid.h"

namespace spira {

namespace {

size_t checkedPointCount(const std::vector<std::vector<Vec3>>& contours, const char* who)
{
  if (contours.empty() || contours[0].empty())
    throw InternalError(std::string(who) + " needs non-empty contours");
  const size_t n = contours[0].size();
  for (const auto& c : contours)
    if (c.size() != n)
      throw InternalError(std::string(who) + " needs the same number of points on every contour");
  return n;
}

}  // namespace

PrincipalGeneratrix shortestLinkedGeneratrix(const std::vector<std::vector<Vec3>>& contours,
                                             const std::optional<Vec3>& closurePoint)
{
  const size_t n = checkedPointCount(contours, "shortestLinkedGeneratrix");
  const size_t C = contours.size();
  std::vector<double> length(n, 0.0);
  for (size_t k = 0; k < n; ++k) {
    for (size_t c = 0; c + 1 < C; ++c) length[k] += (contours[c + 1][k] - contours[c][k]).norm();
    if (closurePoint) length[k] += (contours[C - 1][k] - *closurePoint).norm();
  }
  const double shortest = *std::min_element(length.begin(), length.end());
  const double tolerance = 1e-12 * std::max(1.0, std::abs(shortest));
  size_t start = 0;
  while (length[start] > shortest + tolerance) ++start;
  PrincipalGeneratrix out;
  out.length = length[start];
  out.index.assign(C, start);
  return out;
}

PrincipalGeneratrix findPrincipalGeneratrix(const std::vector<std::vector<Vec3>>& contours,
                                            const std::optional<Vec3>& closurePoint, Progress* progress)
{
  const size_t C = contours.size();
  const size_t n = checkedPointCount(contours, "findPrincipalGeneratrix");

  // The chain from (c, k) depends only on that point, so next[c][k] and the remaining length
  // from every point, summed from the top down, give every start's chain length in O(n C).
  std::vector<std::vector<size_t>> next(C > 0 ? C - 1 : 0);
  tbb::parallel_for(size_t(0), next.size(), [&](size_t c) {
    if (progress) progress->checkCancel();
    const auto& from = contours[c];
    const auto& to = contours[c + 1];
    // Cells about the larger of the point spacing and the typical gap between the contours keep
    // every query within a ring or two.
    double spacing = 0.0, gap = 0.0;
    for (size_t k = 0; k < n; ++k) {
      spacing += (to[(k + 1) % n] - to[k]).norm();
      gap += (to[k] - from[k]).norm();
    }
    const double cell = std::max(spacing, gap) / static_cast<double>(n);
    const PointGrid grid(to, cell > 0 ? cell : 1.0);
    next[c].resize(n);
    for (size_t k = 0; k < n; ++k) next[c][k] = grid.nearest(from[k]);
  });

  std::vector<double> remaining(n, 0.0), above(n);
  if (closurePoint)
    for (size_t k = 0; k < n; ++k) remaining[k] = (contours[C - 1][k] - *closurePoint).norm();
  for (size_t c = C - 1; c-- > 0;) {
    for (size_t k = 0; k < n; ++k) {
      const size_t j = next[c][k];
      above[k] = (contours[c + 1][j] - contours[c][k]).norm() + remaining[j];
    }
    remaining.swap(above);
  }
  // Shortest chain; chains equal to rounding (a symmetric part) go to the lowest start index.
  const double shortest = *std::min_element(remaining.begin(), remaining.end());
  const double tolerance = 1e-12 * std::max(1.0, std::abs(shortest));
  size_t start = 0;
  while (remaining[start] > shortest + tolerance) ++start;

  PrincipalGeneratrix out;
  out.length = remaining[start];
  out.index.resize(C);
  out.index[0] = start;
  for (size_t c = 0; c + 1 < C; ++c) out.index[c + 1] = next[c][out.index[c]];
  return out;
}

}  // namespace spira
