#pragma once

#include <QString>
#include <QStringList>

#include "spira/document/plan_settings.h"

namespace spira::ui {

// Named plan-settings presets of one user: every section's values and the decomposer and closure
// choices, one JSON file per preset (the project file's plan-settings codec) in a folder of the
// user's configuration (QStandardPaths::AppConfigLocation/presets by default).
class PresetStore {
 public:
  // `dir` empty: the user's configuration folder.
  explicit PresetStore(QString dir = {});

  const QString& directory() const { return dir_; }
  // Preset names, sorted case-insensitively.
  QStringList names() const;
  bool contains(const QString& name) const;
  // Writes atomically; replaces a preset of the same name. Throws InputError for an empty name
  // or one with a path separator, IoError when the folder is not writable.
  void save(const QString& name, const PlanSettings& settings) const;
  // Throws InputError (no such preset, damaged file) or IoError.
  PlanSettings load(const QString& name) const;
  // False when there was no such preset.
  bool remove(const QString& name) const;

  static QString defaultDirectory();

 private:
  QString fileOf(const QString& name) const;

  QString dir_;
};

}  // namespace spira::ui
