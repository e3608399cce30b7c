#include "spira/ui/window/scan_workflow.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLocale>
#include <QMainWindow>
#include <QPushButton>
#include <QSpinBox>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/document/plan_report.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/solid_wall.h"
#include "spira/scan/pair_alignment.h"
#include "spira/scan/quality_indices.h"
#include "spira/scan/scan_alignment.h"
#include "spira/scan/scan_deviation.h"
#include "spira/scan/scan_processing.h"
#include "spira/scan/scan_reader.h"
#include "spira/scan/scan_resume.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/scan_panel.h"
#include "spira/ui/views/continuation_layer.h"
#include "spira/ui/views/pair_picker.h"
#include "spira/ui/views/scan_layer.h"
#include "spira/ui/views/scene_view.h"

namespace spira::ui {

// The cleaned scan in its own frame: aligning again (from picked pairs) starts from it.
struct ScanWorkflow::Loaded {
  std::filesystem::path file;
  QString name;
  PointCloud cloud;
  size_t read = 0, outliers = 0;
};

// The scan placed by a record and measured against one mesh of the part.
struct ScanWorkflow::Shown {
  ScanRecord record;
  std::shared_ptr<const TriangleMesh> mesh;
  PointCloud aligned;  // the part's frame
  std::vector<double> deviation;
  DeviationStats stats;
  QString how;  // how it was placed, for the Scan dock
};

namespace {

// Hand-picked places are a few tenths of a millimetre off; several millimetres means another place.
constexpr double kPairToleranceMm = 5.0;

QString indexText(const QString& name, const IndexStats& s)
{
  const QLocale loc;
  if (s.count == 0) return QObject::tr("%1 not measured").arg(name);
  return QObject::tr("%1 %2 (min %3)").arg(name, loc.toString(s.mean, 'f', 3), loc.toString(s.min, 'f', 3));
}

QString indicesText(const IndexStats& trajectory, const IndexStats& process, const IndexStats& global)
{
  return QObject::tr("%1, %2, %3.")
      .arg(indexText(QObject::tr("trajectory"), trajectory), indexText(QObject::tr("process"), process),
           indexText(QObject::tr("global"), global));
}

QString movedText(const Transform& T)
{
  const QLocale loc;
  return QObject::tr("moved %1 mm and %2° onto the part")
      .arg(loc.toString(T.translation().norm(), 'f', 3),
           loc.toString(radToDeg(Eigen::AngleAxisd(T.linear()).angle()), 'f', 3));
}

PointCloud readClean(const PluginRegistry& registry, const std::filesystem::path& file,
                     const TriangleMesh& part, Progress& progress, ScanFilterReport* filtered)
{
  PointCloud raw = readScan(registry, file, progress);
  if (const auto unit = scanUnitHint(boundsOf(raw), part.bounds()))
    throw InputError("'" + file.filename().string() + "': " + *unit,
                     "export the scan in mm (spira-cli scan-compare --scan-scale reads it scaled)");
  return filterScan(raw, ScanFilterSettings{}, filtered);
}

}  // namespace

ScanWorkflow::ScanWorkflow(Parts parts, QObject* parent)
    : QObject(parent),
      p_(std::move(parts)),
      panel_(new ScanPanel(&p_.window)),
      picker_(std::make_unique<PairPicker>(p_.view)),
      continuation_(std::make_unique<ContinuationLayer>(p_.view.renderer()))
{
  connect(panel_, &ScanPanel::compareRequested, this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        &p_.window, tr("Compare Scan"), QString(),
        tr("Scans (*.ply *.pcd *.xyz *.csv *.txt *.asc *.pts *.stl *.obj);;All files (*)"));
    if (!path.isEmpty()) compareFile(path);
  });
  connect(panel_, &ScanPanel::alignByPointsRequested, this, &ScanWorkflow::alignByPoints);
  connect(panel_, &ScanPanel::pickingCancelled, this, &ScanWorkflow::cancelPicking);
  connect(panel_, &ScanPanel::resumeRequested, this, &ScanWorkflow::chooseResume);
  connect(panel_, &ScanPanel::removeRequested, this, &ScanWorkflow::removeScan);
  connect(picker_.get(), &PairPicker::picked, this, [this] {
    const int next = picker_->pairCount() + 1;
    const bool onPart = picker_->expecting() == PairPicker::Expect::Part;
    panel_->showPicking(onPart ? tr("Pair %1: click a place on the part.").arg(next)
                               : tr("Pair %1: click the same place on the scan.").arg(next),
                        picker_->pairCount(), onPart && picker_->pairCount() >= 3);
  });
  connect(picker_.get(), &PairPicker::missed, this, [this] {
    p_.log.warning(picker_->expecting() == PairPicker::Expect::Part
                       ? tr("The click missed the part.")
                       : tr("The click missed the scan's points."),
                   tr("Click on it; drag to turn the view."));
  });
  connect(&p_.tasks, &TaskRunner::finished, this, [this] {
    if (reloadPending_)
      QMetaObject::invokeMethod(
          this, [this] { reloadRecord(); }, Qt::QueuedConnection);
  });
  subscription_ = p_.doc.subscribe([this](const ChangeSet& c) { onDocumentChanged(c); });
  ChangeSet all;
  all.flags = ~0u;
  onDocumentChanged(all);
}

