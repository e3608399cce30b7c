#include "spira/document/undo_stack.h"

#include <algorithm>

#include "spira/base/error.h"

namespace spira {

UndoStack::UndoStack(std::size_t limit) : limit_(std::max<std::size_t>(limit, 1)) {}

void UndoStack::push(std::string name, DocumentState before, std::string mergeKey)
{
  if (clean_ > static_cast<long long>(index_)) clean_ = -1;  // the saved state was a redo step
  steps_.resize(index_);
  const bool merge = !mergeKey.empty() && index_ > 0 && steps_[index_ - 1].mergeKey == mergeKey && !isClean();
  if (merge) return;  // the top step already holds the state before the whole drag
  steps_.push_back(Step{std::move(name), std::move(mergeKey), std::move(before)});
  ++index_;
  trimToLimit();
}

std::string UndoStack::undoText() const
{
  return canUndo() ? steps_[index_ - 1].name : std::string();
}

std::string UndoStack::redoText() const
{
  return canRedo() ? steps_[index_].name : std::string();
}

DocumentState UndoStack::undo(DocumentState live)
{
  if (!canUndo()) throw InternalError("nothing to undo");
  --index_;
  std::swap(steps_[index_].state, live);
  return live;
}

DocumentState UndoStack::redo(DocumentState live)
{
  if (!canRedo()) throw InternalError("nothing to redo");
  std::swap(steps_[index_].state, live);
  ++index_;
  return live;
}

void UndoStack::setLimit(std::size_t limit)
{
  limit_ = std::max<std::size_t>(limit, 1);
  trimToLimit();
}

void UndoStack::trimToLimit()
{
  if (steps_.size() <= limit_) return;
  const std::size_t drop = steps_.size() - limit_;
  // The oldest undo steps go first; if that is not enough, the redo steps farthest away.
  const std::size_t front = std::min(drop, index_);
  steps_.erase(steps_.begin(), steps_.begin() + static_cast<std::ptrdiff_t>(front));
  index_ -= front;
  if (clean_ >= 0)
    clean_ = clean_ < static_cast<long long>(front) ? -1 : clean_ - static_cast<long long>(front);
  steps_.resize(limit_);
  if (clean_ > static_cast<long long>(steps_.size())) clean_ = -1;
}

void UndoStack::setClean()
{
  clean_ = static_cast<long long>(index_);
}

void UndoStack::clear()
{
  steps_.clear();
  index_ = 0;
  clean_ = 0;
}

}  // namespace spira
