#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "spira/document/change_set.h"
#include "spira/document/document_state.h"
#include "spira/document/undo_stack.h"

namespace spira {

// Owns the current DocumentState, the undo stack, the file path and the change subscribers.
//
// User edits are named transactions: each makes one undo step, nested edits merge into the
// outermost one, an edit that changes nothing makes no step and no notification. After an edit
// the results it made stale are dropped (table in invalidation.cpp); results stored inside a
// transaction after its input edits are kept, being computed for the new inputs.
// Results stored by the computation (setResults...) are not undo steps and do not mark the
// document modified, but undo restores whole snapshots, results included.
//
// Not thread-safe: use it from one thread (the GUI thread); callbacks run on that thread, after
// the state is updated. Workers take snapshot() and hand results back to that thread.
class Document {
 public:
  using Callback = std::function<void(const ChangeSet&)>;
  using SubscriptionId = std::uint64_t;

  Document();
  explicit Document(DocumentState initial);
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  // --- State ---
  const DocumentState& state() const { return state_; }
  DocumentState snapshot() const { return state_; }
  const std::shared_ptr<const Part>& part() const { return state_.part; }
  const std::shared_ptr<const Substrate>& substrate() const { return state_.substrate; }
  const std::shared_ptr<const CellRecord>& cell() const { return state_.cell; }
  const std::shared_ptr<const PlanSettings>& settings() const { return state_.settings; }
  const std::shared_ptr<const ScanRecord>& scan() const { return state_.scan; }
  const Results& results() const { return state_.results; }
  // Increases on every change of the state (edits, undo/redo, results, open).
  std::uint64_t revision() const { return revision_; }

  // --- User edits (each one undo step, named for the Edit menu) ---
  // Runs `fn` on the live state as one step. If `fn` throws, the state is restored and the
  // exception propagates. `mergeKey`: see UndoStack::push.
  void edit(const std::string& name, const std::function<void(DocumentState&)>& fn,
            const std::string& mergeKey = {});

  void setPart(Part part, const std::string& name = "Import part");
  void clearPart(const std::string& name = "Remove part");
  void setPartPlacement(const Transform& T_world_part, const std::string& name = "Move part",
                        const std::string& mergeKey = {});
  void setLowerBoundaryOverride(int loopIndex, const std::string& name = "Choose lower boundary");
  void setSubstrate(Substrate substrate, const std::string& name = "Change substrate");
  void setCell(CellRecord cell, const std::string& name = "Change cell");
  void clearCell(const std::string& name = "Remove cell");
  void setScan(ScanRecord scan, const std::string& name = "Compare scan");
  void clearScan(const std::string& name = "Remove scan");
  void setPlanSettings(PlanSettings settings, const std::string& name = "Change plan settings");
  void setDecomposer(const std::string& pluginId, const std::string& name = "Choose decomposer");
  void setClosureFinder(const std::string& pluginId, const std::string& name = "Choose closure finder");
  // Replaces the values of one section; the default name is "Change <section> parameters".
  void setPluginParams(const std::string& section, ParamSet values, const std::string& name = {});
  // Sets one value; merges with the previous edit of the same key (slider drags); the default
  // name is "Change <key>".
  void setParam(const std::string& section, const std::string& key, ParamValue value,
                const std::string& name = {});

  // Groups edits into one undo step: everything done through the Document between construction
  // and commit() is one step named `name`. Destroyed without commit(), it rolls the edits back.
  // Transactions nest; inner ones merge into the outer one.
  class Transaction {
   public:
    Transaction(Document& doc, std::string name, std::string mergeKey = {});
    ~Transaction();
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    void commit();
    // The live state, for edits not covered by the setters.
    DocumentState& state();

   private:
    Document& doc_;
    bool open_ = true;
  };

  // --- Results (not undo steps) ---
  void setResults(Results results);
  void setField(std::shared_ptr<const FieldResult> r, std::shared_ptr<const FieldStageReport> report = {});
  void setGeneratrices(std::shared_ptr<const Generatrices> r,
                       std::shared_ptr<const GeneratricesStageReport> report = {});
  void setSpiral(std::shared_ptr<const Trajectory> r, std::shared_ptr<const SpiralStageReport> report = {});
  void setProcess(std::shared_ptr<const Trajectory> r, std::shared_ptr<const ProcessStageReport> report = {});
  void setKinematics(std::shared_ptr<const KinematicsResult> r,
                     std::shared_ptr<const KinematicsStageReport> report = {});
  void setExport(std::shared_ptr<const ExportStageResult> r);
  void invalidateFrom(Stage s);
  void clearResults() { invalidateFrom(Stage::Field); }

  // --- Undo ---
  const UndoStack& undoStack() const { return undo_; }
  bool canUndo() const { return undo_.canUndo() && !inTransaction(); }
  bool canRedo() const { return undo_.canRedo() && !inTransaction(); }
  // Throw InternalError inside a transaction or with nothing to undo/redo.
  void undo();
  void redo();
  void setUndoLimit(std::size_t limit);
  bool inTransaction() const { return !levels_.empty(); }

  // --- File ---
  bool isModified() const { return !undo_.isClean(); }
  void markSaved();
  const std::filesystem::path& filePath() const { return filePath_; }
  // Writes to filePath(); throws InputError when the document has no file yet (use saveAs).
  void save();
  // Writes the project and, on success, makes `path` the document's file and marks it clean.
  void saveAs(const std::filesystem::path& path);
  // Loads `path`; on success replaces the state, clears the undo stack and marks clean. On any
  // error (thrown) the document is unchanged.
  void open(const std::filesystem::path& path);
  // An empty, clean document with no file.
  void reset();

  // --- Notifications ---
  // Callbacks must not throw. They may edit the document (nested notifications follow) and may
  // unsubscribe, themselves included.
  SubscriptionId subscribe(Callback callback);
  void unsubscribe(SubscriptionId id);

 private:
  struct Level {
    std::string name;
    std::string mergeKey;
    DocumentState before;
  };
  void beginLevel(std::string name, std::string mergeKey);
  void commitLevel();
  void rollbackLevel();
  void changeResults(const std::function<void(Results&)>& fn);
  void replaceAll(DocumentState state, std::filesystem::path path);
  void notify(const ChangeSet& changes);

  DocumentState state_;
  UndoStack undo_;
  std::vector<Level> levels_;
  std::filesystem::path filePath_;
  std::uint64_t revision_ = 0;
  std::map<SubscriptionId, Callback> subscribers_;
  SubscriptionId nextSubscription_ = 1;
};

}  // namespace spira
