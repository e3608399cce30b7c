// Comfort features of the main window: presets per user, autosave and recovery after a crash,
// light and dark themes, the Help menu (About, shortcuts, guided sample), and the GUI thread
// staying responsive while a plan runs (UiWatchdog).
#include <atomic>
#include <chrono>
#include <iostream>
#include <thread>
#include <vector>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStyle>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include "builtin_plugins.h"

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/document/document.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/preset_bar.h"
#include "spira/ui/panels/presets.h"
#include "spira/ui/views/interactive_quality.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/autosave.h"
#include "spira/ui/window/comfort_features.h"
#include "spira/ui/window/guided_tour.h"
#include "spira/ui/window/help_dialogs.h"
#include "spira/ui/window/main_window.h"
#include "spira/ui/window/theme.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"
#include "support/ui_watchdog.h"

namespace spira::test {
namespace {

using ui::MainWindow;
using ui::MainWindowOptions;

ui::ComfortFeatures* comfortOf(MainWindow& w)
{
  return w.findChild<ui::ComfortFeatures*>();
}

QString domeFile()
{
  return qpath(sourceDir() / "resources" / "samples" / "dome.stl");
}

TEST(Presets, SaveLoadRoundTripAndBadNames)
{
  TempDir dir;
  ui::PresetStore store(qpath(dir.path() / "presets"));
  EXPECT_TRUE(store.names().isEmpty());
  PlanSettings s;
  s.decomposerId = "decomposer.isovalue";
  s.params[PlanSettings::kSpiralSection].set("h", 1.75);
  s.params[PlanSettings::kProcessSection].set("ts", 9.5);
  s.params["export.krl"].set("program_name", std::string("DOME_A"));
  store.save("Steel 2 mm", s);
  store.save("aluminium", PlanSettings{});
  EXPECT_EQ(store.names(), (QStringList{"aluminium", "Steel 2 mm"}));
  EXPECT_EQ(store.load("Steel 2 mm"), s);
  EXPECT_NE(store.load("aluminium"), s);
  EXPECT_THROW(store.save("", s), InputError);
  EXPECT_THROW(store.save("a/b", s), InputError);
  EXPECT_THROW(store.load("missing"), InputError);
  QFile damaged(qpath(dir.path() / "presets" / "broken.preset.json"));
  ASSERT_TRUE(damaged.open(QIODevice::WriteOnly));
  damaged.write("{ not json");
  damaged.close();
  EXPECT_THROW(store.load("broken"), InputError);
  EXPECT_TRUE(store.remove("aluminium"));
  EXPECT_FALSE(store.contains("aluminium"));
}

TEST(Presets, ApplyingOneIsOneUndoStepInThePlanPanel)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  ui::PresetBar* bar = comfortOf(w)->presetBar();
  ASSERT_NE(bar, nullptr);
  EXPECT_TRUE(w.planPanel()->isAncestorOf(bar));
  // The user's configuration folder (a private one in tests).
  EXPECT_TRUE(bar->store().directory().endsWith("/presets"));
  for (const QString& n : bar->store().names()) bar->remove(n);

