#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "spira/base/transform.h"
#include "spira/robotcell/cell_record.h"

class vtkActor;
class vtkRenderer;

namespace spira {
class RobotCell;
struct RobotShapes;
}  // namespace spira

namespace spira::ui {

// The robot cell in the 3D view: the arm's links, the positioner and the torch, each one actor
// whose geometry is built once and whose user matrix forward kinematics moves (cheap enough for
// 30 poses a second). Link geometry is the URDF's collision meshes (link_shapes.h); a missing mesh
// shows as a stand-in cube and a warning.
//
// Frames: the layer anchors the cell so that, with the positioner's axes at 0, the part sits where
// the scene draws it: T_scene_cell = T_scene_part * T_cell_part(0)^-1, T_cell_part(e) being where
// the cell places the part (T_mount_part on the fixed table, or on the positioner's table at axes
// e). When the positioner turns, everything else the scene draws (part, spiral, plate, bead) rides
// on its table: those actors get partMotion() = T_cell_part(e) T_cell_part(0)^-1 in the scene
// frame as their user matrix.
class RobotLayer {
 public:
  explicit RobotLayer(vtkRenderer* renderer);
  ~RobotLayer();

  // Builds the cell's actors; null removes them. Throws what RobotCell throws (unreadable URDF).
  // Returns the warnings (missing meshes).
  std::vector<std::string> setCell(const CellRecord* cell);
  bool hasCell() const { return cell_ != nullptr; }
  const RobotCell* cell() const { return cell_.get(); }

  // Where the scene draws the part (the document's placement).
  void setScenePart(const Transform& T_scene_part);
  // Poses the arm (controller degrees A1..A6 / J1..J6) and the positioner (E1, E2, degrees).
  void setPose(const std::array<double, 6>& robotDeg, const std::array<double, 2>& externalDeg = {});
  // The home pose: every controller axis at 0 (clamped into its limits).
  void setHomePose();

  void setVisible(bool on);
  bool visible() const { return visible_; }

  // Arm link actors (in link order) and their current T_scene_link.
  size_t linkCount() const { return links_.size(); }
  const std::string& linkName(size_t k) const { return links_.at(k).name; }
  vtkActor* linkActor(size_t k) const;
  Transform linkTransform(size_t k) const;
  // FK of the arm link `k` at a pose, without moving anything (checks and tests).
  Transform linkTransformAt(size_t k, const std::array<double, 6>& robotDeg,
                            const std::array<double, 2>& externalDeg) const;
  // How the positioner moved the part from its drawn place (identity without one).
  const Transform& partMotion() const { return partMotion_; }
  // T_scene_tcp of the current pose.
  Transform tcpTransform() const;
  // Bounds of the whole cell at the current pose, scene frame (xmin, xmax, ymin, ymax, zmin, zmax).
  std::array<double, 6> bounds() const;
  vtkActor* torchActor() const { return torch_; }

 private:
  struct Piece {
    std::string name;
    vtkSmartPointer<vtkActor> actor;
    size_t shape = 0;  // index into the robot's or positioner's shapes
  };
  Transform cellPart(const std::array<double, 2>& externalDeg) const;  // T_cell_part(e)
  Transform sceneCell() const;                                         // the anchor
  void moveOtherActors();
  void clear();

  vtkSmartPointer<vtkRenderer> renderer_;  // kept alive until the layer's actors are removed
  std::unique_ptr<RobotCell> cell_;
  std::unique_ptr<RobotShapes> robotShapes_;
  std::unique_ptr<RobotShapes> positionerShapes_;
  std::vector<Piece> links_;
  std::vector<Piece> positionerLinks_;
  vtkNew<vtkActor> torch_;
  Transform T_scene_part_ = Transform::Identity();
  Transform partMotion_ = Transform::Identity();
  std::array<double, 6> robotDeg_{};
  std::array<double, 2> externalDeg_{};
  bool visible_ = true;
};

}  // namespace spira::ui
