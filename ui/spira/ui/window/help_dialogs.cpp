#include "spira/ui/window/help_dialogs.h"

#include <algorithm>
#include <vector>

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QIcon>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <vtkVersion.h>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#if __has_include(<CGAL/version_macros.h>)
#include <CGAL/version_macros.h>
#endif
#if __has_include(<opencascade/Standard_Version.hxx>)
#include <opencascade/Standard_Version.hxx>
#endif

#include "spira/base/version.h"

namespace spira::ui {

namespace {

QString row(const QString& a, const QString& b, const QString& c = {})
{
  QString r = QStringLiteral("<tr><td>%1</td><td>&nbsp;&nbsp;%2</td>").arg(a, b);
  if (!c.isEmpty()) r += QStringLiteral("<td>&nbsp;&nbsp;%1</td>").arg(c);
  return r + QStringLiteral("</tr>");
}

QString plainText(QString text)
{
  text.remove('&');
  if (text.endsWith(QLatin1String("..."))) text.chop(3);
  return text.toHtmlEscaped();
}

QDialog* textDialog(QWidget* parent, const QString& title, const QString& html, QSize size)
{
  auto* dialog = new QDialog(parent);
  dialog->setWindowTitle(title);
  auto* layout = new QVBoxLayout(dialog);
  auto* browser = new QTextBrowser(dialog);
  browser->setOpenExternalLinks(true);
  browser->setHtml(html);
  layout->addWidget(browser);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
  QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
  layout->addWidget(buttons);
  dialog->resize(size);
  return dialog;
}

}  // namespace

QString aboutText()
{
  QString libs;
  libs += row(QStringLiteral("Qt"), QString::fromUtf8(qVersion()), QStringLiteral("LGPL-3.0"));
  libs += row(QStringLiteral("VTK"), QString::fromUtf8(vtkVersion::GetVTKVersion()),
              QStringLiteral("BSD-3-Clause"));
  libs += row(
      QStringLiteral("Eigen"),
      QStringLiteral("%1.%2.%3").arg(EIGEN_WORLD_VERSION).arg(EIGEN_MAJOR_VERSION).arg(EIGEN_MINOR_VERSION),
      QStringLiteral("MPL-2.0"));
#ifdef CGAL_VERSION_STR
  libs += row(QStringLiteral("CGAL"), QStringLiteral(CGAL_VERSION_STR), QStringLiteral("GPL-3.0 / LGPL-3.0"));
#endif
#ifdef OCC_VERSION_COMPLETE
  libs += row(QStringLiteral("Open CASCADE"), QStringLiteral(OCC_VERSION_COMPLETE),
              QStringLiteral("LGPL-2.1 with exception"));
#endif
  libs += row(QStringLiteral("nlohmann/json"),
              QStringLiteral("%1.%2.%3")
                  .arg(NLOHMANN_JSON_VERSION_MAJOR)
                  .arg(NLOHMANN_JSON_VERSION_MINOR)
                  .arg(NLOHMANN_JSON_VERSION_PATCH),
              QStringLiteral("MIT"));
  libs += row(QStringLiteral("Assimp, urdfdom, CHOLMOD, TBB"), QObject::tr("as installed"), QString());

  QString robots;
  robots += row(QStringLiteral("KUKA KR 16-2"), QStringLiteral("ros-industrial/kuka_experimental"),
                QStringLiteral("Apache-2.0"));
  robots += row(QStringLiteral("FANUC M-20iA (ARC Mate 120iC)"), QStringLiteral("ros-industrial/fanuc"),
                QStringLiteral("BSD-3-Clause"));
  robots += row(QObject::tr("2-axis tilt-rotate positioner"), QObject::tr("written for Spira"),
                QObject::tr("Spira's licence"));

  return QObject::tr(
             "<h2>Spira %1</h2>"
             "<p>Continuous spiral path planning for robotic wire-arc additive manufacturing: one "
             "uninterrupted deposition path on a thin-walled part, from the part to the robot program.</p>"
             "<h3>Built with</h3><table>%2</table>"
             "<h3>Bundled robot descriptions</h3>"
             "<p>URDF models and meshes, each with its upstream licence file beside it "
             "(<tt>LICENSE-upstream</tt>):</p><table>%3</table>")
      .arg(QString::fromUtf8(kVersion), libs, robots);
}

void showAboutDialog(QWidget* parent)
{
  QDialog* d = textDialog(parent, QObject::tr("About Spira"), aboutText(), QSize(560, 520));
  d->setObjectName(QStringLiteral("aboutDialog"));
  d->setWindowIcon(QIcon(QStringLiteral(":/spira/icons/spira.svg")));
  d->exec();
  delete d;
}

QString shortcutsText(QMainWindow* window)
{
  std::vector<std::pair<QString, QString>> rows;
  QList<QAction*> pending = window->menuBar()->actions();
  while (!pending.isEmpty()) {
    QAction* a = pending.takeFirst();
    if (QMenu* sub = a->menu()) pending += sub->actions();
    if (a->shortcuts().isEmpty() || a->text().isEmpty()) continue;
    QStringList keys;
    for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText).toHtmlEscaped();
    rows.emplace_back(plainText(a->text()), keys.join(QStringLiteral(", ")));
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  QString html = QObject::tr("<h3>Keyboard shortcuts</h3><table cellpadding=\"3\">");
  for (const auto& [command, keys] : rows) html += row(command, QStringLiteral("<b>%1</b>").arg(keys));
  html += QObject::tr(
      "</table><p>In the 3D view: drag to rotate, Shift-drag or middle-drag to pan, wheel to "
      "zoom.</p>");
  return html;
}

QDialog* showShortcutsDialog(QMainWindow* window)
{
  QDialog* d = textDialog(window, QObject::tr("Keyboard Shortcuts"), shortcutsText(window), QSize(460, 560));
  d->setObjectName(QStringLiteral("shortcutsDialog"));
  d->setAttribute(Qt::WA_DeleteOnClose);
  d->show();
  return d;
}

}  // namespace spira::ui
