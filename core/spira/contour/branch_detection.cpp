#include "spira/contour/branch_detection.h"

namespace spira {

std::vector<size_t> contourCounts(const std::vector<IsoLevel>& levels)
{
  std::vector<size_t> counts;
  counts.reserve(levels.size());
  for (const auto& l : levels) counts.push_back(l.contours.size());
  return counts;
}

double meanZ(const IsoLevel& level)
{
  double sum = 0.0;
  size_t n = 0;
  for (const auto& c : level.contours) {
    for (const auto& p : c.points) sum += p.position.z();
    n += c.points.size();
  }
  return n ? sum / static_cast<double>(n) : 0.0;
}

std::vector<BranchChange> findBranchChanges(const std::vector<IsoLevel>& levels)
{
  std::vector<BranchChange> out;
  for (size_t k = 1; k < levels.size(); ++k) {
    const size_t before = levels[k - 1].contours.size(), after = levels[k].contours.size();
    if (before == after) continue;
    BranchChange c;
    c.levelIndex = k;
    c.value = levels[k].value;
    c.before = before;
    c.after = after;
    c.meanZ = meanZ(levels[k]);
    out.push_back(c);
  }
  return out;
}

}  // namespace spira
