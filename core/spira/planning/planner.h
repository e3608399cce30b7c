#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/substrate_surface.h"
#include "spira/path/process_model.h"
#include "spira/path/spiral_report.h"
#include "spira/planning/branch_split.h"
#include "spira/planning/part_topology.h"
#include "spira/planning/solid_wall.h"
#include "spira/planning/stage_clock.h"
#include "spira/plugin/closure_finder.h"
#include "spira/plugin/parameter.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/plugin/strategy_name.h"
#include "spira/verify/deposit_check.h"

namespace spira {

// Everything a plan is computed from but the surface. `params` holds the values per plugin id and
// per settings section (settings_sections.h), as PlanSettings stores them.
struct PlanChoices {
  double substrateZ = 0.0;
  int lowerLoopOverride = -1;
  // The material this part stands on lies this far below its lower edge, along the surface (a
  // branch above a junction gap), mm: its first ring is laid measured from there.
  double baseSupportGap = 0.0;
  // A watertight thin-walled solid is planned on its mid-surface (docs/thin-walled-solids.md);
  // false refuses it like any closed mesh.
  bool midSurfaceOfSolid = true;
  // Built on a surface that is not the plane z = substrateZ (a pipe, a curved plate), in the part frame;
  // nullptr: the plane.
  std::shared_ptr<const SubstrateSurface> substrate;
  std::string decomposerId = kDefaultDecomposerId;
  std::string closureFinderId = kDefaultClosureFinderId;
  std::map<std::string, ParamSet> params;
};

// Everything a plan is computed from.
struct PlanRequest : PlanChoices {
  PlanRequest(const TriangleMesh& m, const MeshReport& r) : mesh(m), report(r) {}
  // The same choices on another surface (a mid-surface, a sub-part).
  PlanRequest(const TriangleMesh& m, const MeshReport& r, const PlanChoices& choices)
      : PlanChoices(choices), mesh(m), report(r)
  {
  }
  const TriangleMesh& mesh;  // welded, in the part frame (z up, substrate plane below)
  const MeshReport& report;  // validateMesh(mesh)
};

// One sub-path of a plan: a mono-branch sub-part of a multi-branch part, or the whole part.
struct PathSummary {
  int path = 0;
  int parent = -1;  // the sub-path it is built on (-1: the substrate)
  int depth = 0;    // splits between it and the base
  bool trunk = true;
  PartClass partClass = PartClass::Unsupported;  // of the sub-part: open, or closed (a capped branch)
  double baseLevel = 0.0;                 // geodesic distance from the part's base to its lower edge, mm
  double area = 0.0;                      // mm^2 of the part's surface it covers
  size_t firstPoint = 0, pointCount = 0;  // its points in the plan's trajectory
  std::string fieldKind;
  bool hasClosure = false;
  ClosureResult closure;
  size_t generatrices = 0;
  SpiralReport spiral;  // its own report: violation indices count from its first point
  ProcessReport process;
  std::vector<std::string> warnings;
  size_t depositFlags = 0;  // points of this sub-path the deposit check flagged
  bool feasible() const { return depositFlags == 0; }
};

// How a multi-branch part was split (see branch_split.h).
struct BranchingSummary {
  std::vector<BranchSaddle> saddles;
  double junctionGap = 0.0;      // mm of geodesic distance between a trunk's top and its branches' bases
  double junctionGapArea = 0.0;  // mm^2 of surface in those gaps, not deposited
  bool depthLimited = false;
};

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
  // The sub-paths in build order (each after the one it stands on); one for a mono-branch part.
  // A multi-branch part's trajectory holds them one after the other, TrajectoryPoint::path
  // numbering them; each is one continuous spiral with its own arc start and stop. Then `field` is
  // the geodesic distance from the base the part was split with, `generatrices` all sub-parts'
  // generatrices in path order, and `spiral.report` and `process` add the sub-paths up (counts and
  // lengths summed, extremes over all, violations indexed in the whole trajectory).
  std::vector<PathSummary> paths;
  std::optional<BranchingSummary> branching;  // set for a multi-branch part
  // Set for a thin-walled solid: everything above (field, topology, deposit check) is of its
  // mid-surface, SolidWall::midSurface.
  std::optional<SolidWall> solid;
  // Set when the decomposer laid the path in layers (decomposer.constant_distance): what it measured.
  std::optional<LayerStats> layers;

  // The verdict, from the trajectory alone (docs/deposit-check.md); spiral.report keeps the
  // heights the spiral builder planned. Process-limit violations do not make a plan infeasible:
  // the speeds are clamped to the limits and each violation is reported.
  DepositCheckReport deposits;
  bool feasible() const { return deposits.feasible; }
};

// Runs the CTPP pipeline: a watertight thin-walled solid replaced by its mid-surface, part topology, scalar
// field (harmonic for open parts; geodesic distance from the base and the closure point for closed ones),
// decomposition into generatrices, the continuous spiral with its start-up and deposit heights, and the
// process channels. A multi-branch part (more than two free edges, or a field whose contours part into
// several loops at least pi x bead width long) is split into mono-branch sub-parts (branch_split.h), each
// planned on its own, trunk first (thesis 000_dbb97c2716e10cc3.txt §3.4.3).
// Last, the deposit check judges the trajectory on its own (see deposit_check.h).
// Throws InputError/AlgorithmError for parts or settings it cannot plan; an infeasible plan is a
// result (feasible() == false), not an error.
PlanOutput planPart(const PluginRegistry& registry, const PlanRequest& request, Progress& progress);

// The mono-branch pipeline alone, without looking for branches: what planPart runs on a part
// that does not branch and on each sub-part of one that does.
PlanOutput planMonoBranch(const PluginRegistry& registry, const PlanRequest& request, Progress& progress);

// The deposit check the plan ends with, on a path changed after planning (a thermal re-planning's
// thinner band), in the request's frame: its window, bead width and substrate, its surface when
// `againstSurface` (not for a solid, planned on its mid-surface).
DepositCheckReport checkPlannedDeposits(const PluginRegistry& registry, const PlanRequest& request,
                                        const Trajectory& path, bool againstSurface, Progress& progress);

}  // namespace spira
