// File > Compare Scan and the Scan dock: the scan loop (scan_workflow.h) installed on the window.
#include <QFileDialog>
#include <QMenu>
#include <QSlider>

#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/scan_panel.h"
#include "spira/ui/window/main_window.h"
#include "spira/ui/window/scan_workflow.h"

namespace spira::ui {

void MainWindow::installScanWorkflow()
{
  ScanWorkflow::Parts parts{
      *this,
      doc_,
      registry_,
      *view_,
      *tasks_,
      *log_,
      [this](const QString& t, const QString& m, const QString& h) { reportError(t, m, h); },
      [this] { return busy(); },
      [this] { display_->resultsChanged(); },
      [this](int revolution) { display_->revolutionSlider()->setValue(revolution); },
      options_.interactive};
  scan_ = new ScanWorkflow(std::move(parts), this);
  ScanPanel* dock = scan_->panel();
  addDockWidget(Qt::RightDockWidgetArea, dock);
  tabifyDockWidget(planPanel_, dock);
  planPanel_->raise();
  QAction* toggle = dock->toggleViewAction();
  toggle->setText(tr("Sc&an"));
  toggle->setToolTip(tr("The compared scan: deviation histogram, alignment by points, resume from scan"));
  for (QWidget* w : actions_.viewIso->associatedWidgets())
    if (auto* viewMenu = qobject_cast<QMenu*>(w)) viewMenu->insertAction(log_->toggleViewAction(), toggle);
  connect(scan_, &ScanWorkflow::compared, this, &MainWindow::scanCompared);
}

void MainWindow::chooseScan()
{
  if (busy()) return;
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Compare Scan"), QString(),
      tr("Scans (*.ply *.pcd *.xyz *.csv *.txt *.asc *.pts *.stl *.obj);;All files (*)"));
  if (!path.isEmpty()) compareScanFile(path);
}

bool MainWindow::compareScanFile(const QString& path)
{
  return scan_->compareFile(path);
}

}  // namespace spira::ui