  PlanSettings custom = *doc.settings();
  custom.params[PlanSettings::kSpiralSection].set("h", 2.4);
  custom.params[PlanSettings::kProcessSection].set("ts", 7.0);
  doc.setPlanSettings(custom);
  bar->saveCurrentAs("thick walls");
  EXPECT_EQ(bar->combo()->currentText(), "thick walls");
  const PlanSettings defaults;
  doc.setPlanSettings(defaults);
  ASSERT_NE(*doc.settings(), custom);
  const size_t steps = doc.undoStack().count();
  const int item = bar->combo()->findText("thick walls");
  ASSERT_GT(item, 0);
  emit bar->combo()->activated(item);
  EXPECT_EQ(*doc.settings(), custom);
  EXPECT_EQ(doc.undoStack().count(), steps + 1);
  EXPECT_EQ(doc.undoStack().undoText(), "Apply preset thick walls");
  doc.undo();
  EXPECT_EQ(*doc.settings(), defaults);
  bar->remove("thick walls");
  EXPECT_EQ(bar->combo()->count(), 1);
}

// A crash: the window and its autosave go away without the clean-exit call. The next session
// finds the recovery file and restores the same document.
TEST(Autosave, RecoversTheDocumentAfterACrash)
{
  TempDir dir;
  const QString recovery = qpath(dir.path() / "recovery");
  DocumentState crashed;
  {
    Document doc;
    MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
    ui::Autosave autosave(doc, {recovery, 40});
    EXPECT_FALSE(autosave.recoveryAvailable());
    ASSERT_TRUE(openAndWait(w, domeFile()));
    Transform T = Transform::Identity();
    T.translation() = Vec3(12.5, -3.0, 4.0);
    doc.setPartPlacement(T);
    doc.setParam(PlanSettings::kSpiralSection, "h", 2.2);
    autosave.waitForWrite();  // a write begun before the edits does not count
    QSignalSpy saved(&autosave, &ui::Autosave::saved);
    ASSERT_TRUE(waitFor([&] { return saved.count() > 0; }, 10000)) << "no autosave within 10 s";
    // Not over the user's file: the document has none, the copy is in the recovery folder.
    EXPECT_TRUE(QFile::exists(autosave.recoveryFile()));
    EXPECT_TRUE(autosave.recoveryFile().startsWith(recovery));
    crashed = doc.snapshot();
  }  // no finishCleanly(): as after a crash

  Document doc;
  ui::Autosave next(doc, {recovery, 1000000});
  ASSERT_TRUE(next.recoveryAvailable());
  EXPECT_TRUE(next.recoveredFrom().isEmpty());  // the work was untitled
  next.restore();
  ASSERT_TRUE(doc.part());
  EXPECT_EQ(*doc.part(), *crashed.part);
  EXPECT_TRUE(doc.part()->T_world_part.isApprox(crashed.part->T_world_part));
  EXPECT_EQ(*doc.settings(), *crashed.settings);
  EXPECT_EQ(*doc.substrate(), *crashed.substrate);
  EXPECT_TRUE(doc.isModified());  // recovered work is unsaved work
  EXPECT_TRUE(doc.filePath().empty());
  EXPECT_EQ(doc.undoStack().undoText(), "Recover autosaved work");

  next.finishCleanly();
  EXPECT_FALSE(QFile::exists(next.recoveryFile()));
  ui::Autosave after(doc, {recovery, 1000000});
  EXPECT_FALSE(after.recoveryAvailable());  // a clean exit leaves nothing to recover
}

TEST(Autosave, SecondLiveSessionNeitherRecoversNorOverwritesTheFirst)
{
  TempDir dir;
  const QString recovery = qpath(dir.path() / "recovery");
  Document a, b;
  ui::Autosave first(a, {recovery, 1000000});
  a.setParam(PlanSettings::kSpiralSection, "h", 2.1);
  ASSERT_TRUE(first.saveNow());
  first.waitForWrite();
  ui::Autosave second(b, {recovery, 1000000});
  EXPECT_FALSE(second.recoveryAvailable());  // the first session is alive, not crashed
  EXPECT_NE(second.recoveryFile(), first.recoveryFile());
  EXPECT_FALSE(second.saveNow());  // b is unmodified: nothing to save
}

TEST(Themes, LightAndDarkAreLegibleAndSaved)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, domeFile()));
  ASSERT_TRUE(planAndWait(w));
  ASSERT_TRUE(doc.results().spiral) << w.lastErrorMessage().toStdString();
  QActionGroup* themes = comfortOf(w)->themeActions();
  ASSERT_NE(themes, nullptr);
  ASSERT_EQ(themes->actions().size(), 3);
  QAction* light = w.findChild<QAction*>("theme_light");
  QAction* dark = w.findChild<QAction*>("theme_dark");
  QAction* system = w.findChild<QAction*>("theme_system");
  ASSERT_TRUE(light && dark && system);

  auto contrast = [](const QColor& a, const QColor& b) { return std::abs(a.lightness() - b.lightness()); };
  light->trigger();
  QTest::qWait(100);  // the layout is put back after the style's relayout
  EXPECT_EQ(QApplication::style()->objectName().toLower(), "fusion");
  EXPECT_FALSE(ui::paletteIsDark());
  EXPECT_EQ(QSettings().value("view/theme").toString(), "light");
  const QPalette lp = QApplication::palette();
  EXPECT_GT(contrast(lp.color(QPalette::WindowText), lp.color(QPalette::Window)), 150);
  const QImage lightImage = w.captureImage();
  const int lightDockWidth = w.displayPanel()->width();
  saveDocScreenshot(lightImage, "theme-light.png");

  dark->trigger();
  QTest::qWait(100);  // the layout is put back after the style's relayout
  EXPECT_TRUE(ui::paletteIsDark());
  EXPECT_EQ(ui::savedTheme(), ui::Theme::Dark);
  const QPalette dp = QApplication::palette();
  EXPECT_GT(contrast(dp.color(QPalette::WindowText), dp.color(QPalette::Window)), 150);
  EXPECT_GT(contrast(dp.color(QPalette::Text), dp.color(QPalette::Base)), 150);
  // Secondary text (palette(mid)) stays readable on the dark window.
  EXPECT_GT(contrast(dp.color(QPalette::Mid), dp.color(QPalette::Window)), 80);
  // The 3D view stays light enough for its dark labels and legends.
  double bg[3];
  w.sceneView()->renderer()->GetBackground(bg);
  EXPECT_GT(0.299 * bg[0] + 0.587 * bg[1] + 0.114 * bg[2], 0.45);
  const QImage darkImage = w.captureImage();
  // The docks keep their width across the change (a new style must not squeeze them).
  EXPECT_EQ(w.displayPanel()->width(), lightDockWidth);
  saveDocScreenshot(darkImage, "theme-dark.png");
  // The panels changed colour, not only the title bar: compare the left dock area.
  const QRect docks(0, 60, 300, 500);
  EXPECT_GT(meanDifference(lightImage, darkImage, docks), 40.0);
  EXPECT_GT(distinctColours(darkImage, sceneRect(w)), 400);

  system->trigger();
  EXPECT_EQ(ui::currentTheme(), ui::Theme::System);
}

