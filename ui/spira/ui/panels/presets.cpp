#include "spira/ui/panels/presets.h"

#include <algorithm>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"

namespace spira::ui {

namespace {

constexpr const char* kSuffix = ".preset.json";
constexpr int kFormat = 1;

std::filesystem::path fsPath(const QString& p)
{
  return std::filesystem::path(p.toStdString());
}

}  // namespace

PresetStore::PresetStore(QString dir) : dir_(dir.isEmpty() ? defaultDirectory() : std::move(dir)) {}

QString PresetStore::defaultDirectory()
{
  return QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation) + QStringLiteral("/presets");
}

QString PresetStore::fileOf(const QString& name) const
{
  const QString trimmed = name.trimmed();
  if (trimmed.isEmpty())
    throw InputError("a preset needs a name", "type a name for the preset, such as \"Steel 2 mm wall\"");
  if (trimmed.contains('/') || trimmed.contains('\\') || trimmed.startsWith('.'))
    throw InputError("the preset name '" + trimmed.toStdString() + "' cannot be a file name",
                     "leave out '/', '\\' and a leading '.'");
  return QDir(dir_).filePath(trimmed + QString::fromUtf8(kSuffix));
}

QStringList PresetStore::names() const
{
  QStringList out;
  const QString suffix = QString::fromUtf8(kSuffix);
  for (const QString& f : QDir(dir_).entryList({QStringLiteral("*") + suffix}, QDir::Files))
    out << f.left(f.size() - suffix.size());
  std::sort(out.begin(), out.end(), [](const QString& a, const QString& b) {
    return QString::compare(a, b, Qt::CaseInsensitive) < 0;
  });
  return out;
}

bool PresetStore::contains(const QString& name) const
{
  return QFileInfo::exists(fileOf(name));
}

void PresetStore::save(const QString& name, const PlanSettings& settings) const
{
  const QString file = fileOf(name);
  ensureWritableDirectory(fsPath(dir_));
  const nlohmann::json j{{"spira_preset", kFormat},
                         {"name", name.trimmed().toStdString()},
                         {"plan", planSettingsToJson(settings)}};
  writeFileAtomically(fsPath(file), j.dump(2) + "\n");
}

PlanSettings PresetStore::load(const QString& name) const
{
  const QString file = fileOf(name);
  if (!QFileInfo::exists(file))
    throw InputError("there is no preset named '" + name.trimmed().toStdString() + "'",
                     "pick one of the saved presets or save the current settings under that name");
  const std::string text = readFile(fsPath(file));
  nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object() || !j.contains("plan"))
    throw InputError("the preset file " + file.toStdString() + " is damaged",
                     "delete the preset and save it again");
  if (j.value("spira_preset", 0) > kFormat)
    throw InputError("the preset '" + name.toStdString() + "' was saved by a newer Spira",
                     "update Spira or save the preset again");
  return planSettingsFromJson(j.at("plan"));
}

bool PresetStore::remove(const QString& name) const
{
  return QFile::remove(fileOf(name));
}

}  // namespace spira::ui
