#include "spira/ui/views/robot_layer.h"

#include <algorithm>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkCylinderSource.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include "spira/base/units.h"
#include "spira/robotcell/link_shapes.h"
#include "spira/robotcell/robot_cell.h"
#include "spira/ui/views/vtk_mesh.h"

namespace spira::ui {
namespace {

vtkSmartPointer<vtkMatrix4x4> toVtk(const Transform& T)
{
  auto m = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m->SetElement(r, c, T.matrix()(r, c));
  return m;
}

vtkSmartPointer<vtkActor> meshActor(const TriangleMesh& mesh, const double colour[3])
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(toPolyData(mesh));
  normals->SetFeatureAngle(35.0);
  normals->Update();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* p = actor->GetProperty();
  p->SetColor(colour[0], colour[1], colour[2]);
  p->SetAmbient(0.2);
  p->SetDiffuse(0.8);
  p->SetSpecular(0.25);
  p->SetSpecularPower(30.0);
  return actor;
}

// A cylinder of `radius` from z0 to z1 along the local z axis.
vtkSmartPointer<vtkPolyData> zCylinder(double radius, double z0, double z1)
{
  vtkNew<vtkCylinderSource> c;
  c->SetRadius(radius);
  c->SetHeight(z1 - z0);
  c->SetResolution(32);
  vtkNew<vtkTransform> t;
  t->Translate(0, 0, 0.5 * (z0 + z1));
  t->RotateX(90.0);  // the source's axis is y
  vtkNew<vtkTransformPolyDataFilter> f;
  f->SetInputConnection(c->GetOutputPort());
  f->SetTransform(t);
  f->Update();
  return f->GetOutput();
}

// The torch in its TCP frame: the nozzle cone from the TCP back along -z, the body behind it and a
// neck on to the flange (TCP z out of the nozzle, tool/TCP lengths from the cell).
vtkSmartPointer<vtkPolyData> torchGeometry(const ToolRecord& tool)
{
  vtkNew<vtkAppendPolyData> all;
  vtkNew<vtkConeSource> nozzle;
  nozzle->SetResolution(32);
  nozzle->SetRadius(tool.nozzleRadius);
  nozzle->SetHeight(tool.nozzleLength);
  nozzle->SetCenter(0, 0, -0.5 * tool.nozzleLength);
  nozzle->SetDirection(0, 0, 1);  // apex at the TCP
  nozzle->Update();
  all->AddInputData(nozzle->GetOutput());
  const double bodyEnd = -(tool.nozzleLength + tool.torchBodyLength);
  all->AddInputData(zCylinder(tool.torchBodyRadius, bodyEnd, -tool.nozzleLength));
  const double flangeZ = -tool.T_flange_tcp.translation().norm();
  if (flangeZ < bodyEnd - 1.0) all->AddInputData(zCylinder(0.6 * tool.torchBodyRadius, flangeZ, bodyEnd));
  all->Update();
  return all->GetOutput();
}

Eigen::VectorXd headOf(const Eigen::VectorXd& q, size_t n)
{
  return q.head(static_cast<Eigen::Index>(n));
}

}  // namespace

RobotLayer::RobotLayer(vtkRenderer* renderer) : renderer_(renderer)
{
  vtkNew<vtkPolyDataMapper> mapper;
  torch_->SetMapper(mapper);
  torch_->GetProperty()->SetColor(0.30, 0.31, 0.34);
  torch_->GetProperty()->SetSpecular(0.4);
  torch_->VisibilityOff();
  renderer_->AddActor(torch_);
}

RobotLayer::~RobotLayer()
{
  clear();
  renderer_->RemoveActor(torch_);
}

void RobotLayer::clear()
{
  for (const Piece& p : links_) renderer_->RemoveActor(p.actor);
  for (const Piece& p : positionerLinks_) renderer_->RemoveActor(p.actor);
  links_.clear();
  positionerLinks_.clear();
  robotShapes_.reset();
  positionerShapes_.reset();
  cell_.reset();
  torch_->VisibilityOff();
  partMotion_ = Transform::Identity();
  moveOtherActors();
}

