#include "spira/ui/panels/display_panel.h"

#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QSlider>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QToolButton>
#include <QVBoxLayout>

#include "spira/ui/charts/process_chart.h"
#include "spira/ui/views/field_layer.h"
#include "spira/ui/views/path_layers.h"
#include "spira/ui/views/scan_layer.h"
#include "spira/ui/views/scene_view.h"
#include "spira/ui/views/spiral_layer.h"
#include "spira/ui/views/thermal_layer.h"

namespace spira::ui {

DisplayPanel::DisplayPanel(SceneView* view, ProcessChart* chart, QAction* chartToggle, QWidget* parent)
    : QDockWidget(tr("Display"), parent), view_(view), chart_(chart)
{
  setObjectName(QStringLiteral("displayDock"));
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  layout->setContentsMargins(6, 6, 6, 6);

  layout->addLayout(buildPartRow(body));
  layout->addWidget(buildFieldBox(body));
  layout->addWidget(buildPathsBox(body));
  layout->addWidget(buildSpiralBox(body));
  finishLayout(body, layout, chartToggle);
  connectControls();
  resultsChanged();
}

QFormLayout* DisplayPanel::buildPartRow(QWidget* body)
{
  auto* partForm = new QFormLayout;
  partStyle_ = new QComboBox(body);
  partStyle_->setObjectName(QStringLiteral("partStyleCombo"));
  partStyle_->addItem(tr("Shaded"), static_cast<int>(PartStyle::Shaded));
  partStyle_->addItem(tr("Coloured by the field"), static_cast<int>(PartStyle::Field));
  partStyle_->addItem(tr("Transparent"), static_cast<int>(PartStyle::Transparent));
  partStyle_->addItem(tr("Hidden"), static_cast<int>(PartStyle::Hidden));
  partStyle_->addItem(tr("Temperature (thermal stage)"), static_cast<int>(PartStyle::Temperature));
  partStyle_->setToolTip(tr("How the part's surface is drawn under the plan"));
  partStyle_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  partStyle_->setMinimumContentsLength(12);
  partForm->addRow(tr("Part"), partStyle_);
  return partForm;
}

QGroupBox* DisplayPanel::buildFieldBox(QWidget* body)
{
  fieldBox_ = new QGroupBox(tr("Scalar field"), body);
  auto* fieldForm = new QFormLayout(fieldBox_);
  auto* range = new QHBoxLayout;
  fieldMin_ = new QDoubleSpinBox(fieldBox_);
  fieldMax_ = new QDoubleSpinBox(fieldBox_);
  for (QDoubleSpinBox* b : {fieldMin_, fieldMax_}) {
    b->setKeyboardTracking(false);
    b->setRange(0.0, 1.0);  // the field's own range once there is one
    b->setDecimals(2);
  }
  fieldMin_->setToolTip(tr("Field value drawn in the lowest colour"));
  fieldMax_->setToolTip(tr("Field value drawn in the highest colour"));
  fieldAuto_ = new QToolButton(fieldBox_);
  fieldAuto_->setText(tr("Full"));
  fieldAuto_->setToolTip(tr("Colour the whole range of the field"));
  range->addWidget(fieldMin_, 1);
  range->addWidget(new QLabel(QStringLiteral("–"), fieldBox_));
  range->addWidget(fieldMax_, 1);
  range->addWidget(fieldAuto_);
  fieldForm->addRow(tr("Range"), range);
  isoLines_ = new QSpinBox(fieldBox_);
  isoLines_->setRange(0, 60);
  isoLines_->setValue(view_->fieldLayer().isoLineCount());
  isoLines_->setSpecialValueText(tr("none"));
  isoLines_->setToolTip(tr("About how many iso-lines to draw, at a round spacing"));
  fieldForm->addRow(tr("Iso-lines"), isoLines_);

  return fieldBox_;
}

QGroupBox* DisplayPanel::buildPathsBox(QWidget* body)
{
  auto* pathsBox = new QGroupBox(tr("Decomposition"), body);
  auto* pathsLayout = new QVBoxLayout(pathsBox);
  generatrices_ = new QCheckBox(tr("Generatrices"), pathsBox);
  generatrices_->setToolTip(tr("The curves from the base up along which the spiral climbs"));
  closure_ = new QCheckBox(tr("Closure point"), pathsBox);
  closure_->setChecked(true);
  closure_->setToolTip(tr("Closed parts: where the spiral ends"));
  scan_ = new QCheckBox(tr("Compared scan"), pathsBox);
  scan_->setChecked(true);
  scan_->setToolTip(tr("File > Compare Scan: the scan on the part, coloured by its deviation from it"));
  guide_ = new QCheckBox(tr("Guide curve"), pathsBox);
  guide_->setChecked(true);
  guide_->setToolTip(tr("Tubes (constant distance): the centre line the layers are laid about"));
  pathsLayout->addWidget(generatrices_);
  pathsLayout->addWidget(guide_);
  pathsLayout->addWidget(closure_);
  pathsLayout->addWidget(scan_);
  return pathsBox;
}

QGroupBox* DisplayPanel::buildSpiralBox(QWidget* body)
{
  spiralBox_ = new QGroupBox(tr("Spiral"), body);
  auto* spiralForm = new QFormLayout(spiralBox_);
  spiral_ = new QCheckBox(tr("Show"), spiralBox_);
  spiral_->setChecked(true);
  tube_ = new QCheckBox(tr("As a tube"), spiralBox_);
  tube_->setToolTip(tr("Draw the path as a tube a little thinner than a layer (slower on long paths)"));
  auto* checks = new QHBoxLayout;
  checks->addWidget(spiral_);
  checks->addWidget(tube_);
  frames_ = new QCheckBox(tr("Torch frames"), spiralBox_);
  frames_->setObjectName(QStringLiteral("framesCheck"));
  frames_->setToolTip(
      tr("Draw the torch frame (x red: travel, y green, z blue: torch axis) every few points"));
  connect(frames_, &QCheckBox::toggled, this, &DisplayPanel::framesToggled);
  checks->addWidget(frames_);
  checks->addStretch(1);
  spiralForm->addRow(checks);
  channel_ = new QComboBox(spiralBox_);
  channel_->setObjectName(QStringLiteral("channelCombo"));
  for (int c = 0; c < kSpiralChannelCount; ++c) {
    const SpiralChannelInfo info = spiralChannelInfo(static_cast<SpiralChannel>(c));
    channel_->addItem(info.unit.isEmpty() ? info.name : QStringLiteral("%1 (%2)").arg(info.name, info.unit),
                      c);
  }
  channel_->setToolTip(tr("The channel the spiral is coloured by"));
  channel_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  channel_->setMinimumContentsLength(12);
  spiralForm->addRow(tr("Colour by"), channel_);
  revolution_ = new QSlider(Qt::Horizontal, spiralBox_);
  revolution_->setObjectName(QStringLiteral("revolutionSlider"));
  revolution_->setRange(0, 0);
  revolution_->setToolTip(tr("Show the build up to this revolution (layer)"));
  spiralForm->addRow(tr("Build up to"), revolution_);
  revolutionText_ = new QLabel(spiralBox_);
  revolutionText_->setObjectName(QStringLiteral("revolutionLabel"));
  revolutionText_->setWordWrap(true);
  // Up to three wrapped lines; a short dock must not clip them.
  revolutionText_->setMinimumHeight(3 * revolutionText_->fontMetrics().lineSpacing() + 4);
  spiralForm->addRow(QString(), revolutionText_);

  return spiralBox_;
}

void DisplayPanel::finishLayout(QWidget* body, QVBoxLayout* layout, QAction* chartToggle)
{
  auto* chartButton = new QToolButton(body);
  chartButton->setDefaultAction(chartToggle);
  chartButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
  chartButton->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  layout->addWidget(chartButton);
  layout->addStretch(1);
  // Short screens scroll the controls rather than squeeze them.
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(body);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setWidget(scroll);
}

void DisplayPanel::connectControls()
{
  connect(partStyle_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    if (!updating_) setPartStyle(static_cast<PartStyle>(partStyle_->currentData().toInt()));
  });
  connect(fieldMin_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
          &DisplayPanel::applyFieldRange);
  connect(fieldMax_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
          &DisplayPanel::applyFieldRange);
  connect(fieldAuto_, &QToolButton::clicked, this, [this] {
    const auto [lo, hi] = view_->fieldLayer().dataRange();
    setFieldRange(lo, hi);
  });
  connect(isoLines_, QOverload<int>::of(&QSpinBox::valueChanged), this, [this](int n) {
    view_->fieldLayer().setIsoLineCount(n);
    render();
  });
  connect(generatrices_, &QCheckBox::toggled, this, &DisplayPanel::setGeneratricesVisible);
  connect(closure_, &QCheckBox::toggled, this, [this](bool on) {
    view_->pathLayers().setClosureVisible(on);
    render();
  });
  connect(scan_, &QCheckBox::toggled, this, [this](bool on) {
    view_->scanLayer().setVisible(on);
    render();
  });
  connect(guide_, &QCheckBox::toggled, this, [this](bool on) {
    view_->pathLayers().setGuideVisible(on);
    render();
  });
  connect(spiral_, &QCheckBox::toggled, this, [this](bool on) {
    view_->spiralLayer().setVisible(on);
    render();
  });
  connect(tube_, &QCheckBox::toggled, this, &DisplayPanel::setTube);
  connect(channel_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    if (!updating_) setChannel(static_cast<SpiralChannel>(channel_->currentData().toInt()));
  });
  connect(revolution_, &QSlider::valueChanged, this, &DisplayPanel::setRevolutionLimit);
}

