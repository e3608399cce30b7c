#include "spira/ui/window/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>

#include <vtkPolyData.h>
#include <vtkVersion.h>

#include "spira/base/version.h"
#include "spira/ui/charts/joint_chart.h"
#include "spira/ui/charts/process_chart.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/document_tree.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/placement_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/simulation_panel.h"
#include "spira/ui/panels/stage_progress.h"
#include "spira/ui/panels/thermal_panel.h"
#include "spira/ui/views/cell_workspace.h"
#include "spira/ui/views/interactive_quality.h"
#include "spira/ui/views/path_inspector.h"
#include "spira/ui/views/point_selection.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/application.h"
#include "spira/ui/window/comfort_features.h"
#include "spira/ui/window/help_dialogs.h"
#include "spira/ui/window/recent_files.h"

namespace spira::ui {

namespace {

const char* const kGeometryKey = "mainWindow/geometry";
const char* const kStateKey = "mainWindow/state";
const char* const kEdgesKey = "view/showEdges";
const char* const kBoundingBoxKey = "view/showBoundingBox";

}  // namespace

MainWindow::MainWindow(Document& doc, const PluginRegistry& registry, MainWindowOptions options,
                       QWidget* parent)
    : QMainWindow(parent), doc_(doc), registry_(registry), options_(options)
{
  initResources();
  setObjectName("mainWindow");
  setWindowIcon(QIcon(":/spira/icons/spira.svg"));
  setAcceptDrops(true);
  setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);

  view_ = new SceneView(this);
  view_->setObjectName("sceneView");
  setCentralWidget(view_);

  tree_ = new DocumentTree(this);
  treeDock_ = new QDockWidget(tr("Document"), this);
  treeDock_->setObjectName("documentDock");
  treeDock_->setWidget(tree_);
  addDockWidget(Qt::LeftDockWidgetArea, treeDock_);

  log_ = new LogPanel(this);
  addDockWidget(Qt::BottomDockWidgetArea, log_);
  chart_ = new ProcessChart(this);
  addChartDock();
  selection_ = new PointSelection(this);
  jointChart_ = new JointChart(selection_, this);
  addJointDock();
  addThermalDock();

  planPanel_ = new PlanPanel(doc_, registry_, this);
  addDockWidget(Qt::RightDockWidgetArea, planPanel_);
  display_ = new DisplayPanel(view_, chart_, chartDock_->toggleViewAction(), this);
  addDockWidget(Qt::LeftDockWidgetArea, display_);
  tabifyDockWidget(treeDock_, display_);
  treeDock_->raise();

  createActionsAndTasks();
  createStatusBar();
  createCellWorkspace();
  connectActions();
  // Placement dock, presets, themes, help, autosave: before the layout is restored, which includes its dock.
  installComfortFeatures();
  installScanWorkflow();
  restoreLayout();

  subscription_ = doc_.subscribe([this](const ChangeSet& c) { onDocumentChanged(c); });
  ChangeSet all;
  all.flags = ~0u;
  onDocumentChanged(all);
  log_->info(tr("Spira %1 ready.").arg(QString::fromUtf8(kVersion)));
}

void MainWindow::addChartDock()
{
  chartDock_ = new QDockWidget(tr("Process Chart"), this);
  chartDock_->setObjectName("chartDock");
  chartDock_->setWidget(chart_);
  addDockWidget(Qt::BottomDockWidgetArea, chartDock_);
  tabifyDockWidget(log_, chartDock_);
  chartDock_->hide();
  QAction* chartToggle = chartDock_->toggleViewAction();
  chartToggle->setText(tr("Process &Chart"));
  chartToggle->setToolTip(tr("Deposit height, travel speed and wire feed along the path"));
  chartToggle->setShortcut(QKeySequence(Qt::Key_C));
  // Shown, the chart comes to the front of its tab group with room for its three rows.
  connect(chartToggle, &QAction::toggled, this, [this](bool on) {
    if (!on) return;
    // After the dock layout has placed the newly shown dock in its tab group.
    QTimer::singleShot(0, this, [this] {
      chartDock_->raise();
      if (chartDock_->height() < 280) resizeDocks({chartDock_}, {300}, Qt::Vertical);
    });
  });
}

