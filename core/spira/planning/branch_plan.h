#pragma once

#include "spira/planning/branch_split.h"
#include "spira/planning/planner.h"

namespace spira {

// A mono-branch plan as its single path (path 0, the trunk, on the substrate).
PathSummary wholePathSummary(const PlanOutput& plan);

// Plans every piece of `pieces` with planMonoBranch (the settings, strategy and closure finder of
// `whole`), each from its own lower edge, and lays the sub-paths one after the other into `out`,
// which already holds the whole part's topology and stage timings: trajectory points numbered by
// path, generatrices in path order, the reports added up (see PlanOutput), one PathSummary per
// piece and the branching summary. The field becomes the splitting field (geodesic distance from
// the base). Errors from a piece are rethrown with the sub-part named.
void planBranchPieces(const PluginRegistry& registry, const PlanRequest& whole, BranchDecomposition pieces,
                      PlanOutput& out, Progress& progress);

// Adds a sub-path's spiral report to a running total whose trajectory already holds `offset`
// points (the violations are re-indexed). `first`: the total is still empty.
void addSpiralReport(SpiralReport& total, const SpiralReport& part, size_t offset, bool first);
void addProcessReport(ProcessReport& total, const ProcessReport& part, size_t offset, bool first);

}  // namespace spira
