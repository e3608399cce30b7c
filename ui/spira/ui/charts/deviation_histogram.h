#pragma once

#include <vector>

#include <QWidget>

namespace spira {
struct DeviationStats;
}  // namespace spira

namespace spira::ui {

// The distribution of a scan's signed deviations from the part: one bar per bin, coloured as the 3D
// view colours its points (the same scale, symmetric about 0 to `limit`), with the mean and the 95 %
// band marked, so a sag shows as a shoulder and stray points as a long tail.
class DeviationHistogram : public QWidget {
  Q_OBJECT

 public:
  explicit DeviationHistogram(QWidget* parent = nullptr);

  // No bins clears it.
  void setData(const DeviationStats& stats, double limit);
  void clear();
  bool hasData() const { return !counts_.empty(); }
  size_t binCount() const { return counts_.size(); }
  QSize sizeHint() const override { return {320, 170}; }
  QSize minimumSizeHint() const override { return {200, 120}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  std::vector<size_t> counts_;
  double binMin_ = 0.0, binWidth_ = 0.0, mean_ = 0.0, p95_ = 0.0, limit_ = 1.0;
};

}  // namespace spira::ui