ScanWorkflow::~ScanWorkflow()
{
  p_.doc.unsubscribe(subscription_);
}

bool ScanWorkflow::hasComparison() const
{
  return shown_ && p_.doc.scan() && shown_->record == *p_.doc.scan();
}

std::optional<Transform> ScanWorkflow::shownTransform() const
{
  if (hasComparison()) return shown_->record.T_part_scan;
  if (loaded_ && unplaced_) return Transform::Identity();
  return std::nullopt;
}

bool ScanWorkflow::compareFile(const QString& path)
{
  const auto part = p_.doc.part();
  if (!part || !part->mesh) {
    p_.reportError(tr("Compare scan"),
                   tr("There is no part to compare %1 with.").arg(QFileInfo(path).fileName()),
                   tr("Import the part first (File > Import Part)."));
    return false;
  }
  if (p_.busy()) {
    p_.reportError(tr("Compare scan"), tr("Cannot compare %1 while another task runs.").arg(path),
                   tr("Wait for it to finish or cancel it."));
    return false;
  }
  picker_->stop();
  struct Outcome {
    std::shared_ptr<Loaded> loaded = std::make_shared<Loaded>();
    std::shared_ptr<Shown> shown = std::make_shared<Shown>();
    QString unplaced;  // why the fit could not place it
  };
  auto out = std::make_shared<Outcome>();
  const std::shared_ptr<const TriangleMesh> mesh = part->mesh;
  const PluginRegistry& registry = p_.registry;
  const bool asTaken = panel_->placeAsTaken();
  out->loaded->file = std::filesystem::u8path(path.toStdString());
  out->loaded->name = QFileInfo(path).fileName();
  p_.log.info(tr("Comparing the scan %1 with the part ...").arg(out->loaded->name));
  p_.tasks.start(
      tr("Comparing %1").arg(out->loaded->name),
      [&registry, mesh, out, asTaken](Progress& progress) {
        Loaded& l = *out->loaded;
        ScanFilterReport filtered;
        l.cloud = readClean(registry, l.file, *mesh, progress, &filtered);
        l.read = filtered.read, l.outliers = filtered.outliers;
        SubProgress aligning(progress, 0.1, 0.7, "aligning");
        AlignResult fit;
        if (!asTaken) {
          try {
            fit = alignScan(l.cloud, *mesh, Transform::Identity(), AlignSettings{}, aligning);
          } catch (const InputError& e) {
            out->unplaced = QString::fromStdString(e.what());
            return;
          }
        }
        Shown& s = *out->shown;
        s.record.file = l.file.string();
        s.record.T_part_scan = fit.T_part_scan;
        s.record.rmsMm = fit.rmsMm;
        s.mesh = mesh;
        s.aligned = transformed(l.cloud, fit.T_part_scan);
        SubProgress measuring(progress, 0.7, 1.0, "deviation");
        s.deviation = scanDeviation(s.aligned, *mesh, measuring);
        s.stats = deviationStats(s.deviation);
      },
      [this, path, out, asTaken](const TaskOutcome& outcome) {
        const QString name = out->loaded->name;
        if (outcome.status == TaskOutcome::Status::Cancelled) {
          p_.log.info(tr("Comparing %1 cancelled.").arg(name));
          emit compared(path, false);
          return;
        }
        if (!outcome.succeeded()) {
          p_.reportError(tr("Compare scan"), outcome.message, outcome.hint);
          emit compared(path, false);
          return;
        }
        loaded_ = out->loaded;
        const QLocale loc;
        const QString counts = tr("%1 points read, %2 stray removed")
                                   .arg(loc.toString(qulonglong(out->loaded->read)),
                                        loc.toString(qulonglong(out->loaded->outliers)));
        if (!out->unplaced.isEmpty()) {
          unplaced_ = true;
          const auto placed = p_.doc.part();
          p_.view.scanLayer().setScan(loaded_->cloud, {}, DeviationStats{},
                                      placed ? placed->T_world_part : Transform::Identity());
          BoundingBox box;
          for (const Vec3& q : loaded_->cloud.points)
            box.extend((placed ? placed->T_world_part : Transform::Identity()) * q);
          p_.view.fitViewIncluding(box);
          panel_->showUnaligned(name, out->unplaced);
          panel_->raise();
          if (p_.layersChanged) p_.layersChanged();
          p_.reportError(
              tr("Compare scan"), tr("The fit cannot place %1 on the part: %2").arg(name, out->unplaced),
              tr("Align by Points (Scan dock): click three places on the part, each followed by the "
                 "same place on the scan."));
          emit compared(path, false);
          return;
        }
        out->shown->how = asTaken ? tr("%1; taken as placed, in the part's frame").arg(counts)
                                  : tr("%1; %2, residual %3 mm")
                                        .arg(counts, movedText(out->shown->record.T_part_scan),
                                             loc.toString(out->shown->record.rmsMm, 'f', 3));
        shown_ = out->shown;
        p_.doc.setScan(shown_->record);
        show();
        panel_->raise();
        const DeviationStats& st = shown_->stats;
        p_.log.info(tr("Scan %1: %2. Deviation from the part: mean %3 mm, RMS %4 mm, 95 % within %5 mm.")
                        .arg(name, shown_->how, loc.toString(st.mean, 'f', 3), loc.toString(st.rms, 'f', 3),
                             loc.toString(st.p95, 'f', 3)));
        emit compared(path, true);
      });
  return true;
}

