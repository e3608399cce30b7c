#include "spira/ui/panels/log_panel.h"

#include <QApplication>
#include <QClipboard>
#include <QListWidget>
#include <QMenu>
#include <QStyle>
#include <QTime>

namespace spira::ui {

namespace {

constexpr int kLevelRole = Qt::UserRole + 1;
// Older lines are dropped so a long session does not grow the list without bound.
constexpr int kMaxEntries = 5000;

}  // namespace

LogPanel::LogPanel(QWidget* parent) : QDockWidget(tr("Messages"), parent), list_(new QListWidget(this))
{
  setObjectName("messagesDock");
  list_->setObjectName("messagesList");
  list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  list_->setWordWrap(true);
  list_->setIconSize(QSize(16, 16));
  list_->setAlternatingRowColors(false);
  list_->setUniformItemSizes(false);
  list_->setContextMenuPolicy(Qt::CustomContextMenu);
  connect(list_, &QListWidget::customContextMenuRequested, this, &LogPanel::showContextMenu);
  setWidget(list_);
}

void LogPanel::info(const QString& message)
{
  add(LogLevel::Info, message);
}
void LogPanel::warning(const QString& message, const QString& hint)
{
  add(LogLevel::Warning, message, hint);
}
void LogPanel::error(const QString& message, const QString& hint)
{
  add(LogLevel::Error, message, hint);
}

void LogPanel::add(LogLevel level, const QString& message, const QString& hint)
{
  QString line = QStringLiteral("[%1] %2").arg(QTime::currentTime().toString("hh:mm:ss"), message);
  if (!hint.isEmpty()) line += QStringLiteral("\n    Hint: %1").arg(hint);
  auto* item = new QListWidgetItem(line);
  item->setData(kLevelRole, static_cast<int>(level));
  QStyle* st = style();
  switch (level) {
    case LogLevel::Info:
      item->setIcon(st->standardIcon(QStyle::SP_MessageBoxInformation));
      break;
    case LogLevel::Warning:
      item->setIcon(st->standardIcon(QStyle::SP_MessageBoxWarning));
      item->setForeground(QColor(150, 90, 0));
      break;
    case LogLevel::Error:
      item->setIcon(st->standardIcon(QStyle::SP_MessageBoxCritical));
      item->setForeground(QColor(198, 30, 30));
      break;
  }
  item->setToolTip(line);
  list_->addItem(item);
  while (list_->count() > kMaxEntries) delete list_->takeItem(0);
  list_->scrollToBottom();
  // An error the user cannot see is an error the user does not know about.
  if (level == LogLevel::Error && !isVisible() && parentWidget() && parentWidget()->isVisible()) show();
}

void LogPanel::clear()
{
  list_->clear();
}

int LogPanel::count() const
{
  return list_->count();
}

LogLevel LogPanel::level(int row) const
{
  return static_cast<LogLevel>(list_->item(row)->data(kLevelRole).toInt());
}

QString LogPanel::text(int row) const
{
  return list_->item(row)->text();
}

void LogPanel::showContextMenu(const QPoint& pos)
{
  QMenu menu(this);
  QAction* copy = menu.addAction(tr("Copy"));
  copy->setEnabled(!list_->selectedItems().isEmpty());
  QAction* clearAll = menu.addAction(tr("Clear"));
  QAction* chosen = menu.exec(list_->viewport()->mapToGlobal(pos));
  if (chosen == copy) {
    QStringList lines;
    for (int i = 0; i < list_->count(); ++i) {
      if (list_->item(i)->isSelected()) lines << list_->item(i)->text();
    }
    QApplication::clipboard()->setText(lines.join('\n'));
  } else if (chosen == clearAll) {
    clear();
  }
}

}  // namespace spira::ui
