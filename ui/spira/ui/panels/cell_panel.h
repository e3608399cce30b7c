#pragma once

#include <QStringList>
#include <QWidget>

#include "spira/document/document.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;

namespace spira::ui {

class LogPanel;

// The robot cell of the document: choose a bundled cell (resources/cells) or load a .cell file,
// read the robot, controller, tool and positioner values (with units), and edit the part's
// placement in the cell and the torch's sizes. Every change is one undoable Document::setCell.
class CellPanel : public QWidget {
  Q_OBJECT

 public:
  CellPanel(Document& doc, LogPanel* log, QWidget* parent = nullptr);

  // The folder of the bundled cells ($SPIRA_RESOURCE_DIR/cells, the installed or the source tree's).
  static QString bundledCellDir();
  static QStringList bundledCells();  // full paths of the *.cell files there
  // Reads `file` and makes it the document's cell (one undo step); false (and a message) on error.
  bool loadCell(const QString& file);
  // Refreshes the shown values from the document.
  void refresh();

  QComboBox* cellCombo() const { return combo_; }
  QDoubleSpinBox* partOffset(int axis) const { return offset_[axis]; }
  QDoubleSpinBox* partTurn() const { return turn_; }
  QDoubleSpinBox* tcpLength() const { return tcp_; }
  QDoubleSpinBox* nozzleRadius() const { return nozzle_; }
  QLabel* summary() const { return summary_; }

 private:
  void applyEdits();
  QDoubleSpinBox* lengthBox(double min, double max, const QString& tip);

  Document& doc_;
  LogPanel* log_;
  QComboBox* combo_;
  QPushButton* load_;
  QLabel* summary_;
  QDoubleSpinBox* offset_[3];
  QDoubleSpinBox* turn_;
  QDoubleSpinBox* tcp_;
  QDoubleSpinBox* nozzle_;
  bool updating_ = false;
};

}  // namespace spira::ui