void ScanWorkflow::onDocumentChanged(const ChangeSet& changes)
{
  // The continuation belongs to the plan it was made from: a new plan (or part) drops it, a later stage
  // of the same plan (the robot's motion solved afterwards) does not.
  if (continuation_->hasContinuation() &&
      (changes.has(Change::Part) || p_.doc.results().process != continuationPlan_)) {
    continuation_->clear();
    panel_->showContinuation({});
    continuationPlan_.reset();
  }
  if (changes.has(Change::Scan) || changes.has(Change::Part)) {
    const auto& record = p_.doc.scan();
    const auto part = p_.doc.part();
    if (!record) {
      if (!unplaced_) {  // a scan waiting for picked pairs stays
        picker_->stop();
        p_.view.scanLayer().setScan(PointCloud{}, {}, DeviationStats{}, Transform::Identity());
        panel_->clear();
        continuation_->clear();
        if (p_.layersChanged) p_.layersChanged();
      }
    } else if (shown_ && shown_->record == *record && part && shown_->mesh == part->mesh) {
      show();
    } else if (part && part->mesh) {
      reloadRecord();
    }
  }
  refreshResume();
  p_.view.scheduleRender();
}

void ScanWorkflow::show()
{
  if (!shown_) return;
  unplaced_ = false;
  const auto part = p_.doc.part();
  p_.view.scanLayer().setScan(shown_->aligned, shown_->deviation, shown_->stats,
                              part ? part->T_world_part : Transform::Identity());
  panel_->showComparison(QFileInfo(QString::fromStdString(shown_->record.file)).fileName(), shown_->how,
                         shown_->stats, p_.view.scanLayer().scaleLimit());
  refreshResume();
  if (p_.layersChanged) p_.layersChanged();
  p_.view.scheduleRender();
}

