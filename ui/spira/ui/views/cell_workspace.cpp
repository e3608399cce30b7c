#include "spira/ui/views/cell_workspace.h"

#include <algorithm>

#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>

#include <vtkRenderer.h>

#include "spira/base/error.h"
#include "spira/planning/plan_schemas.h"
#include "spira/ui/panels/cell_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/simulation_panel.h"
#include "spira/ui/views/bead_layer.h"
#include "spira/ui/views/path_layers.h"
#include "spira/ui/views/robot_layer.h"
#include "spira/ui/views/scene_view.h"

namespace spira::ui {

CellWorkspace::CellWorkspace(QMainWindow& window, QDockWidget& planDock, Document& doc, SceneView& view,
                             LogPanel& log)
    : QObject(&window), doc_(doc), view_(view), log_(log)
{
  robot_ = std::make_unique<RobotLayer>(view.renderer());
  bead_ = std::make_unique<BeadLayer>(view.renderer());
  cellPanel_ = new CellPanel(doc, &log, &window);
  cellDock_ = new QDockWidget(tr("Cell"), &window);
  cellDock_->setObjectName(QStringLiteral("cellDock"));
  auto* scroll = new QScrollArea(&window);
  scroll->setWidget(cellPanel_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  cellDock_->setWidget(scroll);
  // With the plan settings (a tab beside them) and the simulation's controls below them: the
  // window keeps its size and the 3D view its width.
  window.addDockWidget(Qt::RightDockWidgetArea, cellDock_);
  simulation_ = new SimulationPanel(
      *robot_, *bead_, [this] { redraw(); }, &window);
  simulationDock_ = new QDockWidget(tr("Simulation"), &window);
  simulationDock_->setObjectName(QStringLiteral("simulationDock"));
  simulationDock_->setWidget(simulation_);
  window.addDockWidget(Qt::RightDockWidgetArea, simulationDock_);
  // Split first: a dock split off a tabbed one would join its tabs.
  window.splitDockWidget(&planDock, simulationDock_, Qt::Vertical);
  window.tabifyDockWidget(&planDock, cellDock_);
  cellDock_->hide();
  simulationDock_->hide();
  subscription_ = doc_.subscribe([this](const ChangeSet& c) { onChanged(c); });
  rebuildCell();
  updateMotion();
}

CellWorkspace::~CellWorkspace()
{
  doc_.unsubscribe(subscription_);
}

void CellWorkspace::onChanged(const ChangeSet& c)
{
  if (c.has(Change::Cell)) rebuildCell();
  if (c.has(Change::Part) && doc_.part()) {
    robot_->setScenePart(doc_.part()->T_world_part);
    updateMotion();
  } else if ((c.has(Change::Results) && c.hasStage(Stage::Kinematics)) || c.has(Change::Cell))
    updateMotion();
}

void CellWorkspace::rebuildCell()
{
  cellPanel_->refresh();
  const CellRecord* cell = doc_.cell().get();
  try {
    for (const std::string& w : robot_->setCell(cell)) log_.warning(QString::fromStdString(w));
  } catch (const Error& e) {
    robot_->setCell(nullptr);
    log_.error(tr("Cannot show the cell: %1").arg(QString::fromStdString(e.what())),
               QString::fromStdString(e.hint()));
  }
  if (doc_.part()) robot_->setScenePart(doc_.part()->T_world_part);
  if (robot_->hasCell()) {
    cellDock_->show();
    cellDock_->raise();
    simulationDock_->show();
    fitCell();
  }
  redraw();
}

void CellWorkspace::redraw()
{
  view_.pathLayers().setPartMotion(robot_->partMotion());
  view_.scheduleRender();
}

void CellWorkspace::updateMotion()
{
  const auto& k = doc_.results().kinematics;
  const Transform T_scene_part = doc_.part() ? doc_.part()->T_world_part : Transform::Identity();
  const double bead = 0.5 * beadWidthOf(doc_.settings()->section(PlanSettings::kProcessSection));
  bead_->setMotion(robot_->hasCell() ? k.get() : nullptr, T_scene_part, bead);
  if (!robot_->hasCell())
    simulation_->setMotion(nullptr, tr("Choose a cell (Cell dock) and plan to simulate the robot."));
  else if (!k)
    simulation_->setMotion(nullptr, tr("Plan (F5) to solve the robot's motion on this cell."));
  else
    simulation_->setMotion(k);
  if (k && robot_->hasCell()) fitCell();
  if (!k && robot_->hasCell()) robot_->setHomePose();
  redraw();
}

void CellWorkspace::fitCell()
{
  if (!robot_->hasCell()) return;
  std::array<double, 6> b = robot_->bounds();
  if (doc_.part() && doc_.part()->mesh && !doc_.part()->mesh->empty()) {
    for (const Vec3& v : doc_.part()->mesh->vertices) {
      const Vec3 w = doc_.part()->T_world_part * v;
      for (int i = 0; i < 3; ++i)
        b[2 * i] = std::min(b[2 * i], w[i]), b[2 * i + 1] = std::max(b[2 * i + 1], w[i]);
    }
  }
  vtkRenderer* r = view_.renderer();
  r->ResetCamera(b.data());
  r->ResetCameraClippingRange();
  view_.scheduleRender();
}

}  // namespace spira::ui
