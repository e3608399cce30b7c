#include "spira/ui/panels/cell_panel.h"

#include <cmath>

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/robotcell/cell_file.h"
#include "spira/ui/panels/log_panel.h"

namespace spira::ui {
namespace {

constexpr int kNameRole = Qt::UserRole + 1;  // the cell's own name

QString fromStd(const std::string& s)
{
  return QString::fromStdString(s);
}

QString axisLine(const CellAxis& a, const QString& name)
{
  return QObject::tr("%1: %2 to %3 deg, %4 deg/s")
      .arg(name)
      .arg(a.minDeg, 0, 'g', 6)
      .arg(a.maxDeg, 0, 'g', 6)
      .arg(a.maxSpeedDegPerS, 0, 'g', 5);
}

}  // namespace

CellPanel::CellPanel(Document& doc, LogPanel* log, QWidget* parent) : QWidget(parent), doc_(doc), log_(log)
{
  setObjectName(QStringLiteral("cellPanel"));
  auto* layout = new QVBoxLayout(this);
  auto* pick = new QFormLayout;
  combo_ = new QComboBox(this);
  combo_->setToolTip(tr("The robot cell the plan is solved on (robot, torch, positioner)"));
  combo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo_->setMinimumContentsLength(16);
  combo_->addItem(tr("No cell"), QString());
  for (const QString& f : bundledCells()) {
    try {
      // Listed by the name people know the cell by; a cell that does not read is left out.
      const QString name = fromStd(readCellFile(f.toStdString()).name);
      combo_->addItem(name, f);
      combo_->setItemData(combo_->count() - 1, name, kNameRole);
      combo_->setItemData(combo_->count() - 1, f, Qt::ToolTipRole);
    } catch (const Error&) {
    }
  }
  pick->addRow(tr("Cell"), combo_);
  load_ = new QPushButton(tr("Load .cell file..."), this);
  pick->addRow(QString(), load_);
  layout->addLayout(pick);

  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(summary_);

  auto* placement = new QGroupBox(tr("Part in the cell"), this);
  auto* pf = new QFormLayout(placement);
  const char* axes[3] = {"X", "Y", "Z"};
  for (int k = 0; k < 3; ++k) {
    offset_[k] =
        lengthBox(-5000.0, 5000.0, tr("Offset of the part's frame in its mount frame (table or world)"));
    pf->addRow(tr("%1 (mm)").arg(QLatin1String(axes[k])), offset_[k]);
  }
  turn_ = new QDoubleSpinBox(this);
  turn_->setRange(-360.0, 360.0);
  turn_->setDecimals(2);
  turn_->setSuffix(tr(" deg"));
  turn_->setToolTip(tr("Rotation of the part about the mount's vertical axis"));
  pf->addRow(tr("Turn"), turn_);
  layout->addWidget(placement);

  auto* torch = new QGroupBox(tr("Torch"), this);
  auto* tf = new QFormLayout(torch);
  tcp_ = lengthBox(0.0, 2000.0, tr("Distance from the flange to the TCP along the flange's z axis"));
  tf->addRow(tr("TCP length (mm)"), tcp_);
  nozzle_ = lengthBox(0.5, 100.0, tr("Nozzle radius, used by the torch collision checks"));
  tf->addRow(tr("Nozzle radius (mm)"), nozzle_);
  layout->addWidget(torch);
  layout->addStretch(1);

  connect(combo_, qOverload<int>(&QComboBox::activated), this, [this](int i) {
    const QString file = combo_->itemData(i).toString();
    if (file.isEmpty()) {
      if (doc_.cell()) doc_.clearCell();
    } else {
      loadCell(file);
    }
  });
  connect(load_, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Load Robot Cell"), bundledCellDir(),
                                                      tr("Robot cells (*.cell);;All files (*)"));
    if (!file.isEmpty()) loadCell(file);
  });
  for (QDoubleSpinBox* b : {offset_[0], offset_[1], offset_[2], turn_, tcp_, nozzle_})
    connect(b, &QDoubleSpinBox::editingFinished, this, &CellPanel::applyEdits);
  refresh();
}

QDoubleSpinBox* CellPanel::lengthBox(double min, double max, const QString& tip)
{
  auto* b = new QDoubleSpinBox(this);
  b->setRange(min, max);
  b->setDecimals(2);
  b->setToolTip(tip);
  return b;
}

QString CellPanel::bundledCellDir()
{
  const QString env = qEnvironmentVariable("SPIRA_RESOURCE_DIR");
  QStringList candidates;
  if (!env.isEmpty()) candidates << env + QStringLiteral("/cells");
  candidates << QCoreApplication::applicationDirPath() + QStringLiteral("/../share/spira/cells");
#ifdef SPIRA_RESOURCE_SOURCE_DIR
  candidates << QStringLiteral(SPIRA_RESOURCE_SOURCE_DIR "/cells");
#endif
  for (const QString& c : candidates)
    if (QDir(c).exists()) return QDir(c).canonicalPath();
  return QString();
}

QStringList CellPanel::bundledCells()
{
  const QString dir = bundledCellDir();
  QStringList out;
  if (dir.isEmpty()) return out;
  for (const QString& f : QDir(dir).entryList({QStringLiteral("*.cell")}, QDir::Files, QDir::Name))
    out << dir + QLatin1Char('/') + f;
  return out;
}

