#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include <QObject>
#include <QString>

#include "spira/document/document.h"
#include "spira/document/scan_record.h"

class QMainWindow;

namespace spira {
class PluginRegistry;
struct Trajectory;
}  // namespace spira

namespace spira::ui {

class ContinuationLayer;
class LogPanel;
class PairPicker;
class ScanPanel;
class SceneView;
class TaskRunner;
struct TaskOutcome;

// The scan loop in the window: a scan read, cleaned and aligned to the part (by the fit from where it
// lies, or from pairs of places picked on the part and on the scan), kept in the document as its file
// and alignment (so undo, save and open bring it back), shown coloured by its deviation with the
// histogram in the Scan dock, and the rest of a build re-planned from it and drawn over the plan.
class ScanWorkflow : public QObject {
  Q_OBJECT

 public:
  struct Parts {
    QMainWindow& window;
    Document& doc;
    const PluginRegistry& registry;
    SceneView& view;
    TaskRunner& tasks;
    LogPanel& log;
    std::function<void(const QString& title, const QString& message, const QString& hint)> reportError;
    std::function<bool()> busy;
    std::function<void()> layersChanged;     // the Display dock's boxes follow the scene's layers
    std::function<void(int)> showBuildUpTo;  // the spiral drawn up to this revolution (Display dock)
    bool interactive = true;
  };
  explicit ScanWorkflow(Parts parts, QObject* parent = nullptr);
  ~ScanWorkflow() override;

  ScanPanel* panel() const { return panel_; }
  PairPicker* picker() const { return picker_.get(); }
  ContinuationLayer& continuationLayer() { return *continuation_; }

  // Reads, cleans and aligns the scan in the background; on success the document keeps it (one undo
  // step). A scan the fit cannot place (far off the part) stays shown, grey, for Align by Points.
  bool compareFile(const QString& path);
  // Align by Points: starts picking, or (with three pairs or more picked) aligns from them.
  void alignByPoints();
  void cancelPicking();
  // Re-plans the rest of the document's plan from the scan of the wall after `at` points were laid.
  bool resumeFromScan(size_t at, double beadWidthMm);
  // Asks for the points laid and the bead width, then resumes (interactive windows).
  void chooseResume();
  void removeScan();
  bool hasComparison() const;
  bool hasLoadedScan() const { return loaded_ != nullptr; }

 signals:
  void compared(const QString& path, bool ok);
  void aligned(bool ok);
  void resumed(bool ok);

 private:
  struct Loaded;
  struct Shown;
  void onDocumentChanged(const ChangeSet& changes);
  void show();
  void reloadRecord();
  void alignFrom(const Transform& T_initial, const QString& how, double pairsRmsMm);
  void refreshResume();
  std::optional<Transform> shownTransform() const;

  Parts p_;
  ScanPanel* panel_ = nullptr;
  std::unique_ptr<PairPicker> picker_;
  std::unique_ptr<ContinuationLayer> continuation_;
  Document::SubscriptionId subscription_ = 0;
  std::shared_ptr<const Loaded> loaded_;                // the cleaned scan in its own frame
  std::shared_ptr<const Shown> shown_;                  // its comparison for a record
  std::shared_ptr<const Trajectory> continuationPlan_;  // the plan the continuation was made from
  bool reloadPending_ = false;
  bool unplaced_ = false;  // the view shows loaded_ where it lies, waiting for picked pairs
};

}  // namespace spira::ui
