#include "spira/ui/window/autosave.h"

#include <algorithm>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QLockFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/document/project_file.h"

namespace spira::ui {

namespace {

constexpr const char* kIntervalKey = "autosave/intervalMinutes";
constexpr int kDefaultMinutes = 2;

std::filesystem::path fsPath(const QString& p)
{
  return std::filesystem::path(p.toStdString());
}

QString sidecarOf(const QString& recovery)
{
  return recovery + QStringLiteral(".json");
}

}  // namespace

QString Autosave::defaultDirectory()
{
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/recovery");
}

int Autosave::intervalFromSettings()
{
  const double minutes = QSettings().value(kIntervalKey, kDefaultMinutes).toDouble();
  // A broken setting must not turn autosave into a busy loop.
  return static_cast<int>(std::max(0.1, minutes) * 60000.0);
}

Autosave::Autosave(Document& doc, Options options, QObject* parent)
    : QObject(parent),
      doc_(doc),
      dir_(options.directory.isEmpty() ? defaultDirectory() : options.directory),
      intervalMs_(options.intervalMs >= 0 ? options.intervalMs : intervalFromSettings())
{
  QDir().mkpath(dir_);
  lock_ = std::make_unique<QLockFile>(QDir(dir_).filePath(QStringLiteral("session.lock")));
  // Only a live process holds the lock: one that crashed left a stale lock, which tryLock takes.
  lock_->setStaleLockTime(0);
  if (lock_->tryLock(0)) {
    recoveryAvailable_ = QFile::exists(recoveryFile());
  } else {
    // Another Spira runs on this folder: this session keeps its recovery file beside it.
    dir_ = QDir(dir_).filePath(QStringLiteral("session-%1").arg(QCoreApplication::applicationPid()));
    QDir().mkpath(dir_);
    lock_ = std::make_unique<QLockFile>(QDir(dir_).filePath(QStringLiteral("session.lock")));
    lock_->tryLock(0);
  }
  savedRevision_ = doc_.revision();
  timer_ = new QTimer(this);
  timer_->setInterval(intervalMs_);
  connect(timer_, &QTimer::timeout, this, &Autosave::tick);
  timer_->start();
}

Autosave::~Autosave()
{
  // Not a clean exit unless finishCleanly() ran: the recovery file stays for the next session.
  waitForWrite();
}

QString Autosave::recoveryFile() const
{
  return QDir(dir_).filePath(QStringLiteral("recovery.spira"));
}

QString Autosave::recoveredFrom() const
{
  QFile f(sidecarOf(recoveryFile()));
  if (!f.open(QIODevice::ReadOnly)) return {};
  const auto j = nlohmann::json::parse(f.readAll().toStdString(), nullptr, false);
  return j.is_object() ? QString::fromStdString(j.value("file", std::string())) : QString();
}

void Autosave::restore()
{
  DocumentState state = loadProject(fsPath(recoveryFile()));
  Results results = state.results;
  doc_.edit(QCoreApplication::translate("Autosave", "Recover autosaved work").toStdString(),
            [&](DocumentState& s) { s = std::move(state); });
  // Results are not undo steps: stored after the edit, as a plan's are.
  doc_.setResults(std::move(results));
  recoveryAvailable_ = false;
  savedRevision_ = 0;  // write the recovered work again at the next tick
}

void Autosave::discard()
{
  waitForWrite();
  QFile::remove(recoveryFile());
  QFile::remove(sidecarOf(recoveryFile()));
  recoveryAvailable_ = false;
}

bool Autosave::saveNow()
{
  // The previous session's work is not overwritten before the user has chosen what to do with it.
  if (finished_ || recoveryAvailable_) return false;
  if (write_.valid() && write_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  waitForWrite();  // ready: reports the previous write
  if (!doc_.isModified()) {
    // Saved by the user since: the recovery copy would only be older than the file.
    QFile::remove(recoveryFile());
    QFile::remove(sidecarOf(recoveryFile()));
    savedRevision_ = doc_.revision();
    return false;
  }
  if (doc_.revision() == savedRevision_) return false;
  savedRevision_ = doc_.revision();
  auto state = std::make_shared<const DocumentState>(doc_.snapshot());
  const std::string original = doc_.filePath().string();
  const QString file = recoveryFile();
  write_ = std::async(std::launch::async, [state, original, file]() -> QString {
    try {
      saveProject(*state, fsPath(file));
      writeFileAtomically(fsPath(sidecarOf(file)), nlohmann::json{{"file", original}}.dump() + "\n");
      return {};
    } catch (const Error& e) {
      return QString::fromStdString(e.fullMessage());
    } catch (const std::exception& e) {
      return QString::fromUtf8(e.what());
    }
  });
  return true;
}

void Autosave::waitForWrite()
{
  if (!write_.valid()) return;
  const QString error = write_.get();
  if (error.isEmpty())
    emit saved(recoveryFile());
  else
    emit saveFailed(error);
}

void Autosave::tick()
{
  saveNow();
}

void Autosave::finishCleanly()
{
  timer_->stop();
  waitForWrite();
  finished_ = true;
  QFile::remove(recoveryFile());
  QFile::remove(sidecarOf(recoveryFile()));
  lock_->unlock();
}

}  // namespace spira::ui
