#pragma once

#include <QString>
#include <QWidget>

namespace spira::ui {

// One line of text, elided to the width it is given (the full text in its tooltip). Unlike a
// QLabel, a new text never changes its size hint, so it only repaints itself: a QLabel's setText
// asks the whole main window to lay itself out again (10-20 ms each on software OpenGL), which
// progress text changing many times a second cannot afford.
class StatusLine : public QWidget {
  Q_OBJECT

 public:
  explicit StatusLine(QWidget* parent = nullptr);

  void setText(const QString& text);
  const QString& text() const { return text_; }

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QString text_;
};

}  // namespace spira::ui
