#pragma once

#include <QElapsedTimer>
#include <QObject>

class QTimer;

namespace spira::ui {

// Measures how long the GUI thread goes without serving its event loop: a timer on that thread
// ticks every `intervalMs`, and the longest time between two ticks is the worst freeze a user
// would have felt (the interval itself included). For test builds and benchmarks.
class UiWatchdog : public QObject {
  Q_OBJECT

 public:
  explicit UiWatchdog(int intervalMs = 10, QObject* parent = nullptr);

  void start();
  void stop();
  bool running() const;

  // Milliseconds, over the ticks since start().
  double worstGapMs() const { return worst_; }
  double meanGapMs() const { return ticks_ > 0 ? total_ / static_cast<double>(ticks_) : 0.0; }
  long long ticks() const { return ticks_; }
  int intervalMs() const { return interval_; }

 private:
  void tick();

  QTimer* timer_ = nullptr;
  QElapsedTimer clock_;
  qint64 lastNs_ = 0;
  double worst_ = 0.0;
  double total_ = 0.0;
  long long ticks_ = 0;
  int interval_;
};

}  // namespace spira::ui
