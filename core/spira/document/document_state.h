#pragma once

#include <memory>

#include "spira/document/part.h"
#include "spira/document/plan_settings.h"
#include "spira/document/results.h"
#include "spira/document/scan_record.h"
#include "spira/document/substrate.h"
#include "spira/robotcell/cell_record.h"

namespace spira {

// Everything the user works on, as shared immutable values: copying a state is a handful of
// pointer copies, so undo snapshots and worker-thread snapshots are cheap. To change a member,
// replace its pointer (e.g. `s.part = std::make_shared<Part>(edited)`), never cast away const.
struct DocumentState {
  std::shared_ptr<const Part> part;  // null: no part imported yet
  std::shared_ptr<const Substrate> substrate = std::make_shared<const Substrate>();
  std::shared_ptr<const CellRecord> cell;  // null: no cell chosen
  std::shared_ptr<const PlanSettings> settings = std::make_shared<const PlanSettings>();
  std::shared_ptr<const ScanRecord> scan;  // null: no scan compared
  Results results;

  // Same inputs (part, substrate, cell, settings, scan), compared by pointer then by value.
  bool sameInputs(const DocumentState& o) const;
  bool operator==(const DocumentState& o) const { return sameInputs(o) && results == o.results; }
  bool operator!=(const DocumentState& o) const { return !(*this == o); }
};

// Value equality of two shared values: equal pointers, or both set and equal values.
template <class T>
bool sameValue(const std::shared_ptr<const T>& a, const std::shared_ptr<const T>& b)
{
  return a == b || (a && b && *a == *b);
}

}  // namespace spira
