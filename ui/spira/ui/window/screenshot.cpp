#include "spira/ui/window/screenshot.h"

#include "spira/document/plan_report.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QImage>
#include <QImageWriter>
#include <QTextStream>
#include <QWindow>
#include <nlohmann/json.hpp>

#include "spira/document/document.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"

namespace spira::ui {

namespace {

void printError(QTextStream& err, const QString& message, const QString& hint)
{
  err << "spira: " << message << "\n";
  if (!hint.isEmpty()) err << "hint: " << hint << "\n";
  err.flush();
}

// Shown windows get their first paint (and the GL widget its context) through the event loop.
void waitForExposure(QWidget& w)
{
  QElapsedTimer timer;
  timer.start();
  while (timer.elapsed() < 5000 && !(w.windowHandle() && w.windowHandle()->isExposed())) {
    QApplication::processEvents(QEventLoop::AllEvents, 20);
  }
  for (int i = 0; i < 5; ++i) QApplication::processEvents(QEventLoop::AllEvents, 20);
}

}  // namespace

int takeScreenshot(const ScreenshotRequest& request, const PluginRegistry& registry, QTextStream& err)
{
  const QFileInfo input(request.input);
  if (!input.exists() || !input.isFile()) {
    printError(err,
               QStringLiteral("cannot read %1: no such file").arg(QDir::toNativeSeparators(request.input)),
               QStringLiteral("check the path of the part or project to show"));
    return kExitBadInput;
  }
  const QByteArray format = QFileInfo(request.output).suffix().toLower().toLatin1();
  if (!QImageWriter::supportedImageFormats().contains(format)) {
    printError(err, QStringLiteral("cannot write %1: unknown image format").arg(request.output),
               QStringLiteral("name the screenshot .png or .jpg"));
    return kExitUsage;
  }

  Document doc;
  MainWindow window(doc, registry, MainWindowOptions{false, false});
  window.resize(request.size);
  window.show();
  waitForExposure(window);
  if (!window.sceneView()->hasOpenGL()) {
    printError(err,
               QStringLiteral("no OpenGL context for the 3D view on the '%1' platform")
                   .arg(QGuiApplication::platformName()),
               QStringLiteral("run with an X display, or headless through xvfb-run -a"));
    return kExitBadInput;
  }

  bool ok = false;
  bool done = false;
  QObject::connect(&window, &MainWindow::fileOpened, [&](const QString&, bool success) {
    ok = success;
    done = true;
  });
  window.openFile(request.input);
  window.waitUntilIdle();
  while (!done) QApplication::processEvents(QEventLoop::AllEvents, 20);
  if (!ok) {
    printError(err, window.lastErrorMessage(), window.lastErrorHint());
    return kExitBadInput;
  }

  int planned = kExitOk;
  if (request.plan) {
    bool finished = false;
    TaskOutcome outcome;
    QObject::connect(&window, &MainWindow::planFinished, [&](const TaskOutcome& o) {
      outcome = o;
      finished = true;
    });
    window.plan();
    while (!finished) QApplication::processEvents(QEventLoop::AllEvents, 20);
    window.waitUntilIdle();
    if (!outcome.succeeded()) {
      printError(err, QStringLiteral("the part could not be planned: %1").arg(outcome.message), outcome.hint);
      return kExitBadInput;
    }
    const std::optional<PlanReportSummary> plan = planSummaryOf(doc.results());
    if (!plan || !plan->feasible.value_or(false)) planned = kExitInfeasible;
  }

  const QImage image = window.captureImage();
  if (image.isNull()) {
    printError(err, QStringLiteral("the window could not be rendered"),
               QStringLiteral("run under a display, or headless with xvfb-run -a"));
    return kExitBadInput;
  }
  QImageWriter writer(request.output, format);
  if (!writer.write(image)) {
    printError(err, QStringLiteral("cannot write %1: %2").arg(request.output, writer.errorString()),
               QStringLiteral("choose a folder you can write to"));
    return kExitBadInput;
  }
  return planned;
}

}  // namespace spira::ui