std::vector<std::string> RobotLayer::setCell(const CellRecord* record)
{
  clear();
  if (!record) return {};
  auto cell = std::make_unique<RobotCell>(*record);
  std::vector<std::string> warnings;
  robotShapes_ = std::make_unique<RobotShapes>(
      readRobotShapes(record->robotUrdf, record->robotBaseLink, record->robotTipLink));
  warnings = robotShapes_->warnings;
  // FANUC arms are yellow, KUKA and ABB arms orange: the colours users know them by.
  const double fanuc[3] = {0.93, 0.76, 0.12}, kuka[3] = {0.96, 0.47, 0.09}, standIn[3] = {0.85, 0.2, 0.75};
  const double abb[3] = {0.74, 0.35, 0.16};
  const double* armColour = record->controller == ControllerFamily::FanucR30iB ? fanuc
                            : record->controller == ControllerFamily::AbbIrc5  ? abb
                                                                               : kuka;
  for (size_t k = 0; k < robotShapes_->links.size(); ++k) {
    const LinkShape& s = robotShapes_->links[k];
    // The visual mesh when it read; otherwise the collision shape, in magenta if that is a stand-in.
    const bool standInShown = !s.displayIsVisual && s.standInCube;
    links_.push_back({s.link, meshActor(s.display, standInShown ? standIn : armColour), k});
    if (s.joints == 0) links_.back().actor->GetProperty()->SetColor(0.25, 0.26, 0.28);  // the fixed foot
  }
  if (record->hasPositioner()) {
    positionerShapes_ = std::make_unique<RobotShapes>(
        readRobotShapes(record->positionerUrdf, record->positionerBaseLink, record->positionerTipLink));
    warnings.insert(warnings.end(), positionerShapes_->warnings.begin(), positionerShapes_->warnings.end());
    const double grey[3] = {0.45, 0.46, 0.5}, steel[3] = {0.72, 0.73, 0.76};
    for (size_t k = 0; k < positionerShapes_->links.size(); ++k) {
      const LinkShape& s = positionerShapes_->links[k];
      positionerLinks_.push_back({s.link, meshActor(s.display, s.joints == 0 ? grey : steel), k});
    }
  }
  for (const Piece& p : links_) renderer_->AddActor(p.actor);
  for (const Piece& p : positionerLinks_) renderer_->AddActor(p.actor);
  vtkPolyDataMapper::SafeDownCast(torch_->GetMapper())->SetInputData(torchGeometry(record->tool));
  cell_ = std::move(cell);
  setHomePose();
  setVisible(visible_);
  return warnings;
}

void RobotLayer::setScenePart(const Transform& T_scene_part)
{
  T_scene_part_ = T_scene_part;
  if (cell_) setPose(robotDeg_, externalDeg_);
}

Transform RobotLayer::cellPart(const std::array<double, 2>& externalDeg) const
{
  // The part sits on its mount turned as the scene turns it (cellForPlacement): a tilted part
  // stands on an upright cell.
  const CellRecord& r = cell_->record();
  const Transform mountPart = mountPartForPlacement(r.T_mount_part, T_scene_part_);
  if (!cell_->positioner() || r.mounting != PartMounting::Positioner) return mountPart;
  const Eigen::Vector2d e(degToRad(externalDeg[0]), degToRad(externalDeg[1]));
  return r.T_world_positioner * cell_->positioner()->forward(e) * mountPart;
}

Transform RobotLayer::sceneCell() const
{
  return T_scene_part_ * cellPart({0.0, 0.0}).inverse();
}

void RobotLayer::moveOtherActors()
{
  const bool still = partMotion_.isApprox(Transform::Identity(), 1e-12);
  vtkActorCollection* actors = renderer_->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) {
    if (a == torch_.Get()) continue;
    bool mine = false;
    for (const Piece& p : links_) mine = mine || p.actor == a;
    for (const Piece& p : positionerLinks_) mine = mine || p.actor == a;
    if (mine) continue;
    if (still) {
      if (a->GetUserMatrix()) a->SetUserMatrix(nullptr);
    } else {
      a->SetUserMatrix(toVtk(partMotion_));
    }
  }
}

