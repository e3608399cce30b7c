#pragma once

#include <functional>

class QDockWidget;
class QMainWindow;
class QString;

namespace spira {
class Document;
}  // namespace spira

namespace spira::ui {

struct Actions;
class DisplayPanel;
class LogPanel;
class PlanPanel;
class SceneView;
class SimulationPanel;
class TaskRunner;

// What the main window hands to the features built on it (comfort features, the guided sample):
// its parts and commands by reference, so that a feature needs neither the window's class nor a
// search of its children. Every reference outlives the features (they are the window's children).
struct WindowParts {
  QMainWindow& window;
  Document& doc;
  const Actions& actions;
  SceneView& view;
  QDockWidget& treeDock;
  DisplayPanel& display;
  PlanPanel& plan;
  LogPanel& log;
  TaskRunner& tasks;
  SimulationPanel& simulation;
  // The window's commands (MainWindow::openFile, plan and busy).
  std::function<void(const QString&)> openFile;
  std::function<void()> runPlan;
  std::function<bool()> busy;
};

}  // namespace spira::ui
