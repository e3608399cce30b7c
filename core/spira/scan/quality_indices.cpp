#include "spira/scan/quality_indices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <tbb/parallel_for.h>

#include "spira/base/error.h"
#include "spira/scan/scan_processing.h"

namespace spira {
namespace {

bool deposited(const TrajectoryPoint& p)
{
  return p.arcOn && p.height > 0.0;
}

}  // namespace

double qualityIndex(double errorMm, double beadHeightMm)
{
  return std::max(0.0, 1.0 - std::abs(errorMm) / beadHeightMm);
}

IndexStats indexStats(const std::vector<double>& values)
{
  IndexStats s;
  double sum = 0.0;
  size_t below = 0;
  s.min = std::numeric_limits<double>::infinity();
  for (double v : values) {
    if (std::isnan(v)) continue;
    ++s.count;
    sum += v;
    s.min = std::min(s.min, v);
    below += v < 0.9;
  }
  if (s.count == 0) return IndexStats{};
  s.mean = sum / double(s.count);
  s.belowNinety = double(below) / double(s.count);
  return s;
}

std::vector<double> trajectoryIndex(const Trajectory& plan, size_t at, const MeshDistance& surface)
{
  at = std::min(at, plan.size());
  std::vector<double> out(at, NAN);
  tbb::parallel_for(size_t(0), at, [&](size_t i) {
    const TrajectoryPoint& p = plan.points[i];
    if (deposited(p)) out[i] = qualityIndex(surface.closest(p.position).signedDistance, p.height);
  });
  return out;
}

std::vector<double> processIndex(const Trajectory& plan, const MeasuredEdge& edge)
{
  const std::vector<size_t> below = pointsBelow(plan);
  std::vector<double> out(edge.points.size(), NAN);
  for (size_t e = 0; e < edge.points.size(); ++e) {
    if (edge.samples[e] == 0) continue;
    // What the plan built up on this generatrix to the top bead: the beads under it and itself.
    double built = 0.0;
    for (size_t j = edge.points[e]; j != std::numeric_limits<size_t>::max(); j = below[j])
      if (deposited(plan.points[j])) built += plan.points[j].height;
    if (built > 0.0) out[e] = qualityIndex(edge.shortfall[e], built);
  }
  return out;
}

std::vector<size_t> nearestDeposited(const Trajectory& plan, size_t at, const PointCloud& scan)
{
  std::vector<Vec3> laid;
  std::vector<size_t> index;
  for (size_t i = 0; i < std::min(at, plan.size()); ++i)
    if (deposited(plan.points[i])) {
      laid.push_back(plan.points[i].position);
      index.push_back(i);
    }
  if (laid.empty())
    throw InputError("no point of the plan before point " + std::to_string(at) + " deposits anything",
                     "give the number of points deposited when the scan was taken (--at)");
  std::vector<size_t> nearest = nearestPoints(laid, scan.points);
  for (size_t& n : nearest) n = index[n];
  return nearest;
}

std::vector<double> globalIndex(const Trajectory& plan, const std::vector<size_t>& nearest,
                                const std::vector<double>& deviation)
{
  if (deviation.size() != nearest.size()) throw InternalError("a deviation for each scan point is needed");
  std::vector<double> out(nearest.size());
  for (size_t k = 0; k < nearest.size(); ++k)
    out[k] = qualityIndex(deviation[k], plan.points[nearest[k]].height);
  return out;
}

std::vector<double> globalIndex(const Trajectory& plan, size_t at, const PointCloud& scan,
                                const std::vector<double>& deviation)
{
  if (deviation.size() != scan.size()) throw InternalError("a deviation for each scan point is needed");
  return globalIndex(plan, nearestDeposited(plan, at, scan), deviation);
}

std::vector<double> deviationAlongPlan(size_t at, const std::vector<size_t>& nearest,
                                       const std::vector<double>& deviation)
{
  if (deviation.size() != nearest.size()) throw InternalError("a deviation for each scan point is needed");
  std::vector<double> sum(at, 0.0);
  std::vector<size_t> count(at, 0);
  for (size_t k = 0; k < nearest.size(); ++k)
    if (nearest[k] < at) sum[nearest[k]] += deviation[k], ++count[nearest[k]];
  for (size_t i = 0; i < at; ++i) sum[i] = count[i] > 0 ? sum[i] / double(count[i]) : NAN;
  return sum;
}

}  // namespace spira
