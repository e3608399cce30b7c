#include "support/ui_watchdog.h"

#include <algorithm>

#include <QTimer>

namespace spira::ui {

UiWatchdog::UiWatchdog(int intervalMs, QObject* parent) : QObject(parent), interval_(intervalMs)
{
  timer_ = new QTimer(this);
  timer_->setTimerType(Qt::PreciseTimer);
  timer_->setInterval(interval_);
  connect(timer_, &QTimer::timeout, this, &UiWatchdog::tick);
}

void UiWatchdog::start()
{
  worst_ = total_ = 0.0;
  ticks_ = 0;
  clock_.start();
  lastNs_ = 0;
  timer_->start();
}

void UiWatchdog::stop()
{
  // The time since the last tick counts too: a freeze at the very end is still a freeze.
  if (timer_->isActive()) tick();
  timer_->stop();
}

bool UiWatchdog::running() const
{
  return timer_->isActive();
}

void UiWatchdog::tick()
{
  const qint64 now = clock_.nsecsElapsed();
  const double gap = static_cast<double>(now - lastNs_) / 1e6;
  lastNs_ = now;
  worst_ = std::max(worst_, gap);
  total_ += gap;
  ++ticks_;
}

}  // namespace spira::ui
