#include "spira/ui/charts/compare_view.h"

#include <algorithm>
#include <cmath>

#include <QComboBox>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "spira/base/error.h"
#include "spira/document/document.h"
#include "spira/mesh/mesh_report.h"
#include "spira/pipeline/comparison_reader.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/plugin/strategy_name.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/views/color_maps.h"
#include "spira/ui/views/interaction_style.h"

namespace spira::ui {

namespace {

QString fromStd(const std::string& s)
{
  return QString::fromStdString(s);
}

// A refusal and what to do about it, as rich text: the hint on its own line.
QString withHint(const QString& message, const QString& hint)
{
  return hint.isEmpty()
             ? message.toHtmlEscaped()
             : message.toHtmlEscaped() + "<br>" + QObject::tr("To fix it: %1").arg(hint.toHtmlEscaped());
}

}  // namespace

CompareView::CompareView(Document& doc, const PluginRegistry& registry, QWidget* parent)
    : QWidget(parent, Qt::Window), doc_(doc), registry_(registry)
{
  setObjectName(QStringLiteral("compareView"));
  setWindowTitle(tr("Strategy Comparison"));
  resize(1200, 680);
  tasks_ = new TaskRunner(this, this);

  auto* bar = new QHBoxLayout;
  run_ = new QPushButton(tr("Compare on the Current Part"), this);
  run_->setToolTip(tr("Plan the part with every decomposer and with planar 2.5D slicing, in the background"));
  open_ = new QPushButton(tr("Open compare.csv..."), this);
  open_->setToolTip(tr("Show a comparison written by 'spira-cli compare PART -o DIR'"));
  cancel_ = new QPushButton(tr("Cancel"), this);
  cancel_->setVisible(false);
  status_ = new QLabel(this);
  status_->setObjectName(QStringLiteral("compareStatus"));
  status_->setWordWrap(true);
  bar->addWidget(run_);
  bar->addWidget(open_);
  bar->addWidget(cancel_);
  bar->addWidget(status_, 1);

  auto* grid = new QGridLayout;
  grid->setHorizontalSpacing(10);
  lut_ = makeLookupTable(ColorMap::Window, 0.0, 1.0);
  linker_->SetClientData(this);
  linker_->SetCallback(&CompareView::onInteraction);
  for (int k = 0; k < kSides; ++k) {
    const auto i = static_cast<size_t>(k);
    pickers_[i] = new QComboBox(this);
    pickers_[i]->setObjectName(QStringLiteral("strategy%1").arg(k));
    pickers_[i]->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    auto* head = new QHBoxLayout;
    head->addWidget(new QLabel(k == 0 ? tr("Left:") : tr("Right:"), this));
    head->addWidget(pickers_[i], 1);
    grid->addLayout(head, 0, k);
    widgets_[i] = new QVTKOpenGLNativeWidget(this);
    widgets_[i]->setRenderWindow(windows_[i]);
    widgets_[i]->setMinimumSize(320, 280);
    windows_[i]->AddRenderer(renderers_[i]);
    windows_[i]->SetMultiSamples(4);
    renderers_[i]->GradientBackgroundOn();
    renderers_[i]->SetBackground(0.70, 0.75, 0.81);
    renderers_[i]->SetBackground2(0.93, 0.95, 0.97);
    renderers_[i]->SetActiveCamera(camera_);
    mappers_[i]->SetInputData(data_[i]);
    mappers_[i]->SetLookupTable(lut_);
    mappers_[i]->UseLookupTableScalarRangeOn();
    mappers_[i]->SetScalarModeToUsePointData();
    actors_[i]->SetMapper(mappers_[i]);
    actors_[i]->GetProperty()->SetLineWidth(2.0f);
    actors_[i]->GetProperty()->SetPointSize(3.0f);
    actors_[i]->GetProperty()->SetLighting(false);
    renderers_[i]->AddActor(actors_[i]);
    vtkNew<QuietTrackballStyle> style;
    style->AddObserver(vtkCommand::InteractionEvent, linker_);
    windows_[i]->GetInteractor()->SetInteractorStyle(style);
    grid->addWidget(widgets_[i], 1, k);
    grid->setColumnStretch(k, 1);
    summaries_[i] = new QLabel(this);
    summaries_[i]->setObjectName(QStringLiteral("summary%1").arg(k));
    summaries_[i]->setWordWrap(true);
    summaries_[i]->setTextFormat(Qt::RichText);
    summaries_[i]->setMinimumHeight(52);
    summaries_[i]->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    grid->addWidget(summaries_[i], 2, k);
    connect(pickers_[i], qOverload<int>(&QComboBox::currentIndexChanged), this, [this, k](int) {
      if (!updating_) showSide(k);
    });
  }
  grid->setRowStretch(1, 1);
  // One legend for both views (they share the scale), at the right view's outer edge.
  legend_ = std::make_unique<ColorLegend>(renderers_[1], ColorLegend::Side::Right);
  legend_->setLookupTable(lut_);
  legend_->setVisible(false);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addLayout(grid, 1);

  connect(run_, &QPushButton::clicked, this, &CompareView::runOnPart);
  connect(cancel_, &QPushButton::clicked, this, &CompareView::cancel);
  connect(open_, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Open a comparison"), QString(),
                                                      tr("Strategy comparison (compare.csv compare.json)"));
    if (!file.isEmpty()) openFile(file);
  });
  status_->setText(
      tr("Compare the planning strategies on the current part, or open the compare.csv "
         "written by <tt>spira-cli compare</tt>."));
}

