#pragma once

#include <memory>
#include <optional>
#include <utility>

#include <vtkSmartPointer.h>
#include <QImage>
#include <QMainWindow>

#include "spira/document/document.h"
#include "spira/mesh/mesh_report.h"
#include "spira/ui/window/actions.h"

class QLabel;
class vtkPolyData;

namespace spira {
struct DocumentPlan;
class PluginRegistry;
}  // namespace spira

namespace spira::ui {

class DisplayPanel;
class DocumentTree;
class LogPanel;
class PlanPanel;
class ProcessChart;
class ExportDialog;
class CompareView;
class PathInspector;
class JointChart;
class ThermalPanel;
class CellWorkspace;
class ComfortFeatures;
class PointSelection;
class RecentFiles;
class ScanWorkflow;
class SceneView;
class TaskRunner;
struct TaskOutcome;

struct MainWindowOptions {
  // Restore and save the window layout in QSettings (off for screenshots and tests, whose
  // pictures must not depend on a user's saved layout).
  bool persistLayout = true;
  // Show message boxes and prompts. Off, errors only go to the messages panel and closing never
  // asks to save (batch screenshots, tests).
  bool interactive = true;
};

// Spira's main window: document tree, 3D view, messages, menus and toolbars. It shows the
// Document it is given and edits it only through the Document's API; every view is refreshed
// from the Document's change notifications, never from what the window itself just did.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  // `registry` (the plugins: importers, decomposers, exporters) must outlive the window.
  MainWindow(Document& doc, const PluginRegistry& registry, MainWindowOptions options = {},
             QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a project (.spira) or imports a part (any importer extension). Imports run on a worker
  // thread; fileOpened() reports the outcome either way.
  void openFile(const QString& path);
  void importPartFile(const QString& path);
  bool openProjectFile(const QString& path);
  // Save to the document's file (asks for one when it has none and the window is interactive).
  bool saveProject();
  bool saveProjectAs(const QString& path);

  // Plans the document's part with its settings on a worker thread; the window stays usable
  // and the Plan dock shows the progress. planFinished() reports the outcome.
  void plan();
  // Stops a running plan; the document keeps its previous results.
  void cancelPlan();
  bool planning() const { return planning_; }

  bool busy() const;
  // Runs the event loop until a running import has finished.
  void waitUntilIdle();
  // The whole window as it is on screen, 3D view included.
  QImage captureImage();
  // The last error shown, "message" and "hint" (empty when none yet).
  QString lastErrorMessage() const { return lastError_; }
  QString lastErrorHint() const { return lastHint_; }

  Document& document() { return doc_; }
  const Actions& actions() const { return actions_; }
  SceneView* sceneView() const { return view_; }
  DocumentTree* documentTree() const { return tree_; }
  LogPanel* logPanel() const { return log_; }
  PlanPanel* planPanel() const { return planPanel_; }
  DisplayPanel* displayPanel() const { return display_; }
  ProcessChart* processChart() const { return chart_; }
  QDockWidget* chartDock() const { return chartDock_; }
  TaskRunner* taskRunner() const { return tasks_; }
  RecentFiles* recentFiles() const { return recent_; }
  // Point selection, 3D marker, chart cursor and torch-frame glyphs (path_inspector.h).
  PathInspector* pathInspector() const { return inspector_; }
  // The selected path point, shared by the charts, the 3D view and the status bar.
  PointSelection* pointSelection() const { return selection_; }
  JointChart* jointChart() const { return jointChart_; }
  // The thermal stage's verdict, time slider and probe chart (hidden until a plan has thermal results).
  ThermalPanel* thermalPanel() const { return thermal_; }
  QDockWidget* jointDock() const { return jointDock_; }
  CellWorkspace* cellWorkspace() const { return cellWorkspace_; }
  // Placement, presets, themes, help and autosave (comfort_features.h).
  ComfortFeatures* comfortFeatures() const { return comfort_; }
  // Builds the part on the surface in `path` (a pipe, a curved plate, a previous part), one undo step.
  // The file is read in the background (progress and Cancel in the status bar); substrateRead() says
  // how it went, the error shown when it cannot be read. False when another task runs.
  bool useSubstrateFile(const QString& path);
  // Reads a scan of the part in the background, cleans it of stray points, aligns it to the part
  // (point-to-plane ICP) and shows it coloured by its deviation; scanCompared() says how it went, the
  // error shown when it cannot be read or aligned. False when there is no part or another task runs.
  bool compareScanFile(const QString& path);
  // The Scan dock, alignment by picked pairs and Resume from Scan.
  ScanWorkflow* scanWorkflow() const { return scan_; }
  // File > Export Robot Program (made on first use).
  ExportDialog* exportDialog();
  void showExportDialog();
  // Plan > Compare Strategies (made on first use).
  CompareView* compareView();
  void showCompareView();

 signals:
  void fileOpened(const QString& path, bool ok);
  void substrateRead(const QString& path, bool ok);
  void scanCompared(const QString& path, bool ok);
  void planFinished(const spira::ui::TaskOutcome& outcome);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  // Construction stages (the constructor makes the view and the docks, then calls these in order).
  void addChartDock();
  void addJointDock();
  void addThermalDock();
  void createActionsAndTasks();
  void createStatusBar();
  void createCellWorkspace();
  void installComfortFeatures();
  void installScanWorkflow();
  void restoreLayout();
  void connectActions();
  void onDocumentChanged(const ChangeSet& changes);
  void refreshScene(bool partChanged);
  void refreshResults();
  void finishPlan(const TaskOutcome& outcome, const DocumentState& snapshot, const DocumentPlan& result);
  void refreshTree();
  void refreshUndoActions();
  void refreshTitle();
  void refreshStatus();
  const MeshReport* partReport();
  void reportError(const QString& title, const QString& message, const QString& hint);
  bool maybeSave();
  void chooseImport();
  void chooseSubstrateMesh();
  void chooseScan();
  void chooseOpen();
  bool chooseSaveAs();
  void undo();
  void redo();
  void showAbout();
  QString dialogDirectory() const;
  void rememberDirectory(const QString& file);

  Document& doc_;
  const PluginRegistry& registry_;
  MainWindowOptions options_;
  Document::SubscriptionId subscription_ = 0;
  SceneView* view_ = nullptr;
  DocumentTree* tree_ = nullptr;
  QDockWidget* treeDock_ = nullptr;
  LogPanel* log_ = nullptr;
  PlanPanel* planPanel_ = nullptr;
  DisplayPanel* display_ = nullptr;
  ProcessChart* chart_ = nullptr;
  QDockWidget* chartDock_ = nullptr;
  bool planning_ = false;
  bool hadSpiral_ = false;
  Actions actions_;
  RecentFiles* recent_ = nullptr;
  TaskRunner* tasks_ = nullptr;
  PathInspector* inspector_ = nullptr;
  PointSelection* selection_ = nullptr;
  JointChart* jointChart_ = nullptr;
  QDockWidget* jointDock_ = nullptr;
  ThermalPanel* thermal_ = nullptr;
  bool hadThermal_ = false;
  CellWorkspace* cellWorkspace_ = nullptr;
  ComfortFeatures* comfort_ = nullptr;
  ScanWorkflow* scan_ = nullptr;
  ExportDialog* exportDialog_ = nullptr;
  CompareView* compareView_ = nullptr;
  QLabel* meshLabel_ = nullptr;
  QLabel* unitsLabel_ = nullptr;
  // Derived view data, keyed by the mesh it was computed from: the validation report is costly
  // on large meshes, so it is computed once per mesh (an import hands over its own).
  std::shared_ptr<const TriangleMesh> reportMesh_;
  std::optional<MeshReport> report_;
  std::shared_ptr<const Part> shownPart_;
  std::shared_ptr<const TriangleMesh> shownSubstrate_;  // the substrate mesh the view shows
  bool substrateShown_ = false;
  // The 3D view's surface of the last imported mesh, built by the import job (the mesh is
  // immutable, so it stays right for that mesh, also after an undo back to it).
  std::pair<std::shared_ptr<const TriangleMesh>, vtkSmartPointer<vtkPolyData>> preparedSurface_;
  QString lastError_;
  QString lastHint_;
};

}  // namespace spira::ui
