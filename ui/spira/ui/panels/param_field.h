#pragma once

#include <QWidget>

#include "spira/plugin/parameter.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;
class QToolButton;

namespace spira::ui {

// The editor of one parameter, built from its ParamDef: a spin box with the schema's range and
// unit suffix (numbers), a combo box (choices), a check box (bools), a line edit with a browse
// button (paths) or a plain line edit (strings), followed by a "reset to default" button.
// It shows what it is given and reports what the user did; the value lives in the Document.
class ParamField : public QWidget {
  Q_OBJECT

 public:
  explicit ParamField(ParamDef def, QWidget* parent = nullptr);

  const ParamDef& def() const { return def_; }
  // Shows `value`; `isDefault` enables the reset button when false. Emits nothing.
  void setValue(const ParamValue& value, bool isDefault);
  ParamValue value() const;
  bool isDefault() const { return isDefault_; }

  // The editing widget (QDoubleSpinBox, QSpinBox, QComboBox, QCheckBox or QLineEdit).
  QWidget* editor() const { return editor_; }
  QToolButton* resetButton() const { return reset_; }
  QToolButton* browseButton() const { return browse_; }
  // The value as the schema's unit shows it: "2 mm", "centered", "on".
  static QString displayText(const ParamDef& def, const ParamValue& value);

 signals:
  void edited(const spira::ParamValue& value);
  void resetRequested();

 private:
  void buildNumber();
  void buildChoice();
  void buildPath();
  void emitEdited();
  void browse();

  ParamDef def_;
  QWidget* editor_ = nullptr;
  QDoubleSpinBox* doubleBox_ = nullptr;
  QSpinBox* intBox_ = nullptr;
  QComboBox* combo_ = nullptr;
  QCheckBox* check_ = nullptr;
  QLineEdit* line_ = nullptr;
  QToolButton* browse_ = nullptr;
  QToolButton* reset_ = nullptr;
  bool isDefault_ = true;
  bool updating_ = false;
};

}  // namespace spira::ui

Q_DECLARE_METATYPE(spira::ParamValue)
