#include "spira/ui/panels/scan_panel.h"

#include <algorithm>

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include "spira/scan/scan_deviation.h"
#include "spira/ui/charts/deviation_histogram.h"

namespace spira::ui {

ScanPanel::ScanPanel(QWidget* parent) : QDockWidget(tr("Scan"), parent)
{
  setObjectName(QStringLiteral("scanDock"));
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  status_ = new QLabel(body);
  status_->setObjectName(QStringLiteral("scanStatus"));
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  stats_ = new QLabel(body);
  stats_->setObjectName(QStringLiteral("scanStats"));
  stats_->setWordWrap(true);
  stats_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  histogram_ = new DeviationHistogram(body);
  continuation_ = new QLabel(body);
  continuation_->setObjectName(QStringLiteral("scanContinuation"));
  continuation_->setWordWrap(true);
  continuation_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  continuation_->hide();

  placement_ = new QComboBox(body);
  placement_->setObjectName(QStringLiteral("scanPlacement"));
  placement_->addItem(tr("Place scans by the fit"));
  placement_->addItem(tr("Take scans as placed (part frame)"));
  placement_->setToolTip(
      tr("By the fit: the scan is registered to the part from where it lies (a scan of the "
         "whole part, taken anywhere). As placed: its coordinates are the part's already "
         "(a scanner calibrated to the cell), as for a scan of a wall half built."));

  auto* buttons = new QGridLayout;
  compare_ = new QPushButton(tr("Compare Scan..."), body);
  compare_->setToolTip(tr("Read a scan of the part (point cloud or mesh), align it and show its deviation"));
  align_ = new QPushButton(tr("Align by Points"), body);
  align_->setObjectName(QStringLiteral("alignByPointsButton"));
  align_->setToolTip(
      tr("Click three or more places on the part, each followed by the same place on the "
         "scan; the pairs place the scan, then the fit refines it"));
  cancelPick_ = new QPushButton(tr("Cancel Picking"), body);
  cancelPick_->hide();
  resume_ = new QPushButton(tr("Resume from Scan..."), body);
  resume_->setObjectName(QStringLiteral("resumeFromScanButton"));
  resume_->setToolTip(tr("Re-plan the rest of the build from the wall's top as the scan measures it"));
  remove_ = new QPushButton(tr("Remove"), body);
  remove_->setToolTip(tr("Remove the scan from the project (undoable)"));
  buttons->addWidget(compare_, 0, 0);
  buttons->addWidget(align_, 0, 1);
  buttons->addWidget(resume_, 1, 0);
  buttons->addWidget(remove_, 1, 1);
  buttons->addWidget(cancelPick_, 2, 1);

  layout->addWidget(status_);
  layout->addWidget(stats_);
  layout->addWidget(histogram_, 1);
  layout->addWidget(placement_);
  layout->addLayout(buttons);
  layout->addWidget(continuation_);
  layout->addStretch(0);
  setWidget(body);

  connect(compare_, &QPushButton::clicked, this, &ScanPanel::compareRequested);
  connect(align_, &QPushButton::clicked, this, &ScanPanel::alignByPointsRequested);
  connect(cancelPick_, &QPushButton::clicked, this, &ScanPanel::pickingCancelled);
  connect(resume_, &QPushButton::clicked, this, &ScanPanel::resumeRequested);
  connect(remove_, &QPushButton::clicked, this, &ScanPanel::removeRequested);
  clear();
}

void ScanPanel::showComparison(const QString& name, const QString& fit, const DeviationStats& stats,
                               double limit)
{
  hasScan_ = true;
  setPicking(false);
  const QLocale loc;
  status_->setText(
      tr("<b>%1</b>: %2 points.<br>%3.")
          .arg(name.toHtmlEscaped(), loc.toString(qulonglong(stats.count)), fit.toHtmlEscaped()));
  stats_->setText(
      tr("Deviation from the part (mm, + outside): mean %1, RMS %2, 95 % within %3, from %4 to %5")
          .arg(loc.toString(stats.mean, 'f', 3), loc.toString(stats.rms, 'f', 3),
               loc.toString(stats.p95, 'f', 3), loc.toString(stats.min, 'f', 3),
               loc.toString(stats.max, 'f', 3)));
  stats_->show();
  histogram_->setData(stats, limit);
  histogram_->show();
  align_->setText(tr("Align by Points"));
  align_->setEnabled(true);
  remove_->setEnabled(true);
  resume_->setEnabled(canResume_);
}

void ScanPanel::showUnaligned(const QString& name, const QString& why)
{
  hasScan_ = false;
  setPicking(false);
  status_->setText(
      tr("<b>%1</b> is not placed on the part: %2").arg(name.toHtmlEscaped(), why.toHtmlEscaped()));
  stats_->setText(
      tr("Align by Points: click a place on the part, then the same place on the scan (grey), "
         "three times or more."));
  stats_->show();
  histogram_->clear();
  histogram_->hide();
  align_->setText(tr("Align by Points"));
  align_->setEnabled(true);
  remove_->setEnabled(false);
  resume_->setEnabled(false);
}

void ScanPanel::showPicking(const QString& instruction, int pairs, bool canAlign)
{
  setPicking(true);
  stats_->setText(instruction);
  stats_->show();
  histogram_->hide();
  align_->setText(canAlign ? tr("Align with %n Pair(s)", nullptr, pairs)
                           : tr("Pick %1 More").arg(std::max(1, 3 - pairs)));
  align_->setEnabled(canAlign);
}

void ScanPanel::showContinuation(const QString& summary)
{
  continuation_->setText(summary);
  continuation_->setVisible(!summary.isEmpty());
}

void ScanPanel::clear()
{
  hasScan_ = false;
  setPicking(false);
  status_->setText(
      tr("No scan. Compare one (File > Compare Scan) to see where the part deviates, and re-plan "
         "the rest of a build from a scan of the wall as it stands."));
  stats_->clear();
  stats_->hide();
  histogram_->clear();
  histogram_->hide();
  showContinuation({});
  align_->setText(tr("Align by Points"));
  align_->setEnabled(false);
  remove_->setEnabled(false);
  resume_->setEnabled(false);
}

bool ScanPanel::placeAsTaken() const
{
  return placement_->currentIndex() == 1;
}

void ScanPanel::setCanResume(bool on)
{
  canResume_ = on;
  resume_->setEnabled(on && hasScan_ && !picking_);
}

void ScanPanel::setPicking(bool on)
{
  picking_ = on;
  cancelPick_->setVisible(on);
  compare_->setEnabled(!on);
  resume_->setEnabled(!on && hasScan_ && canResume_);
}

}  // namespace spira::ui