Transform RobotLayer::linkTransformAt(size_t k, const std::array<double, 6>& robotDeg,
                                      const std::array<double, 2>& externalDeg) const
{
  const LinkShape& s = robotShapes_->links.at(links_.at(k).shape);
  const Eigen::VectorXd q = cell_->convention().fromControllerDeg(robotDeg);
  return sceneCell() * cell_->worldBase() * s.chain->forward(headOf(q, s.joints));
}

void RobotLayer::setPose(const std::array<double, 6>& robotDeg, const std::array<double, 2>& externalDeg)
{
  robotDeg_ = robotDeg;
  externalDeg_ = externalDeg;
  if (!cell_) {
    partMotion_ = Transform::Identity();
    moveOtherActors();
    return;
  }
  const Transform T_scene_cell = sceneCell();
  partMotion_ = T_scene_cell * cellPart(externalDeg) * (T_scene_cell * cellPart({0.0, 0.0})).inverse();
  moveOtherActors();
  const Eigen::VectorXd q = cell_->convention().fromControllerDeg(robotDeg);
  for (const Piece& p : links_) {
    const LinkShape& s = robotShapes_->links[p.shape];
    p.actor->SetUserMatrix(toVtk(T_scene_cell * cell_->worldBase() * s.chain->forward(headOf(q, s.joints))));
  }
  if (positionerShapes_) {
    const Eigen::Vector2d e(degToRad(externalDeg[0]), degToRad(externalDeg[1]));
    for (const Piece& p : positionerLinks_) {
      const LinkShape& s = positionerShapes_->links[p.shape];
      p.actor->SetUserMatrix(
          toVtk(T_scene_cell * cell_->record().T_world_positioner * s.chain->forward(headOf(e, s.joints))));
    }
  }
  torch_->SetUserMatrix(toVtk(tcpTransform()));
}

void RobotLayer::setHomePose()
{
  std::array<double, 6> q{};
  if (cell_) {
    const auto& limits = cell_->convention().axisLimits();
    for (size_t k = 0; k < 6; ++k) q[k] = std::clamp(0.0, limits[k].minDeg, limits[k].maxDeg);
  }
  setPose(q, {});
}

vtkActor* RobotLayer::linkActor(size_t k) const
{
  return links_.at(k).actor;
}

Transform RobotLayer::linkTransform(size_t k) const
{
  return linkTransformAt(k, robotDeg_, externalDeg_);
}

Transform RobotLayer::tcpTransform() const
{
  if (!cell_) return Transform::Identity();
  const Eigen::VectorXd q = cell_->convention().fromControllerDeg(robotDeg_);
  return sceneCell() * cell_->worldBase() * cell_->arm().forward(q) * cell_->record().tool.T_flange_tcp;
}

void RobotLayer::setVisible(bool on)
{
  visible_ = on;
  for (const Piece& p : links_) p.actor->SetVisibility(on);
  for (const Piece& p : positionerLinks_) p.actor->SetVisibility(on);
  torch_->SetVisibility(on && cell_ != nullptr);
}

std::array<double, 6> RobotLayer::bounds() const
{
  std::array<double, 6> b{1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  auto grow = [&b](vtkActor* a) {
    double ab[6];
    a->GetBounds(ab);
    for (int i = 0; i < 3; ++i)
      b[2 * i] = std::min(b[2 * i], ab[2 * i]), b[2 * i + 1] = std::max(b[2 * i + 1], ab[2 * i + 1]);
  };
  for (const Piece& p : links_) grow(p.actor);
  for (const Piece& p : positionerLinks_) grow(p.actor);
  if (cell_) grow(torch_);
  return b;
}

}  // namespace spira::ui
