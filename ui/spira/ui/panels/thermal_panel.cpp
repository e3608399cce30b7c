#include "spira/ui/panels/thermal_panel.h"

#include <algorithm>
#include <cmath>

#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include "spira/document/results.h"
#include "spira/pipeline/planned_path.h"
#include "spira/ui/charts/probe_chart.h"
#include "spira/ui/panels/simulation_clock.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/thermal_layer.h"

namespace spira::ui {

namespace {

constexpr int kPlaybackMs = 80;  // per frame: the dome's 200 frames in 16 s

QString durationText(double s)
{
  const QLocale loc;
  if (s < 120.0) return QObject::tr("%1 s").arg(loc.toString(s, 'f', 1));
  const auto whole = static_cast<long long>(std::lround(s));
  return QObject::tr("%1 min %2 s").arg(whole / 60).arg(whole % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace

ThermalPanel::ThermalPanel(SceneView& view, QWidget* parent) : QDockWidget(tr("Thermal"), parent), view_(view)
{
  setObjectName(QStringLiteral("thermalDock"));
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  layout->setContentsMargins(4, 4, 4, 4);
  summary_ = new QLabel(body);
  summary_->setObjectName(QStringLiteral("thermalSummary"));
  summary_->setTextFormat(Qt::RichText);
  summary_->setWordWrap(true);
  layout->addWidget(summary_);

  auto* row = new QHBoxLayout;
  show_ = new QToolButton(body);
  show_->setObjectName(QStringLiteral("thermalShowOnPart"));
  show_->setText(tr("Show on the part"));
  show_->setToolTip(tr("Colour the deposit by its temperature at the time chosen on the slider"));
  connect(show_, &QToolButton::clicked, this, &ThermalPanel::showOnPart);
  row->addWidget(show_);
  playPause_ = new QToolButton(body);
  playPause_->setObjectName(QStringLiteral("thermalPlay"));
  playPause_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  playPause_->setToolTip(tr("Play the build's temperatures"));
  connect(playPause_, &QToolButton::clicked, this, [this] { playing() ? pause() : play(); });
  row->addWidget(playPause_);
  slider_ = new QSlider(Qt::Horizontal, body);
  slider_->setObjectName(QStringLiteral("thermalFrameSlider"));
  slider_->setToolTip(tr("The time of the build shown on the part"));
  connect(slider_, &QSlider::valueChanged, this, &ThermalPanel::frameChanged);
  row->addWidget(slider_, 1);
  time_ = new QLabel(body);
  time_->setObjectName(QStringLiteral("thermalTime"));
  time_->setMinimumWidth(
      time_->fontMetrics().horizontalAdvance(QStringLiteral("t = 000 min 00 s of 000 min 00 s")));
  row->addWidget(time_);
  layout->addLayout(row);

  chart_ = new ProbeChart(body);
  chart_->setMinimumHeight(140);
  layout->addWidget(chart_, 1);
  setWidget(body);

  timer_.setInterval(kPlaybackMs);
  connect(&timer_, &QTimer::timeout, this, [this] {
    if (slider_->value() >= slider_->maximum())
      pause();
    else
      slider_->setValue(slider_->value() + 1);
  });
  setResults(Results());
}

void ThermalPanel::setResults(const Results& r)
{
  pause();
  result_ = r.thermal && !r.thermal->frames.empty() ? r.thermal : nullptr;
  const ThermalStageReport* report = r.reports.thermal.get();
  const std::shared_ptr<const Trajectory> path = processPathOf(r);
  pointTimes_.clear();
  if (result_ && path && path->size() == result_->pointCount()) {
    const SimulationClock clock(*path);
    for (size_t i = 0; i < clock.size(); ++i) pointTimes_.push_back(clock.time(i));
  }
  const QLocale loc;
  if (!result_ || !report) {
    summary_->setText(
        tr("No thermal results. Enable <i>Simulate the heat of the build</i> on the Plan dock's "
           "Thermal tab and plan (F5)."));
  } else {
    QString limit;
    if (report->interpassLimit > 0.0)
      limit = report->pointsOverLimit > 0
                  ? tr(", <span style='color:#be2828'>above the %1 °C limit at %2 points</span>")
                        .arg(loc.toString(report->interpassLimit, 'f', 0),
                             loc.toString(qlonglong(report->pointsOverLimit)))
                  : tr(", within the %1 °C limit").arg(loc.toString(report->interpassLimit, 'f', 0));
    const QString risk = report->riskPoints > 0
                             ? tr("<span style='color:#be2828'><b>%1 points at risk of collapse</b></span>")
                                   .arg(loc.toString(qlonglong(report->riskPoints)))
                             : tr("<b>no collapse risk</b>");
    summary_->setText(
        tr("%1 (melts at %2 °C), %3 W: peak up to %4 °C, interpass up to %5 °C%6; %7 (Bond number up to %8). "
           "Energy in %9 kJ, stored %10 kJ, lost %11 kJ. %12 nodes, %13 steps over %14.")
            .arg(QString::fromStdString(report->material), loc.toString(report->meltingTemperature, 'f', 0),
                 loc.toString(report->power, 'f', 0), loc.toString(report->maxPeak, 'f', 0),
                 loc.toString(report->maxInterpass, 'f', 0), limit, risk,
                 loc.toString(report->maxBond, 'f', 2), loc.toString(report->energyIn / 1000.0, 'f', 1))
            .arg(loc.toString(report->energyStored / 1000.0, 'f', 1),
                 loc.toString(report->energyLost / 1000.0, 'f', 1), loc.toString(qlonglong(report->nodes)),
                 loc.toString(qlonglong(report->steps)), durationText(report->simulatedTime)));
  }
  for (QWidget* w :
       {static_cast<QWidget*>(slider_), static_cast<QWidget*>(show_), static_cast<QWidget*>(playPause_)})
    w->setEnabled(result_ != nullptr);
  hottest_ = -1;
  if (result_)
    for (size_t i = 0; i < result_->interpass.size(); ++i)
      if (std::isfinite(result_->interpass[i]) &&
          (hottest_ < 0 || result_->interpass[i] > result_->interpass[static_cast<size_t>(hottest_)]))
        hottest_ = static_cast<long long>(i);
  chart_->setResult(result_, report ? report->meltingTemperature : 0.0,
                    report ? report->interpassLimit : 0.0);
  setPoint(selected_ >= 0 && result_ && static_cast<size_t>(selected_) < result_->pointCount() ? selected_
                                                                                               : -1);
  const QSignalBlocker block(slider_);
  slider_->setRange(0, result_ ? static_cast<int>(result_->frames.size()) - 1 : 0);
  slider_->setValue(slider_->maximum());
  frameChanged(slider_->value());
}

void ThermalPanel::setPoint(long long index)
{
  selected_ = index;
  // Nothing selected: the hottest point at the torch's return, the one the limit is about.
  if (index < 0) index = hottest_;
  const bool known = index >= 0 && static_cast<size_t>(index) < pointTimes_.size();
  chart_->setPoint(index, known ? pointTimes_[static_cast<size_t>(index)] : -1.0);
}

void ThermalPanel::setTime(double t)
{
  if (result_) slider_->setValue(static_cast<int>(result_->frames.frameAt(t)));
}

void ThermalPanel::setTimeOfPoint(long long index)
{
  if (index >= 0 && static_cast<size_t>(index) < pointTimes_.size())
    setTime(pointTimes_[static_cast<size_t>(index)]);
}

void ThermalPanel::showOnPart()
{
  if (!result_) return;
  view_.setPartStyle(PartStyle::Temperature);
  emit partStyleChanged();
}

void ThermalPanel::play()
{
  if (!result_) return;
  if (slider_->value() >= slider_->maximum()) slider_->setValue(0);
  timer_.start();
  playPause_->setIcon(style()->standardIcon(QStyle::SP_MediaPause));
}

void ThermalPanel::pause()
{
  timer_.stop();
  playPause_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
}

void ThermalPanel::frameChanged(int frame)
{
  ThermalLayer& layer = view_.thermalLayer();
  if (!result_) {
    time_->setText(QString());
    chart_->setCursorTime(-1.0);
    return;
  }
  layer.setFrame(static_cast<size_t>(std::max(0, frame)));
  const double t = layer.frameTime();
  time_->setText(tr("t = %1 of %2").arg(durationText(t), durationText(result_->frames.times.back())));
  chart_->setCursorTime(t);
  view_.scheduleRender();
}

}  // namespace spira::ui