void ScanWorkflow::reloadRecord()
{
  const auto record = p_.doc.scan();
  const auto part = p_.doc.part();
  reloadPending_ = false;
  if (!record || !part || !part->mesh) return;
  if (p_.busy()) {
    reloadPending_ = true;
    return;
  }
  auto shown = std::make_shared<Shown>();
  auto loaded = std::make_shared<Loaded>();
  shown->record = *record;
  shown->mesh = part->mesh;
  loaded->file = std::filesystem::u8path(record->file);
  loaded->name = QFileInfo(QString::fromStdString(record->file)).fileName();
  const PluginRegistry& registry = p_.registry;
  p_.tasks.start(
      tr("Reading the scan %1").arg(loaded->name),
      [&registry, shown, loaded](Progress& progress) {
        ScanFilterReport filtered;
        loaded->cloud = readClean(registry, loaded->file, *shown->mesh, progress, &filtered);
        loaded->read = filtered.read, loaded->outliers = filtered.outliers;
        shown->aligned = transformed(loaded->cloud, shown->record.T_part_scan);
        SubProgress measuring(progress, 0.5, 1.0, "deviation");
        shown->deviation = scanDeviation(shown->aligned, *shown->mesh, measuring);
        shown->stats = deviationStats(shown->deviation);
      },
      [this, shown, loaded](const TaskOutcome& outcome) {
        if (!outcome.succeeded()) {
          panel_->clear();
          if (outcome.status == TaskOutcome::Status::Failed)
            p_.log.error(
                tr("The project's scan %1 cannot be read: %2").arg(loaded->name, outcome.message),
                tr("Put the file back (or beside the project) and open it again, or compare the scan "
                   "again (File > Compare Scan)."));
          return;
        }
        if (!p_.doc.scan() || !(*p_.doc.scan() == shown->record)) return;  // changed meanwhile
        const QLocale loc;
        shown->how = tr("%1 points; placed as recorded: %2, residual %3 mm")
                         .arg(loc.toString(qulonglong(loaded->read)), movedText(shown->record.T_part_scan),
                              loc.toString(shown->record.rmsMm, 'f', 3));
        loaded_ = loaded;
        shown_ = shown;
        show();
      });
}

void ScanWorkflow::alignByPoints()
{
  const auto part = p_.doc.part();
  if (!loaded_ || !part || !part->mesh || !shownTransform()) {
    p_.reportError(tr("Align by points"), tr("There is no scan to align."),
                   tr("Compare a scan first (File > Compare Scan)."));
    return;
  }
  if (!picker_->active()) {
    picker_->start(p_.view.partActor(), p_.view.scanLayer().actor());
    panel_->showPicking(tr("Pair 1: click a place on the part."), 0, false);
    return;
  }
  if (picker_->pairCount() < 3 || picker_->expecting() != PairPicker::Expect::Part) return;
  const Transform toPart = part->T_world_part.inverse();
  const Transform toScan = shownTransform()->inverse() * toPart;
  std::vector<PointPair> pairs;
  for (int i = 0; i < picker_->pairCount(); ++i)
    pairs.push_back({toPart * picker_->partPoints()[size_t(i)], toScan * picker_->scanPoints()[size_t(i)]});
  PairFit fit;
  try {
    fit = fitPointPairs(pairs, kPairToleranceMm);
  } catch (const InputError& e) {
    p_.reportError(tr("Align by points"), QString::fromStdString(e.what()), QString::fromStdString(e.hint()));
    emit aligned(false);
    return;
  }
  picker_->stop();
  const QLocale loc;
  alignFrom(
      fit.T_part_scan,
      tr("%n picked pair(s), %1 mm RMS", nullptr, int(pairs.size())).arg(loc.toString(fit.rmsMm, 'f', 2)),
      fit.rmsMm);
}

void ScanWorkflow::cancelPicking()
{
  picker_->stop();
  if (hasComparison())
    show();
  else if (loaded_ && unplaced_)
    panel_->showUnaligned(loaded_->name, tr("no pairs picked"));
  else
    panel_->clear();
}