void MainWindow::addJointDock()
{
  jointDock_ = new QDockWidget(tr("Joint Chart"), this);
  jointDock_->setObjectName("jointDock");
  jointDock_->setWidget(jointChart_);
  addDockWidget(Qt::BottomDockWidgetArea, jointDock_);
  tabifyDockWidget(log_, jointDock_);
  jointDock_->hide();
  QAction* jointToggle = jointDock_->toggleViewAction();
  jointToggle->setText(tr("&Joint Chart"));
  jointToggle->setToolTip(tr("The robot's and positioner's axes along the path, with their limits"));
  jointToggle->setShortcut(QKeySequence(Qt::Key_J));
  connect(jointToggle, &QAction::toggled, this, [this](bool on) {
    if (!on) return;
    QTimer::singleShot(0, this, [this] {
      jointDock_->raise();
      if (jointDock_->height() < 330) resizeDocks({jointDock_}, {340}, Qt::Vertical);
    });
  });
}

void MainWindow::addThermalDock()
{
  thermal_ = new ThermalPanel(*view_, this);
  addDockWidget(Qt::BottomDockWidgetArea, thermal_);
  tabifyDockWidget(log_, thermal_);
  thermal_->hide();
  QAction* toggle = thermal_->toggleViewAction();
  toggle->setText(tr("&Thermal"));
  toggle->setToolTip(tr("The heat of the build: temperatures over time, collapse risk, probe chart"));
  connect(selection_, &PointSelection::changed, thermal_, &ThermalPanel::setPoint);
  connect(toggle, &QAction::toggled, this, [this](bool on) {
    if (!on) return;
    QTimer::singleShot(0, this, [this] {
      thermal_->raise();
      if (thermal_->height() < 300) resizeDocks({thermal_}, {320}, Qt::Vertical);
    });
  });
}

void MainWindow::createActionsAndTasks()
{
  QAction* chartToggle = chartDock_->toggleViewAction();
  QAction* jointToggle = jointDock_->toggleViewAction();
  actions_ = Actions::create(
      this, {treeDock_->toggleViewAction(), display_->toggleViewAction(), planPanel_->toggleViewAction(),
             log_->toggleViewAction(), chartToggle, jointToggle});
  planPanel_->setPlanAction(actions_.plan);
  // The bottom strip (messages, or the chart with its long abscissa) spans the whole width.
  setCorner(Qt::BottomLeftCorner, Qt::BottomDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);
  resizeDocks({treeDock_, planPanel_}, {320, 370}, Qt::Horizontal);
  resizeDocks({log_}, {150}, Qt::Vertical);
  recent_ = new RecentFiles(actions_.recentMenu, this);
  tasks_ = new TaskRunner(this, this);
  connect(tasks_, &TaskRunner::progressed, this, [this](double fraction, const QString& stage) {
    if (planning_) planPanel_->progress()->setProgress(fraction, stage);
  });
  connect(planPanel_->progress(), &StageProgress::cancelRequested, this, &MainWindow::cancelPlan);
}

void MainWindow::createStatusBar()
{
  meshLabel_ = new QLabel(this);
  unitsLabel_ = new QLabel(tr("Units: mm"), this);
  unitsLabel_->setToolTip(tr("Lengths are shown and stored in millimetres"));
  statusBar()->addPermanentWidget(meshLabel_);
  statusBar()->addPermanentWidget(unitsLabel_);
  inspector_ = new PathInspector(selection_, view_, chart_, log_, statusBar(), this);
}

