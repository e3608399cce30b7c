#pragma once

#include <QSize>
#include <QString>

#include "spira/base/exit_code.h"

class QTextStream;

namespace spira {
class PluginRegistry;
}  // namespace spira

namespace spira::ui {

struct ScreenshotRequest {
  QString input;   // a part (any importer extension) or a .spira project
  QString output;  // image file; the format follows the extension (PNG, JPEG...)
  QSize size{1280, 800};
  bool plan = false;  // plan the part (with the project's or default settings) before rendering
};

// The `spira --screenshot` command: opens `input` in a fresh main window (default layout, no
// prompts), plans it when asked, renders it and writes the whole window to `output`. Needs a QApplication.
// Errors are written to `err` as "spira: message" and "hint: ..."; returns an ExitCode.
int takeScreenshot(const ScreenshotRequest& request, const PluginRegistry& registry, QTextStream& err);

}  // namespace spira::ui
