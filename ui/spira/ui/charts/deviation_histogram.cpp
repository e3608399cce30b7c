#include "spira/ui/charts/deviation_histogram.h"

#include <algorithm>
#include <cmath>

#include <vtkLookupTable.h>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>

#include "spira/scan/scan_deviation.h"
#include "spira/ui/views/color_maps.h"

namespace spira::ui {

DeviationHistogram::DeviationHistogram(QWidget* parent) : QWidget(parent)
{
  setObjectName(QStringLiteral("deviationHistogram"));
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
}

void DeviationHistogram::setData(const DeviationStats& stats, double limit)
{
  counts_ = stats.histogram;
  binMin_ = stats.binMin;
  binWidth_ = stats.binWidth;
  mean_ = stats.mean;
  p95_ = stats.p95;
  limit_ = std::max(limit, 1e-3);
  update();
}

void DeviationHistogram::clear()
{
  counts_.clear();
  update();
}

void DeviationHistogram::paintEvent(QPaintEvent*)
{
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette& pal = palette();
  p.fillRect(rect(), pal.base());
  const QFontMetrics fm(font());
  const int axisH = fm.height() + 6, top = fm.height() + 6, left = 8, right = 8;
  const QRectF plot(left, top, std::max(10, width() - left - right), std::max(10, height() - top - axisH));
  if (counts_.empty() || binWidth_ <= 0.0) {
    p.setPen(pal.color(QPalette::PlaceholderText));
    p.drawText(rect(), Qt::AlignCenter, tr("No scan compared"));
    return;
  }
  const double lo = binMin_, hi = binMin_ + binWidth_ * double(counts_.size());
  const size_t tallest = *std::max_element(counts_.begin(), counts_.end());
  const auto xOf = [&](double v) { return plot.left() + (v - lo) / (hi - lo) * plot.width(); };
  const vtkSmartPointer<vtkLookupTable> lut = makeLookupTable(ColorMap::Window, -limit_, limit_);

  // The 95 % band behind the bars: the points within it lie between these lines.
  const QColor band = pal.color(QPalette::Highlight);
  QColor bandFill = band;
  bandFill.setAlphaF(0.10);
  const double bandLo = std::max(lo, -p95_), bandHi = std::min(hi, p95_);
  if (bandHi > bandLo)
    p.fillRect(QRectF(xOf(bandLo), plot.top(), xOf(bandHi) - xOf(bandLo), plot.height()), bandFill);

  for (size_t b = 0; b < counts_.size(); ++b) {
    if (counts_[b] == 0 || tallest == 0) continue;
    double rgb[3];
    lut->GetColor(lo + (double(b) + 0.5) * binWidth_, rgb);
    const double h = plot.height() * double(counts_[b]) / double(tallest);
    const QRectF bar(xOf(lo + double(b) * binWidth_), plot.bottom() - h,
                     plot.width() / double(counts_.size()), h);
    p.fillRect(bar.adjusted(0.5, 0, -0.5, 0), QColor::fromRgbF(rgb[0], rgb[1], rgb[2]));
  }
  p.setPen(QPen(pal.color(QPalette::Text), 1.0));
  p.drawLine(QPointF(plot.left(), plot.bottom()), QPointF(plot.right(), plot.bottom()));

  const QLocale loc;
  const auto mark = [&](double v, const QColor& c, Qt::PenStyle style) {
    if (v < lo || v > hi) return;
    p.setPen(QPen(c, 1.5, style));
    p.drawLine(QPointF(xOf(v), plot.top()), QPointF(xOf(v), plot.bottom()));
  };
  mark(0.0, pal.color(QPalette::Text), Qt::DotLine);
  mark(mean_, QColor(20, 20, 20), Qt::SolidLine);
  p.setPen(pal.color(QPalette::Text));
  const QString meanText = tr("mean %1 mm").arg(loc.toString(mean_, 'f', 3));
  const QString bandText = tr("95 % within ±%1 mm").arg(loc.toString(p95_, 'f', 3));
  p.drawText(QRectF(left, 0, plot.width(), top), Qt::AlignLeft | Qt::AlignVCenter, meanText);
  p.drawText(QRectF(left, 0, plot.width(), top), Qt::AlignRight | Qt::AlignVCenter, bandText);

  // Axis: the ends and zero, in mm.
  const QRectF axis(plot.left(), plot.bottom() + 2, plot.width(), axisH - 2);
  p.drawText(axis, Qt::AlignLeft | Qt::AlignTop, loc.toString(lo, 'f', 2));
  p.drawText(axis, Qt::AlignRight | Qt::AlignTop, tr("%1 mm").arg(loc.toString(hi, 'f', 2)));
  if (lo < 0.0 && hi > 0.0) {
    const double x0 = xOf(0.0);
    const QString zero = QStringLiteral("0");
    const int w = fm.horizontalAdvance(zero);
    if (x0 - w > plot.left() + fm.horizontalAdvance(loc.toString(lo, 'f', 2)) + 4 &&
        x0 + w < plot.right() - fm.horizontalAdvance(tr("%1 mm").arg(loc.toString(hi, 'f', 2))) - 4)
      p.drawText(QRectF(x0 - w, axis.top(), 2 * w, axis.height()), Qt::AlignHCenter | Qt::AlignTop, zero);
  }
}

}  // namespace spira::ui