void MainWindow::createCellWorkspace()
{
  // Made once the window's own docks are laid out, so the cell's docks take their room from the
  // plan's column and not from the 3D view.
  cellWorkspace_ = new CellWorkspace(*this, *planPanel_, doc_, *view_, *log_);
  QAction* cellToggle = cellWorkspace_->cellDock()->toggleViewAction();
  cellToggle->setText(tr("C&ell"));
  cellToggle->setToolTip(tr("The robot cell: robot, torch, positioner and where the part sits"));
  QAction* simulationToggle = cellWorkspace_->simulationDock()->toggleViewAction();
  simulationToggle->setText(tr("&Simulation"));
  simulationToggle->setToolTip(tr("Play the planned motion on the cell"));
  for (QWidget* w : actions_.viewIso->associatedWidgets())
    if (auto* viewMenu = qobject_cast<QMenu*>(w))
      viewMenu->insertActions(log_->toggleViewAction(),
                              {cellToggle, simulationToggle, thermal_->toggleViewAction()});
  // Playing the motion moves the temperatures shown on the part along with the torch.
  connect(thermal_, &ThermalPanel::partStyleChanged, display_, &DisplayPanel::resultsChanged);
  connect(cellWorkspace_->simulationPanel(), &SimulationPanel::indexChanged, thermal_,
          [this](int i) { thermal_->setTimeOfPoint(i); });
  // A point picked on a chart or in 3D also poses the robot there, once the plan's motion is solved.
  connect(selection_, &PointSelection::changed, this, [this](long long i) {
    SimulationPanel* sim = cellWorkspace_->simulationPanel();
    if (i >= 0 && sim->hasMotion() && !sim->playing()) sim->setIndex(static_cast<size_t>(i));
  });
  connect(display_, &DisplayPanel::framesToggled, inspector_, &PathInspector::setFramesVisible);
}

void MainWindow::installComfortFeatures()
{
  const WindowParts parts{*this,
                          doc_,
                          actions_,
                          *view_,
                          *treeDock_,
                          *display_,
                          *planPanel_,
                          *log_,
                          *tasks_,
                          *cellWorkspace_->simulationPanel(),
                          [this](const QString& path) { openFile(path); },
                          [this] { plan(); },
                          [this] { return busy(); }};
  comfort_ = new ComfortFeatures(parts, options_.persistLayout, options_.interactive);
  connect(this, &MainWindow::fileOpened, comfort_, &ComfortFeatures::fileOpened);
  connect(this, &MainWindow::planFinished, comfort_, &ComfortFeatures::planFinished);
  connect(comfort_->placementPanel(), &PlacementPanel::substrateMeshRequested, this,
          [this] { chooseSubstrateMesh(); });
}

void MainWindow::restoreLayout()
{
  if (options_.persistLayout) {
    QSettings settings;
    restoreGeometry(settings.value(kGeometryKey).toByteArray());
    restoreState(settings.value(kStateKey).toByteArray());
    actions_.showEdges->setChecked(settings.value(kEdgesKey, false).toBool());
    actions_.showBoundingBox->setChecked(settings.value(kBoundingBoxKey, false).toBool());
  }
  view_->setEdgesVisible(actions_.showEdges->isChecked());
  view_->setBoundingBoxVisible(actions_.showBoundingBox->isChecked());
}

MainWindow::~MainWindow()
{
  doc_.unsubscribe(subscription_);
  // The worker may still be reading a file; TaskRunner's destructor cancels and joins it.
  delete tasks_;
  tasks_ = nullptr;
}