bool CellPanel::loadCell(const QString& file)
{
  try {
    CellRecord cell = readCellFile(file.toStdString());
    doc_.setCell(std::move(cell), tr("Choose cell %1").arg(QFileInfo(file).completeBaseName()).toStdString());
    if (log_) log_->info(tr("Cell: %1.").arg(fromStd(doc_.cell()->name)));
    return true;
  } catch (const Error& e) {
    if (log_) log_->error(tr("Cannot load the cell %1: %2").arg(file, fromStd(e.what())), fromStd(e.hint()));
  }
  refresh();
  return false;
}

void CellPanel::refresh()
{
  updating_ = true;
  const auto& cell = doc_.cell();
  int index = 0;
  if (cell) {
    // The combo shows the bundled cell of the same name, when there is one.
    index = combo_->findData(fromStd(cell->name), kNameRole);
    if (index < 0) {
      combo_->addItem(fromStd(cell->name), QString());
      index = combo_->count() - 1;
      combo_->setItemData(index, fromStd(cell->name), kNameRole);
    }
  }
  combo_->setCurrentIndex(index);
  const bool on = cell != nullptr;
  for (QWidget* w : std::initializer_list<QWidget*>{offset_[0], offset_[1], offset_[2], turn_, tcp_, nozzle_})
    w->setEnabled(on);
  if (!cell) {
    summary_->setText(
        tr("No robot cell: the plan is a torch path in the part's frame. Choose a cell to "
           "solve the robot's joints and simulate."));
    updating_ = false;
    return;
  }
  QStringList lines;
  lines << tr("<b>%1</b>").arg(fromStd(cell->name).toHtmlEscaped());
  lines << tr("Robot: %1").arg(QFileInfo(fromStd(cell->robotUrdf)).dir().dirName());
  lines << tr("Controller: %1")
               .arg(cell->controller == ControllerFamily::FanucR30iB ? tr("FANUC R-30iB (TP)")
                    : cell->controller == ControllerFamily::AbbIrc5  ? tr("ABB IRC5 (RAPID)")
                                                                     : tr("KUKA KRC4 (KRL)"));
  const QString axisPrefix = cell->controller == ControllerFamily::FanucR30iB ? "J"
                             : cell->controller == ControllerFamily::AbbIrc5  ? "rax_"
                                                                              : "A";
  for (size_t k = 0; k < cell->robotAxes.size(); ++k)
    lines << axisLine(cell->robotAxes[k], axisPrefix + QString::number(k + 1));
  const Vec3 tcp = cell->tool.T_flange_tcp.translation();
  lines
      << tr("Tool: TCP at (%1, %2, %3) mm from the flange; nozzle %4 mm radius, %5 mm long; body %6 x %7 mm")
             .arg(tcp.x(), 0, 'f', 1)
             .arg(tcp.y(), 0, 'f', 1)
             .arg(tcp.z(), 0, 'f', 1)
             .arg(cell->tool.nozzleRadius, 0, 'g', 4)
             .arg(cell->tool.nozzleLength, 0, 'g', 4)
             .arg(cell->tool.torchBodyRadius, 0, 'g', 4)
             .arg(cell->tool.torchBodyLength, 0, 'g', 4);
  if (cell->hasPositioner()) {
    lines << tr("Positioner: 2-axis tilt-rotate at (%1, %2, %3) mm%4")
                 .arg(cell->T_world_positioner.translation().x(), 0, 'f', 0)
                 .arg(cell->T_world_positioner.translation().y(), 0, 'f', 0)
                 .arg(cell->T_world_positioner.translation().z(), 0, 'f', 0)
                 .arg(cell->keepBuildVertical ? tr(", keeps the build direction vertical") : QString());
    for (size_t k = 0; k < cell->positionerAxes.size(); ++k)
      lines << axisLine(cell->positionerAxes[k], QStringLiteral("E%1").arg(k + 1));
  } else {
    lines << tr("Positioner: none (part on a fixed table)");
  }
  lines << tr("Part mounted on the %1")
               .arg(cell->mounting == PartMounting::Positioner ? tr("positioner table") : tr("fixed table"));
  lines << tr("Cable twist limit |q4 + q6|: %1 deg").arg(cell->cableTwistLimitDeg, 0, 'g', 4);
  summary_->setText(lines.join(QStringLiteral("<br>")));
  const Vec3 t = cell->T_mount_part.translation();
  for (int k = 0; k < 3; ++k) offset_[k]->setValue(t[k]);
  const Mat3 R = cell->T_mount_part.rotation();
  turn_->setValue(radToDeg(std::atan2(R(1, 0), R(0, 0))));
  tcp_->setValue(tcp.z());
  nozzle_->setValue(cell->tool.nozzleRadius);
  updating_ = false;
}

void CellPanel::applyEdits()
{
  if (updating_ || !doc_.cell()) return;
  CellRecord c = *doc_.cell();
  // The turn replaces the rotation about the vertical; tilts of the mount stay.
  const Mat3 R = c.T_mount_part.rotation();
  const double current = std::atan2(R(1, 0), R(0, 0));
  const double wanted = degToRad(turn_->value());
  Transform T = c.T_mount_part;
  T.linear() = Eigen::AngleAxisd(wanted - current, Vec3::UnitZ()).toRotationMatrix() * R;
  T.translation() = Vec3(offset_[0]->value(), offset_[1]->value(), offset_[2]->value());
  c.T_mount_part = T;
  c.tool.T_flange_tcp.translation().z() = tcp_->value();
  c.tool.nozzleRadius = nozzle_->value();
  if (c == *doc_.cell()) return;
  doc_.setCell(std::move(c), tr("Edit cell").toStdString());
}

}  // namespace spira::ui
