#pragma once

#include <string>
#include <vector>

#include "spira/kinematics/joint_vector.h"
#include "spira/robotcell/link_shapes.h"
#include "spira/robotcell/robot_cell.h"

namespace spira {

// The robot's links against the part, the plate under it and the positioner, at given joints:
// link meshes placed by forward kinematics, hierarchies tested pairwise (collision/mesh_intersection.h).
// The torch is checked against the deposit separately (collision/torch_collision_checker.h).
class RobotCollisionModel {
 public:
  // Reads the collision meshes of the cell's arm and positioner (missing meshes: a stand-in cube and
  // a warning). `part` is the part's mesh in its own frame; a plate of `plateSize` (mm, x y z)
  // lies under the part frame's origin, its top at z = plateTopZ in the part frame.
  RobotCollisionModel(const RobotCell& cell, const TriangleMesh& part,
                      const Vec3& plateSize = Vec3(600, 600, 20), double plateTopZ = 0.0);

  const std::vector<std::string>& warnings() const { return warnings_; }

  // Names of the arm links that come within `margin` mm of the part, the plate or the positioner,
  // for arm joints q (URDF, rad), the part placed at T_base_part and the positioner at axes e.
  std::vector<std::string> armHits(const JointVector& q, const Transform& basePart, const Eigen::Vector2d& e,
                                   double margin = 0.0) const;

 private:
  const RobotCell& cell_;
  RobotShapes arm_;
  RobotShapes positioner_;
  TriangleBvh part_;
  TriangleBvh plate_;
  Transform partPlate_ = Transform::Identity();  // T_part_plate
  std::vector<std::string> warnings_;
};

}  // namespace spira
