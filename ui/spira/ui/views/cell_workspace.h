#pragma once

#include <memory>

#include <QObject>

#include "spira/document/document.h"

class QDockWidget;
class QMainWindow;

namespace spira::ui {

class BeadLayer;
class CellPanel;
class LogPanel;
class RobotLayer;
class SceneView;
class SimulationPanel;

// The robot cell side of the main window: the Cell and Simulation docks and the cell's layers in
// the 3D view (robot, positioner, torch, growing bead). It listens to the document: a new cell
// rebuilds the robot (missing meshes warned in the messages panel) and fits the camera to the
// whole cell; a new kinematics result feeds the simulation.
class CellWorkspace : public QObject {
  Q_OBJECT

 public:
  // `planDock`: the window's plan settings, which the Cell dock joins as a tab.
  CellWorkspace(QMainWindow& window, QDockWidget& planDock, Document& doc, SceneView& view, LogPanel& log);
  ~CellWorkspace() override;

  CellPanel* cellPanel() const { return cellPanel_; }
  SimulationPanel* simulationPanel() const { return simulation_; }
  QDockWidget* cellDock() const { return cellDock_; }
  QDockWidget* simulationDock() const { return simulationDock_; }
  RobotLayer& robotLayer() { return *robot_; }
  BeadLayer& beadLayer() { return *bead_; }
  // Frames the whole cell (robot, positioner and part) in the view.
  void fitCell();

 private:
  void onChanged(const ChangeSet& c);
  void rebuildCell();
  void updateMotion();
  // Schedules a frame after the robot moved, with what the positioner carries brought along.
  void redraw();

  Document& doc_;
  SceneView& view_;
  LogPanel& log_;
  std::unique_ptr<RobotLayer> robot_;
  std::unique_ptr<BeadLayer> bead_;
  CellPanel* cellPanel_ = nullptr;
  SimulationPanel* simulation_ = nullptr;
  QDockWidget* cellDock_ = nullptr;
  QDockWidget* simulationDock_ = nullptr;
  Document::SubscriptionId subscription_ = 0;
};

}  // namespace spira::ui
