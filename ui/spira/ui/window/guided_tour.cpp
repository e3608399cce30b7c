#include "spira/ui/window/guided_tour.h"

#include <QAction>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMainWindow>
#include <QPushButton>
#include <QStandardPaths>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include "spira/base/error.h"
#include "spira/document/document.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/display_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/window/actions.h"

namespace spira::ui {

namespace {

struct StepText {
  const char* title;
  const char* detail;
};

const StepText kSteps[GuidedTour::StepCount] = {
    {QT_TRANSLATE_NOOP("GuidedTour", "1. Open the sample dome"),
     QT_TRANSLATE_NOOP("GuidedTour",
                       "A hemisphere of radius 60 mm standing on the substrate. Your own parts come in "
                       "with File > Import Part (Ctrl+I) or by dropping a file on the window.")},
    {QT_TRANSLATE_NOOP("GuidedTour", "2. Plan the spiral"),
     QT_TRANSLATE_NOOP("GuidedTour",
                       "Plan (F5) computes the field, the generatrices, the spiral and the process on a "
                       "worker thread: the window stays usable and Esc cancels.")},
    {QT_TRANSLATE_NOOP("GuidedTour", "3. Inspect the result"),
     QT_TRANSLATE_NOOP("GuidedTour",
                       "The Display panel colours the spiral by deposit height, speed or wire feed; its "
                       "revolution slider shows the build layer by layer. Drag in the view to turn it.")},
    {QT_TRANSLATE_NOOP("GuidedTour", "4. Export the robot program"),
     QT_TRANSLATE_NOOP("GuidedTour",
                       "The export dialog writes KUKA KRL or FANUC TP with a preview of the first lines "
                       "and the warnings to read before writing.")},
};

QString translated(const char* text)
{
  return QCoreApplication::translate("GuidedTour", text);
}

}  // namespace

GuidedTour::GuidedTour(const WindowParts& parts) : QDialog(&parts.window, Qt::Tool), parts_(parts)
{
  setObjectName(QStringLiteral("guidedTour"));
  setWindowTitle(tr("Guided Sample"));
  setModal(false);
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  for (const StepText& s : kSteps) list_->addItem(translated(s.title));
  list_->setMaximumHeight(list_->sizeHintForRow(0) * (StepCount + 1) + 8);
  layout->addWidget(list_);
  detail_ = new QLabel(this);
  detail_->setWordWrap(true);
  detail_->setMinimumHeight(64);
  detail_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  layout->addWidget(detail_);
  auto* buttons = new QHBoxLayout;
  doIt_ = new QPushButton(tr("Do It"), this);
  doIt_->setDefault(true);
  next_ = new QPushButton(tr("Next"), this);
  auto* close = new QPushButton(tr("Close"), this);
  buttons->addWidget(doIt_);
  buttons->addWidget(next_);
  buttons->addStretch(1);
  buttons->addWidget(close);
  layout->addLayout(buttons);
  resize(420, 300);

  connect(doIt_, &QPushButton::clicked, this, [this] { runStep(); });
  connect(next_, &QPushButton::clicked, this, [this] { setCurrent(std::min(current_ + 1, StepCount - 1)); });
  connect(close, &QPushButton::clicked, this, &QDialog::close);
  connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
    if (row >= 0 && row != current_) setCurrent(row);
  });
  setCurrent(0);
}

QString GuidedTour::sampleDomeFile()
{
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
         QStringLiteral("/samples/dome.stl");
}

bool GuidedTour::isDone(int step) const
{
  return step >= 0 && step < StepCount && done_[step];
}

void GuidedTour::setCurrent(int step)
{
  current_ = step;
  list_->setCurrentRow(step);
  detail_->setText(translated(kSteps[step].detail));
  next_->setEnabled(step < StepCount - 1);
  for (int i = 0; i < StepCount; ++i) {
    QListWidgetItem* item = list_->item(i);
    QFont f = item->font();
    f.setBold(i == current_);
    item->setFont(f);
  }
}

void GuidedTour::markDone(int step)
{
  done_[step] = true;
  list_->item(step)->setIcon(style()->standardIcon(QStyle::SP_DialogApplyButton));
  if (step == current_ && step + 1 < StepCount) setCurrent(step + 1);
}

bool GuidedTour::runStep(int step)
{
  if (step < 0) step = current_;
  setCurrent(step);
  if (parts_.busy() && step != Inspect) {
    detail_->setText(tr("Spira is busy with another task; wait for it to finish, then press Do It again."));
    return false;
  }
  switch (step) {
    case OpenSample: {
      const QString file = sampleDomeFile();
      try {
        QDir().mkpath(QFileInfo(file).path());
        const int segments = segmentsForEdge(60.0, 2.0);
        writeMesh(makeHemisphere(60.0, segments, segments / 4), std::filesystem::path(file.toStdString()));
      } catch (const Error& e) {
        detail_->setText(tr("Could not write the sample: %1").arg(QString::fromStdString(e.fullMessage())));
        return false;
      }
      samplePath_ = file;
      parts_.openFile(file);
      return true;
    }
    case Plan:
      if (!parts_.doc.part()) {
        detail_->setText(tr("Open the sample dome first (step 1)."));
        return false;
      }
      highlight(parts_.plan.planButton());
      parts_.runPlan();
      return true;
    case Inspect:
      parts_.display.show();
      parts_.display.raise();
      parts_.view.setCameraPreset(CameraPreset::Iso);
      highlight(parts_.display.channelCombo());
      markDone(Inspect);
      return true;
    case Export: {
      QAction* exportAction = parts_.actions.exportProgram;
      if (!exportAction || !exportAction->isEnabled()) {
        detail_->setText(exportAction ? tr("Export needs a plan: do step 2 first.")
                                      : tr("This build has no export command."));
        return false;
      }
      markDone(Export);
      // After this call returns: the export dialog may be modal.
      QTimer::singleShot(0, exportAction, &QAction::trigger);
      return true;
    }
    default:
      return false;
  }
}

void GuidedTour::onFileOpened(const QString& path, bool ok)
{
  if (ok && !samplePath_.isEmpty() && QFileInfo(path) == QFileInfo(samplePath_)) markDone(OpenSample);
}

void GuidedTour::onPlanFinished(const TaskOutcome& outcome)
{
  if (outcome.succeeded() && parts_.doc.results().spiral) markDone(Plan);
}

void GuidedTour::highlight(QWidget* widget)
{
  if (!widget) return;
  QPointer<QWidget> target(widget);
  const QString before = widget->styleSheet();
  const QString border = QStringLiteral("border: 2px solid palette(highlight);");
  widget->setStyleSheet(before.isEmpty() ? border : before + QLatin1Char(';') + border);
  QTimer::singleShot(1500, this, [target, before] {
    if (target) target->setStyleSheet(before);
  });
}

}  // namespace spira::ui
