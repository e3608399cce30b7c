#pragma once

#include <array>
#include <string>
#include <vector>

#include "spira/base/transform.h"

namespace spira {

// Limits of one axis in the CONTROLLER's convention (degrees, degrees per second).
struct AxisLimit {
  std::string name;  // "A1".."A6", "J1".."J6", "rax_1".."rax_6", "E1", "E2"
  double minDeg = -180.0;
  double maxDeg = 180.0;
  double maxSpeedDegPerS = 180.0;
};

// One solved point of a joint trajectory, index-aligned with the Trajectory it was solved from.
// Joint values are in the controller's convention (signs, offsets and couplings applied), in
// degrees, so exporters print them without converting.
struct JointPoint {
  std::array<double, 6> robotDeg{};     // A1..A6 (KUKA), J1..J6 (FANUC) or rax_1..rax_6 (ABB)
  std::array<double, 2> externalDeg{};  // E1, E2 of the positioner; unused without one
  // T_base_tcp: TCP pose in the robot's controller base frame ($ROBROOT / FANUC World), mm.
  Transform baseTcp = Transform::Identity();
  int kukaStatus = 0;            // KRL S bits
  int kukaTurn = 0;              // KRL T bits
  std::string fanucConfig;       // TP CONFIG string, e.g. "N U T, 0, 0, 0"
  std::array<int, 4> abbConf{};  // RAPID confdata cf1, cf4, cf6, cfx
  bool reachable = true;
  double dexterity = 1.0;  // smallest/largest singular value ratio, 0 at a singularity
  bool collision = false;
};

// A robot (and optional positioner) trajectory. `controller` is "kuka_krc4", "fanuc_r30ib" or
// "abb_irc5".
struct JointTrajectory {
  std::string controller;
  std::string cellName;
  bool hasPositioner = false;
  // T_tool0_tcp the poses were solved with: the torch an exporter declares (RAPID tooldata).
  Transform flangeTcp = Transform::Identity();
  std::array<AxisLimit, 6> robotLimits{};
  std::array<AxisLimit, 2> externalLimits{};
  std::vector<JointPoint> points;

  size_t size() const { return points.size(); }
};

}  // namespace spira
