#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "spira/base/transform.h"

namespace spira {

// The persisted, editable description of the robot cell. It holds what the user chose and typed
// (file paths, frames, tool sizes, axis mapping and limits); the kinematic model is built from it
// elsewhere. Angles here are in degrees because they mirror controller and data-sheet values;
// convert with degToRad where they are used. Lengths are mm.

enum class ControllerFamily { KukaKrc4, FanucR30iB, AbbIrc5 };
const char* controllerFamilyName(ControllerFamily c);  // "kuka_krc4", "fanuc_r30ib", "abb_irc5"

enum class PartMounting { FixedTable, Positioner };
const char* partMountingName(PartMounting m);  // "fixed_table", "positioner"

// The welding torch on the flange.
struct ToolRecord {
  // TCP frame -> flange frame (p_flange = T_flange_tcp * p_tcp). The TCP z axis points out of the
  // nozzle, along the wire.
  Transform T_flange_tcp = Transform::Identity();
  double nozzleRadius = 8.0;       // mm
  double nozzleLength = 25.0;      // mm, from the TCP back along -z
  double torchBodyRadius = 20.0;   // mm
  double torchBodyLength = 150.0;  // mm, behind the nozzle

  bool operator==(const ToolRecord& o) const;
  bool operator!=(const ToolRecord& o) const { return !(*this == o); }
};

// One controller axis (A1..A6, then external axes E1..): which URDF joint drives it and how the
// controller's angle relates to the URDF angle (q_urdf = sign * (q_controller + offsetDeg)),
// with the controller's software limits.
struct CellAxis {
  std::string urdfJoint;
  int sign = 1;  // +1 or -1
  double offsetDeg = 0.0;
  double minDeg = -180.0;
  double maxDeg = 180.0;
  double maxSpeedDegPerS = 100.0;

  bool operator==(const CellAxis& o) const;
  bool operator!=(const CellAxis& o) const { return !(*this == o); }
};

struct CellRecord {
  std::string name;
  std::string robotUrdf;  // path of the robot URDF
  // The chain the kinematics solve: from the URDF link that is the controller's base frame
  // ($ROBROOT; FANUC World, "base" in ROS-Industrial URDFs) to the flange link (tool0).
  std::string robotBaseLink = "base_link";
  std::string robotTipLink = "tool0";
  ControllerFamily controller = ControllerFamily::KukaKrc4;
  // FANUC J2/J3 linkage: URDF q3 = J3 + factor * J2 (1 for most FANUC arms, 0 for none).
  int j23Coupling = 0;
  // Robot base frame -> world frame (p_world = T_world_robotbase * p_base).
  Transform T_world_robotbase = Transform::Identity();
  ToolRecord tool;
  std::string positionerUrdf;  // empty: no positioner
  // Positioner base frame -> world frame.
  Transform T_world_positioner = Transform::Identity();
  std::string positionerBaseLink = "base_link";
  std::string positionerTipLink = "table_top";
  PartMounting mounting = PartMounting::FixedTable;
  // Part frame -> mount frame: the world for a fixed table, the positioner's table top (tip link)
  // when mounted on the positioner. The part frame is the frame its mesh coordinates are in.
  Transform T_mount_part = Transform::Identity();
  // Positioner: turn the table so that the local build direction stays vertical (flat welding).
  bool keepBuildVertical = true;
  // Torch cable: |q4 + q6| limit for torch-carried cables, degrees (0: no limit).
  double cableTwistLimitDeg = 120.0;
  std::vector<CellAxis> robotAxes;       // controller order A1..A6
  std::vector<CellAxis> positionerAxes;  // controller order E1..

  bool hasPositioner() const { return !positionerUrdf.empty(); }

  bool operator==(const CellRecord& o) const;
  bool operator!=(const CellRecord& o) const { return !(*this == o); }
};

// The cell with the part turned on its mount the way the document turns it in the world
// (T_world_part's rotation; its translation is the scene's business). The cell's T_mount_part then
// places the part's build frame, the one it is planned in with the world's up: a part lying in
// its file but placed upright stands upright on the table too.
CellRecord cellForPlacement(const CellRecord& cell, const Transform& T_world_part);
// Its T_mount_part alone.
Transform mountPartForPlacement(const Transform& T_mount_part, const Transform& T_world_part);

// JSON form (also usable as a stand-alone cell file). Transforms are 16 numbers, row-major.
// Throws InputError naming the bad field.
nlohmann::json cellRecordToJson(const CellRecord& c);
CellRecord cellRecordFromJson(const nlohmann::json& j);

}  // namespace spira