void ScanWorkflow::alignFrom(const Transform& T_initial, const QString& how, double)
{
  const auto part = p_.doc.part();
  if (!loaded_ || !part || !part->mesh || p_.busy()) {
    emit aligned(false);
    return;
  }
  const std::shared_ptr<const Loaded> loaded = loaded_;
  auto shown = std::make_shared<Shown>();
  shown->mesh = part->mesh;
  shown->record.file = loaded->file.string();
  if (p_.doc.scan() && p_.doc.scan()->file == shown->record.file)
    shown->record.depositedTo = p_.doc.scan()->depositedTo;
  p_.tasks.start(
      tr("Aligning %1").arg(loaded->name),
      [loaded, shown, T_initial](Progress& progress) {
        SubProgress aligning(progress, 0.0, 0.7, "aligning");
        const AlignResult fit = alignScan(loaded->cloud, *shown->mesh, T_initial, AlignSettings{}, aligning);
        shown->record.T_part_scan = fit.T_part_scan;
        shown->record.rmsMm = fit.rmsMm;
        shown->aligned = transformed(loaded->cloud, fit.T_part_scan);
        SubProgress measuring(progress, 0.7, 1.0, "deviation");
        shown->deviation = scanDeviation(shown->aligned, *shown->mesh, measuring);
        shown->stats = deviationStats(shown->deviation);
      },
      [this, shown, loaded, how](const TaskOutcome& outcome) {
        if (!outcome.succeeded()) {
          if (outcome.status == TaskOutcome::Status::Failed)
            p_.reportError(tr("Align by points"), outcome.message, outcome.hint);
          panel_->showUnaligned(loaded->name, outcome.message);
          emit aligned(false);
          return;
        }
        const QLocale loc;
        shown->how =
            tr("Placed by %1, then the fit: %2, residual %3 mm")
                .arg(how, movedText(shown->record.T_part_scan), loc.toString(shown->record.rmsMm, 'f', 3));
        shown_ = shown;
        p_.doc.setScan(shown->record, "Align scan by points");
        show();
        p_.view.fitView();
        p_.log.info(tr("Scan %1: %2.").arg(loaded->name, shown->how));
        emit aligned(true);
      });
}

void ScanWorkflow::refreshResume()
{
  const Results& r = p_.doc.results();
  panel_->setCanResume(r.process && !r.process->empty() && planWindow(r).has_value());
}

bool ScanWorkflow::resumeFromScan(size_t at, double beadWidthMm)
{
  const Results& r = p_.doc.results();
  const std::optional<PlanWindow> window = planWindow(r);
  if (!r.process || r.process->empty() || !window) {
    p_.reportError(tr("Resume from scan"), tr("There is no planned path to resume."),
                   tr("Plan the part first (Plan > Plan)."));
    emit resumed(false);
    return false;
  }
  if (!hasComparison()) {
    p_.reportError(tr("Resume from scan"), tr("There is no aligned scan of the wall."),
                   tr("Compare the scan of the wall as it stands (File > Compare Scan)."));
    emit resumed(false);
    return false;
  }
  if (p_.busy()) {
    emit resumed(false);
    return false;
  }
  const std::shared_ptr<const Trajectory> plan = r.process;
  const std::shared_ptr<const Shown> shown = shown_;
  ResumeSettings settings;
  settings.hMin = window->hMin;
  settings.hMax = window->hMax;
  settings.process = processSettingsFrom(p_.doc.settings()->section(PlanSettings::kProcessSection));
  settings.process.beadWidth = beadWidthMm;
  struct Outcome {
    Resumed resumed;
    IndexStats trajectory, process, global;
  };
  auto result = std::make_shared<Outcome>();
  const std::optional<PlanReportSummary> summary = planSummaryOf(r);
  const bool solid = summary && summary->solidWall;
  p_.tasks.start(
      tr("Resuming from the scan"),
      [plan, shown, settings, at, beadWidthMm, result, solid](Progress& progress) {
        progress.report(0.1, "measuring the top edge");
        const MeasuredEdge edge = measureTopEdge(*plan, at, shown->aligned, beadWidthMm);
        progress.checkCancel();
        progress.report(0.4, "re-planning");
        result->resumed = resumeFromEdge(*plan, at, edge, settings);
        progress.report(0.6, "quality indices");
        // A solid's plan runs on its wall's mid-surface: its trajectory index is measured there.
        const std::unique_ptr<TriangleMesh> mid =
            solid ? std::make_unique<TriangleMesh>(
                        *plannableMidSurface(*shown->mesh, beadWidthMm).wall.midSurface)
                  : nullptr;
        result->trajectory = indexStats(trajectoryIndex(*plan, at, MeshDistance(mid ? *mid : *shown->mesh)));
        result->process = indexStats(processIndex(*plan, edge));
        result->global = indexStats(globalIndex(*plan, at, shown->aligned, shown->deviation));
      },
      [this, result, at, plan, window = *window](const TaskOutcome& outcome) {
        if (!outcome.succeeded()) {
          if (outcome.status == TaskOutcome::Status::Failed)
            p_.reportError(tr("Resume from scan"), outcome.message, outcome.hint);
          emit resumed(false);
          return;
        }
        const auto part = p_.doc.part();
        const Resumed& done = result->resumed;
        continuation_->setContinuation(done.continuation, window.hMin - window.tolerance,
                                       window.hMax + window.tolerance,
                                       part ? part->T_world_part : Transform::Identity());
        continuationPlan_ = plan;
        if (p_.showBuildUpTo) p_.showBuildUpTo(plan->points[at - 1].revolution);
        const ResumeReport& rep = done.report;
        const QLocale loc;
        const QString text =
            tr("<b>Continuation</b> from point %1 (drawn thick, the plan shown as built so far): %2 points, "
               "the arc restarting at the orange dot.<br>%3")
                .arg(loc.toString(qulonglong(at)), loc.toString(qulonglong(done.continuation.size())),
                     QString::fromStdString(rep.summary()).toHtmlEscaped()) +
            tr("<br>Quality indices of the build so far (1: as planned; 0.92: off by 8 % of a bead): %1")
                .arg(indicesText(result->trajectory, result->process, result->global));
        panel_->showContinuation(text);
        p_.log.info(tr("Quality indices of the build to point %1: %2")
                        .arg(at)
                        .arg(indicesText(result->trajectory, result->process, result->global)));
        if (rep.reachesTop())
          p_.log.info(tr("Resumed from point %1: %2").arg(at).arg(QString::fromStdString(rep.summary())));
        else
          p_.log.error(tr("Resumed from point %1: %2").arg(at).arg(QString::fromStdString(rep.summary())),
                       tr("Lay the missing height by hand, or widen the process window."));
        if (p_.doc.scan() && p_.doc.scan()->depositedTo != at) {
          ScanRecord record = *p_.doc.scan();
          record.depositedTo = at;
          if (shown_ && shown_->record == *p_.doc.scan()) {
            auto moved = std::make_shared<Shown>(*shown_);
            moved->record = record;
            shown_ = moved;
          }
          p_.doc.setScan(record, "Resume from scan");
        }
        if (p_.layersChanged) p_.layersChanged();
        p_.view.scheduleRender();
        emit resumed(rep.reachesTop());
      });
  return true;
}

