#include "support/gui_test_support.h"

#include <cstdlib>
#include <set>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/main_window.h"
#include "support/test_support.h"

namespace spira::test {

std::filesystem::path writeOpenCylinderStl(const std::filesystem::path& dir, const std::string& name)
{
  const std::filesystem::path file = dir / name;
  writeMesh(makeOpenCylinder(30.0, 60.0, kCylinderSegments, kCylinderRings), file, MeshFileFormat::StlBinary);
  return file;
}

QString qpath(const std::filesystem::path& p)
{
  return QString::fromStdString(p.string());
}

void showAndWait(spira::ui::MainWindow& window)
{
  window.resize(1280, 800);
  window.show();
  if (!QTest::qWaitForWindowExposed(&window, 10000)) std::abort();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
}

bool openAndWait(spira::ui::MainWindow& window, const QString& file)
{
  QSignalSpy spy(&window, &spira::ui::MainWindow::fileOpened);
  window.openFile(file);
  if (spy.isEmpty() && !spy.wait(60000)) return false;
  return spy.takeFirst().at(1).toBool();
}

int distinctColours(const QImage& image, const QRect& rect)
{
  std::set<QRgb> colours;
  const QRect r = rect.intersected(image.rect());
  for (int y = r.top(); y <= r.bottom(); ++y) {
    for (int x = r.left(); x <= r.right(); ++x) colours.insert(image.pixel(x, y) & 0xffffffu);
  }
  return static_cast<int>(colours.size());
}

double meanDifference(const QImage& a, const QImage& b, const QRect& rect)
{
  const QRect r = rect.intersected(a.rect()).intersected(b.rect());
  if (r.isEmpty()) return 0.0;
  double sum = 0.0;
  for (int y = r.top(); y <= r.bottom(); ++y) {
    for (int x = r.left(); x <= r.right(); ++x) {
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q));
    }
  }
  return sum / (3.0 * r.width() * r.height());
}

QRect rectIn(spira::ui::MainWindow& window, const QWidget* widget)
{
  return QRect(widget->mapTo(&window, QPoint(0, 0)), widget->size());
}

QString saveDocScreenshot(const QImage& image, const QString& name)
{
  QString dir = qEnvironmentVariable("SPIRA_SCREENSHOT_DIR");
  if (dir.isEmpty()) dir = qpath(sourceDir() / "docs" / "screenshots");
  QDir().mkpath(dir);
  const QString file = QDir(dir).filePath(name);
  if (!image.save(file)) ADD_FAILURE() << "cannot write " << file.toStdString();
  return file;
}

bool waitFor(const std::function<bool()>& done, int ms)
{
  QElapsedTimer timer;
  timer.start();
  while (!done() && timer.elapsed() < ms) QApplication::processEvents(QEventLoop::AllEvents, 10);
  return done();
}

bool planAndWait(spira::ui::MainWindow& window, int ms)
{
  bool finished = false;
  const auto c = QObject::connect(&window, &spira::ui::MainWindow::planFinished, [&] { finished = true; });
  window.actions().plan->trigger();
  const bool ok = waitFor([&] { return finished; }, ms);
  QObject::disconnect(c);
  return ok;
}

QRect sceneRect(spira::ui::MainWindow& window)
{
  spira::ui::SceneView* view = window.sceneView();
  return QRect(view->mapTo(&window, QPoint(0, 0)), view->size());
}

}  // namespace spira::test
