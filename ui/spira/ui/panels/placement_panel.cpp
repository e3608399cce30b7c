#include "spira/ui/panels/placement_panel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "spira/base/error.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/planning/level_base.h"
#include "spira/planning/part_topology.h"

namespace spira::ui {

namespace {

constexpr double kDeg = M_PI / 180.0;

// -0 and 180 - 1e-13 read as 0 and 180 in the spin boxes.
double tidyAngle(double deg)
{
  if (std::abs(deg) < 1e-9) return 0.0;
  if (deg <= -180.0 + 1e-9) return 180.0;
  return deg;
}

QDoubleSpinBox* makeField(double range, const QString& suffix, const QString& tip, QWidget* parent)
{
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(-range, range);
  box->setDecimals(2);
  box->setSuffix(suffix);
  box->setToolTip(tip);
  box->setAlignment(Qt::AlignRight);
  // One edit per step or per finished entry, never per typed digit.
  box->setKeyboardTracking(false);
  // Sized for "-100000.00 mm" the box would be wider than the dock and clipped: it takes the
  // width the dock has instead.
  box->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  box->setMinimumWidth(box->fontMetrics().horizontalAdvance(QStringLiteral("-0000.00 mm")) + 30);
  return box;
}

}  // namespace

Transform Placement::toTransform() const
{
  Transform T = Transform::Identity();
  T.linear() = (Eigen::AngleAxisd(rotationDeg.z() * kDeg, Vec3::UnitZ()) *
                Eigen::AngleAxisd(rotationDeg.y() * kDeg, Vec3::UnitY()) *
                Eigen::AngleAxisd(rotationDeg.x() * kDeg, Vec3::UnitX()))
                   .toRotationMatrix();
  T.translation() = translation;
  return T;
}

Placement Placement::fromTransform(const Transform& T)
{
  const Mat3 R = T.linear();
  Placement p;
  p.translation = T.translation();
  const double b = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  double a = 0.0, c = 0.0;
  if (std::abs(R(2, 0)) < 1.0 - 1e-12) {
    a = std::atan2(R(2, 1), R(2, 2));
    c = std::atan2(R(1, 0), R(0, 0));
  } else {
    // Gimbal lock (Y = +-90 deg): only a + c or a - c is defined; put it all on Z.
    c = std::atan2(-R(0, 1), R(1, 1));
  }
  p.rotationDeg = Vec3(tidyAngle(a / kDeg), tidyAngle(b / kDeg), tidyAngle(c / kDeg));
  return p;
}

Transform droppedOnPlane(const TriangleMesh& mesh, const Transform& T, double planeZ)
{
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& v : mesh.vertices) {
    const double z = (T * v).z();
    if (std::isfinite(z)) lowest = std::min(lowest, z);
  }
  Transform out = T;
  if (std::isfinite(lowest)) out.translation().z() += planeZ - lowest;
  return out;
}