void MainWindow::connectActions()
{
  const Actions& a = actions_;
  connect(a.importPart, &QAction::triggered, this, &MainWindow::chooseImport);
  connect(a.compareScan, &QAction::triggered, this, &MainWindow::chooseScan);
  connect(a.openProject, &QAction::triggered, this, &MainWindow::chooseOpen);
  connect(a.save, &QAction::triggered, this, &MainWindow::saveProject);
  connect(a.saveAs, &QAction::triggered, this, &MainWindow::chooseSaveAs);
  connect(a.quit, &QAction::triggered, this, &QWidget::close);
  connect(a.undo, &QAction::triggered, this, &MainWindow::undo);
  connect(a.redo, &QAction::triggered, this, &MainWindow::redo);
  connect(a.showEdges, &QAction::toggled, view_, &SceneView::setEdgesVisible);
  connect(a.showBoundingBox, &QAction::toggled, view_, &SceneView::setBoundingBoxVisible);
  connect(a.showSubstrate, &QAction::toggled, this, [this] { refreshScene(false); });
  connect(a.viewIso, &QAction::triggered, this, [this] { view_->setCameraPreset(CameraPreset::Iso); });
  connect(a.viewFront, &QAction::triggered, this, [this] { view_->setCameraPreset(CameraPreset::Front); });
  connect(a.viewTop, &QAction::triggered, this, [this] { view_->setCameraPreset(CameraPreset::Top); });
  connect(a.viewSide, &QAction::triggered, this, [this] { view_->setCameraPreset(CameraPreset::Side); });
  connect(a.fitView, &QAction::triggered, view_, &SceneView::fitView);
  connect(a.plan, &QAction::triggered, this, &MainWindow::plan);
  connect(a.cancelPlan, &QAction::triggered, this, &MainWindow::cancelPlan);
  connect(a.exportProgram, &QAction::triggered, this, &MainWindow::showExportDialog);
  connect(a.compareStrategies, &QAction::triggered, this, &MainWindow::showCompareView);
  connect(a.about, &QAction::triggered, this, &MainWindow::showAbout);
  connect(a.aboutQt, &QAction::triggered, qApp, &QApplication::aboutQt);
  connect(recent_, &RecentFiles::openRequested, this, [this](const QString& path) {
    if (QFileInfo(path).suffix().compare("spira", Qt::CaseInsensitive) == 0 && !maybeSave()) return;
    openFile(path);
  });
}

void MainWindow::onDocumentChanged(const ChangeSet& changes)
{
  const bool part = changes.has(Change::Part);
  if (part || changes.has(Change::Substrate)) refreshScene(part);
  if (part || changes.has(Change::Results)) refreshResults();
  if (part || changes.has(Change::Substrate) || changes.has(Change::Cell) || changes.has(Change::Settings) ||
      changes.has(Change::Results) || changes.has(Change::Scan)) {
    refreshTree();
  }
  if (part) refreshStatus();
  if (changes.has(Change::UndoStack)) refreshUndoActions();
  if (changes.has(Change::Modified) || changes.has(Change::FilePath)) refreshTitle();
}

const MeshReport* MainWindow::partReport()
{
  const auto& part = doc_.part();
  if (!part || !part->mesh) return nullptr;
  if (part->mesh != reportMesh_ || !report_) {
    report_ = validateMesh(*part->mesh);
    reportMesh_ = part->mesh;
  }
  return &*report_;
}

void MainWindow::refreshScene(bool partChanged)
{
  const std::shared_ptr<const Part>& part = doc_.part();
  // Re-upload the mesh only when the part value changed: undoing a substrate edit keeps it.
  if (partChanged && part != shownPart_) {
    shownPart_ = part;
    if (!part || !part->mesh) {
      view_->showPart(nullptr);
    } else if (part->T_world_part.isApprox(Transform::Identity())) {
      const bool prepared = preparedSurface_.first == part->mesh;
      view_->showPart(part->mesh.get(), prepared ? preparedSurface_.second : nullptr);
    } else {
      const TriangleMesh placed = part->mesh->transformed(part->T_world_part);
      view_->showPart(&placed);
    }
  }
  const Substrate& s = *doc_.substrate();
  const bool shown = actions_.showSubstrate->isChecked();
  const bool plate = shown && s.kind == Substrate::Kind::Plane;
  view_->showSubstrate(plate ? std::optional<double>(s.planeZ) : std::nullopt);
  if (s.mesh != shownSubstrate_ || shown != substrateShown_) {
    shownSubstrate_ = s.mesh;
    substrateShown_ = shown;
    view_->showSubstrateMesh(shown && s.kind == Substrate::Kind::Mesh ? s.mesh.get() : nullptr);
  }
}

void MainWindow::refreshTree()
{
  tree_->refresh(doc_, partReport());
}

