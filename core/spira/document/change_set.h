#pragma once

#include <cstdint>
#include <set>
#include <string>

#include "spira/document/stage.h"

namespace spira {

// What changed in one notification, so views update only that.
enum class Change : std::uint32_t {
  Part = 1u << 0,  // mesh, placement, name or lower-boundary choice
  Substrate = 1u << 1,
  Cell = 1u << 2,
  Settings = 1u << 3,   // strategy choice or parameter values (see ChangeSet::sections)
  Results = 1u << 4,    // see ChangeSet::stages
  UndoStack = 1u << 5,  // steps, undo/redo texts
  Modified = 1u << 6,   // Document::isModified() flipped
  FilePath = 1u << 7,
  Scan = 1u << 8,  // the compared scan (an input of no stage: no result goes stale)
};

struct ChangeSet {
  std::uint32_t flags = 0;
  StageMask stages = 0;            // stages whose result or report changed (with Change::Results)
  std::set<std::string> sections;  // settings sections whose values changed (with Change::Settings)
  bool strategyChanged = false;    // decomposer or closure finder id changed (with Change::Settings)

  bool has(Change c) const { return (flags & static_cast<std::uint32_t>(c)) != 0; }
  bool hasStage(Stage s) const { return (stages & stageBit(s)) != 0; }
  bool empty() const { return flags == 0; }
  void add(Change c) { flags |= static_cast<std::uint32_t>(c); }
  ChangeSet& operator|=(const ChangeSet& o);
};

}  // namespace spira
