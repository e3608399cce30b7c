#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli_common.h"
#include "part_loading.h"
#include "part_placement.h"
#include "spira/document/document_state.h"
#include "spira/pipeline/document_plan.h"

namespace spira::cli {

// The flags that say how a part file is planned, shared by 'plan' and 'thermal': the importer's and
// the plan's parameter flags, the placement, --strategy and --no-mid-surface.
struct PartPlanFlags {
  explicit PartPlanFlags(const PluginRegistry& registry) : importFlags(registry), planFlags(registry) {}
  // Takes --strategy, the placement flags and --no-mid-surface from `args`.
  void take(Args& args);
  // The parameter flags' targets (plan sections, plugins, importers), for takeParamFlags and help.
  std::vector<FlagTarget> targets() const;

  ImporterFlags importFlags;
  PlanFlags planFlags;
  PartPlacement placement;
  std::string strategy;
  bool noMidSurface = false;
  std::string substrate;  // --substrate (plan only): empty for the plate
};

// A part file planned: the document it was planned as, the plan and its report.json (with the
// placement's drop and levelling and the import time), and what the placement did.
struct PlannedPart {
  DocumentState snapshot;
  DocumentPlan plan;
  PlacementChange placed;
};

// Imports `file`, places it and plans it, on `cell` when given (the robot's joints then solved).
// Prints the placement's changes and the import warnings.
PlannedPart planPartFile(const PluginRegistry& registry, const std::string& file, PartPlanFlags& flags,
                         std::shared_ptr<const CellRecord> cell, bool keepCollisions, Progress& progress);

}  // namespace spira::cli
