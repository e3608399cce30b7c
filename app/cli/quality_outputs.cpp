#include "quality_outputs.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/planning/solid_wall.h"

namespace spira::cli {

nlohmann::json indexStatsJson(const IndexStats& s)
{
  if (s.count == 0) return nullptr;
  return {{"count", s.count}, {"mean", s.mean}, {"min", s.min}, {"below_0_9", s.belowNinety}};
}

CompareQuality compareQuality(const PlanFolder& plan, size_t at, const TriangleMesh& part,
                              const std::string& partName, const PointCloud& scan,
                              const std::vector<double>& deviation, double beadWidth)
{
  CompareQuality q;
  q.at = at;
  std::unique_ptr<TriangleMesh> mid;
  if (plan.report.solidWall)
    mid = std::make_unique<TriangleMesh>(*plannableMidSurface(part, beadWidth).wall.midSurface);
  {
    const MeshDistance surface(mid ? *mid : part);
    q.trajectory = trajectoryIndex(plan.trajectory, at, surface);
  }
  const IndexStats t = indexStats(q.trajectory);
  size_t off = 0;
  for (double v : q.trajectory) off += v == 0.0;
  // A plan of another part, or of this one placed elsewhere, lies off it everywhere; a plan of this
  // part may miss it by a bead in places (a seam, a closure), never at most of its points.
  if (t.count > 0 && 2 * off > t.count)
    throw InputError(std::to_string(off) + " of the plan's " + std::to_string(t.count) +
                         " deposited points before --at lie a bead height or more off " + partName +
                         (mid ? "'s mid-surface" : "'s surface"),
                     "give the part the plan was made from, as its file holds it (the plan's drop along z is "
                     "applied to it)");
  try {
    q.edge = measureTopEdge(plan.trajectory, at, scan, beadWidth);
    q.process = processIndex(plan.trajectory, q.edge);
  } catch (const InputError& e) {
    // A scan of the part's lower half still has a trajectory and a global index to give.
    q.edgeMissing = e.what();
  }
  const std::vector<size_t> nearest = nearestDeposited(plan.trajectory, at, scan);
  q.global = globalIndex(plan.trajectory, nearest, deviation);
  q.deviationAlongPlan = deviationAlongPlan(at, nearest, deviation);
  return q;
}

std::string qualityCsv(const Trajectory& plan, const CompareQuality& q)
{
  std::vector<double> process(q.at, NAN);
  for (size_t e = 0; e < q.process.size(); ++e) process[q.edge.points[e]] = q.process[e];
  std::string out = "index,x,y,z,h_mm,trajectory_index,process_index,scan_deviation_mm\n";
  out.reserve(out.size() + q.at * 80);
  for (size_t i = 0; i < q.at; ++i) {
    if (std::isnan(q.trajectory[i])) continue;
    const TrajectoryPoint& p = plan.points[i];
    appendNumber(out, static_cast<long long>(i));
    for (double v : {p.position.x(), p.position.y(), p.position.z(), p.height, q.trajectory[i]}) {
      out += ',';
      appendNumber(out, v);
    }
    out += ',';
    if (!std::isnan(process[i])) appendNumber(out, process[i]);
    out += ',';
    if (!std::isnan(q.deviationAlongPlan[i])) appendNumber(out, q.deviationAlongPlan[i]);
    out += '\n';
  }
  return out;
}

nlohmann::json qualityJson(const std::string& planDir, const CompareQuality& q)
{
  nlohmann::json j = {{"plan", planDir},
                      {"at", q.at},
                      {"trajectory", indexStatsJson(indexStats(q.trajectory))},
                      {"process", indexStatsJson(indexStats(q.process))},
                      {"global", indexStatsJson(indexStats(q.global))}};
  if (!q.edgeMissing.empty()) j["process_missing"] = q.edgeMissing;
  return j;
}

std::string qualitySummary(const CompareQuality& q)
{
  const auto mean = [](const std::vector<double>& v) {
    const IndexStats s = indexStats(v);
    return s.count == 0 ? std::string("none") : significantText(s.mean, 4);
  };
  std::string s = "quality indices (1 = as planned; means): trajectory " + mean(q.trajectory) + ", process " +
                  mean(q.process) + ", global " + mean(q.global);
  if (!q.edgeMissing.empty()) s += " (no process index: " + q.edgeMissing + ")";
  return s;
}

}  // namespace spira::cli