CompareView::~CompareView()
{
  delete tasks_;
  tasks_ = nullptr;
}

bool CompareView::busy() const
{
  return tasks_->busy();
}

void CompareView::cancel()
{
  tasks_->cancel();
}

void CompareView::runOnPart()
{
  if (tasks_->busy()) return;
  const auto snapshot = std::make_shared<const DocumentState>(doc_.snapshot());
  if (!snapshot->part || !snapshot->part->mesh || snapshot->part->mesh->empty()) {
    status_->setText(tr("<b>There is no part to compare on.</b> Import a part first (File > Import Part)."));
    emit comparisonReady(false);
    return;
  }
  auto result = std::make_shared<Comparison>();
  const PluginRegistry* registry = &registry_;
  run_->setEnabled(false);
  open_->setEnabled(false);
  cancel_->setVisible(true);
  status_->setText(tr("Planning the part with every strategy..."));
  connect(
      tasks_, &TaskRunner::progressed, this,
      [this](double f, const QString& stage) {
        if (tasks_->busy())
          status_->setText(
              tr("Comparing: %1 (%2 %)").arg(stage).arg(static_cast<int>(std::lround(100.0 * f))));
      },
      Qt::UniqueConnection);
  tasks_->start(
      tr("Comparing strategies"),
      [snapshot, registry, result](Progress& progress) {
        const TriangleMesh& mesh = *snapshot->part->mesh;
        const MeshReport report = validateMesh(mesh);
        PlanRequest request(mesh, report);
        request.substrateZ = snapshot->substrate->planeZ - snapshot->part->T_world_part.translation().z();
        request.lowerLoopOverride = snapshot->part->lowerBoundaryOverride;
        request.closureFinderId = snapshot->settings->closureFinderId;
        request.params = snapshot->settings->params;
        *result = compareStrategies(*registry, request, progress);
      },
      [this, result](const TaskOutcome& outcome) { finishRun(outcome, result); },
      TaskRunner::Display::Signals);
}

void CompareView::finishRun(const TaskOutcome& outcome, const std::shared_ptr<Comparison>& result)
{
  run_->setEnabled(true);
  open_->setEnabled(true);
  cancel_->setVisible(false);
  if (!outcome.succeeded()) {
    status_->setText(
        outcome.status == TaskOutcome::Status::Cancelled
            ? tr("Comparison cancelled.")
            : tr("<b>The comparison failed:</b> %1").arg(withHint(outcome.message, outcome.hint)));
    emit comparisonReady(false);
    return;
  }
  setComparison(std::move(*result));
  emit comparisonReady(true);
}

bool CompareView::openFile(const QString& path)
{
  try {
    setComparison(readComparison(path.toStdString()));
  } catch (const Error& e) {
    status_->setText(
        tr("<b>Cannot open the comparison:</b> %1").arg(withHint(fromStd(e.what()), fromStd(e.hint()))));
    return false;
  }
  return true;
}

