#include "spira/ui/panels/simulation_panel.h"

#include <algorithm>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include "spira/document/kinematics_result.h"
#include "spira/ui/views/bead_layer.h"
#include "spira/ui/views/robot_layer.h"

namespace spira::ui {
namespace {

QString clockText(double seconds)
{
  const int s = static_cast<int>(seconds + 0.5);
  return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace

SimulationPanel::SimulationPanel(RobotLayer& robot, BeadLayer& bead, std::function<void()> render,
                                 QWidget* parent)
    : QWidget(parent), robot_(robot), bead_(bead), render_(std::move(render))
{
  setObjectName(QStringLiteral("simulationPanel"));
  auto* layout = new QVBoxLayout(this);
  auto* row = new QHBoxLayout;
  auto button = [this, row](QStyle::StandardPixmap icon, const QString& tip) {
    auto* b = new QToolButton(this);
    b->setIcon(style()->standardIcon(icon));
    b->setToolTip(tip);
    b->setAutoRaise(true);
    row->addWidget(b);
    return b;
  };
  back_ = button(QStyle::SP_MediaSeekBackward, tr("Step back one point"));
  playPause_ = button(QStyle::SP_MediaPlay, tr("Play / pause the simulation (Space in this panel)"));
  forward_ = button(QStyle::SP_MediaSeekForward, tr("Step forward one point"));
  speed_ = new QDoubleSpinBox(this);
  speed_->setRange(0.1, 2000.0);
  speed_->setDecimals(1);
  speed_->setValue(1.0);
  speed_->setSuffix(tr(" x real time"));
  speed_->setToolTip(tr("Playback speed; 1 x plays the path at its travel speeds"));
  row->addWidget(speed_, 1);
  layout->addLayout(row);
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setToolTip(tr("Position along the path"));
  layout->addWidget(slider_);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  // Two lines (position, then dexterity and margin): a short dock must not clip them.
  status_->setMinimumHeight(2 * status_->fontMetrics().lineSpacing() + 4);
  layout->addWidget(status_);
  layout->addStretch(1);

  timer_.setInterval(33);
  connect(&timer_, &QTimer::timeout, this, &SimulationPanel::tick);
  connect(back_, &QToolButton::clicked, this, &SimulationPanel::stepBackward);
  connect(forward_, &QToolButton::clicked, this, &SimulationPanel::stepForward);
  connect(playPause_, &QToolButton::clicked, this, [this] { playing() ? pause() : play(); });
  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    if (static_cast<size_t>(v) != index_) setIndex(static_cast<size_t>(v));
  });
  setMotion(nullptr, tr("Choose a cell and plan to simulate the robot."));
}

void SimulationPanel::setMotion(std::shared_ptr<const KinematicsResult> motion, const QString& reason)
{
  pause();
  motion_ = motion && motion->size() > 0 ? std::move(motion) : nullptr;
  clock_ = motion_ ? SimulationClock(motion_->path) : SimulationClock();
  index_ = 0;
  time_ = 0.0;
  slider_->blockSignals(true);
  slider_->setRange(0, motion_ ? static_cast<int>(motion_->size()) - 1 : 0);
  slider_->setValue(0);
  slider_->blockSignals(false);
  if (motion_) {
    setIndex(0);
  } else {
    status_->setText(reason);
    updateControls();
  }
}

void SimulationPanel::setIndex(size_t i)
{
  if (!motion_) return;
  index_ = std::min(i, motion_->size() - 1);
  if (!playing()) time_ = clock_.time(index_);
  const JointPoint& p = motion_->joints.points[index_];
  robot_.setPose(p.robotDeg, p.externalDeg);
  bead_.showUpTo(index_);
  slider_->blockSignals(true);
  slider_->setValue(static_cast<int>(index_));
  slider_->blockSignals(false);
  status_->setText(statusText());
  updateControls();
  if (render_) render_();
  emit indexChanged(static_cast<int>(index_));
}

QString SimulationPanel::statusText() const
{
  if (!motion_) return status_->text();
  const KinematicsCheck& c = motion_->checks[index_];
  QString text = tr("Point %1 of %2, revolution %3, %4 of %5")
                     .arg(index_ + 1)
                     .arg(motion_->size())
                     .arg(motion_->path.points[index_].revolution + 1)
                     .arg(clockText(clock_.time(index_)), clockText(clock_.duration()));
  if (c.collision) text += tr("\nCOLLISION at this point");
  if (!c.reachable) text += tr("\nUNREACHABLE: the robot cannot hold this pose");
  text += tr("\nDexterity %1, joint-limit margin %2 deg")
              .arg(c.dexterity, 0, 'f', 3)
              .arg(c.limitMarginDeg, 0, 'f', 1);
  const long long flagged = bead_.shownFlagCount();
  if (flagged > 0) text += tr("\n%n point(s) flagged so far (red)", nullptr, static_cast<int>(flagged));
  return text;
}

void SimulationPanel::stepForward()
{
  pause();
  if (motion_ && index_ + 1 < motion_->size()) setIndex(index_ + 1);
}

void SimulationPanel::stepBackward()
{
  pause();
  if (motion_ && index_ > 0) setIndex(index_ - 1);
}

void SimulationPanel::play()
{
  if (!motion_) return;
  if (index_ + 1 >= motion_->size()) setIndex(0);  // replay from the start
  time_ = clock_.time(index_);
  wall_.start();
  const bool was = timer_.isActive();
  timer_.start();
  updateControls();
  if (!was) emit playingChanged(true);
}

void SimulationPanel::pause()
{
  const bool was = timer_.isActive();
  timer_.stop();
  updateControls();
  if (was) emit playingChanged(false);
}

double SimulationPanel::speed() const
{
  return speed_->value();
}

void SimulationPanel::setSpeed(double timesRealTime)
{
  speed_->setValue(timesRealTime);
}

void SimulationPanel::tick()
{
  if (!motion_) return pause();
  // Wall-clock time, not tick counts: a slow frame does not slow the simulated robot down.
  time_ += 1e-3 * static_cast<double>(wall_.restart()) * speed();
  const size_t next = clock_.indexAt(time_);
  if (next != index_) setIndex(next);
  if (index_ + 1 >= motion_->size()) pause();
}

void SimulationPanel::updateControls()
{
  const bool on = motion_ != nullptr;
  for (QWidget* w : std::initializer_list<QWidget*>{back_, playPause_, forward_, speed_, slider_})
    w->setEnabled(on);
  playPause_->setIcon(style()->standardIcon(playing() ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

}  // namespace spira::ui
