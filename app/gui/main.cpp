// spira [FILE]                       open a part or a project
// spira --recover [FILE]             restore the autosaved work of a session that crashed
// spira --screenshot IMAGE [--plan] FILE
//                                    render FILE in the main window (planned), write IMAGE, exit
// spira --version | --help
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

#include <QApplication>
#include <QTextStream>
#include <QTimer>

#include "builtin_plugins.h"
#include "spira/base/version.h"
#include "spira/document/document.h"
#include "spira/io/isolated_import.h"
#include "spira/ui/window/application.h"
#include "spira/ui/window/comfort_features.h"
#include "spira/ui/window/main_window.h"
#include "spira/ui/window/screenshot.h"

namespace {

constexpr const char* kUsage =
    "Usage: spira [--recover] [FILE]\n"
    "       spira --screenshot IMAGE [--plan] FILE\n"
    "       spira --version | --help\n"
    "\n"
    "Spira plans one continuous spiral deposition path for robotic wire-arc additive manufacturing.\n"
    "\n"
    "  FILE                    a part mesh (STL, ...) to import or a .spira project to open\n"
    "  --recover               restore the work autosaved by a session that did not exit\n"
    "                          normally, without asking\n"
    "  --screenshot IMAGE FILE open FILE, write the main window to IMAGE (.png, .jpg) and exit;\n"
    "                          runs without a display when xvfb-run is installed\n"
    "  --plan                  with --screenshot: plan the part first, so the picture shows\n"
    "                          the planned spiral\n"
    "  --version               print the version and exit\n"
    "  --help                  print this help and exit\n"
    "\n"
    "Exit codes: 0 success, 1 rendering or writing failed, 2 bad command line, 3 unreadable input\n"
    "or a part that cannot be planned, 4 a plan that is not feasible (the picture is still written).\n";

struct Command {
  bool help = false;
  bool version = false;
  bool recover = false;
  std::string screenshot;  // IMAGE
  bool plan = false;       // plan the part before the screenshot
  std::string file;
};

// Parsed by hand, before QApplication: --version and --help must work without a display.
bool parse(int argc, char** argv, Command& cmd, std::string& error)
{
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      cmd.help = true;
    } else if (a == "--version" || a == "-v") {
      cmd.version = true;
    } else if (a == "--recover") {
      cmd.recover = true;
    } else if (a == "--plan") {
      cmd.plan = true;
    } else if (a == "--screenshot") {
      if (i + 1 >= argc) {
        error = "--screenshot needs an image file name";
        return false;
      }
      cmd.screenshot = argv[++i];
    } else if (a.size() > 1 && a[0] == '-') {
      error = "unknown option " + a;
      return false;
    } else if (cmd.file.empty()) {
      cmd.file = a;
    } else {
      error = "only one file can be opened, got " + cmd.file + " and " + a;
      return false;
    }
  }
  if (cmd.plan && cmd.screenshot.empty()) {
    error = "--plan goes with --screenshot (in the window, press Plan or F5)";
    return false;
  }
  if (!cmd.screenshot.empty() && cmd.file.empty()) {
    error = "--screenshot needs the part or project to show";
    return false;
  }
  return true;
}

bool hasDisplay()
{
  const char* x = std::getenv("DISPLAY");
  const char* wl = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wl && *wl);
}

// With no display at all, rerun the screenshot under a private X server: VTK's OpenGL needs one
// (Debian's VTK has no EGL or OSMesa backend), and headless batch use is what --screenshot is for.
void reexecUnderXvfb(char** argv)
{
  // Also with QT_QPA_PLATFORM=offscreen: Qt's offscreen platform gets OpenGL only through GLX.
  if (hasDisplay() || std::getenv("SPIRA_NO_XVFB")) return;
  setenv("SPIRA_NO_XVFB", "1", 1);  // the child must not try again
  std::vector<char*> args{const_cast<char*>("xvfb-run"), const_cast<char*>("-a"), const_cast<char*>("-s"),
                          const_cast<char*>("-screen 0 1920x1200x24")};
  for (char** a = argv; *a; ++a) args.push_back(*a);
  args.push_back(nullptr);
  execvp("xvfb-run", args.data());
  // Not installed: fall through and try Qt's offscreen platform.
}

// Batch screenshots print only what went wrong with the job: Qt's platform chatter (runtime
// directories, size hints, GL fallbacks) goes to stderr only with SPIRA_VERBOSE set.
void quietQtMessages(QtMsgType type, const QMessageLogContext&, const QString& message)
{
  if (type == QtCriticalMsg || type == QtFatalMsg) std::cerr << message.toLocal8Bit().constData() << "\n";
}

}  // namespace

int main(int argc, char** argv)
{
  Command cmd;
  std::string error;
  if (!parse(argc, argv, cmd, error)) {
    std::cerr << "spira: " << error << "\n" << kUsage;
    return spira::kExitUsage;
  }
  if (cmd.help) {
    std::cout << kUsage;
    return spira::kExitOk;
  }
  if (cmd.version) {
    std::cout << "spira " << spira::kVersion << "\n";
    return spira::kExitOk;
  }
  if (!cmd.screenshot.empty()) {
    // Checked here too so a typo fails fast, without starting an X server first.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(cmd.file, ec)) {
      std::cerr << "spira: cannot read " << cmd.file << ": no such file\n"
                << "hint: check the path of the part or project to show\n";
      return spira::kExitBadInput;
    }
    reexecUnderXvfb(argv);
    if (!hasDisplay() && !std::getenv("QT_QPA_PLATFORM")) setenv("QT_QPA_PLATFORM", "offscreen", 1);
    if (!std::getenv("SPIRA_VERBOSE")) qInstallMessageHandler(quietQtMessages);
  }

  spira::ui::prepareApplication();
  QApplication app(argc, argv);
  spira::ui::configureApplication(app);
  // Loads the CAD and link-mesh readers while the window comes up, so the first import and the
  // first cell do not wait for them.
  spira::prestartImportHelper();

  if (!cmd.screenshot.empty()) {
    QTextStream err(stderr);
    spira::ui::ScreenshotRequest request;
    request.input = QString::fromLocal8Bit(cmd.file.c_str());
    request.output = QString::fromLocal8Bit(cmd.screenshot.c_str());
    request.plan = cmd.plan;
    return spira::ui::takeScreenshot(request, spira::builtinRegistry(), err);
  }

  spira::Document doc;
  spira::ui::MainWindow window(doc, spira::builtinRegistry());
  window.show();
  if (cmd.recover) {
    window.comfortFeatures()->offerRecovery(true);
  }
  if (!cmd.file.empty()) {
    const QString file = QString::fromLocal8Bit(cmd.file.c_str());
    // After the event loop starts, so the window is up and can show the import's progress.
    QTimer::singleShot(0, &window, [&window, file] { window.openFile(file); });
  }
  return app.exec();
}
