#pragma once

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "spira/document/document_state.h"
#include "spira/pipeline/document_plan.h"
#include "spira/robotcell/robot_cell.h"

namespace spira::python {

// spira.Cell: a .cell file read, and the cell solvable from it.
struct LoadedCell {
  std::string path;  // the .cell file; a project's cell: its name (program headers name it so)
  std::shared_ptr<const CellRecord> record;
  std::shared_ptr<const RobotCell> cell;
};

// spira.Plan: a part planned as 'spira-cli plan' plans it, with what export needs.
struct PlannedPart {
  std::string partPath;
  DocumentState snapshot;
  std::shared_ptr<DocumentPlan> plan;
  std::shared_ptr<const Trajectory> path;  // plannedPathOf: what trajectory.csv holds
  std::vector<bool> collision;             // per point of `path` (with a cell)
  std::optional<LoadedCell> cell;
};

// spira.Cell, spira.read_cell, spira.Plan, spira.plan and Plan.export.
void bindPlan(pybind11::module_& m);

}  // namespace spira::python
