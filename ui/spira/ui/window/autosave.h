#pragma once

#include <future>
#include <memory>

#include <QObject>
#include <QString>

#include "spira/document/document.h"

class QLockFile;
class QTimer;

namespace spira::ui {

// Autosave and crash recovery. While the session runs, the document is written every few
// minutes, when it has unsaved changes, to a recovery project in the user's data folder (never
// over the user's file). A clean exit (finishCleanly) deletes it; a crash leaves it, and the
// next session finds it: recoveryAvailable() is true when the recovery file exists and no
// running Spira holds the session lock of that folder.
//
// The snapshot is taken on the GUI thread (cheap: the state shares its meshes) and encoded and
// written on a worker thread, so a large project never freezes the window.
class Autosave : public QObject {
  Q_OBJECT

 public:
  struct Options {
    QString directory;    // empty: QStandardPaths::AppDataLocation + "/recovery"
    int intervalMs = -1;  // < 0: the "autosave/intervalMinutes" setting (default 2 minutes)
  };

  Autosave(Document& doc, Options options, QObject* parent = nullptr);
  ~Autosave() override;

  static QString defaultDirectory();
  static int intervalFromSettings();  // ms
  QString recoveryFile() const;
  const QString& directory() const { return dir_; }
  int intervalMs() const { return intervalMs_; }

  // What the previous session left, found when this one started (before it wrote anything).
  bool recoveryAvailable() const { return recoveryAvailable_; }
  // The original file of the recovered work ("" for an untitled document).
  QString recoveredFrom() const;
  // Loads the previous session's recovery file into `doc` as one undo step ("Recover autosaved
  // work"); the document stays modified and untitled so the user chooses where to save it.
  // Throws InputError / IoError when the file cannot be read.
  void restore();
  // Deletes the previous session's recovery file.
  void discard();

  // Writes the recovery file now when the document has unsaved changes; returns whether it
  // wrote. waitForWrite() blocks until a running write has finished.
  bool saveNow();
  void waitForWrite();
  // The session ends normally: stop, delete the recovery file, release the lock.
  void finishCleanly();

 signals:
  void saved(const QString& file);
  void saveFailed(const QString& message);

 private:
  void tick();

  Document& doc_;
  QString dir_;
  int intervalMs_;
  QTimer* timer_ = nullptr;
  std::unique_ptr<QLockFile> lock_;
  std::future<QString> write_;  // error message, empty on success
  std::uint64_t savedRevision_ = 0;
  bool recoveryAvailable_ = false;
  bool finished_ = false;
};

}  // namespace spira::ui
