#include "spira/ui/window/application.h"

#include <QApplication>
#include <QIcon>
#include <QSurfaceFormat>

#include <QVTKOpenGLNativeWidget.h>

#include "spira/base/version.h"

// Q_INIT_RESOURCE must run at global scope; spira_ui is static, so its compiled-in resources
// are only linked when something calls their initialiser.
static void initSpiraUiResources()
{
  Q_INIT_RESOURCE(spira_ui);
}

namespace spira::ui {

void initResources()
{
  static const bool done = (initSpiraUiResources(), true);
  (void)done;
}

void prepareApplication()
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  // Share contexts so dock or tab moves (which re-parent the GL widget) keep its resources.
  QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
  QCoreApplication::setAttribute(Qt::AA_EnableHighDpiScaling);
  QCoreApplication::setAttribute(Qt::AA_UseHighDpiPixmaps);
}

void configureApplication(QApplication& app)
{
  QCoreApplication::setOrganizationName(QStringLiteral("Spira"));
  QCoreApplication::setApplicationName(QStringLiteral("Spira"));
  QCoreApplication::setApplicationVersion(QString::fromUtf8(kVersion));
  QGuiApplication::setApplicationDisplayName(QString::fromUtf8(kApplicationName));
  QGuiApplication::setDesktopFileName(QStringLiteral("spira"));
  initResources();
  app.setWindowIcon(QIcon(QStringLiteral(":/spira/icons/spira.svg")));
}

}  // namespace spira::ui