void CompareView::setComparison(Comparison comparison)
{
  comparison_ = std::move(comparison);
  // The window (with the planner's tolerance) is the scale, as in the main view's height channel;
  // without one, the heights' own range.
  double lo = comparison_.hMin - comparison_.tolerance, hi = comparison_.hMax + comparison_.tolerance;
  if (!(hi > lo)) {
    lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const StrategyOutcome& s : comparison_.strategies)
      for (double h : s.heights) lo = std::min(lo, h), hi = std::max(hi, h);
    if (!(hi > lo)) lo = 0.0, hi = std::max(1.0, hi);
  }
  range_ = {lo, hi};
  lut_->SetTableRange(lo, hi);
  lut_->Build();
  legend_->setTitle(tr("Deposit height (mm)"));
  legend_->setLabelFormat(labelFormatFor(lo, hi));
  if (comparison_.hMax > comparison_.hMin)
    legend_->setLabels({comparison_.hMin, comparison_.h, comparison_.hMax});
  updating_ = true;
  std::vector<int> ran;  // strategies with points to show
  for (int k = 0; k < kSides; ++k) {
    QComboBox* c = pickers_[static_cast<size_t>(k)];
    c->clear();
    for (size_t i = 0; i < comparison_.strategies.size(); ++i) {
      const StrategyOutcome& s = comparison_.strategies[i];
      QString name = fromStd(s.strategy);
      if (const Plugin* p = registry_.find(decomposerIdOf(s.strategy))) name = fromStd(p->label());
      if (s.strategy == "planar_2.5d") name = tr("Planar 2.5D slicing (baseline)");
      c->addItem(s.ran ? name : tr("%1 (failed)").arg(name), static_cast<int>(i));
      if (k == 0 && s.ran && !s.points.empty()) ran.push_back(static_cast<int>(i));
    }
  }
  updating_ = false;
  // By default the first strategy that ran on the left, against the baseline (listed last) or the
  // next strategy that ran on the right.
  const int left = ran.empty() ? 0 : ran.front();
  const int right = ran.size() < 2 ? left : ran.back();
  setStrategy(0, left);
  setStrategy(1, right);
  legend_->setVisible(!comparison_.strategies.empty());
  const QLocale loc;
  status_->setText(tr("%n strategies compared; process window %1 .. %2 mm (h = %3 mm).", nullptr,
                      static_cast<int>(comparison_.strategies.size()))
                       .arg(loc.toString(comparison_.hMin, 'f', 2), loc.toString(comparison_.hMax, 'f', 2),
                            loc.toString(comparison_.h, 'f', 2)));
  fitCamera();
}

void CompareView::setStrategy(int side, int index)
{
  QComboBox* c = pickers_.at(static_cast<size_t>(side));
  const int row = c->findData(index);
  if (row < 0) return;
  if (c->currentIndex() == row)
    showSide(side);
  else
    c->setCurrentIndex(row);
}

int CompareView::strategy(int side) const
{
  const QComboBox* c = pickers_.at(static_cast<size_t>(side));
  return c->currentIndex() < 0 ? -1 : c->currentData().toInt();
}

vtkLookupTable* CompareView::lookupTable() const
{
  return lut_;
}

vtkRenderer* CompareView::renderer(int side) const
{
  return renderers_.at(static_cast<size_t>(side));
}

vtkPolyData* CompareView::polyData(int side) const
{
  return data_.at(static_cast<size_t>(side));
}