void MainWindow::refreshUndoActions()
{
  const UndoStack& stack = doc_.undoStack();
  const QString undoName = QString::fromStdString(stack.undoText());
  const QString redoName = QString::fromStdString(stack.redoText());
  actions_.undo->setEnabled(doc_.canUndo());
  actions_.redo->setEnabled(doc_.canRedo());
  actions_.undo->setText(doc_.canUndo() ? tr("&Undo %1").arg(undoName) : tr("&Undo"));
  actions_.redo->setText(doc_.canRedo() ? tr("&Redo %1").arg(redoName) : tr("&Redo"));
  // Toolbar buttons stay short; the tooltip names the step.
  actions_.undo->setIconText(tr("Undo"));
  actions_.redo->setIconText(tr("Redo"));
  actions_.undo->setToolTip(doc_.canUndo() ? tr("Undo %1").arg(undoName) : tr("Nothing to undo"));
  actions_.redo->setToolTip(doc_.canRedo() ? tr("Redo %1").arg(redoName) : tr("Nothing to redo"));
}

void MainWindow::refreshTitle()
{
  const std::filesystem::path& file = doc_.filePath();
  const QString name = file.empty() ? tr("Untitled") : QString::fromStdString(file.filename().string());
  // Qt appends the application display name ("Spira") where the platform shows it.
  setWindowTitle(QStringLiteral("%1[*]").arg(name));
  setWindowModified(doc_.isModified());
}

void MainWindow::refreshStatus()
{
  const auto& part = doc_.part();
  if (!part || !part->mesh) {
    meshLabel_->setText(tr("No part"));
    return;
  }
  const QLocale loc;
  meshLabel_->setText(tr("Vertices: %1   Triangles: %2")
                          .arg(loc.toString(static_cast<qulonglong>(part->mesh->vertexCount())),
                               loc.toString(static_cast<qulonglong>(part->mesh->faceCount()))));
}

void MainWindow::reportError(const QString& title, const QString& message, const QString& hint)
{
  lastError_ = message;
  lastHint_ = hint;
  log_->error(message, hint);
  if (!options_.interactive) return;
  QMessageBox box(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
  if (!hint.isEmpty()) box.setInformativeText(hint);
  box.exec();
}

void MainWindow::undo()
{
  if (!doc_.canUndo()) return;
  const QString name = QString::fromStdString(doc_.undoStack().undoText());
  doc_.undo();
  log_->info(tr("Undid %1.").arg(name));
}

void MainWindow::redo()
{
  if (!doc_.canRedo()) return;
  const QString name = QString::fromStdString(doc_.undoStack().redoText());
  doc_.redo();
  log_->info(tr("Redid %1.").arg(name));
}

bool MainWindow::maybeSave()
{
  if (!doc_.isModified() || !options_.interactive) return true;
  const auto answer = QMessageBox::warning(
      this, tr("Unsaved changes"), tr("The project has unsaved changes. Save them first?"),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Save) return saveProject();
  return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
  if (busy()) tasks_->cancel();
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  if (options_.persistLayout) {
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    settings.setValue(kEdgesKey, actions_.showEdges->isChecked());
    settings.setValue(kBoundingBoxKey, actions_.showBoundingBox->isChecked());
  }
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
  if (event->mimeData()->hasUrls() && event->mimeData()->urls().size() == 1 &&
      event->mimeData()->urls().first().isLocalFile()) {
    event->acceptProposedAction();
  }
}

void MainWindow::dropEvent(QDropEvent* event)
{
  const QString path = event->mimeData()->urls().first().toLocalFile();
  event->acceptProposedAction();
  if (QFileInfo(path).suffix().compare("spira", Qt::CaseInsensitive) == 0 && !maybeSave()) return;
  openFile(path);
}

void MainWindow::showAbout()
{
  showAboutDialog(this);
}

QImage MainWindow::captureImage()
{
  // A picture is still: drawn at full quality even while a job keeps the view fast.
  InteractiveQuality* quality = comfort_->interactiveQuality();
  if (quality) quality->fullQualityNow();
  view_->render();
  QApplication::processEvents();
  QImage image = grab().toImage();
  if (quality && quality->held()) quality->interactionStarted();
  return image;
}

}  // namespace spira::ui
