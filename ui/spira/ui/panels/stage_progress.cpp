#include "spira/ui/panels/stage_progress.h"

#include <algorithm>
#include <cmath>

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStyle>

#include "spira/ui/window/status_line.h"

namespace spira::ui {

StageProgress::StageProgress(QWidget* parent) : QWidget(parent)
{
  setObjectName(QStringLiteral("stageProgress"));
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 4, 0, 0);
  grid->setVerticalSpacing(2);
  what_ = new StatusLine(this);
  what_->setObjectName(QStringLiteral("stageText"));
  grid->addWidget(what_, 0, 0, 1, 2);
  const auto& spans = planStageSpans();
  for (int i = 0; i < kPlanStageCount; ++i) {
    labels_[i] = new QLabel(tr(spans[static_cast<size_t>(i)].label), this);
    bars_[i] = new QProgressBar(this);
    bars_[i]->setRange(0, 100);
    bars_[i]->setTextVisible(true);
    bars_[i]->setMaximumHeight(fontMetrics().height() + 2);
    grid->addWidget(labels_[i], i + 1, 0);
    grid->addWidget(bars_[i], i + 1, 1);
  }
  cancel_ = new QPushButton(style()->standardIcon(QStyle::SP_DialogCancelButton), tr("Cancel"), this);
  cancel_->setObjectName(QStringLiteral("cancelPlan"));
  cancel_->setToolTip(tr("Stop planning; the previous results stay (Esc)"));
  connect(cancel_, &QPushButton::clicked, this, &StageProgress::cancelRequested);
  grid->addWidget(cancel_, kPlanStageCount + 1, 1, Qt::AlignRight);
  // The optional thermal stage's row only while a plan runs it, so the dock keeps its size otherwise.
  labels_[kThermalPlanStage]->hide();
  bars_[kThermalPlanStage]->hide();
  grid->setColumnStretch(1, 1);
}

void StageProgress::start(bool thermal)
{
  labels_[kThermalPlanStage]->setVisible(thermal);
  bars_[kThermalPlanStage]->setVisible(thermal);
  running_ = true;
  current_ = 0;
  for (QProgressBar* b : bars_) b->setValue(0);
  what_->setText(tr("Starting..."));
  highlightStage(0);
  cancel_->setEnabled(true);
  emit runningChanged(true);
}

void StageProgress::highlightStage(int stage)
{
  if (stage == highlighted_) return;
  highlighted_ = stage;
  for (int i = 0; i < kPlanStageCount; ++i) {
    QPalette p = palette();
    if (i == stage) p.setColor(QPalette::WindowText, p.color(QPalette::Highlight));
    labels_[static_cast<size_t>(i)]->setPalette(p);
  }
}

void StageProgress::setProgress(double fraction, const QString& what)
{
  const auto& spans = planStageSpans();
  current_ = planStageAt(fraction);
  for (int i = 0; i < kPlanStageCount; ++i) {
    const PlanStageSpan& s = spans[static_cast<size_t>(i)];
    const double within = std::clamp((fraction - s.begin) / (s.end - s.begin), 0.0, 1.0);
    bars_[i]->setValue(i < current_ ? 100 : i > current_ ? 0 : static_cast<int>(std::floor(100.0 * within)));
  }
  highlightStage(current_);
  if (!what.isEmpty()) what_->setText(what.left(1).toUpper() + what.mid(1) + QStringLiteral("..."));
}

void StageProgress::stop()
{
  running_ = false;
  cancel_->setEnabled(false);
  highlightStage(-1);
  emit runningChanged(false);
}

bool StageProgress::stageShown(int stage) const
{
  return !bars_.at(static_cast<size_t>(stage))->isHidden();
}

int StageProgress::stagePercent(int stage) const
{
  return bars_.at(static_cast<size_t>(stage))->value();
}

}  // namespace spira::ui