TEST(HelpMenu, AboutShortcutsAndTheGuidedSample)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  const QString about = ui::aboutText();
  for (const char* text :
       {"0.1", "VTK", "Qt", "Eigen", "KUKA KR 16-2", "Apache-2.0", "FANUC M-20iA", "BSD-3-Clause"})
    EXPECT_TRUE(about.contains(text)) << text;
  const QString keys = ui::shortcutsText(&w);
  EXPECT_TRUE(keys.contains("Plan")) << keys.toStdString();
  EXPECT_TRUE(keys.contains("F5"));
  EXPECT_TRUE(keys.contains("Ctrl+Z"));
  EXPECT_TRUE(keys.contains("Guided Sample"));

  ui::ComfortFeatures* comfort = comfortOf(w);
  QMenu* help = nullptr;
  for (QAction* m : w.menuBar()->actions())
    if (m->text().remove('&') == "Help") help = m->menu();
  ASSERT_NE(help, nullptr);
  EXPECT_TRUE(help->actions().contains(comfort->tourAction()));
  EXPECT_TRUE(help->actions().contains(comfort->shortcutsAction()));

  ui::GuidedTour* tour = comfort->guidedTour();
  tour->show();
  EXPECT_FALSE(tour->isModal());
  EXPECT_EQ(tour->currentStep(), ui::GuidedTour::OpenSample);
  EXPECT_FALSE(tour->runStep(ui::GuidedTour::Plan));  // no part yet: says so, does nothing
  EXPECT_FALSE(w.planning());
  QSignalSpy opened(&w, &MainWindow::fileOpened);
  ASSERT_TRUE(tour->runStep(ui::GuidedTour::OpenSample));
  ASSERT_TRUE(waitFor([&] { return tour->isDone(ui::GuidedTour::OpenSample); }, 60000));
  ASSERT_TRUE(doc.part());
  // The dome made in code is the bundled sample.
  const size_t faces = doc.part()->mesh->faceCount();
  ASSERT_TRUE(openAndWait(w, domeFile()));
  EXPECT_EQ(doc.part()->mesh->faceCount(), faces);
  doc.undo();
  EXPECT_EQ(tour->currentStep(), ui::GuidedTour::Plan);
  ASSERT_TRUE(tour->runStep());
  ASSERT_TRUE(waitFor([&] { return tour->isDone(ui::GuidedTour::Plan); }, 240000));
  EXPECT_TRUE(doc.results().spiral);
  ASSERT_TRUE(tour->runStep());  // inspect
  EXPECT_TRUE(tour->isDone(ui::GuidedTour::Inspect));
  EXPECT_TRUE(w.displayPanel()->isVisible());
  EXPECT_EQ(tour->currentStep(), ui::GuidedTour::Export);
  // Export opens the export dialog when the window has an export command; close what it opens.
  QTimer closer;
  QObject::connect(&closer, &QTimer::timeout, [] {
    if (QWidget* modal = QApplication::activeModalWidget()) modal->close();
  });
  closer.start(50);
  const bool exported = tour->runStep();
  QTest::qWait(300);
  EXPECT_EQ(exported, tour->isDone(ui::GuidedTour::Export));
  tour->close();
}

