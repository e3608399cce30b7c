#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plan_folder.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/scan/quality_indices.h"

namespace spira::cli {

nlohmann::json indexStatsJson(const IndexStats& s);  // {count, mean, min, below_0_9}; null when empty

// The indices of a scan compared with the part and with the plan it was built from (scan-compare
// --plan --at): the plan, the part and the scan in the plan's frame.
struct CompareQuality {
  size_t at = 0;
  std::vector<double> trajectory;          // per plan point before `at`, NaN for none
  MeasuredEdge edge;                       // empty when the scan covers none of the top edge
  std::vector<double> process;             // per edge.points
  std::vector<double> global;              // per scan point
  std::vector<double> deviationAlongPlan;  // per plan point before at: the mean deviation of its scan points
  std::string edgeMissing;                 // why there is no process index, if there is none
};

// `part` the part as the plan placed it. A thin-walled solid's plan runs on its mid-surface, so the
// trajectory index is measured against that. Throws InputError when the plan does not lie on the part.
CompareQuality compareQuality(const PlanFolder& plan, size_t at, const TriangleMesh& part,
                              const std::string& partName, const PointCloud& scan,
                              const std::vector<double>& deviation, double beadWidth);

// quality.csv: index,x,y,z,h_mm,trajectory_index,process_index, one row per deposited plan point
// before `at` (process_index empty but at the measured edge points).
std::string qualityCsv(const Trajectory& plan, const CompareQuality& q);

// deviation.json's quality_indices.
nlohmann::json qualityJson(const std::string& planDir, const CompareQuality& q);

// "quality indices (1 = as planned; means): trajectory 0.9999, process 0.92, global 0.75"
std::string qualitySummary(const CompareQuality& q);

}  // namespace spira::cli
