// File > Compare Scan: a scan of the part aligned to it and coloured by its deviation.
#include <memory>

#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/scan/scan_alignment.h"
#include "spira/scan/scan_deviation.h"
#include "spira/scan/scan_processing.h"
#include "spira/scan/scan_reader.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/views/scan_layer.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"

namespace spira::ui {

namespace {

// What the background task hands back.
struct ComparedScan {
  PointCloud scan;  // aligned, in the part's frame
  size_t read = 0, outliers = 0;
  AlignResult fit;
  std::vector<double> deviation;
  DeviationStats stats;
};

}  // namespace

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
  const auto part = doc_.part();
  if (!part || !part->mesh) {
    reportError(tr("Compare scan"),
                tr("There is no part to compare %1 with.").arg(QFileInfo(path).fileName()),
                tr("Import the part first (File > Import Part)."));
    return false;
  }
  if (busy()) {
    reportError(tr("Compare scan"), tr("Cannot compare %1 while another task runs.").arg(path),
                tr("Wait for it to finish or cancel it."));
    return false;
  }
  const PluginRegistry& registry = registry_;
  const std::shared_ptr<const TriangleMesh> mesh = part->mesh;
  auto result = std::make_shared<ComparedScan>();
  const std::filesystem::path file = std::filesystem::u8path(path.toStdString());
  const QString name = QFileInfo(path).fileName();
  log_->info(tr("Comparing the scan %1 with the part ...").arg(name));
  tasks_->start(
      tr("Comparing %1").arg(name),
      [&registry, mesh, result, file](Progress& progress) {
        PointCloud raw = readScan(registry, file, progress);
        result->read = raw.size();
        if (const auto unit = scanUnitHint(boundsOf(raw), mesh->bounds()))
          throw InputError("'" + file.filename().string() + "': " + *unit,
                           "export the scan in mm (spira-cli scan-compare --scan-scale reads it scaled)");
        ScanFilterReport filtered;
        PointCloud clean = filterScan(raw, ScanFilterSettings{}, &filtered);
        result->outliers = filtered.outliers;
        SubProgress aligning(progress, 0.1, 0.7, "aligning");
        result->fit = alignScan(clean, *mesh, Transform::Identity(), AlignSettings{}, aligning);
        result->scan = transformed(clean, result->fit.T_part_scan);
        SubProgress measuring(progress, 0.7, 1.0, "deviation");
        result->deviation = scanDeviation(result->scan, *mesh, measuring);
        result->stats = deviationStats(result->deviation);
      },
      [this, path, name, result](const TaskOutcome& outcome) {
        if (outcome.status == TaskOutcome::Status::Cancelled) {
          log_->info(tr("Comparing %1 cancelled.").arg(name));
          emit scanCompared(path, false);
          return;
        }
        if (!outcome.succeeded()) {
          reportError(tr("Compare scan"), outcome.message, outcome.hint);
          emit scanCompared(path, false);
          return;
        }
        const auto placed = doc_.part();
        view_->scanLayer().setScan(result->scan, result->deviation, result->stats,
                                   placed ? placed->T_world_part : Transform::Identity());
        view_->scheduleRender();
        display_->resultsChanged();
        const QLocale loc;
        const Eigen::AngleAxisd turn(result->fit.T_part_scan.linear());
        log_->info(
            tr("Scan %1: %2 points (%3 stray removed), moved %4 mm and %5 deg onto the part, residual %6 mm. "
               "Deviation from the part: mean %7 mm, RMS %8 mm, 95 % within %9 mm.")
                .arg(name)
                .arg(loc.toString(qulonglong(result->read)))
                .arg(loc.toString(qulonglong(result->outliers)))
                .arg(loc.toString(result->fit.T_part_scan.translation().norm(), 'f', 3))
                .arg(loc.toString(radToDeg(turn.angle()), 'f', 3))
                .arg(loc.toString(result->fit.rmsMm, 'f', 3))
                .arg(loc.toString(result->stats.mean, 'f', 3))
                .arg(loc.toString(result->stats.rms, 'f', 3))
                .arg(loc.toString(result->stats.p95, 'f', 3)));
        emit scanCompared(path, true);
      });
  return true;
}

}  // namespace spira::ui
