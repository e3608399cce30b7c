#pragma once

#include <QWidget>

#include "spira/document/document.h"
#include "spira/ui/panels/presets.h"

class QComboBox;
class QToolButton;

namespace spira::ui {

// A row above the plan settings: the user's presets in a combo, "Save As Preset..." and
// "Delete". Choosing a preset replaces the whole plan settings (every section and both strategy
// choices) in one undo step.
class PresetBar : public QWidget {
  Q_OBJECT

 public:
  PresetBar(Document& doc, PresetStore store, QWidget* parent = nullptr);

  // What the widgets do, without dialogs. Errors (bad name, unwritable folder, damaged preset)
  // are thrown as spira::Error.
  void saveCurrentAs(const QString& name);
  void apply(const QString& name);
  void remove(const QString& name);

  QComboBox* combo() const { return combo_; }
  const PresetStore& store() const { return store_; }
  // Re-reads the preset folder.
  void reload();

 signals:
  // An error a user should read (message, hint), from a widget action.
  void failed(const QString& message, const QString& hint);

 private:
  void askAndSave();
  void askAndRemove();
  template <class Fn>
  void guarded(Fn&& fn);

  Document& doc_;
  PresetStore store_;
  QComboBox* combo_ = nullptr;
  QToolButton* save_ = nullptr;
  QToolButton* delete_ = nullptr;
};

}  // namespace spira::ui