void CompareView::showSide(int side)
{
  const auto k = static_cast<size_t>(side);
  const int index = strategy(side);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkDoubleArray> heights;
  heights->SetName("height");
  QString summary;
  bool asLine = false;
  const QLocale loc;
  if (index >= 0 && index < static_cast<int>(comparison_.strategies.size())) {
    const StrategyOutcome& s = comparison_.strategies[static_cast<size_t>(index)];
    const vtkIdType n = static_cast<vtkIdType>(s.points.size());
    points->SetNumberOfPoints(n);
    heights->SetNumberOfValues(n);
    for (vtkIdType i = 0; i < n; ++i) {
      points->SetPoint(i, s.points[static_cast<size_t>(i)].data());
      heights->SetValue(i, s.heights[static_cast<size_t>(i)]);
    }
    // One spiral reads as a line; layer contours (and several sub-paths, whose joins the file
    // does not mark) as dots.
    asLine = s.kind == "ctpp" && s.paths <= 1 && s.arcStarts <= 1 && n > 1;
    if (asLine) {
      cells->InsertNextCell(static_cast<int>(n));
      for (vtkIdType i = 0; i < n; ++i) cells->InsertCellPoint(i);
    } else {
      for (vtkIdType i = 0; i < n; ++i) cells->InsertNextCell(1, &i);
    }
    const QString verdict = !s.ran ? tr("<span style='color:#b42020'><b>failed</b></span>: %1")
                                         .arg(fromStd(s.failure).toHtmlEscaped())
                            : s.feasible ? tr("<span style='color:#1e7a34'><b>feasible</b></span>")
                                         : tr("<span style='color:#b42020'><b>infeasible</b></span>");
    summary = tr("<b>%1</b> &mdash; %2").arg(pickers_[k]->currentText().toHtmlEscaped(), verdict);
    if (s.ran) {
      summary +=
          tr("<br>Deposit %1 .. %2 mm (mean %3 mm); %4 of %5 points outside the window")
              .arg(loc.toString(s.depositMin, 'f', 3), loc.toString(s.depositMax, 'f', 3),
                   loc.toString(s.depositMean, 'f', 3), loc.toString(static_cast<qulonglong>(s.outside)),
                   loc.toString(static_cast<qulonglong>(s.points.size())));
      if (s.kind == "planar")
        summary += tr("<br>%1 layers").arg(s.revolutions);
      else if (s.maxKinkDeg >= 0.0)
        summary += tr("<br>%1 layers at a constant distance, layer kink up to %2 deg")
                       .arg(s.revolutions)
                       .arg(loc.toString(s.maxKinkDeg, 'f', 1));
      else
        summary += tr("<br>%1 revolutions, %2 sub-path(s), generatrices %3 .. %4 mm")
                       .arg(s.revolutions)
                       .arg(static_cast<qulonglong>(s.paths))
                       .arg(loc.toString(s.generatrixLengthMin, 'f', 1),
                            loc.toString(s.generatrixLengthMax, 'f', 1));
      summary += tr("; %n arc start(s)", nullptr, s.arcStarts);
      if (s.runtime > 0.0) summary += tr("; planned in %1 s").arg(loc.toString(s.runtime, 'f', 2));
    }
  }
  data_[k]->SetPoints(points);
  vtkNew<vtkCellArray> none;
  data_[k]->SetLines(asLine ? cells.Get() : none.Get());
  data_[k]->SetVerts(asLine ? none.Get() : cells.Get());
  data_[k]->GetPointData()->SetScalars(heights);
  data_[k]->Modified();
  summaries_[k]->setText(summary);
  renderAll();
}

void CompareView::fitCamera()
{
  double bounds[6] = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
  for (const auto& d : data_) {
    if (d->GetNumberOfPoints() == 0) continue;
    double b[6];
    d->GetBounds(b);
    for (int i = 0; i < 3; ++i)
      bounds[2 * i] = std::min(bounds[2 * i], b[2 * i]),
                 bounds[2 * i + 1] = std::max(bounds[2 * i + 1], b[2 * i + 1]);
  }
  if (!(bounds[1] >= bounds[0])) return;
  // The main view's iso direction: from the front right, above.
  camera_->SetFocalPoint(0.0, 0.0, 0.0);
  camera_->SetPosition(1.0, -1.6, 1.1);
  camera_->SetViewUp(0.0, 0.0, 1.0);
  renderers_[0]->ResetCamera(bounds);
  camera_->Zoom(1.15);
  renderAll();
}

void CompareView::renderAll()
{
  for (size_t k = 0; k < kSides; ++k) {
    renderers_[k]->ResetCameraClippingRange();
    if (widgets_[k]->isVisible()) windows_[k]->Render();
  }
}

void CompareView::onInteraction(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* self = static_cast<CompareView*>(clientData);
  if (self->updating_) return;
  self->updating_ = true;
  self->renderAll();
  self->updating_ = false;
}

QImage CompareView::grabViews()
{
  renderAll();
  return grab().toImage();
}

}  // namespace spira::ui
