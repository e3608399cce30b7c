// The export dialog on a planned cylinder: the exporter's schema as a panel, a preview of each
// file it would write, the warnings before writing, and the files written where asked (all or
// none), read back.
#include <fstream>

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTabWidget>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include "builtin_plugins.h"

#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/path/tool_frame.h"
#include "spira/ui/jobs/export_request.h"
#include "spira/ui/panels/export_dialog.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/param_field.h"
#include "spira/ui/panels/param_panel.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::ExportDialog;
using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;

// Waits until the preview the last change asked for has run; returns whether it could.
bool waitPreview(ExportDialog* d)
{
  waitFor([] { return false; }, 50);
  if (!waitFor([&] { return !d->previewBusy(); }, 120000)) return false;
  return d->previewOk();
}

QString tabText(ExportDialog* d, int i)
{
  return static_cast<QPlainTextEdit*>(d->previewTabs()->widget(i))->toPlainText();
}

bool logContains(MainWindow& w, const QString& text)
{
  for (int i = 0; i < w.logPanel()->count(); ++i)
    if (w.logPanel()->text(i).contains(text)) return true;
  return false;
}

TEST(ExportDialog, PreviewsWarnsAndWritesTheProgram)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);

  // Before a plan there is nothing to export: the dialog says so and Export is off.
  w.actions().exportProgram->trigger();
  ExportDialog* d = w.exportDialog();
  ASSERT_TRUE(waitFor([&] { return d->isVisible(); }, 5000));
  EXPECT_FALSE(waitPreview(d));
  EXPECT_FALSE(d->exportButton()->isEnabled());
  EXPECT_TRUE(d->summaryLabel()->text().contains("Plan the part first"));
  d->close();

  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().process);
  w.actions().exportProgram->trigger();
  ASSERT_TRUE(waitFor([&] { return d->isVisible(); }, 5000));

  // KRL: the exporter's schema as a panel, the .src and .dat pair previewed.
  d->setExporter("export.krl");
  ASSERT_TRUE(waitPreview(d)) << d->summaryLabel()->text().toStdString();
  ASSERT_NE(d->exporterPanel("export.krl"), nullptr);
  EXPECT_NE(d->exporterPanel("export.krl")->field("force"), nullptr);
  ASSERT_EQ(d->previewTabs()->count(), 2);
  EXPECT_TRUE(d->previewTabs()->tabText(0).endsWith(".src")) << d->previewTabs()->tabText(0).toStdString();
  EXPECT_TRUE(d->previewTabs()->tabText(1).endsWith(".dat"));
  const QString src = tabText(d, 0);
  EXPECT_TRUE(src.contains("DEF ")) << src.toStdString();
  EXPECT_TRUE(src.contains("cylinder")) << "the header names the part\n" << src.toStdString();
  EXPECT_LE(src.count('\n'), ExportDialog::kPreviewLines + 2);
  EXPECT_TRUE(src.contains("more line")) << "a long file says how much is not shown";
  // Without a cell the targets are part-frame poses: said before anything is written.
  EXPECT_TRUE(d->warnings().join(' ').contains("No robot cell")) << d->warnings().join('|').toStdString();

  // A parameter edited in the panel changes the preview: the program name.
  d->setExporterValue("program_name", std::string("wall_test"));
  ASSERT_TRUE(waitPreview(d));
  EXPECT_EQ(d->previewTabs()->tabText(0).toLower(), "wall_test.src");

  // FANUC TP: one .ls file, written into the folder chosen, reported in the messages panel.
  d->setExporter("export.fanuc_tp");
  ASSERT_TRUE(waitPreview(d));
  ASSERT_EQ(d->previewTabs()->count(), 1);
  EXPECT_TRUE(tabText(d, 0).startsWith("/PROG")) << tabText(d, 0).left(200).toStdString();
  const std::filesystem::path out = dir / "program";
  std::filesystem::create_directories(out);
  d->setOutputFolder(qpath(out));
  QSignalSpy written(d, &ExportDialog::exported);
  d->exportButton()->click();
  ASSERT_TRUE(waitFor([&] { return !written.isEmpty(); }, 60000));
  ASSERT_TRUE(written.first().at(0).toBool()) << d->summaryLabel()->text().toStdString();
  const QStringList files = written.first().at(1).toStringList();
  ASSERT_EQ(files.size(), 1);
  ASSERT_TRUE(std::filesystem::exists(files[0].toStdString()));
  EXPECT_TRUE(logContains(w, "Exported")) << "the messages panel names the files";
  EXPECT_EQ(doc.settings()->section("export.fanuc_tp").values().size(), 0u) << "defaults stay defaults";

  // Read back: the first arc move's target is the first planned point's TCP pose (part frame).
  std::ifstream in(files[0].toStdString(), std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\r\n"), std::string::npos) << "TP files have CRLF line endings";
  const QString all = QString::fromStdString(text);
  const QRegularExpressionMatch arc = QRegularExpression(QStringLiteral(R"(\d+:\s+Arc Start\[)")).match(all);
  ASSERT_TRUE(arc.hasMatch()) << "one arc start";
  const QString beforeArc = all.left(arc.capturedStart(0));
  QString lastTarget;
  QRegularExpressionMatchIterator moves =
      QRegularExpression(QStringLiteral(R"(L P\[(\d+)\])")).globalMatch(beforeArc);
  while (moves.hasNext()) lastTarget = moves.next().captured(1);
  ASSERT_FALSE(lastTarget.isEmpty()) << "the arc starts after a linear move onto its first point\n"
                                     << beforeArc.toStdString();
  const QRegularExpressionMatch pose =
      QRegularExpression(
          QStringLiteral("P\\[") + lastTarget +
          QStringLiteral(
              R"(\]\{[\s\S]*?X =\s*(-?[\d.]+)\s*mm,\s*Y =\s*(-?[\d.]+)\s*mm,\s*Z =\s*(-?[\d.]+)\s*mm,\s*W =\s*(-?[\d.]+)\s*deg,\s*P =\s*(-?[\d.]+)\s*deg,\s*R =\s*(-?[\d.]+)\s*deg)"))
          .match(all);
  ASSERT_TRUE(pose.hasMatch());
  const auto m = [&](int k) { return pose.captured(k).toDouble(); };
  const TrajectoryPoint& first = doc.results().process->points.front();
  EXPECT_NEAR(m(1), first.position.x(), 0.01);
  EXPECT_NEAR(m(2), first.position.y(), 0.01);
  EXPECT_NEAR(m(3), first.position.z(), 0.01);
  // WPR: R = Rz(r) Ry(p) Rx(w); its z axis is the torch axis, -build.
  const double deg = kPi / 180.0;
  const Mat3 R = (Eigen::AngleAxisd(m(6) * deg, Vec3::UnitZ()) *
                  Eigen::AngleAxisd(m(5) * deg, Vec3::UnitY()) * Eigen::AngleAxisd(m(4) * deg, Vec3::UnitX()))
                     .toRotationMatrix();
  EXPECT_LT((R.col(2) - toolFrame(first).linear().col(2)).norm(), 1e-4);

  // A folder that cannot be written fails before anything is written.
  d->setOutputFolder(qpath(dir / "missing" / "folder"));
  written.clear();
  d->exportProgram();
  ASSERT_FALSE(written.isEmpty());
  EXPECT_FALSE(written.first().at(0).toBool());
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
  d->close();
}

