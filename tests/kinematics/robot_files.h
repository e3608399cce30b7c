#pragma once

#include <string>

#include "spira/base/transform.h"
#include "spira/kinematics/joint_vector.h"

namespace spira::test {

// The bundled robot description `name` (kuka_kr16_2, fanuc_m20ia, positioner_2axis):
// $SPIRA_ROBOTS_DIR/<name>/robot.urdf if set, else resources/robots/<name>/robot.urdf in the
// source tree.
std::string robotUrdf(const std::string& name);

// Forward kinematics composed by hand from the joint origins and axes listed in
// resources/robots/README.md (mm), independently of the URDF reader: base_link -> tool0.
Transform handKukaKr16(const JointVector& q);
Transform handFanucM20ia(const JointVector& q);

// Position and rotation distances of two poses.
double positionGap(const Transform& a, const Transform& b);
double rotationGap(const Transform& a, const Transform& b);

}  // namespace spira::test
