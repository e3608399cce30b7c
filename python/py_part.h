#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "py_options.h"
#include "py_progress.h"
#include "spira/document/part.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/part_placement.h"

namespace spira::python {

// spira.Part: a part file imported and placed as 'spira-cli plan PART' places it.
struct LoadedPart {
  std::shared_ptr<const Part> part;
  MeshReport report;
  std::string importerId;
  std::vector<std::string> warnings;
  PartPlacementOptions placement;
  PlacementChange placed;
  double importSeconds = 0.0;
};

// How a part file is read and placed: the placement arguments (lower_loop, substrate_z, drop,
// level_base) and the importers' settings (unit, ...), whose targets the caller hands to
// Options::takeSettings with its own.
struct ImportChoices {
  ImportChoices();
  ImportChoices(const ImportChoices&) = delete;  // targets point into values
  ImportChoices& operator=(const ImportChoices&) = delete;
  // Takes the placement arguments from `options`.
  void takePlacement(Options& options);

  PartPlacementOptions placement;
  std::map<std::string, ParamSet> values;  // by importer id
  std::vector<FlagTarget> targets;
};

// Imports and places `path` as `choices` say, the GIL released meanwhile.
LoadedPart loadPart(const std::string& path, const ImportChoices& choices, PythonProgress& progress);

// spira.Part and spira.load_part.
void bindPart(pybind11::module_& m);

}  // namespace spira::python
