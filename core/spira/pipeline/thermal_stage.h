#pragma once

#include <memory>

#include "spira/document/results.h"
#include "spira/path/process_model.h"
#include "spira/pipeline/thermal_schema.h"
#include "spira/thermal/thermal_study.h"

namespace spira {

class Progress;

struct ThermalStageSettings {
  bool enabled = false;
  // The mesh's shell thickness and substrate plane are the plan's: thermal_stage.cpp fills them.
  ThermalStudySettings study;
  double arcRadius = 0.0;       // mm; 0: half the bead width
  double interpassLimit = 0.0;  // C; 0: none
  // The remedies that re-plan to the limit (thermal_replan.h); none: the limit is only reported.
  bool remedyDeposit = false, remedyHeat = true, remedyDwell = false;
  double maxDwell = 600.0;  // s
  double windowMin = 0.0;   // mm: the spiral's h_min, the deposit remedy's floor (the plan fills it)
};

// Throws InputError for values outside the schema, an unknown material, or no arc power (power 0
// without voltage and current).
ThermalStageSettings thermalStageSettingsFrom(const ParamSet& values);

// The thermal stage of a plan: the heat of the build along the process stage's path (thermal.md).
struct ThermalStageOutput {
  std::shared_ptr<const ThermalStageResult> result;
  std::shared_ptr<const ThermalStageReport> report;
};

// The study's settings for `path`: the section's, with the shell as thick as the bead (`beadWidth`,
// mm, the process section's), the arc's radius half of it unless set, resting on the plane under
// the first revolution.
ThermalStudySettings thermalStudySettingsFor(const Trajectory& path, const ThermalStageSettings& settings,
                                             double beadWidth);

// Simulates `path` (InputError for bad settings or a path without process channels; Cancelled).
// With an interpass limit and the remedy on, re-plans it within `process`'s limits: the result then
// holds the re-planned path and the report whether the limit is met and at what cost.
ThermalStageOutput runThermalStage(const Trajectory& path, const ThermalStageSettings& settings,
                                   const ProcessSettings& process, Progress& progress);

// What the document keeps of a study: the shell, the per-point and per-node values, the quantised frames.
ThermalStageResult thermalStageResultOf(const ThermalStudy& study);
ThermalStageReport thermalStageReportOf(const ThermalStudy& study, const ThermalStudySettings& settings,
                                        double interpassLimit);

}  // namespace spira