void DisplayPanel::render()
{
  view_->scheduleRender();
}

void DisplayPanel::resultsChanged()
{
  updating_ = true;
  FieldLayer& field = view_->fieldLayer();
  SpiralLayer& spiral = view_->spiralLayer();
  fieldBox_->setEnabled(field.hasField());
  if (field.hasField()) {
    const auto [lo, hi] = field.dataRange();
    const auto [shownLo, shownHi] = field.range();
    const double step = hi > lo ? std::pow(10.0, std::floor(std::log10((hi - lo) / 100.0))) : 0.01;
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step))));
    for (QDoubleSpinBox* b : {fieldMin_, fieldMax_}) {
      b->setDecimals(decimals);
      b->setSingleStep(step);
      b->setRange(lo, hi);
    }
    fieldMin_->setValue(shownLo);
    fieldMax_->setValue(shownHi);
  }
  // Choices that have nothing to show are greyed out.
  if (auto* model = qobject_cast<QStandardItemModel*>(partStyle_->model()))
    model->item(partStyle_->findData(static_cast<int>(PartStyle::Field)))->setEnabled(field.hasField());
  if (auto* model = qobject_cast<QStandardItemModel*>(partStyle_->model()))
    model->item(partStyle_->findData(static_cast<int>(PartStyle::Temperature)))
        ->setEnabled(view_->thermalLayer().hasResult());
  const PathLayers& paths = view_->pathLayers();
  generatrices_->setText(
      paths.stride() > 1 ? tr("Generatrices (1 in %1 of %2)").arg(paths.stride()).arg(paths.generatrixCount())
                         : tr("Generatrices"));
  guide_->setEnabled(paths.hasGuide());
  scan_->setEnabled(view_->scanLayer().hasScan());
  spiralBox_->setEnabled(spiral.hasTrajectory());
  if (auto* model = qobject_cast<QStandardItemModel*>(channel_->model())) {
    for (int c = 0; c < kSpiralChannelCount; ++c)
      model->item(c)->setEnabled(spiral.channelAvailable(static_cast<SpiralChannel>(c)));
  }
  channel_->setCurrentIndex(channel_->findData(static_cast<int>(spiral.channel())));
  revolution_->setRange(0, std::max(0, spiral.revolutionCount() - 1));
  revolution_->setValue(spiral.revolutionLimit());
  partStyle_->setCurrentIndex(partStyle_->findData(static_cast<int>(view_->partStyle())));
  updating_ = false;
  refreshRevolutionText();
}

