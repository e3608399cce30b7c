#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "spira/document/document_state.h"

namespace spira {

// A stack of named document snapshots. A step holds one whole DocumentState: while the step is
// applied (undoable) it holds the state before it; once undone it holds the state to redo. Undo
// and redo swap that snapshot with the live state, so results computed after an edit come back
// on redo and results computed before it come back on undo.
//
// The clean index is the number of applied steps at the last save; isClean() compares with it.
// It becomes unreachable when the saved state is cut away (new edit after undo, depth limit).
class UndoStack {
 public:
  static constexpr std::size_t kDefaultLimit = 200;

  explicit UndoStack(std::size_t limit = kDefaultLimit);

  // Records an edit: `before` is the state the edit started from. Drops all redo steps. With a
  // non-empty `mergeKey` equal to the top step's, and the top step not at the clean index, the
  // edit merges into the top step (a dragged slider makes one step).
  void push(std::string name, DocumentState before, std::string mergeKey = {});

  bool canUndo() const { return index_ > 0; }
  bool canRedo() const { return index_ < steps_.size(); }
  // Name of the step undo/redo would apply; empty if none.
  std::string undoText() const;
  std::string redoText() const;

  // Moves one step back/forward: `live` is the current state; it is kept in the step and the
  // state to show is returned. Throws InternalError if there is nothing to undo/redo.
  DocumentState undo(DocumentState live);
  DocumentState redo(DocumentState live);

  std::size_t count() const { return steps_.size(); }
  std::size_t index() const { return index_; }  // number of applied steps
  const std::string& text(std::size_t i) const { return steps_.at(i).name; }

  std::size_t limit() const { return limit_; }
  // At least 1; drops the oldest steps if needed.
  void setLimit(std::size_t limit);

  void setClean();
  bool isClean() const { return clean_ == static_cast<long long>(index_); }
  // Number of applied steps at the last save, or -1 when that state is no longer reachable.
  long long cleanIndex() const { return clean_; }

  // Forgets every step; the current state becomes the clean one.
  void clear();

 private:
  struct Step {
    std::string name;
    std::string mergeKey;
    DocumentState state;
  };
  void trimToLimit();

  std::vector<Step> steps_;
  std::size_t index_ = 0;
  long long clean_ = 0;
  std::size_t limit_;
};

}  // namespace spira
