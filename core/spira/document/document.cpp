#include "spira/document/document.h"

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/document/invalidation.h"
#include "spira/document/project_file.h"

namespace spira {

namespace {

void requireNoTransaction(bool inTransaction, const char* what)
{
  if (inTransaction) throw InternalError(std::string(what) + " while a transaction is open");
}

// The Document always has a substrate and plan settings, so views never test for null.
void fillDefaults(DocumentState& s)
{
  if (!s.substrate) s.substrate = std::make_shared<const Substrate>();
  if (!s.settings) s.settings = std::make_shared<const PlanSettings>();
}

const void* resultPointer(const Results& r, Stage s)
{
  switch (s) {
    case Stage::Field:
      return r.field.get();
    case Stage::Generatrices:
      return r.generatrices.get();
    case Stage::Spiral:
      return r.spiral.get();
    case Stage::Process:
      return r.process.get();
    case Stage::Thermal:
      return r.thermal.get();
    case Stage::Kinematics:
      return r.kinematics.get();
    case Stage::Export:
      return r.exported.get();
  }
  return nullptr;
}

void resetResult(Results& r, Stage s)
{
  switch (s) {
    case Stage::Field:
      r.field.reset();
      break;
    case Stage::Generatrices:
      r.generatrices.reset();
      break;
    case Stage::Spiral:
      r.spiral.reset();
      break;
    case Stage::Process:
      r.process.reset();
      break;
    case Stage::Thermal:
      r.thermal.reset();
      break;
    case Stage::Kinematics:
      r.kinematics.reset();
      break;
    case Stage::Export:
      r.exported.reset();
      break;
  }
}

// Drops the results of stages `from` and later that are still those of `before`. Results stored
// during the edit (after the inputs changed, inside a transaction) were computed for the new
// inputs and stay; the Results setters already dropped the stages after them.
void dropStaleResults(Results& now, const Results& before, Stage from)
{
  for (int i = stageIndex(from); i < kStageCount; ++i) {
    const Stage s = stageAt(i);
    if (resultPointer(now, s) == resultPointer(before, s)) resetResult(now, s);
    if (now.reports.identical(s, before.reports)) now.reports.reset(s);
  }
}

}  // namespace

Document::Document() = default;

Document::Document(DocumentState initial) : state_(std::move(initial))
{
  fillDefaults(state_);
}

// --- Transactions ---

void Document::beginLevel(std::string name, std::string mergeKey)
{
  levels_.push_back(Level{std::move(name), std::move(mergeKey), state_});
}

void Document::commitLevel()
{
  Level level = std::move(levels_.back());
  levels_.pop_back();
  fillDefaults(state_);
  if (const auto stage = firstInvalidatedStage(level.before, state_))
    dropStaleResults(state_.results, level.before.results, *stage);
  if (!levels_.empty()) return;  // the outermost level makes the step

  ChangeSet changes = diffStates(level.before, state_);
  if (changes.empty()) {
    // Keep the original pointers: equal values, and cheaper comparisons later.
    state_ = std::move(level.before);
    return;
  }
  const bool wasModified = isModified();
  undo_.push(std::move(level.name), std::move(level.before), std::move(level.mergeKey));
  ++revision_;
  changes.add(Change::UndoStack);
  if (wasModified != isModified()) changes.add(Change::Modified);
  notify(changes);
}

void Document::rollbackLevel()
{
  state_ = std::move(levels_.back().before);
  levels_.pop_back();
}

void Document::edit(const std::string& name, const std::function<void(DocumentState&)>& fn,
                    const std::string& mergeKey)
{
  beginLevel(name, mergeKey);
  try {
    fn(state_);
  } catch (...) {
    rollbackLevel();
    throw;
  }
  commitLevel();
}

Document::Transaction::Transaction(Document& doc, std::string name, std::string mergeKey) : doc_(doc)
{
  doc_.beginLevel(std::move(name), std::move(mergeKey));
}

Document::Transaction::~Transaction()
{
  if (open_) doc_.rollbackLevel();
}

void Document::Transaction::commit()
{
  if (!open_) throw InternalError("transaction committed twice");
  open_ = false;
  doc_.commitLevel();
}

DocumentState& Document::Transaction::state()
{
  return doc_.state_;
}

// --- Typed edits ---

void Document::setPart(Part part, const std::string& name)
{
  edit(name, [&](DocumentState& s) { s.part = std::make_shared<const Part>(std::move(part)); });
}

void Document::clearPart(const std::string& name)
{
  edit(name, [](DocumentState& s) { s.part.reset(); });
}

void Document::setPartPlacement(const Transform& T_world_part, const std::string& name,
                                const std::string& mergeKey)
{
  if (!state_.part) throw InputError("there is no part to place", "import a part first");
  edit(
      name,
      [&](DocumentState& s) {
        Part p = *s.part;
        p.T_world_part = T_world_part;
        s.part = std::make_shared<const Part>(std::move(p));
      },
      mergeKey);
}

void Document::setLowerBoundaryOverride(int loopIndex, const std::string& name)
{
  if (!state_.part)
    throw InputError("there is no part whose lower boundary could be chosen", "import a part first");
  if (loopIndex < Part::kAutomaticLowerBoundary)
    throw InputError("invalid lower boundary index " + std::to_string(loopIndex),
                     "choose one of the part's boundary loops, or automatic");
  edit(name, [&](DocumentState& s) {
    Part p = *s.part;
    p.lowerBoundaryOverride = loopIndex;
    s.part = std::make_shared<const Part>(std::move(p));
  });
}

void Document::setSubstrate(Substrate substrate, const std::string& name)
{
  edit(name,
       [&](DocumentState& s) { s.substrate = std::make_shared<const Substrate>(std::move(substrate)); });
}

void Document::setScan(ScanRecord scan, const std::string& name)
{
  edit(name, [&](DocumentState& s) { s.scan = std::make_shared<const ScanRecord>(std::move(scan)); });
}

void Document::clearScan(const std::string& name)
{
  edit(name, [](DocumentState& s) { s.scan.reset(); });
}

void Document::setCell(CellRecord cell, const std::string& name)
{
  edit(name, [&](DocumentState& s) { s.cell = std::make_shared<const CellRecord>(std::move(cell)); });
}

void Document::clearCell(const std::string& name)
{
  edit(name, [](DocumentState& s) { s.cell.reset(); });
}

void Document::setPlanSettings(PlanSettings settings, const std::string& name)
{
  edit(name,
       [&](DocumentState& s) { s.settings = std::make_shared<const PlanSettings>(std::move(settings)); });
}

void Document::setDecomposer(const std::string& pluginId, const std::string& name)
{
  PlanSettings s = *state_.settings;
  s.decomposerId = pluginId;
  setPlanSettings(std::move(s), name);
}

void Document::setClosureFinder(const std::string& pluginId, const std::string& name)
{
  PlanSettings s = *state_.settings;
  s.closureFinderId = pluginId;
  setPlanSettings(std::move(s), name);
}

void Document::setPluginParams(const std::string& section, ParamSet values, const std::string& name)
{
  PlanSettings s = *state_.settings;
  s.params[section] = std::move(values);
  setPlanSettings(std::move(s), name.empty() ? "Change " + section + " parameters" : name);
}

void Document::setParam(const std::string& section, const std::string& key, ParamValue value,
                        const std::string& name)
{
  PlanSettings settings = *state_.settings;
  settings.params[section].set(key, std::move(value));
  edit(
      name.empty() ? "Change " + key : name,
      [&](DocumentState& s) { s.settings = std::make_shared<const PlanSettings>(std::move(settings)); },
      "param:" + section + "/" + key);
}

// --- Results ---

void Document::changeResults(const std::function<void(Results&)>& fn)
{
  if (inTransaction()) {
    fn(state_.results);  // part of the open transaction's step
    return;
  }
  const Results before = state_.results;
  fn(state_.results);
  ChangeSet changes;
  changes.stages = before.differingStages(state_.results);
  if (!changes.stages) return;
  changes.add(Change::Results);
  ++revision_;
  notify(changes);
}

void Document::setResults(Results results)
{
  changeResults([&](Results& r) { r = std::move(results); });
}

void Document::setField(std::shared_ptr<const FieldResult> r, std::shared_ptr<const FieldStageReport> report)
{
  changeResults([&](Results& res) { res.setField(std::move(r), std::move(report)); });
}

void Document::setGeneratrices(std::shared_ptr<const Generatrices> r,
                               std::shared_ptr<const GeneratricesStageReport> report)
{
  changeResults([&](Results& res) { res.setGeneratrices(std::move(r), std::move(report)); });
}

void Document::setSpiral(std::shared_ptr<const Trajectory> r, std::shared_ptr<const SpiralStageReport> report)
{
  changeResults([&](Results& res) { res.setSpiral(std::move(r), std::move(report)); });
}

void Document::setProcess(std::shared_ptr<const Trajectory> r,
                          std::shared_ptr<const ProcessStageReport> report)
{
  changeResults([&](Results& res) { res.setProcess(std::move(r), std::move(report)); });
}

void Document::setKinematics(std::shared_ptr<const KinematicsResult> r,
                             std::shared_ptr<const KinematicsStageReport> report)
{
  changeResults([&](Results& res) { res.setKinematics(std::move(r), std::move(report)); });
}

void Document::setExport(std::shared_ptr<const ExportStageResult> r)
{
  changeResults([&](Results& res) { res.setExport(std::move(r)); });
}

void Document::invalidateFrom(Stage s)
{
  changeResults([&](Results& res) { res.invalidateFrom(s); });
}

// --- Undo ---

void Document::undo()
{
  requireNoTransaction(inTransaction(), "undo");
  const bool wasModified = isModified();
  DocumentState restored = undo_.undo(state_);
  ChangeSet changes = diffStates(state_, restored);
  state_ = std::move(restored);
  ++revision_;
  changes.add(Change::UndoStack);
  if (wasModified != isModified()) changes.add(Change::Modified);
  notify(changes);
}

void Document::redo()
{
  requireNoTransaction(inTransaction(), "redo");
  const bool wasModified = isModified();
  DocumentState restored = undo_.redo(state_);
  ChangeSet changes = diffStates(state_, restored);
  state_ = std::move(restored);
  ++revision_;
  changes.add(Change::UndoStack);
  if (wasModified != isModified()) changes.add(Change::Modified);
  notify(changes);
}

void Document::setUndoLimit(std::size_t limit)
{
  const bool wasModified = isModified();
  undo_.setLimit(limit);
  ChangeSet changes;
  changes.add(Change::UndoStack);
  if (wasModified != isModified()) changes.add(Change::Modified);
  notify(changes);
}

// --- File ---

void Document::markSaved()
{
  const bool wasModified = isModified();
  undo_.setClean();
  if (wasModified) {
    ChangeSet changes;
    changes.add(Change::Modified);
    notify(changes);
  }
}

void Document::save()
{
  if (filePath_.empty()) throw InputError("the project has no file name yet", "use Save As to choose one");
  saveAs(filePath_);
}

void Document::saveAs(const std::filesystem::path& path)
{
  requireNoTransaction(inTransaction(), "save");
  saveProject(state_, path);
  ChangeSet changes;
  if (path != filePath_) changes.add(Change::FilePath);
  if (isModified()) changes.add(Change::Modified);
  filePath_ = path;
  undo_.setClean();
  if (!changes.empty()) notify(changes);
}

void Document::open(const std::filesystem::path& path)
{
  requireNoTransaction(inTransaction(), "open");
  replaceAll(loadProject(path), path);
}

void Document::reset()
{
  requireNoTransaction(inTransaction(), "new document");
  replaceAll(DocumentState(), {});
}

void Document::replaceAll(DocumentState state, std::filesystem::path path)
{
  fillDefaults(state);
  ChangeSet changes = diffStates(state_, state);
  // Views rebuild everything on a new document, so every flag is set.
  for (std::uint32_t bit = 1; bit <= static_cast<std::uint32_t>(Change::FilePath); bit <<= 1)
    changes.flags |= bit;
  changes.stages = kAllStages;
  changes.strategyChanged = true;
  for (const auto& [section, values] : state.settings->params) changes.sections.insert(section);
  state_ = std::move(state);
  filePath_ = std::move(path);
  undo_.clear();
  ++revision_;
  notify(changes);
}

// --- Notifications ---

Document::SubscriptionId Document::subscribe(Callback callback)
{
  const SubscriptionId id = nextSubscription_++;
  subscribers_.emplace(id, std::move(callback));
  return id;
}

void Document::unsubscribe(SubscriptionId id)
{
  subscribers_.erase(id);
}

void Document::notify(const ChangeSet& changes)
{
  std::vector<SubscriptionId> ids;
  ids.reserve(subscribers_.size());
  for (const auto& entry : subscribers_) ids.push_back(entry.first);
  for (SubscriptionId id : ids) {
    auto it = subscribers_.find(id);
    if (it == subscribers_.end()) continue;  // unsubscribed by an earlier callback
    const Callback callback = it->second;    // a copy: the callback may unsubscribe itself
    callback(changes);
  }
}

}  // namespace spira
