// MainWindow: importing parts, opening and saving projects (the File menu).
#include <algorithm>
#include <cmath>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QSettings>
#include <QStandardPaths>

#include <vtkPolyData.h>

#include "spira/base/error.h"
#include "spira/document/project_file.h"
#include "spira/io/import_service.h"
#include "spira/pipeline/document_plan.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/views/vtk_mesh.h"
#include "spira/ui/window/main_window.h"
#include "spira/ui/window/recent_files.h"

namespace spira::ui {

namespace {

const char* const kDirectoryKey = "lastDirectory";

std::filesystem::path toPath(const QString& s)
{
  return std::filesystem::u8path(s.toStdString());
}

QString fromStd(const std::string& s)
{
  return QString::fromStdString(s);
}

// One line on what was imported, then one line per defect kind the validation found.
void logImported(LogPanel* log, const QString& path, const ImportedPart& r)
{
  const QLocale loc;
  const MeshReport& rep = r.report;
  const QString loops = rep.boundaryLoops.size() == 1
                            ? QObject::tr("1 boundary loop")
                            : QObject::tr("%1 boundary loops").arg(rep.boundaryLoops.size());
  log->info(QObject::tr("Imported %1: %2 triangles, %3 vertices, %4 part (%5), %6 s.")
                .arg(QFileInfo(path).fileName(), loc.toString(static_cast<qulonglong>(rep.faceCount)),
                     loc.toString(static_cast<qulonglong>(rep.vertexCount)),
                     QString::fromUtf8(partClassName(rep.partClass)), loops)
                .arg(r.seconds.total(), 0, 'f', 2));
  for (const std::string& w : r.warnings) log->warning(fromStd(w));
  for (const MeshIssue& issue : rep.issues) {
    log->warning(QObject::tr("Mesh check: %1 x %2.")
                     .arg(loc.toString(static_cast<qulonglong>(issue.count)),
                          QString::fromUtf8(meshIssueName(issue.kind))),
                 rep.isPlannable()
                     ? QString()
                     : QObject::tr("Repair the mesh in your CAD or mesh tool and import it again."));
  }
  if (rep.partClass == PartClass::Unsupported) {
    log->warning(QObject::tr("The part cannot be planned as one spiral: %1").arg(fromStd(rep.classReason)));
  }
}

}  // namespace

bool MainWindow::busy() const
{
  return tasks_ && tasks_->busy();
}

void MainWindow::waitUntilIdle()
{
  if (tasks_) tasks_->waitForFinished();
}

void MainWindow::openFile(const QString& path)
{
  if (QFileInfo(path).suffix().compare(QStringLiteral("spira"), Qt::CaseInsensitive) == 0) {
    openProjectFile(path);
  } else {
    importPartFile(path);
  }
}

void MainWindow::importPartFile(const QString& path)
{
  if (busy()) {
    reportError(tr("Import"), tr("Cannot import %1 while another task runs.").arg(path),
                tr("Wait for it to finish or cancel it."));
    emit fileOpened(path, false);
    return;
  }
  const PluginRegistry& registry = registry_;
  auto result = std::make_shared<ImportedPart>();
  auto shaded = std::make_shared<vtkSmartPointer<vtkPolyData>>();
  const std::filesystem::path file = toPath(path);
  log_->info(tr("Importing %1 ...").arg(QDir::toNativeSeparators(path)));
  tasks_->start(
      tr("Importing %1").arg(QFileInfo(path).fileName()),
      [&registry, result, shaded, file](Progress& progress) {
        *result = importPart(registry, file, nullptr, progress);
        // The view's surface too: its normals are the costly part of showing a large part.
        progress.report(1.0, "preparing the view");
        *shaded = toShadedPolyData(result->mesh);
      },
      [this, path, result, shaded](const TaskOutcome& outcome) {
        if (outcome.status == TaskOutcome::Status::Cancelled) {
          log_->info(
              tr("Import of %1 cancelled; the document is unchanged.").arg(QFileInfo(path).fileName()));
          emit fileOpened(path, false);
          return;
        }
        if (!outcome.succeeded()) {
          reportError(tr("Import failed"), outcome.message, outcome.hint);
          emit fileOpened(path, false);
          return;
        }
        Part part;
        part.name = QFileInfo(path).completeBaseName().toStdString();
        part.sourcePath = QFileInfo(path).absoluteFilePath().toStdString();
        part.sourceUnit = result->sourceUnit;
        auto mesh = std::make_shared<const TriangleMesh>(std::move(result->mesh));
        part.mesh = mesh;
        // Hand the import's own validation to the views so they need not redo it.
        reportMesh_ = mesh;
        report_ = result->report;
        preparedSurface_ = {mesh, *shaded};
        logImported(log_, path, *result);
        const Substrate& s = *doc_.substrate();
        const BoundingBox box = result->report.bounds;
        if (s.kind == Substrate::Kind::Plane && !box.empty() &&
            std::abs(box.min.z() - s.planeZ) > 1e-3 * std::max(1.0, box.diagonal())) {
          log_->warning(
              tr("The part's lowest point is at z = %1 mm, the substrate at z = %2 mm.")
                  .arg(box.min.z(), 0, 'f', 2)
                  .arg(s.planeZ, 0, 'f', 2),
              tr("Planning starts on the substrate: move the part onto it or change the substrate height."));
        }
        doc_.setPart(std::move(part), tr("Import Part").toStdString());
        recent_->add(path);
        rememberDirectory(path);
        emit fileOpened(path, true);
      });
}

bool MainWindow::openProjectFile(const QString& path)
{
  if (busy()) {
    reportError(tr("Open project"), tr("Cannot open %1 while another task runs.").arg(path),
                tr("Wait for it to finish or cancel it."));
    emit fileOpened(path, false);
    return false;
  }
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    doc_.open(toPath(path));
  } catch (const Error& e) {
    QApplication::restoreOverrideCursor();
    reportError(tr("Open project failed"), fromStd(e.what()), fromStd(e.hint()));
    emit fileOpened(path, false);
    return false;
  }
  QApplication::restoreOverrideCursor();
  log_->info(tr("Opened project %1.").arg(QDir::toNativeSeparators(path)));
  for (const SettingsProblem& p : settingsProblems(*doc_.settings()))
    log_->warning(tr("The project's settings cannot be planned: %1.").arg(fromStd(p.what)),
                  tr("Change them in the Plan panel: %1.").arg(fromStd(p.hint)));
  recent_->add(path);
  rememberDirectory(path);
  emit fileOpened(path, true);
  return true;
}

