#pragma once

#include <optional>

#include "spira/document/change_set.h"
#include "spira/document/document_state.h"

namespace spira {

// Which inputs differ between two states (results are compared too), as a ChangeSet without the
// UndoStack/Modified/FilePath flags.
ChangeSet diffStates(const DocumentState& before, const DocumentState& after);

// The first stage whose result an edit from `before` to `after` makes stale, or nullopt when the
// edit touches nothing a result depends on. The mapping is the table in invalidation.cpp.
// A task runner also uses it to decide whether a result computed on an older snapshot still
// applies: it does when the returned stage is later than the result's stage.
std::optional<Stage> firstInvalidatedStage(const DocumentState& before, const DocumentState& after);

}  // namespace spira
