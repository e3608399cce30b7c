#pragma once

#include <QObject>

class QAction;
class QMainWindow;
class QMenu;
class QToolBar;

namespace spira::ui {

// Every user command of the main window, created once with its text, shortcut and tip, so
// menus, toolbars and tests share the same QAction objects. Wiring lives in MainWindow.
struct Actions {
  QAction* importPart = nullptr;
  QAction* openProject = nullptr;
  QAction* save = nullptr;
  QAction* saveAs = nullptr;
  QAction* exportProgram = nullptr;
  QAction* compareScan = nullptr;
  QAction* quit = nullptr;
  QAction* undo = nullptr;
  QAction* redo = nullptr;
  QAction* showEdges = nullptr;
  QAction* showBoundingBox = nullptr;
  QAction* showSubstrate = nullptr;
  QAction* viewIso = nullptr;
  QAction* viewFront = nullptr;
  QAction* viewTop = nullptr;
  QAction* viewSide = nullptr;
  QAction* fitView = nullptr;
  QAction* plan = nullptr;
  QAction* cancelPlan = nullptr;
  QAction* compareStrategies = nullptr;
  QAction* about = nullptr;
  QAction* aboutQt = nullptr;
  QMenu* recentMenu = nullptr;  // filled by RecentFiles

  // Creates the actions (children of `window`) and builds the menu bar and the main toolbar.
  // `panelToggles` are the docks' toggleViewActions, listed in the View menu.
  static Actions create(QMainWindow* window, const QList<QAction*>& panelToggles);
};

}  // namespace spira::ui
