#include "spira/ui/window/comfort_features.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QBoxLayout>
#include <QComboBox>
#include <QDateTime>
#include <QDockWidget>
#include <QFileInfo>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QTimer>

#include "spira/base/error.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/placement_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/panels/preset_bar.h"
#include "spira/ui/panels/simulation_panel.h"
#include "spira/ui/views/interactive_quality.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/actions.h"
#include "spira/ui/window/autosave.h"
#include "spira/ui/window/guided_tour.h"
#include "spira/ui/window/help_dialogs.h"
#include "spira/ui/window/theme.h"

namespace spira::ui {

namespace {

QMenu* menuOf(QAction* action)
{
  if (!action) return nullptr;
  for (QWidget* w : action->associatedWidgets())
    if (auto* m = qobject_cast<QMenu*>(w)) return m;
  return nullptr;
}

}  // namespace

ComfortFeatures::ComfortFeatures(const WindowParts& parts, bool userSession, bool interactive)
    : QObject(&parts.window), parts_(parts), interactive_(interactive)
{
  setObjectName(QStringLiteral("comfortFeatures"));
  QMainWindow& window = parts.window;
  Document& doc = parts.doc;
  const Actions& actions = parts.actions;

  quality_ = new InteractiveQuality(&parts.view);
  InteractiveQuality* quality = quality_;
  // A new colouring or build range shows at once in a fast frame, then at full quality.
  connect(parts.display.channelCombo(), QOverload<int>::of(&QComboBox::currentIndexChanged), quality,
          &InteractiveQuality::fastFrame);
  connect(parts.display.revolutionSlider(), &QSlider::valueChanged, quality, &InteractiveQuality::fastFrame);
  connect(&parts.tasks, &TaskRunner::started, quality, &InteractiveQuality::hold);
  connect(&parts.tasks, &TaskRunner::finished, quality, &InteractiveQuality::release);
  connect(&parts.simulation, &SimulationPanel::playingChanged, quality,
          [quality](bool playing) { playing ? quality->hold() : quality->release(); });
  placement_ = new PlacementPanel(doc, &window);
  window.addDockWidget(Qt::LeftDockWidgetArea, placement_);
  window.tabifyDockWidget(&parts.display, placement_);
  connect(placement_, &PlacementPanel::failed, this,
          [this](const QString& message, const QString& hint) { parts_.log.error(message, hint); });
  parts.treeDock.raise();
  // A dock added to the column resets its width: give back the width the window chose.
  window.resizeDocks({&parts.treeDock}, {320}, Qt::Horizontal);

  presets_ = new PresetBar(doc, PresetStore(), &parts.plan);
  if (auto* box = qobject_cast<QBoxLayout*>(parts.plan.widget()->layout())) box->insertWidget(0, presets_);
  connect(presets_, &PresetBar::failed, this, [this](const QString& message, const QString& hint) {
    parts_.log.error(message, hint);
    if (!interactive_) return;
    QMessageBox box(QMessageBox::Warning, tr("Preset"), message, QMessageBox::Ok, &parts_.window);
    box.setInformativeText(hint);
    box.exec();
  });

  if (QMenu* view = menuOf(actions.viewIso)) {
    // The dock toggles close the menu: this one joins them.
    QAction* toggle = placement_->toggleViewAction();
    toggle->setText(tr("&Placement"));
    toggle->setToolTip(tr("Move, rotate and drop the part onto the substrate; choose its base"));
    view->addAction(toggle);
    view->addSeparator();
    themes_ = addThemeMenu(view, this, [this] { themeChanged(); });
    // The group hears of a choice before the theme is applied: a new style relayouts the window
    // and shrinks the docks to their minimum, so the layout is put back afterwards.
    connect(themes_, &QActionGroup::triggered, this,
            [this] { layoutBeforeTheme_ = parts_.window.saveState(); });
  }

  shortcuts_ = new QAction(tr("&Keyboard Shortcuts"), &window);
  shortcuts_->setObjectName(QStringLiteral("shortcutsAction"));
  shortcuts_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F1));
  shortcuts_->setShortcutContext(Qt::WindowShortcut);
  shortcuts_->setStatusTip(tr("List every keyboard shortcut"));
  connect(shortcuts_, &QAction::triggered, this, [this] { showShortcutsDialog(&parts_.window); });
  tour_ = new QAction(tr("&Guided Sample..."), &window);
  tour_->setObjectName(QStringLiteral("guidedTourAction"));
  tour_->setShortcut(QKeySequence::HelpContents);
  tour_->setShortcutContext(Qt::WindowShortcut);
  tour_->setStatusTip(tr("Open the sample dome, plan, inspect and export, step by step"));
  connect(tour_, &QAction::triggered, this, [this] {
    GuidedTour* g = guidedTour();
    g->show();
    g->raise();
  });
  window.addAction(shortcuts_);
  window.addAction(tour_);
  if (QMenu* help = menuOf(actions.about)) {
    help->insertAction(actions.about, tour_);
    help->insertAction(actions.about, shortcuts_);
    help->insertSeparator(actions.about);
  }

  if (userSession) {
    applyTheme(savedTheme());
    themeChanged();
    autosave_ = new Autosave(doc, {}, this);
    connect(autosave_, &Autosave::saveFailed, this, [this](const QString& message) {
      parts_.log.warning(tr("Autosave failed: %1").arg(message),
                         tr("Save the project yourself (Ctrl+S) to keep your work."));
    });
    // Reached only when the application quits normally: a crash leaves the recovery file.
    connect(qApp, &QCoreApplication::aboutToQuit, autosave_, &Autosave::finishCleanly);
    if (interactive) QTimer::singleShot(0, this, [this] { offerRecovery(false); });
  }
}

