#pragma once

#include <memory>
#include <optional>
#include <string>

#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/kinematics/tilt_rotate_positioner.h"
#include "spira/robotcell/cell_record.h"

namespace spira {

// The kinematic model of a cell record: the arm chain with the cell's controller limits, its IK
// and controller convention, the optional positioner, and the frames that place a part.
//
// Frames: world = the cell's frame; base = the arm chain's base link (the controller's base
// frame); T_world_base = T_world_robotroot * T_robotroot_base (fixed URDF joints above the chain).
class RobotCell {
 public:
  // Reads the URDFs. Throws InputError/IoError when a URDF does not parse, a link or joint named by
  // the cell is missing, or an axis mapping is not the controller's (signs 1, offsets 0: the URDFs
  // of resources/robots carry the controllers' senses). A chain that is not a 6R arm with a
  // spherical wrist is NOT an error here: the cell still displays; ikRefusal() says why it cannot
  // solve, and ik() throws it.
  explicit RobotCell(const CellRecord& record);

  const CellRecord& record() const { return record_; }
  const KinematicChain& arm() const { return *arm_; }
  bool canSolve() const { return ik_ != nullptr; }
  const std::string& ikRefusal() const { return ikRefusal_; }
  const ArmIk& ik() const;
  const ControllerConvention& convention() const { return *convention_; }
  const TiltRotatePositioner* positioner() const { return positioner_.get(); }

  const Transform& worldBase() const { return T_world_base_; }
  // T_base_positionerbase: the positioner chain's base in the arm's base frame.
  const Transform& basePositioner() const { return T_base_positioner_; }

  // The solver setup for a part whose mesh frame is placed by the cell (T_mount_part), or by
  // `worldPart` when given (fixed-table cells only: the document's part placement).
  JointPathSetup setup(const std::optional<Transform>& worldPart = std::nullopt) const;
  // setup() with the seed and configuration chosen at the path's first point: of the IK solutions
  // there within the controller limits, the one farthest from them (so the path starts where the
  // arm has the most room). Without any, the first solution; without a solution at all, unchanged
  // (every point is then reported unreachable).
  JointPathSetup seededSetup(const Trajectory& path,
                             const std::optional<Transform>& worldPart = std::nullopt) const;

 private:
  CellRecord record_;
  std::unique_ptr<KinematicChain> arm_;
  std::unique_ptr<ArmIk> ik_;
  std::string ikRefusal_;
  std::unique_ptr<ControllerConvention> convention_;
  std::unique_ptr<TiltRotatePositioner> positioner_;
  Transform T_world_base_ = Transform::Identity();
  Transform T_base_positioner_ = Transform::Identity();
};

}  // namespace spira