void DisplayPanel::setPartStyle(PartStyle style)
{
  view_->setPartStyle(style);
  updating_ = true;
  partStyle_->setCurrentIndex(partStyle_->findData(static_cast<int>(style)));
  updating_ = false;
}

bool DisplayPanel::setChannel(SpiralChannel channel)
{
  const bool ok = view_->spiralLayer().setChannel(channel);
  updating_ = true;
  channel_->setCurrentIndex(channel_->findData(static_cast<int>(view_->spiralLayer().channel())));
  updating_ = false;
  render();
  return ok;
}

void DisplayPanel::setRevolutionLimit(int last)
{
  SpiralLayer& spiral = view_->spiralLayer();
  spiral.setRevolutionLimit(last);
  if (revolution_->value() != spiral.revolutionLimit()) revolution_->setValue(spiral.revolutionLimit());
  refreshRevolutionText();
  const bool all = spiral.revolutionLimit() >= spiral.revolutionCount() - 1;
  emit buildCutChanged(all ? -1.0 : spiral.shownLength());
  if (chart_) chart_->setCursor(all ? -1.0 : spiral.shownLength());
  render();
}

void DisplayPanel::setTube(bool on)
{
  view_->spiralLayer().setTube(on);
  if (tube_->isChecked() != on) tube_->setChecked(on);
  render();
}

void DisplayPanel::setGeneratricesVisible(bool on)
{
  view_->pathLayers().setGeneratricesVisible(on);
  if (generatrices_->isChecked() != on) generatrices_->setChecked(on);
  render();
}

void DisplayPanel::setFieldRange(double lo, double hi)
{
  updating_ = true;
  fieldMin_->setValue(lo);
  fieldMax_->setValue(hi);
  updating_ = false;
  applyFieldRange();
}

void DisplayPanel::applyFieldRange()
{
  if (updating_) return;
  view_->fieldLayer().setRange(fieldMin_->value(), fieldMax_->value());
  render();
}

void DisplayPanel::refreshRevolutionText()
{
  const SpiralLayer& spiral = view_->spiralLayer();
  if (!spiral.hasTrajectory()) {
    revolutionText_->setText(tr("No spiral yet"));
    return;
  }
  // A closed part's spiral ends on its closure point, which the planner numbers as one more
  // revolution: the label counts the rings and names the point.
  const int rings = spiral.revolutionCount() - (spiral.endsOnAPoint() ? 1 : 0);
  const int shown = spiral.revolutionLimit() + 1;
  const QString what = shown > rings ? tr("All %1 revolutions and the closure point").arg(rings)
                                     : tr("Revolution %1 of %2").arg(shown).arg(rings);
  revolutionText_->setText(tr("%1: %2 points, %3 m of path")
                               .arg(what)
                               .arg(spiral.shownPointCount())
                               .arg(spiral.shownLength() / 1000.0, 0, 'f', 2));
}

}  // namespace spira::ui