void ScanWorkflow::chooseResume()
{
  const Results& r = p_.doc.results();
  if (!r.process || r.process->size() < 2) {
    resumeFromScan(0, kDefaultBeadWidth);  // says what is missing
    return;
  }
  const size_t n = r.process->size();
  QDialog dialog(&p_.window);
  dialog.setWindowTitle(tr("Resume from Scan"));
  auto* form = new QFormLayout(&dialog);
  auto* at = new QSpinBox(&dialog);
  at->setRange(1, int(std::min<size_t>(n - 1, 2147483647)));
  const size_t recorded = p_.doc.scan() ? p_.doc.scan()->depositedTo : 0;
  at->setValue(int(recorded > 0 && recorded < n ? recorded : n / 2));
  at->setGroupSeparatorShown(true);
  at->setToolTip(tr("How many of the plan's %1 points were laid when the scan was taken")
                     .arg(QLocale().toString(qulonglong(n))));
  auto* width = new QDoubleSpinBox(&dialog);
  width->setRange(0.5, 50.0);
  width->setDecimals(2);
  width->setSuffix(tr(" mm"));
  width->setValue(processSettingsFrom(p_.doc.settings()->section(PlanSettings::kProcessSection)).beadWidth);
  width->setToolTip(tr("The bead's width: the scan points over each bead's crown are taken within it"));
  form->addRow(tr("Points laid when scanned:"), at);
  form->addRow(tr("Bead width:"), width);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Resume"));
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  form->addRow(buttons);
  if (dialog.exec() == QDialog::Accepted) resumeFromScan(size_t(at->value()), width->value());
}

void ScanWorkflow::removeScan()
{
  picker_->stop();
  unplaced_ = false;
  continuation_->clear();
  if (p_.doc.scan()) {
    p_.doc.clearScan();
  } else {
    ChangeSet c;
    c.add(Change::Scan);
    onDocumentChanged(c);
  }
}

}  // namespace spira::ui
