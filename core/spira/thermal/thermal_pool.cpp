#include "spira/thermal/thermal_pool.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spira {

MeltPoolTracker::MeltPoolTracker(const ThermalMesh& mesh, const Trajectory& trajectory,
                                 double meltingTemperature)
    : mesh_(mesh), trajectory_(trajectory), melt_(meltingTemperature)
{
  const size_t n = mesh.nodeCount();
  NodeAdjacency adjacency = nodeAdjacency(mesh);
  neighbourStart_ = std::move(adjacency.start);
  neighbours_ = std::move(adjacency.neighbours);
  heatPoint_.assign(mesh.heatNode.size(), 0);
  for (size_t p = 0; p < mesh.pointHeatIndex.size(); ++p) {
    const size_t from = size_t(mesh.pointHeatIndex[p]);
    const size_t to =
        p + 1 < mesh.pointHeatIndex.size() ? size_t(mesh.pointHeatIndex[p + 1]) : heatPoint_.size();
    for (size_t h = from; h < to; ++h) heatPoint_[h] = int(p);
  }
  lengths_.assign(mesh.pointHeatIndex.size(), 0.0);
  mark_.assign(n, 0);
}

double MeltPoolTracker::lengthAt(size_t heatIndex, const ThermalStep& step)
{
  const int torch = mesh_.heatNode[heatIndex];
  const auto& T = step.temperature;
  if (!step.deposited[size_t(torch)] || !(T[size_t(torch)] > melt_)) return 0.0;
  const Vec3 origin = mesh_.nodes[size_t(torch)];
  const Vec3 along = trajectory_.points[size_t(heatPoint_[heatIndex])].tangent;
  const auto coordinate = [&](int v) { return (mesh_.nodes[size_t(v)] - origin).dot(along); };
  ++stamp_;
  double lo = 0.0, hi = 0.0;
  stack_.assign(1, torch);
  mark_[size_t(torch)] = stamp_;
  while (!stack_.empty()) {
    const int u = stack_.back();
    stack_.pop_back();
    const double su = coordinate(u);
    lo = std::min(lo, su);
    hi = std::max(hi, su);
    for (int q = neighbourStart_[size_t(u)]; q < neighbourStart_[size_t(u) + 1]; ++q) {
      const int w = neighbours_[size_t(q)];
      if (!step.deposited[size_t(w)]) continue;  // the deposit's front ends the pool
      if (T[size_t(w)] > melt_) {
        if (mark_[size_t(w)] != stamp_) {
          mark_[size_t(w)] = stamp_;
          stack_.push_back(w);
        }
        continue;
      }
      const double f = (T[size_t(u)] - melt_) / (T[size_t(u)] - T[size_t(w)]);
      const double s = su + f * (coordinate(w) - su);
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
  }
  return hi - lo;
}

void MeltPoolTracker::operator()(const ThermalStep& step)
{
  const auto& h = mesh_.heatTime;
  const double eps = 1e-9 * std::max(1.0, step.time);
  if (nextPoint_ >= lengths_.size() || h[size_t(mesh_.pointHeatIndex[nextPoint_])] > step.time + eps) return;
  // The points the torch passed in this step share the pool where it is now (one point per step
  // with the automatic step).
  const size_t now = size_t(std::upper_bound(h.begin(), h.end(), step.time + eps) - h.begin()) - 1;
  const double length = lengthAt(now, step);
  for (; nextPoint_ < lengths_.size() && h[size_t(mesh_.pointHeatIndex[nextPoint_])] <= step.time + eps;
       ++nextPoint_)
    lengths_[nextPoint_] = length;
}

double weightedBondNumber(const ThermalMaterial& material, double poolLength, const Vec3& normal)
{
  constexpr double kGravity = 9.81;  // m/s2 (the source rounds it to 10)
  constexpr double kPi = 3.14159265358979323846;
  const double alpha = std::acos(std::min(1.0, std::abs(normal.normalized().z())));
  const double length = poolLength * 1e-3;
  return material.liquidDensity * length * length * kGravity / material.surfaceTension *
         std::exp(kPi / 4.0 - alpha / 2.0);
}

}  // namespace spira