// The formats added for ABB and gantry cells are offered by the same dialog, each with its preview:
// a RAPID module with one ArcLStart and one ArcLEnd, and G-code for the bundled machine file.
TEST(ExportDialog, PreviewsRapidAndGcode)
{
  TempDir dir;
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, qpath(writeOpenCylinderStl(dir.path()))));
  ASSERT_TRUE(planAndWait(w));
  w.actions().exportProgram->trigger();
  ExportDialog* d = w.exportDialog();
  ASSERT_TRUE(waitFor([&] { return d->isVisible(); }, 5000));

  d->setExporter("export.rapid");
  ASSERT_TRUE(waitPreview(d)) << d->summaryLabel()->text().toStdString();
  ASSERT_GE(d->previewTabs()->count(), 1);
  EXPECT_TRUE(d->previewTabs()->tabText(0).endsWith(".mod")) << d->previewTabs()->tabText(0).toStdString();
  const QString mod = tabText(d, 0);
  EXPECT_TRUE(mod.startsWith("%%%") || mod.contains("MODULE ")) << mod.left(300).toStdString();

  // G-code needs its machine: refused with the reason until one is given.
  d->setExporter("export.gcode");
  EXPECT_FALSE(waitPreview(d));
  d->setExporterValue("machine", (sourceDir() / "resources/machines/gantry_ca_head.machine").string());
  ASSERT_TRUE(waitPreview(d)) << d->summaryLabel()->text().toStdString();
  ASSERT_EQ(d->previewTabs()->count(), 1);
  EXPECT_TRUE(d->previewTabs()->tabText(0).endsWith(".nc")) << d->previewTabs()->tabText(0).toStdString();
  EXPECT_TRUE(tabText(d, 0).contains("G1 ")) << tabText(d, 0).left(300).toStdString();
  d->close();
}

TEST(ExportRequest, WarnsAboutPointsOutsideTheWindowFromThePlan)
{
  Results r;
  Trajectory t;
  for (double h : {2.0, 2.0, 2.6, 1.2, 2.0}) {
    TrajectoryPoint p;
    p.height = h;
    t.points.push_back(p);
  }
  SpiralStageReport window;
  window.h = 2.0;
  window.hMin = 1.8;
  window.hMax = 2.2;
  window.heightTolerance = 0.01;
  r.setSpiral(std::make_shared<const Trajectory>(t), std::make_shared<const SpiralStageReport>(window));
  r.setProcess(std::make_shared<const Trajectory>(t));
  const auto warnings = ui::exportWarnings(r, nullptr);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("2 planned point(s)", 0), 0u) << warnings[0];
}

}  // namespace
}  // namespace spira::test
