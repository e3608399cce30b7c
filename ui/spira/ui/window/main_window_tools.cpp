// MainWindow: the tool windows opened from the menus (robot-program export, strategy comparison).
#include "spira/ui/charts/compare_view.h"
#include "spira/ui/panels/export_dialog.h"
#include "spira/ui/window/main_window.h"

namespace spira::ui {

ExportDialog* MainWindow::exportDialog()
{
  if (!exportDialog_) exportDialog_ = new ExportDialog(doc_, registry_, log_, this);
  return exportDialog_;
}

void MainWindow::showExportDialog()
{
  ExportDialog* d = exportDialog();
  d->show();
  d->raise();
  d->activateWindow();
}

CompareView* MainWindow::compareView()
{
  if (!compareView_) compareView_ = new CompareView(doc_, registry_, this);
  return compareView_;
}

void MainWindow::showCompareView()
{
  CompareView* v = compareView();
  v->show();
  v->raise();
  v->activateWindow();
}

}  // namespace spira::ui
