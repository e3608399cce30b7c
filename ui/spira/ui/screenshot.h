#pragma once

#include <QSize>
#include <QString>

class QTextStream;

namespace spira::ui {

// Exit codes of the `spira` executable.
enum ExitCode : int {
  kExitSuccess = 0,
  kExitFailure = 1,   // could not render or write the image
  kExitUsage = 2,     // bad command line
  kExitBadInput = 3,  // the part or project could not be read, or planned
  kExitInfeasible = 4,  // planned, but the plan is not feasible (the image is still written)
};

struct ScreenshotRequest {
  QString input;   // a part (any importer extension) or a .spira project
  QString output;  // image file; the format follows the extension (PNG, JPEG...)
  QSize size{1280, 800};
  bool plan = false;  // plan the part (with the project's or default settings) before rendering
};

// The `spira --screenshot` command: opens `input` in a fresh main window (default layout, no
// prompts), plans it when asked, renders it and writes the whole window to `output`. Needs a QApplication. Errors are
// written to `err` as "spira: message" and "hint: ..."; returns an ExitCode.
int takeScreenshot(const ScreenshotRequest& request, QTextStream& err);

}  // namespace spira::ui
