#pragma once

#include <filesystem>
#include <functional>

#include <QImage>
#include <QRect>
#include <QString>

class QWidget;

namespace spira::ui {
class MainWindow;
}

namespace spira::test {

// An open cylinder (radius 30 mm, height 60 mm, 64 segments x 12 rings, standing on z = 0)
// written as a binary STL in `dir`; returns the file.
std::filesystem::path writeOpenCylinderStl(const std::filesystem::path& dir,
                                           const std::string& name = "cylinder.stl");
constexpr int kCylinderSegments = 64;
constexpr int kCylinderRings = 12;

QString qpath(const std::filesystem::path& p);

// Shows the window at a fixed size and waits until it is on screen and painted once.
void showAndWait(spira::ui::MainWindow& window);
// Opens `file` through the window (as the user would) and waits for the outcome.
bool openAndWait(spira::ui::MainWindow& window, const QString& file);

// Number of distinct RGB colours in `rect` of `image`.
int distinctColours(const QImage& image, const QRect& rect);
// Mean absolute per-channel difference (0..255) between two images over `rect`.
double meanDifference(const QImage& a, const QImage& b, const QRect& rect);
// The 3D view's rectangle inside the window image.
QRect sceneRect(spira::ui::MainWindow& window);
// The rectangle of `widget` inside its window's image.
QRect rectIn(spira::ui::MainWindow& window, const QWidget* widget);

// Where documentation screenshots go: $SPIRA_SCREENSHOT_DIR, or docs/screenshots in the source
// tree. Saves `image` there as `name` (overwriting) and returns the file.
QString saveDocScreenshot(const QImage& image, const QString& name);

// Runs the event loop until `done` holds or `ms` milliseconds have passed; returns done().
bool waitFor(const std::function<bool()>& done, int ms);

// Plans through the window's Plan action and waits for the outcome (status of the TaskOutcome).
// Returns false when no outcome came within `ms`.
bool planAndWait(spira::ui::MainWindow& window, int ms = 240000);

}  // namespace spira::test
