#pragma once

#include <map>
#include <string>

#include <QWidget>

#include "spira/plugin/parameter.h"

class QLabel;
class QPushButton;

namespace spira::ui {

class ParamField;

// The parameters of one settings section ("spiral", "process" or a plugin id), generated from
// its schema: one group box per category, one row per parameter (label with the schema's tooltip,
// editor, reset), and a button that resets the whole section. Parameters the user changed from
// their default have a bold label.
class ParamPanel : public QWidget {
  Q_OBJECT

 public:
  ParamPanel(std::string section, const ParamSchema& schema, QWidget* parent = nullptr);

  const std::string& section() const { return section_; }
  const ParamSchema& schema() const { return schema_; }
  // Shows the stored values of the section, defaults for the keys not stored. Emits nothing.
  void setStored(const ParamSet& stored);
  ParamField* field(const std::string& key) const;
  QLabel* label(const std::string& key) const;
  QPushButton* resetAllButton() const { return resetAll_; }

 signals:
  // The user set `key` to `value` (only when it differs from what is shown).
  void valueEdited(const std::string& section, const std::string& key, const spira::ParamValue& value);
  void keyResetRequested(const std::string& section, const std::string& key);
  void sectionResetRequested(const std::string& section);

 private:
  std::string section_;
  ParamSchema schema_;
  std::map<std::string, ParamField*> fields_;
  std::map<std::string, QLabel*> labels_;
  std::map<std::string, ParamValue> shown_;
  QPushButton* resetAll_ = nullptr;
};

}  // namespace spira::ui
