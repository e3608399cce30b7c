#include "spira/thermal/thermal_source.h"

#include <algorithm>
#include <cmath>

namespace spira {

SourceLoad::SourceLoad(const ThermalMesh& mesh, const ThermalSettings& settings)
    : mesh_(mesh),
      power_(settings.power),
      perWireFeed_(settings.powerPerWireFeed),
      radius_(settings.sourceRadius),
      table_(settings.powerTable)
{
  if (!(radius_ > 0.0)) return;
  const size_t n = mesh.nodeCount();
  area_.assign(n, 0.0);
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.nodes[size_t(t[0])], &b = mesh.nodes[size_t(t[1])], &c = mesh.nodes[size_t(t[2])];
    const double third = (b - a).cross(c - a).norm() / 6.0;
    for (int v : t) area_[size_t(v)] += third;
  }
  NodeAdjacency adjacency = nodeAdjacency(mesh);
  neighbourStart_ = std::move(adjacency.start);
  neighbours_ = std::move(adjacency.neighbours);
  mark_.assign(n, 0);
}

void SourceLoad::spread(const Vec3& at, int a, int b, double joules, const std::vector<char>& deposited,
                        std::vector<double>& energy)
{
  const double reach2 = 2.25 * radius_ * radius_, scale = 3.0 / (radius_ * radius_);
  ++stamp_;
  // Seeded from both ends of the torch's segment: on a segment longer than 3 R one end alone may not
  // reach, through nodes within 1.5 R, every node the flux covers.
  stack_.assign(1, a);
  if (b != a) stack_.push_back(b);
  mark_[size_t(a)] = mark_[size_t(b)] = stamp_;
  const int near =
      (mesh_.nodes[size_t(a)] - at).squaredNorm() <= (mesh_.nodes[size_t(b)] - at).squaredNorm() ? a : b;
  found_.clear();
  weight_.clear();
  double sum = 0.0;
  while (!stack_.empty()) {
    const int u = stack_.back();
    stack_.pop_back();
    const double d2 = (mesh_.nodes[size_t(u)] - at).squaredNorm();
    if (deposited[size_t(u)]) {
      found_.push_back(u);
      weight_.push_back(area_[size_t(u)] * std::exp(-scale * d2));
      sum += weight_.back();
    }
    for (int q = neighbourStart_[size_t(u)]; q < neighbourStart_[size_t(u) + 1]; ++q) {
      const int w = neighbours_[size_t(q)];
      if (mark_[size_t(w)] == stamp_ || (mesh_.nodes[size_t(w)] - at).squaredNorm() > reach2) continue;
      mark_[size_t(w)] = stamp_;
      stack_.push_back(w);
    }
  }
  if (!(sum > 0.0)) {  // nothing laid around the torch yet: its node takes it all
    energy[size_t(near)] += joules;
    return;
  }
  for (size_t k = 0; k < found_.size(); ++k) energy[size_t(found_[k])] += joules * weight_[k] / sum;
}

double SourceLoad::add(double t0, double t1, const std::vector<char>& deposited, std::vector<double>& energy)
{
  const auto& h = mesh_.heatTime;
  while (segment_ + 1 < h.size() && h[segment_ + 1] <= t0) ++segment_;
  double total = 0.0;
  for (size_t i = segment_; i + 1 < h.size() && h[i] < t1; ++i) {
    const double ta = h[i], tb = h[i + 1];
    const double power = !table_.empty()      ? tablePower(table_, mesh_.heatWireFeed[i])
                         : perWireFeed_ > 0.0 ? perWireFeed_ * mesh_.heatWireFeed[i]
                                              : power_;
    if (!mesh_.heatArcOn[i] || !(tb > ta) || power == 0.0) continue;
    const double s0 = std::max(ta, t0), s1 = std::min(tb, t1);
    if (!(s1 > s0)) continue;
    const int a = mesh_.heatNode[i], b = mesh_.heatNode[i + 1];
    total += power * (s1 - s0);
    if (!(radius_ > 0.0)) {
      const double towardB = ((s1 - ta) * (s1 - ta) - (s0 - ta) * (s0 - ta)) / (2.0 * (tb - ta));
      energy[size_t(a)] += power * (s1 - s0 - towardB);
      energy[size_t(b)] += power * towardB;
      continue;
    }
    // Samples no further apart than R / 2 along the part of the segment run in this step.
    const Vec3 &pa = mesh_.nodes[size_t(a)], &pb = mesh_.nodes[size_t(b)];
    const double run = (pb - pa).norm() * (s1 - s0) / (tb - ta);
    const int samples = std::max(1, int(std::ceil(run / (0.5 * radius_))));
    for (int k = 0; k < samples; ++k) {
      const double f = (s0 + (k + 0.5) * (s1 - s0) / samples - ta) / (tb - ta);
      spread(pa + f * (pb - pa), a, b, power * (s1 - s0) / samples, deposited, energy);
    }
  }
  return total;
}

}  // namespace spira