PlacementPanel::PlacementPanel(Document& doc, QWidget* parent)
    : QDockWidget(tr("Placement"), parent), doc_(doc)
{
  setObjectName(QStringLiteral("placementDock"));
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  layout->setContentsMargins(6, 6, 6, 6);

  const char* axes[3] = {"X", "Y", "Z"};
  auto* move = new QGroupBox(tr("Position (world frame)"), body);
  auto* moveForm = new QFormLayout(move);
  auto* turn = new QGroupBox(tr("Rotation about world X, then Y, then Z"), body);
  auto* turnForm = new QFormLayout(turn);
  for (int i = 0; i < 3; ++i) {
    fields_[static_cast<size_t>(i)] = makeField(
        1.0e5, tr(" mm"), tr("Where the part frame's origin sits along world %1, in mm").arg(axes[i]), move);
    moveForm->addRow(tr("%1").arg(axes[i]), fields_[static_cast<size_t>(i)]);
    auto* angle =
        makeField(180.0, tr(" °"), tr("Rotation of the part about world %1, in degrees").arg(axes[i]), turn);
    angle->setWrapping(true);
    angle->setSingleStep(5.0);
    fields_[static_cast<size_t>(i + 3)] = angle;
    turnForm->addRow(tr("%1").arg(axes[i]), angle);
  }
  for (int i = 0; i < 6; ++i) {
    fields_[static_cast<size_t>(i)]->setObjectName(QStringLiteral("placementField%1").arg(i));
    connect(fields_[static_cast<size_t>(i)], QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
            [this, i] { applyFields(i); });
  }
  layout->addWidget(move);
  layout->addWidget(turn);

  auto* buttons = new QHBoxLayout;
  drop_ = new QPushButton(tr("Drop to Substrate"), body);
  drop_->setObjectName(QStringLiteral("dropToSubstrate"));
  drop_->setToolTip(tr("Move the part along Z until its lowest point touches the substrate plate"));
  connect(drop_, &QPushButton::clicked, this, [this] { dropToSubstrate(); });
  level_ = new QPushButton(tr("Level Base"), body);
  level_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
  level_->setObjectName(QStringLiteral("levelBase"));
  level_->setToolTip(
      tr("Cut the part level through the highest point of its base edge (a scan cut at a slant), then drop "
         "it onto the substrate plate"));
  connect(level_, &QPushButton::clicked, this, [this] { levelBase(); });
  reset_ = new QPushButton(tr("Reset"), body);
  reset_->setToolTip(tr("Put the part back where it was imported: no move, no rotation"));
  connect(reset_, &QPushButton::clicked, this, [this] {
    if (doc_.part()) doc_.setPartPlacement(Transform::Identity(), tr("Reset placement").toStdString());
  });
  buttons->addWidget(drop_);
  buttons->addWidget(reset_);
  layout->addLayout(buttons);

  auto* substrateBox = new QGroupBox(tr("Substrate"), body);
  auto* substrateLayout = new QVBoxLayout(substrateBox);
  substrate_ = new QLabel(substrateBox);
  substrate_->setObjectName(QStringLiteral("substrateLabel"));
  substrate_->setWordWrap(true);
  substrateLayout->addWidget(substrate_);
  auto* substrateButtons = new QHBoxLayout;
  auto* plate = new QPushButton(tr("Plate"), substrateBox);
  plate->setObjectName(QStringLiteral("substratePlate"));
  plate->setToolTip(tr("Build on the flat plate under the part"));
  connect(plate, &QPushButton::clicked, this, [this] { usePlateSubstrate(); });
  auto* pipe = new QPushButton(tr("Pipe..."), substrateBox);
  pipe->setObjectName(QStringLiteral("substratePipe"));
  pipe->setToolTip(
      tr("Build a feature on a pipe: a cylinder of a given radius about the x, y or z axis through "
         "the origin, in the part's coordinates"));
  connect(pipe, &QPushButton::clicked, this, [this] {
    bool ok = false;
    const double radius =
        QInputDialog::getDouble(this, tr("Pipe substrate"), tr("Radius (mm):"), 32.0, 0.1, 100000.0, 2, &ok);
    if (!ok) return;
    const QString axis =
        QInputDialog::getItem(this, tr("Pipe substrate"), tr("Axis through the origin:"),
                              {QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")}, 1, false, &ok);
    if (ok) useCylinderSubstrate(radius, axis.toLatin1().at(0));
  });
  auto* meshButton = new QPushButton(tr("Mesh..."), substrateBox);
  meshButton->setObjectName(QStringLiteral("substrateMesh"));
  meshButton->setToolTip(
      tr("Build on a surface from a file: a pipe, a curved plate or a previous part (STL, OBJ, "
         "PLY, STEP), in the part's coordinates"));
  connect(meshButton, &QPushButton::clicked, this, [this] { emit substrateMeshRequested(); });
  substrateButtons->addWidget(plate);
  substrateButtons->addWidget(pipe);
  substrateButtons->addWidget(meshButton);
  substrateLayout->addLayout(substrateButtons);
  layout->addWidget(substrateBox);

  auto* baseBox = new QGroupBox(tr("Lower boundary (base)"), body);
  auto* baseLayout = new QVBoxLayout(baseBox);
  lower_ = new QComboBox(baseBox);
  lower_->setObjectName(QStringLiteral("lowerBoundaryCombo"));
  lower_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  lower_->setMinimumContentsLength(16);
  lower_->setToolTip(
      tr("The boundary loop the spiral starts from: the edge of the part that stands on the "
         "substrate"));
  connect(lower_, QOverload<int>::of(&QComboBox::activated), this, [this](int item) {
    const int loop = item - 1;  // item 0: automatic
    if (doc_.part() && doc_.part()->lowerBoundaryOverride != loop)
      doc_.setLowerBoundaryOverride(loop, tr("Choose lower boundary").toStdString());
  });
  baseLayout->addWidget(lower_);
  baseLayout->addWidget(level_);
  layout->addWidget(baseBox);
  note_ = new QLabel(body);
  note_->setWordWrap(true);
  note_->setStyleSheet(QStringLiteral("color: palette(mid);"));
  layout->addWidget(note_);
  layout->addStretch(1);
  // Scrolled, so the panel never makes the dock column taller than the window allows.
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(body);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setWidget(scroll);

  subscription_ = doc_.subscribe([this](const ChangeSet& c) { onDocumentChanged(c); });
  refresh();
}

PlacementPanel::~PlacementPanel()
{
  doc_.unsubscribe(subscription_);
}

void PlacementPanel::onDocumentChanged(const ChangeSet& changes)
{
  if (changes.has(Change::Part) || changes.has(Change::Substrate)) refresh();
}

void PlacementPanel::refresh()
{
  const auto& part = doc_.part();
  const bool has = part && part->mesh;
  const Placement p = has ? Placement::fromTransform(part->T_world_part) : Placement{};
  updating_ = true;
  for (int i = 0; i < 3; ++i) {
    fields_[static_cast<size_t>(i)]->setValue(p.translation[i]);
    fields_[static_cast<size_t>(i + 3)]->setValue(p.rotationDeg[i]);
  }
  updating_ = false;
  for (QDoubleSpinBox* f : fields_) f->setEnabled(has);
  const bool plane = doc_.substrate()->kind == Substrate::Kind::Plane;
  if (plane) lastPlateZ_ = doc_.substrate()->planeZ;
  substrate_->setText(plane
                          ? tr("Plate at z = %1 mm").arg(QLocale().toString(doc_.substrate()->planeZ, 'f', 2))
                          : tr("Mesh: %1 (%n triangles)", nullptr,
                               doc_.substrate()->mesh ? int(doc_.substrate()->mesh->faceCount()) : 0)
                                .arg(QString::fromStdString(doc_.substrate()->meshName)));
  drop_->setEnabled(has && plane);
  level_->setEnabled(has && plane);
  reset_->setEnabled(has);
  lower_->setEnabled(has);
  refreshLoops();
  if (!has)
    note_->setText(tr("Import a part to place it."));
  else
    note_->setText(
        plane ? tr("Substrate plate at z = %1 mm.").arg(QLocale().toString(doc_.substrate()->planeZ, 'f', 2))
              : tr("The substrate is a mesh: place the part by its coordinates."));
}

void PlacementPanel::refreshLoops()
{
  const auto& part = doc_.part();
  if (!part || !part->mesh) {
    loopsMesh_.reset();
    lower_->clear();
    return;
  }
  const QLocale loc;
  if (part->mesh != loopsMesh_) {
    loopsMesh_ = part->mesh;
    lower_->clear();
    lower_->addItem(tr("Automatic (the lowest loop)"));
    const MeshReport report = validateMesh(*part->mesh);
    for (size_t i = 0; i < report.boundaryLoops.size(); ++i) {
      const BoundaryLoop& loop = report.boundaryLoops[i];
      lower_->addItem(tr("Loop %1: %2 vertices, %3 mm long, z %4 to %5 mm (part frame)")
                          .arg(i + 1)
                          .arg(loop.vertices.size())
                          .arg(loc.toString(loop.length, 'f', 1), loc.toString(loop.zMin, 'f', 1),
                               loc.toString(loop.zMax, 'f', 1)));
    }
    if (report.boundaryLoops.empty()) lower_->setItemText(0, tr("Automatic (the part has no boundary)"));
  }
  // On a substrate mesh the base is the loop lying on it, not the lowest one.
  if (lower_->count() > 1)
    lower_->setItemText(0, doc_.substrate()->kind == Substrate::Kind::Mesh
                               ? tr("Automatic (the loop on the substrate)")
                               : tr("Automatic (the lowest loop)"));
  const int item = part->lowerBoundaryOverride + 1;
  lower_->setCurrentIndex(item >= 0 && item < lower_->count() ? item : 0);
}

void PlacementPanel::applyFields(int changed)
{
  if (updating_ || !doc_.part()) return;
  Placement p;
  for (int i = 0; i < 3; ++i) {
    p.translation[i] = fields_[static_cast<size_t>(i)]->value();
    p.rotationDeg[i] = fields_[static_cast<size_t>(i + 3)]->value();
  }
  const Transform T = p.toTransform();
  if (T.isApprox(doc_.part()->T_world_part, 1e-12)) return;
  const QString name = changed < 3 ? tr("Move part") : tr("Rotate part");
  doc_.setPartPlacement(T, name.toStdString(), "placement." + std::to_string(changed));
}

void PlacementPanel::useCylinderSubstrate(double radius, char axis)
{
  try {
    auto mesh = std::make_shared<const TriangleMesh>(makePipeAbout(radius, axis, 8.0 * radius));
    doc_.setSubstrate(Substrate::fromMesh(std::move(mesh), tr("pipe R %1 mm about %2")
                                                               .arg(QLocale().toString(radius, 'f', 1))
                                                               .arg(QLatin1Char(axis))
                                                               .toStdString()),
                      tr("Build on a pipe").toStdString());
  } catch (const Error& e) {
    emit failed(QString::fromStdString(e.what()), QString::fromStdString(e.hint()));
  }
}

void PlacementPanel::usePlateSubstrate()
{
  if (doc_.substrate()->kind == Substrate::Kind::Plane) return;
  doc_.setSubstrate(Substrate::plane(lastPlateZ_), tr("Build on the plate").toStdString());
}

bool PlacementPanel::dropToSubstrate()
{
  const auto& part = doc_.part();
  if (!part || !part->mesh || doc_.substrate()->kind != Substrate::Kind::Plane) return false;
  const Transform T = droppedOnPlane(*part->mesh, part->T_world_part, doc_.substrate()->planeZ);
  doc_.setPartPlacement(T, tr("Drop part to substrate").toStdString());
  return true;
}

bool PlacementPanel::levelBase()
{
  const auto& part = doc_.part();
  if (!part || !part->mesh || doc_.substrate()->kind != Substrate::Kind::Plane) return false;
  // The base is levelled in the world, where the substrate is, and the part keeps its frame.
  const Transform& T = part->T_world_part;
  TriangleMesh world = *part->mesh;
  for (Vec3& v : world.vertices) v = T * v;
  const double planeZ = doc_.substrate()->planeZ;
  try {
    const PartTopology topology =
        findPartTopology(validateMesh(world), world, planeZ, part->lowerBoundaryOverride, true);
    LevelledBase levelled = spira::levelBase(world, topology.lower);
    const Transform back = T.inverse();
    for (Vec3& v : levelled.mesh.vertices) v = back * v;
    Part p = *part;
    p.mesh = std::make_shared<const TriangleMesh>(std::move(levelled.mesh));
    p.lowerBoundaryOverride = Part::kAutomaticLowerBoundary;
    p.T_world_part = droppedOnPlane(*p.mesh, T, planeZ);
    doc_.setPart(std::move(p), tr("Level base").toStdString());
  } catch (const Error& e) {
    emit failed(QString::fromStdString(e.what()), QString::fromStdString(e.hint()));
    return false;
  }
  return true;
}

}  // namespace spira::ui
