#include "spira/ui/window/status_line.h"

#include <QPainter>
#include <QStyle>

namespace spira::ui {

StatusLine::StatusLine(QWidget* parent) : QWidget(parent)
{
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
}

void StatusLine::setText(const QString& text)
{
  if (text == text_) return;
  text_ = text;
  setToolTip(text);
  update();
}

QSize StatusLine::sizeHint() const
{
  return QSize(20 * fontMetrics().averageCharWidth(), fontMetrics().height() + 2);
}

QSize StatusLine::minimumSizeHint() const
{
  return QSize(0, fontMetrics().height() + 2);
}

void StatusLine::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  const QRect r = contentsRect();
  painter.setPen(palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::WindowText));
  painter.drawText(r, Qt::AlignLeft | Qt::AlignVCenter,
                   fontMetrics().elidedText(text_, Qt::ElideRight, r.width()));
}

}  // namespace spira::ui