bool MainWindow::saveProject()
{
  if (doc_.filePath().empty()) return options_.interactive && chooseSaveAs();
  try {
    doc_.save();
  } catch (const Error& e) {
    reportError(tr("Save failed"), fromStd(e.what()), fromStd(e.hint()));
    return false;
  }
  log_->info(tr("Saved %1.").arg(QDir::toNativeSeparators(fromStd(doc_.filePath().string()))));
  return true;
}

bool MainWindow::saveProjectAs(const QString& requested)
{
  QString path = requested;
  if (QFileInfo(path).suffix().compare(QStringLiteral("spira"), Qt::CaseInsensitive) != 0) {
    path += QString::fromUtf8(kProjectExtension);
  }
  try {
    doc_.saveAs(toPath(path));
  } catch (const Error& e) {
    reportError(tr("Save failed"), fromStd(e.what()), fromStd(e.hint()));
    return false;
  }
  log_->info(tr("Saved %1.").arg(QDir::toNativeSeparators(path)));
  recent_->add(path);
  rememberDirectory(path);
  return true;
}

void MainWindow::chooseImport()
{
  QStringList patterns;
  for (const std::string& ext : registry_.importExtensions()) patterns << "*." + fromStd(ext);
  QStringList filters;
  if (!patterns.isEmpty()) filters << tr("Part meshes (%1)").arg(patterns.join(' '));
  filters << tr("All files (*)");
  const QString path = QFileDialog::getOpenFileName(this, tr("Import Part"), dialogDirectory(),
                                                    filters.join(QStringLiteral(";;")));
  if (!path.isEmpty()) importPartFile(path);
}

void MainWindow::chooseSubstrateMesh()
{
  if (busy()) return;
  QStringList patterns;
  for (const std::string& ext : registry_.importExtensions()) patterns << "*." + fromStd(ext);
  const QString path = QFileDialog::getOpenFileName(this, tr("Substrate Mesh"), dialogDirectory(),
                                                    tr("Meshes (%1);;All files (*)").arg(patterns.join(' ')));
  if (!path.isEmpty()) useSubstrateFile(path);
}

bool MainWindow::useSubstrateFile(const QString& path)
{
  if (busy()) {
    reportError(tr("Substrate"), tr("Cannot read %1 while another task runs.").arg(path),
                tr("Wait for it to finish or cancel it."));
    return false;
  }
  const PluginRegistry& registry = registry_;
  auto result = std::make_shared<ImportedPart>();
  const std::filesystem::path file = toPath(path);
  const QString name = QFileInfo(path).fileName();
  tasks_->start(
      tr("Reading the substrate %1").arg(name),
      [&registry, result, file](Progress& progress) {
        *result = importPart(registry, file, nullptr, progress);
      },
      [this, path, name, result](const TaskOutcome& outcome) {
        if (outcome.status == TaskOutcome::Status::Cancelled) {
          log_->info(tr("Reading the substrate %1 cancelled; the document is unchanged.").arg(name));
          emit substrateRead(path, false);
          return;
        }
        if (!outcome.succeeded()) {
          reportError(tr("Substrate"), outcome.message, outcome.hint);
          emit substrateRead(path, false);
          return;
        }
        auto mesh = std::make_shared<const TriangleMesh>(std::move(result->mesh));
        doc_.setSubstrate(
            Substrate::fromMesh(std::move(mesh), QFileInfo(path).completeBaseName().toStdString(),
                                path.toStdString()),
            tr("Build on %1").arg(name).toStdString());
        log_->info(tr("Substrate: %1 (%2 triangles). The part's base edge must lie on it.")
                       .arg(name)
                       .arg(doc_.substrate()->mesh->faceCount()));
        emit substrateRead(path, true);
      });
  return true;
}

void MainWindow::chooseOpen()
{
  if (!maybeSave()) return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Open Project"), dialogDirectory(),
                                                    tr("Spira projects (*.spira);;All files (*)"));
  if (!path.isEmpty()) openProjectFile(path);
}

bool MainWindow::chooseSaveAs()
{
  QString start = dialogDirectory();
  if (!doc_.filePath().empty()) {
    start = fromStd(doc_.filePath().string());
  } else if (doc_.part()) {
    start = QDir(start).filePath(fromStd(doc_.part()->name) + QString::fromUtf8(kProjectExtension));
  }
  const QString path =
      QFileDialog::getSaveFileName(this, tr("Save Project As"), start, tr("Spira projects (*.spira)"));
  return !path.isEmpty() && saveProjectAs(path);
}

QString MainWindow::dialogDirectory() const
{
  const QString dir = QSettings().value(kDirectoryKey).toString();
  if (!dir.isEmpty() && QFileInfo(dir).isDir()) return dir;
  return QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
}

void MainWindow::rememberDirectory(const QString& file)
{
  if (options_.persistLayout) QSettings().setValue(kDirectoryKey, QFileInfo(file).absolutePath());
}

}  // namespace spira::ui
