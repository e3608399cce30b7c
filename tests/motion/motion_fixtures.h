#pragma once

#include <memory>
#include <string>

#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/controller_convention.h"
#include "spira/kinematics/joint_path_solver.h"
#include "spira/kinematics/tilt_rotate_positioner.h"
#include "spira/path/trajectory.h"

namespace spira::test {

// resources/robots/<name>/robot.urdf of this source tree.
std::string motionRobotUrdf(const std::string& name);

Transform translation(double x, double y, double z);

// The KUKA KR 16-2 of resources/cells/kuka_kr16_2_table.cell: robot at the world origin, tool
// 350 mm along tool0's z, the part's frame at (1100, 0, 400) mm.
struct KukaCell {
  KukaCell();
  ArmIk ik;
  ControllerConvention convention;
  JointPathSetup setup;  // basePart and flangeTcp of the cell; seed left at zero
  // Seeds the setup with the front/up/noflip solution at the first point of `path` (spin as set).
  void seedAt(const Trajectory& path);
};

// The FANUC M-20iA with the 2-axis positioner of resources/cells/fanuc_m20ia_positioner.cell:
// positioner base 1100 mm in front of the robot's foot (the robot frame "base" is 525 mm above
// the foot), part on the table, tool 350 mm along tool0's z. The rotation axis is endless
// (+-36000 deg) as in the cell file.
struct FanucPositionerCell {
  FanucPositionerCell();
  ArmIk ik;
  ControllerConvention convention;
  std::unique_ptr<TiltRotatePositioner> positioner;
  JointPathSetup setup;
  // Seeds the robot with the torch straight down over the table at the first point's height.
  void seedAt(const Trajectory& path);
};

// Stacked planar circles (radius r, one layer per revolution, `perLayer` points each, layer k at
// height z0 + k dz), travelling counter-clockwise about +Z: n outward, t along the travel,
// b = n x t = +Z. Travel speed `speed` mm/s.
Trajectory stackedCircles(double r, int layers, int perLayer, double z0, double dz, double speed = 10.0);

// A spiral over a sphere of radius r centred at the origin, from the equator (polar angle 90 deg)
// up to polar angle `polarEndDeg`, `turns` turns of `perTurn` points: the build direction
// b = n x t tilts inwards by 90 deg - polar angle. Revolution k = the k-th turn.
Trajectory domeSpiral(double r, double polarEndDeg, int turns, int perTurn, double speed = 10.0);

}  // namespace spira::test
