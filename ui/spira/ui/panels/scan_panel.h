#pragma once

#include <QDockWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace spira {
struct DeviationStats;
}  // namespace spira

namespace spira::ui {

class DeviationHistogram;

// The "Scan" dock: the compared scan (file, points, how the alignment moved it and its residual), its
// deviation statistics and histogram, and the scan loop's commands: compare another scan, align it by
// picked point pairs, re-plan the rest of the build from it, remove it.
class ScanPanel : public QDockWidget {
  Q_OBJECT

 public:
  explicit ScanPanel(QWidget* parent = nullptr);

  // A scan aligned and measured: `fit` says how it was placed, `stats` its deviation, `limit` the
  // colour scale's reach (mm).
  void showComparison(const QString& name, const QString& fit, const DeviationStats& stats, double limit);
  // A scan read but not placed on the part yet: `why`, and what to do.
  void showUnaligned(const QString& name, const QString& why);
  // Picking pairs: the instruction, and whether enough pairs are picked to align.
  void showPicking(const QString& instruction, int pairs, bool canAlign);
  void showContinuation(const QString& summary);
  void clear();
  // Resume needs a planned path and an aligned scan.
  void setCanResume(bool on);

  // How the next scan compared is placed: by the fit from where it lies (false), or as taken, its
  // coordinates already the part's (a scanner calibrated to the cell: a scan of a wall half built).
  bool placeAsTaken() const;
  QComboBox* placementBox() const { return placement_; }
  QLabel* statusLabel() const { return status_; }
  QLabel* statsLabel() const { return stats_; }
  QLabel* continuationLabel() const { return continuation_; }
  DeviationHistogram* histogram() const { return histogram_; }
  QPushButton* alignButton() const { return align_; }
  QPushButton* resumeButton() const { return resume_; }
  QPushButton* removeButton() const { return remove_; }

 signals:
  void compareRequested();
  // Pick mode on, or (while picking) the pairs picked used.
  void alignByPointsRequested();
  void pickingCancelled();
  void resumeRequested();
  void removeRequested();

 private:
  void setPicking(bool on);

  QLabel* status_ = nullptr;
  QLabel* stats_ = nullptr;
  QLabel* continuation_ = nullptr;
  QComboBox* placement_ = nullptr;
  DeviationHistogram* histogram_ = nullptr;
  QPushButton* compare_ = nullptr;
  QPushButton* align_ = nullptr;
  QPushButton* cancelPick_ = nullptr;
  QPushButton* resume_ = nullptr;
  QPushButton* remove_ = nullptr;
  bool picking_ = false;
  bool hasScan_ = false;
  bool canResume_ = false;
};

}  // namespace spira::ui
