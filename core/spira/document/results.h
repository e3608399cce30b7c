#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "spira/document/kinematics_result.h"
#include "spira/document/stage.h"
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

// The staged results of a plan. Each is an immutable value held by shared pointer (null: not
// computed), so copying Results is cheap and an undo snapshot holds them for free.
//
// Kinematics is the typed robot motion (kinematics_result.h). Export is a JSON payload (written
// files and their checksums); the project file stores it as it is.
struct Results {
  std::shared_ptr<const FieldResult> field;
  std::shared_ptr<const Generatrices> generatrices;
  std::shared_ptr<const Trajectory> spiral;   // the continuous spiral, geometry channels
  std::shared_ptr<const Trajectory> process;  // with orientation and process channels
  std::shared_ptr<const KinematicsResult> kinematics;
  std::shared_ptr<const nlohmann::json> exported;
  // Per stage: what the computation reported (timings, warnings, statistics); null if none.
  std::array<std::shared_ptr<const nlohmann::json>, kStageCount> reports;

  // Whether the stage's result is present (reports do not count).
  bool has(Stage s) const;
  // Stages whose result is present.
  StageMask presentStages() const;
  // Drops the result and report of `s` and of every later stage.
  void invalidateFrom(Stage s);
  void clear() { *this = Results(); }

  // Each setter stores the result of one stage and drops every later stage, whose inputs changed.
  void setField(std::shared_ptr<const FieldResult> r);
  void setGeneratrices(std::shared_ptr<const Generatrices> r);
  void setSpiral(std::shared_ptr<const Trajectory> r);
  void setProcess(std::shared_ptr<const Trajectory> r);
  void setKinematics(std::shared_ptr<const KinematicsResult> r);
  void setExport(std::shared_ptr<const nlohmann::json> r);
  // Sets the report of a stage without touching any result.
  void setReport(Stage s, std::shared_ptr<const nlohmann::json> report);
  const std::shared_ptr<const nlohmann::json>& report(Stage s) const { return reports[stageIndex(s)]; }

  // Stages whose result or report differs (by pointer, then by value).
  StageMask differingStages(const Results& o) const;
  bool operator==(const Results& o) const { return differingStages(o) == 0; }
  bool operator!=(const Results& o) const { return !(*this == o); }
};

// Project-file codec; numeric arrays are binary blobs so the round trip is bit-for-bit.
nlohmann::json resultsToJson(const Results& r);
Results resultsFromJson(const nlohmann::json& j);  // throws InputError

}  // namespace spira
