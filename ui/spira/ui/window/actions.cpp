#include "spira/ui/window/actions.h"

#include <QAction>
#include <QApplication>
#include <QIcon>
#include <QMainWindow>
#include <QMenuBar>
#include <QStyle>
#include <QToolBar>

namespace spira::ui {

namespace {

QAction* make(QMainWindow* w, const QString& text, const QString& tip, const QList<QKeySequence>& keys = {})
{
  auto* a = new QAction(text, w);
  a->setStatusTip(tip);
  a->setToolTip(tip);
  a->setShortcuts(keys);
  // Shortcuts work while the 3D view or a dock has focus.
  a->setShortcutContext(Qt::WindowShortcut);
  return a;
}

QAction* makeToggle(QMainWindow* w, const QString& text, const QString& tip, bool on)
{
  QAction* a = make(w, text, tip);
  a->setCheckable(true);
  a->setChecked(on);
  return a;
}

void makeFileActions(Actions& a, QMainWindow* w, QStyle* st)
{
  a.importPart = make(w, QObject::tr("&Import Part..."), QObject::tr("Import a part mesh (STL, ...)"),
                      {QKeySequence(Qt::CTRL | Qt::Key_I)});
  a.importPart->setIcon(QIcon(QStringLiteral(":/spira/icons/import-part.svg")));
  a.openProject = make(w, QObject::tr("&Open Project..."), QObject::tr("Open a Spira project (.spira)"),
                       {QKeySequence::Open});
  a.openProject->setIcon(st->standardIcon(QStyle::SP_DialogOpenButton));
  a.save = make(w, QObject::tr("&Save"), QObject::tr("Save the project"), {QKeySequence::Save});
  a.save->setIcon(st->standardIcon(QStyle::SP_DialogSaveButton));
  a.saveAs = make(w, QObject::tr("Save &As..."), QObject::tr("Save the project under a new name"),
                  {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)});
  a.exportProgram =
      make(w, QObject::tr("&Export Robot Program..."),
           QObject::tr("Write the plan as a KUKA KRL or FANUC TP program, with a preview first"),
           {QKeySequence(Qt::CTRL | Qt::Key_E)});
  a.exportProgram->setObjectName(QStringLiteral("exportProgramAction"));
  a.compareScan = make(w, QObject::tr("Compare &Scan..."),
                       QObject::tr("Align a scan of the part (PLY, PCD, XYZ, CSV) to it and colour it by its "
                                   "deviation from the part"));
  a.compareScan->setObjectName(QStringLiteral("compareScanAction"));
  a.quit = make(w, QObject::tr("&Quit"), QObject::tr("Quit Spira"), {QKeySequence(Qt::CTRL | Qt::Key_Q)});
  a.quit->setMenuRole(QAction::QuitRole);
}

void makeEditAndViewActions(Actions& a, QMainWindow* w, QStyle* st)
{
  a.undo = make(w, QObject::tr("&Undo"), QObject::tr("Undo the last change"),
                {QKeySequence(Qt::CTRL | Qt::Key_Z)});
  a.undo->setIcon(st->standardIcon(QStyle::SP_ArrowBack));
  a.redo = make(w, QObject::tr("&Redo"), QObject::tr("Redo the change undone last"),
                {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  a.redo->setIcon(st->standardIcon(QStyle::SP_ArrowForward));

  a.showEdges =
      makeToggle(w, QObject::tr("Show &Edges"), QObject::tr("Draw the mesh's triangle edges"), false);
  a.showEdges->setShortcut(QKeySequence(Qt::Key_E));
  a.showBoundingBox =
      makeToggle(w, QObject::tr("Show &Bounding Box"), QObject::tr("Draw the part's bounding box"), false);
  a.showBoundingBox->setShortcut(QKeySequence(Qt::Key_B));
  a.showSubstrate =
      makeToggle(w, QObject::tr("Show &Substrate"), QObject::tr("Draw the substrate plate"), true);
  a.viewIso = make(w, QObject::tr("&Iso View"), QObject::tr("Look from the front-right, above"),
                   {QKeySequence(Qt::Key_0)});
  a.viewFront = make(w, QObject::tr("&Front View"), QObject::tr("Look along +Y"), {QKeySequence(Qt::Key_1)});
  a.viewTop = make(w, QObject::tr("&Top View"), QObject::tr("Look down along -Z"), {QKeySequence(Qt::Key_7)});
  a.viewSide = make(w, QObject::tr("&Side View"), QObject::tr("Look along -X"), {QKeySequence(Qt::Key_3)});
  a.fitView =
      make(w, QObject::tr("&Fit to View"), QObject::tr("Frame the whole part"), {QKeySequence(Qt::Key_F)});
}

void makePlanAndHelpActions(Actions& a, QMainWindow* w, QStyle* st)
{
  a.plan =
      make(w, QObject::tr("&Plan"), QObject::tr("Plan the spiral on the part with the current settings (F5)"),
           {QKeySequence(Qt::Key_F5)});
  a.plan->setIcon(QIcon(QStringLiteral(":/spira/icons/plan.svg")));
  a.plan->setObjectName(QStringLiteral("planAction"));
  a.cancelPlan = make(w, QObject::tr("&Cancel Planning"),
                      QObject::tr("Stop the running plan; the previous results stay (Esc)"),
                      {QKeySequence(Qt::Key_Escape)});
  a.cancelPlan->setIcon(st->standardIcon(QStyle::SP_BrowserStop));
  a.cancelPlan->setEnabled(false);
  a.compareStrategies =
      make(w, QObject::tr("Compare &Strategies..."),
           QObject::tr("Plan the part with every strategy and compare their deposit heights side by side"));
  a.compareStrategies->setObjectName(QStringLiteral("compareStrategiesAction"));
  a.about = make(w, QObject::tr("&About Spira"), QObject::tr("Version and licence"));
  a.about->setMenuRole(QAction::AboutRole);
  a.aboutQt = make(w, QObject::tr("About &Qt"), QObject::tr("Qt version and licence"));
  a.aboutQt->setMenuRole(QAction::AboutQtRole);
}

void buildMenus(Actions& a, QMainWindow* w, const QList<QAction*>& panelToggles)
{
  QMenuBar* bar = w->menuBar();
  QMenu* file = bar->addMenu(QObject::tr("&File"));
  file->addAction(a.importPart);
  file->addSeparator();
  file->addAction(a.openProject);
  a.recentMenu = file->addMenu(QObject::tr("Open &Recent"));
  a.recentMenu->setObjectName("recentMenu");
  file->addSeparator();
  file->addAction(a.save);
  file->addAction(a.saveAs);
  file->addSeparator();
  file->addAction(a.exportProgram);
  file->addAction(a.compareScan);
  file->addSeparator();
  file->addAction(a.quit);

  QMenu* edit = bar->addMenu(QObject::tr("&Edit"));
  edit->addAction(a.undo);
  edit->addAction(a.redo);

  QMenu* view = bar->addMenu(QObject::tr("&View"));
  view->addAction(a.viewIso);
  view->addAction(a.viewFront);
  view->addAction(a.viewTop);
  view->addAction(a.viewSide);
  view->addAction(a.fitView);
  view->addSeparator();
  view->addAction(a.showEdges);
  view->addAction(a.showBoundingBox);
  view->addAction(a.showSubstrate);
  view->addSeparator();
  for (QAction* t : panelToggles) view->addAction(t);

  QMenu* planMenu = bar->addMenu(QObject::tr("&Plan"));
  planMenu->addAction(a.plan);
  planMenu->addAction(a.cancelPlan);
  planMenu->addSeparator();
  planMenu->addAction(a.compareStrategies);

  QMenu* help = bar->addMenu(QObject::tr("&Help"));
  help->addAction(a.about);
  help->addAction(a.aboutQt);
}

void buildToolBars(const Actions& a, QMainWindow* w)
{
  QToolBar* tools = w->addToolBar(QObject::tr("Main"));
  tools->setObjectName("mainToolBar");
  tools->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  tools->addAction(a.importPart);
  tools->addAction(a.openProject);
  tools->addAction(a.save);
  tools->addSeparator();
  tools->addAction(a.undo);
  tools->addAction(a.redo);
  tools->addSeparator();
  tools->addAction(a.plan);
  QToolBar* viewBar = w->addToolBar(QObject::tr("View"));
  viewBar->setObjectName("viewToolBar");
  viewBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
  viewBar->addAction(a.viewIso);
  viewBar->addAction(a.viewFront);
  viewBar->addAction(a.viewTop);
  viewBar->addAction(a.viewSide);
  viewBar->addAction(a.fitView);
  viewBar->addSeparator();
  viewBar->addAction(a.showEdges);
  viewBar->addAction(a.showBoundingBox);
  // The buttons keep their size when an action is enabled, disabled or renamed (the undo steps):
  // a tool button whose size may change asks the whole window to lay itself out again on each
  // such change (up to 50 ms with the cell docks open). Their texts are short and fixed.
  for (QToolBar* toolBar : {tools, viewBar})
    for (QAction* action : toolBar->actions())
      if (QWidget* button = toolBar->widgetForAction(action); button && !action->isSeparator())
        button->setFixedSize(button->sizeHint());
}

}  // namespace

Actions Actions::create(QMainWindow* w, const QList<QAction*>& panelToggles)
{
  QStyle* st = w->style();
  Actions a;
  makeFileActions(a, w, st);
  makeEditAndViewActions(a, w, st);
  makePlanAndHelpActions(a, w, st);
  buildMenus(a, w, panelToggles);
  buildToolBars(a, w);
  return a;
}

}  // namespace spira::ui
