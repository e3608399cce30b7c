#pragma once

#include <map>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/path/process_model.h"
#include "spira/path/spiral_report.h"
#include "spira/planning/part_topology.h"
#include "spira/plugin/closure_finder.h"
#include "spira/plugin/parameter.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

// Everything a plan is computed from. `params` holds the values per plugin id and per settings
// section ("spiral", "process"), as PlanSettings stores them.
struct PlanRequest {
  PlanRequest(const TriangleMesh& m, const MeshReport& r) : mesh(m), report(r) {}
  const TriangleMesh& mesh;  // welded, in the part frame (z up, substrate plane below)
  const MeshReport& report;  // validateMesh(mesh)
  double substrateZ = 0.0;
  int lowerLoopOverride = -1;
  std::string decomposerId = "decomposer.isovalue";
  std::string closureFinderId = "closure.max_min_geodesic";
  std::map<std::string, ParamSet> params;
};

// Wall-clock seconds per stage, in pipeline order.
using StageTimings = std::vector<std::pair<std::string, double>>;

struct PlanOutput {
  PartTopology topology;
  std::string fieldKind;  // "geodesic_distance" (closed parts) or "harmonic" (open parts)
  std::vector<double> field;
  bool hasClosure = false;
  ClosureResult closure;
  Generatrices generatrices;
  SpiralResult spiral;  // the trajectory carries the process channels once applyProcess ran
  ProcessReport process;
  StageTimings timings;
  std::vector<std::string> warnings;

  // Within the process window (Eq. 3.6, and Eq. 3.15 on every point). Process-limit
  // violations do not make a plan infeasible: the speeds are clamped to the limits and each
  // violation is reported (they arise where the spiral degenerates, at a closure point).
  bool feasible() const { return spiral.report.feasible; }
};

// Runs the CTPP pipeline: part topology, scalar field (harmonic for open parts; geodesic distance
// from the base and the closure point for closed ones), decomposition into generatrices, the
// continuous spiral with its start-up and deposit heights, and the process channels.
// Throws InputError/AlgorithmError for parts or settings it cannot plan; an infeasible plan is a
// result (feasible() == false), not an error.
PlanOutput planPart(const PluginRegistry& registry, const PlanRequest& request, Progress& progress);

}  // namespace spira
