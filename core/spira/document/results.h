#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "spira/document/kinematics_result.h"
#include "spira/document/stage.h"
#include "spira/document/stage_reports.h"
#include "spira/document/thermal_result.h"
#include "spira/path/trajectory.h"

namespace spira {

// A scalar field on the part's vertices (the input of the decomposition).
struct FieldResult {
  std::string kind;            // what the values are, e.g. "geodesic_distance", "harmonic"
  std::string source;          // how it was made, in plain words (plugin id, base loop...)
  std::vector<double> values;  // one per part vertex

  bool operator==(const FieldResult& o) const;
  bool operator!=(const FieldResult& o) const { return !(*this == o); }
};

// What the stages of a plan reported (stage_reports.h), typed; null: none. The export stage has
// no report: its result lists what it wrote.
struct StageReports {
  std::shared_ptr<const FieldStageReport> field;
  std::shared_ptr<const GeneratricesStageReport> generatrices;
  std::shared_ptr<const SpiralStageReport> spiral;
  std::shared_ptr<const ProcessStageReport> process;
  std::shared_ptr<const ThermalStageReport> thermal;
  std::shared_ptr<const KinematicsStageReport> kinematics;

  // Calls `f` with the member pointer of stage `s`'s report (&StageReports::spiral...) and returns
  // true; false for the export stage, which has no report.
  template <class F>
  static bool visitMember(Stage s, F&& f);

  bool has(Stage s) const;
  void reset(Stage s);
  // The same report object, or two that hold the same values.
  bool same(Stage s, const StageReports& o) const;
  // The same report object (or both none).
  bool identical(Stage s, const StageReports& o) const;
};

template <class F>
bool StageReports::visitMember(Stage s, F&& f)
{
  switch (s) {
    case Stage::Field:
      f(&StageReports::field);
      return true;
    case Stage::Generatrices:
      f(&StageReports::generatrices);
      return true;
    case Stage::Spiral:
      f(&StageReports::spiral);
      return true;
    case Stage::Process:
      f(&StageReports::process);
      return true;
    case Stage::Thermal:
      f(&StageReports::thermal);
      return true;
    case Stage::Kinematics:
      f(&StageReports::kinematics);
      return true;
    case Stage::Export:
      return false;
  }
  return false;
}

// The staged results of a plan. Each is an immutable value held by shared pointer (null: not
// computed), so copying Results is cheap and an undo snapshot holds them for free.
struct Results {
  std::shared_ptr<const FieldResult> field;
  std::shared_ptr<const Generatrices> generatrices;
  std::shared_ptr<const Trajectory> spiral;           // the continuous spiral, geometry channels
  std::shared_ptr<const Trajectory> process;          // with orientation and process channels
  std::shared_ptr<const ThermalStageResult> thermal;  // null: not simulated (the stage is optional)
  std::shared_ptr<const KinematicsResult> kinematics;
  std::shared_ptr<const ExportStageResult> exported;
  StageReports reports;

  // Whether the stage's result is present (reports do not count).
  bool has(Stage s) const;
  // Stages whose result is present.
  StageMask presentStages() const;
  // Drops the result and report of `s` and of every later stage.
  void invalidateFrom(Stage s);
  void clear() { *this = Results(); }

  // Each setter stores the result of one stage with its report and drops every later stage,
  // whose inputs changed.
  void setField(std::shared_ptr<const FieldResult> r, std::shared_ptr<const FieldStageReport> report = {});
  void setGeneratrices(std::shared_ptr<const Generatrices> r,
                       std::shared_ptr<const GeneratricesStageReport> report = {});
  void setSpiral(std::shared_ptr<const Trajectory> r, std::shared_ptr<const SpiralStageReport> report = {});
  void setProcess(std::shared_ptr<const Trajectory> r, std::shared_ptr<const ProcessStageReport> report = {});
  void setThermal(std::shared_ptr<const ThermalStageResult> r,
                  std::shared_ptr<const ThermalStageReport> report = {});
  void setKinematics(std::shared_ptr<const KinematicsResult> r,
                     std::shared_ptr<const KinematicsStageReport> report = {});
  void setExport(std::shared_ptr<const ExportStageResult> r);

  // Stages whose result or report differs (by pointer, then by value).
  StageMask differingStages(const Results& o) const;
  bool operator==(const Results& o) const { return differingStages(o) == 0; }
  bool operator!=(const Results& o) const { return !(*this == o); }
};

// Project-file codec; numeric arrays are binary blobs so the round trip is bit-for-bit.
nlohmann::json resultsToJson(const Results& r);
Results resultsFromJson(const nlohmann::json& j);  // throws InputError

}  // namespace spira
