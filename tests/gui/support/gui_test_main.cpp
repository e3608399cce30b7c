// main() of every GUI test program: one QApplication for all tests, and settings (recent files,
// layout) kept in a private folder so tests neither read nor change the user's.
#include <QApplication>
#include <QDir>
#include <QSettings>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include "spira/ui/window/application.h"

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  QTemporaryDir settingsDir;
  qputenv("XDG_CONFIG_HOME", settingsDir.path().toLocal8Bit());
  // Autosave, presets and samples (QStandardPaths::AppDataLocation) stay private too.
  qputenv("XDG_DATA_HOME", settingsDir.path().toLocal8Bit());
  spira::ui::prepareApplication();
  QApplication app(argc, argv);
  spira::ui::configureApplication(app);
  QCoreApplication::setOrganizationName(QStringLiteral("SpiraTests"));
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
  return RUN_ALL_TESTS();
}