// While a job runs the 3D view draws fast frames (no multisampling, thin lines); screenshots are
// still drawn at full quality, and full quality returns once the job is over and the view still.
TEST(InteractiveQuality, FastWhileAJobRunsFullQualityAfterwardsAndInPictures)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  auto* quality = w.sceneView()->findChild<ui::InteractiveQuality*>();
  ASSERT_NE(quality, nullptr);
  vtkRenderWindow* rw = w.sceneView()->renderer()->GetRenderWindow();
  const int samples = rw->GetMultiSamples();
  ASSERT_GT(samples, 0);
  ASSERT_TRUE(openAndWait(w, domeFile()));
  ASSERT_TRUE(waitFor([&] { return !quality->fast(); }, 10000));
  EXPECT_EQ(rw->GetMultiSamples(), samples);

  // The multisampling of every frame drawn while the plan runs.
  std::vector<int> frames;
  vtkNew<vtkCallbackCommand> onRender;
  onRender->SetClientData(&frames);
  onRender->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    static_cast<std::vector<int>*>(data)->push_back(static_cast<vtkRenderWindow*>(caller)->GetMultiSamples());
  });
  const unsigned long tag = rw->AddObserver(vtkCommand::StartEvent, onRender);
  // A job that runs until the test lets it finish: the checks cannot race its end.
  std::atomic<bool> finish{false};
  ASSERT_TRUE(w.taskRunner()->start(
      "Held job",
      [&finish](Progress& progress) {
        while (!finish) {
          progress.checkCancel();
          std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
      },
      [](const ui::TaskOutcome&) {}, ui::TaskRunner::Display::Signals));
  EXPECT_TRUE(quality->held());
  // Waits for the frames themselves, not a fixed time: a loaded machine renders later.
  const size_t before = frames.size();
  w.sceneView()->scheduleRender();  // a frame while the job runs: fast
  EXPECT_TRUE(waitFor([&] { return frames.size() > before; }, 10000));
  const size_t captureFrame = frames.size();
  w.captureImage();  // a picture: full quality, then fast again
  EXPECT_TRUE(quality->held());
  EXPECT_TRUE(quality->fast());
  w.sceneView()->scheduleRender();
  EXPECT_TRUE(waitFor([&] { return frames.size() > captureFrame + 1; }, 10000));
  finish = true;
  ASSERT_TRUE(waitFor([&] { return !w.taskRunner()->busy(); }, 10000));
  rw->RemoveObserver(tag);
  ASSERT_GT(captureFrame, 0u);
  ASSERT_GT(frames.size(), captureFrame + 1);
  for (size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(frames[i], i == captureFrame ? samples : 0) << "frame " << i;
  EXPECT_FALSE(quality->held());
  ASSERT_TRUE(waitFor([&] { return !quality->fast(); }, 10000));
  EXPECT_EQ(rw->GetMultiSamples(), samples);
}

TEST(UiWatchdog, SeesABlockedGuiThread)
{
  ui::UiWatchdog dog(10);
  dog.start();
  QTest::qWait(50);
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // the GUI thread blocked
  QTest::qWait(30);
  dog.stop();
  EXPECT_GE(dog.worstGapMs(), 150.0);
  EXPECT_GT(dog.ticks(), 3);
}

// The Speed goal is a 100 ms worst stall (bench_render reports the measured value); the bound
// asserted here is loose so a loaded CI machine does not fail it, yet a plan run on the GUI
// thread (seconds) would.
TEST(UiWatchdog, TheGuiThreadStaysResponsiveWhileTheDomePlans)
{
  Document doc;
  MainWindow w(doc, builtinRegistry(), MainWindowOptions{false, false});
  showAndWait(w);
  ASSERT_TRUE(openAndWait(w, domeFile()));
  ui::UiWatchdog dog(10);
  dog.start();
  ASSERT_TRUE(planAndWait(w));
  dog.stop();
  ASSERT_TRUE(doc.results().spiral) << w.lastErrorMessage().toStdString();
  std::cout << "[ watchdog ] dome plan: worst GUI gap " << dog.worstGapMs() << " ms, mean " << dog.meanGapMs()
            << " ms over " << dog.ticks() << " ticks\n";
  EXPECT_GT(dog.ticks(), 0);
  EXPECT_LT(dog.worstGapMs(), 500.0);
}

}  // namespace
}  // namespace spira::test