ComfortFeatures::~ComfortFeatures() = default;

GuidedTour* ComfortFeatures::guidedTour()
{
  if (!guide_) guide_ = new GuidedTour(parts_);
  return guide_;
}

void ComfortFeatures::offerRecovery(bool restoreWithoutAsking)
{
  if (!autosave_ || !autosave_->recoveryAvailable()) return;
  const QString from = autosave_->recoveredFrom();
  const QString what = from.isEmpty() ? tr("an untitled project") : QFileInfo(from).fileName();
  const QDateTime when = QFileInfo(autosave_->recoveryFile()).lastModified();
  if (!restoreWithoutAsking) {
    if (!interactive_) return;
    QMessageBox box(QMessageBox::Question, tr("Recover Work"),
                    tr("Spira did not close normally last time. Work on %1 was autosaved at %2.")
                        .arg(what, QLocale().toString(when, QLocale::ShortFormat)),
                    QMessageBox::NoButton, &parts_.window);
    box.setInformativeText(tr("Restore it? If you discard it, it is deleted."));
    QPushButton* restore = box.addButton(tr("Restore"), QMessageBox::AcceptRole);
    box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
    box.setDefaultButton(restore);
    box.exec();
    if (box.clickedButton() != static_cast<QAbstractButton*>(restore)) {
      autosave_->discard();
      return;
    }
  }
  try {
    autosave_->restore();
    parts_.log.info(tr("Recovered the autosaved work on %1; save it to keep it.").arg(what));
  } catch (const Error& e) {
    parts_.log.error(tr("The autosaved work could not be recovered: %1").arg(QString::fromUtf8(e.what())),
                     QString::fromStdString(e.hint()));
  }
}

void ComfortFeatures::themeChanged()
{
  if (!layoutBeforeTheme_.isEmpty()) {
    // After the style change's own relayout, which is posted.
    QTimer::singleShot(0, this, [this] {
      parts_.window.restoreState(layoutBeforeTheme_);
      layoutBeforeTheme_.clear();
    });
  }
  applySceneBackground(parts_.view.renderer());
  parts_.view.scheduleRender();
}

void ComfortFeatures::fileOpened(const QString& path, bool ok)
{
  if (guide_) guide_->onFileOpened(path, ok);
}

void ComfortFeatures::planFinished(const TaskOutcome& outcome)
{
  if (guide_) guide_->onPlanFinished(outcome);
}

}  // namespace spira::ui
