#include "spira/robotcell/cell_record.h"

#include <limits>

#include "spira/base/error.h"
#include "spira/io/json_codec.h"

namespace spira {

namespace {

constexpr int kCellSchema = 1;

const char* kCellHint = "check the cell file or choose the cell again";

[[noreturn]] void badCell(const std::string& problem)
{
  throw InputError("cell: " + problem, kCellHint);
}

nlohmann::json axisToJson(const CellAxis& a)
{
  return {{"urdf_joint", a.urdfJoint}, {"sign", a.sign},      {"offset_deg", a.offsetDeg},
          {"min_deg", a.minDeg},       {"max_deg", a.maxDeg}, {"max_speed_deg_s", a.maxSpeedDegPerS}};
}

CellAxis axisFromJson(const nlohmann::json& j, const std::string& what)
{
  CellAxis a;
  a.urdfJoint = codec::stringField(j, "urdf_joint", what);
  const std::int64_t sign = codec::intField(j, "sign", what);
  if (sign < std::numeric_limits<int>::min() || sign > std::numeric_limits<int>::max())
    badCell(what + ": sign " + std::to_string(sign) + " is out of range");
  a.sign = static_cast<int>(sign);
  a.offsetDeg = codec::numberField(j, "offset_deg", what);
  a.minDeg = codec::numberField(j, "min_deg", what);
  a.maxDeg = codec::numberField(j, "max_deg", what);
  a.maxSpeedDegPerS = codec::numberField(j, "max_speed_deg_s", what);
  return a;
}

std::vector<CellAxis> axesFromJson(const nlohmann::json& j, const char* key)
{
  const auto& arr = codec::field(j, key, "cell");
  if (!arr.is_array()) badCell(std::string("'") + key + "' is not an array");
  std::vector<CellAxis> axes;
  for (size_t i = 0; i < arr.size(); ++i)
    axes.push_back(axisFromJson(arr[i], std::string(key) + "[" + std::to_string(i) + "]"));
  return axes;
}

}  // namespace

const char* controllerFamilyName(ControllerFamily c)
{
  switch (c) {
    case ControllerFamily::KukaKrc4:
      return "kuka_krc4";
    case ControllerFamily::FanucR30iB:
      return "fanuc_r30ib";
    case ControllerFamily::AbbIrc5:
      return "abb_irc5";
  }
  return "unknown";
}

const char* partMountingName(PartMounting m)
{
  return m == PartMounting::FixedTable ? "fixed_table" : "positioner";
}

bool ToolRecord::operator==(const ToolRecord& o) const
{
  return codec::sameTransform(T_flange_tcp, o.T_flange_tcp) && nozzleRadius == o.nozzleRadius &&
         nozzleLength == o.nozzleLength && torchBodyRadius == o.torchBodyRadius &&
         torchBodyLength == o.torchBodyLength;
}

bool CellAxis::operator==(const CellAxis& o) const
{
  return urdfJoint == o.urdfJoint && sign == o.sign && offsetDeg == o.offsetDeg && minDeg == o.minDeg &&
         maxDeg == o.maxDeg && maxSpeedDegPerS == o.maxSpeedDegPerS;
}

bool CellRecord::operator==(const CellRecord& o) const
{
  return name == o.name && robotUrdf == o.robotUrdf && robotBaseLink == o.robotBaseLink &&
         robotTipLink == o.robotTipLink && controller == o.controller && j23Coupling == o.j23Coupling &&
         positionerBaseLink == o.positionerBaseLink && positionerTipLink == o.positionerTipLink &&
         codec::sameTransform(T_mount_part, o.T_mount_part) && keepBuildVertical == o.keepBuildVertical &&
         cableTwistLimitDeg == o.cableTwistLimitDeg &&
         codec::sameTransform(T_world_robotbase, o.T_world_robotbase) && tool == o.tool &&
         positionerUrdf == o.positionerUrdf &&
         codec::sameTransform(T_world_positioner, o.T_world_positioner) && mounting == o.mounting &&
         robotAxes == o.robotAxes && positionerAxes == o.positionerAxes;
}

Transform mountPartForPlacement(const Transform& T_mount_part, const Transform& T_world_part)
{
  Transform turn = Transform::Identity();
  turn.linear() = T_world_part.linear();
  return T_mount_part * turn;
}

CellRecord cellForPlacement(const CellRecord& cell, const Transform& T_world_part)
{
  CellRecord c = cell;
  c.T_mount_part = mountPartForPlacement(cell.T_mount_part, T_world_part);
  return c;
}

nlohmann::json cellRecordToJson(const CellRecord& c)
{
  nlohmann::json j;
  j["schema"] = kCellSchema;
  j["name"] = c.name;
  j["robot_urdf"] = c.robotUrdf;
  j["robot_base_link"] = c.robotBaseLink;
  j["robot_tip_link"] = c.robotTipLink;
  j["controller"] = controllerFamilyName(c.controller);
  j["j23_coupling"] = c.j23Coupling;
  j["positioner_base_link"] = c.positionerBaseLink;
  j["positioner_tip_link"] = c.positionerTipLink;
  j["T_mount_part"] = codec::transformToJson(c.T_mount_part);
  j["keep_build_vertical"] = c.keepBuildVertical;
  j["cable_twist_limit_deg"] = c.cableTwistLimitDeg;
  j["T_world_robotbase"] = codec::transformToJson(c.T_world_robotbase);
  j["tool"] = {{"T_flange_tcp", codec::transformToJson(c.tool.T_flange_tcp)},
               {"nozzle_radius", c.tool.nozzleRadius},
               {"nozzle_length", c.tool.nozzleLength},
               {"torch_body_radius", c.tool.torchBodyRadius},
               {"torch_body_length", c.tool.torchBodyLength}};
  j["positioner_urdf"] = c.positionerUrdf;
  j["T_world_positioner"] = codec::transformToJson(c.T_world_positioner);
  j["mounting"] = partMountingName(c.mounting);
  j["robot_axes"] = nlohmann::json::array();
  for (const auto& a : c.robotAxes) j["robot_axes"].push_back(axisToJson(a));
  j["positioner_axes"] = nlohmann::json::array();
  for (const auto& a : c.positionerAxes) j["positioner_axes"].push_back(axisToJson(a));
  return j;
}

CellRecord cellRecordFromJson(const nlohmann::json& j)
{
  const std::string what = "cell";
  codec::checkSchema(j, kCellSchema, what);
  CellRecord c;
  c.name = codec::stringField(j, "name", what);
  c.robotUrdf = codec::stringField(j, "robot_urdf", what);
  const std::string controller = codec::stringField(j, "controller", what);
  if (controller == controllerFamilyName(ControllerFamily::KukaKrc4))
    c.controller = ControllerFamily::KukaKrc4;
  else if (controller == controllerFamilyName(ControllerFamily::FanucR30iB))
    c.controller = ControllerFamily::FanucR30iB;
  else if (controller == controllerFamilyName(ControllerFamily::AbbIrc5))
    c.controller = ControllerFamily::AbbIrc5;
  else
    badCell("unknown controller '" + controller + "' (use kuka_krc4, fanuc_r30ib or abb_irc5)");
  c.T_world_robotbase =
      codec::transformFromJson(codec::field(j, "T_world_robotbase", what), "cell T_world_robotbase");
  const auto& tool = codec::field(j, "tool", what);
  c.tool.T_flange_tcp =
      codec::transformFromJson(codec::field(tool, "T_flange_tcp", "cell tool"), "cell T_flange_tcp");
  c.tool.nozzleRadius = codec::numberField(tool, "nozzle_radius", "cell tool");
  c.tool.nozzleLength = codec::numberField(tool, "nozzle_length", "cell tool");
  c.tool.torchBodyRadius = codec::numberField(tool, "torch_body_radius", "cell tool");
  c.tool.torchBodyLength = codec::numberField(tool, "torch_body_length", "cell tool");
  c.positionerUrdf = codec::stringField(j, "positioner_urdf", what);
  c.T_world_positioner =
      codec::transformFromJson(codec::field(j, "T_world_positioner", what), "cell T_world_positioner");
  const std::string mounting = codec::stringField(j, "mounting", what);
  if (mounting == partMountingName(PartMounting::FixedTable))
    c.mounting = PartMounting::FixedTable;
  else if (mounting == partMountingName(PartMounting::Positioner))
    c.mounting = PartMounting::Positioner;
  else
    badCell("unknown mounting '" + mounting + "' (use fixed_table or positioner)");
  c.robotAxes = axesFromJson(j, "robot_axes");
  c.positionerAxes = axesFromJson(j, "positioner_axes");
  // Added after the first projects were written: optional, defaults when absent.
  if (j.contains("robot_base_link")) c.robotBaseLink = codec::stringField(j, "robot_base_link", what);
  if (j.contains("robot_tip_link")) c.robotTipLink = codec::stringField(j, "robot_tip_link", what);
  if (j.contains("j23_coupling")) c.j23Coupling = static_cast<int>(codec::intField(j, "j23_coupling", what));
  if (j.contains("positioner_base_link"))
    c.positionerBaseLink = codec::stringField(j, "positioner_base_link", what);
  if (j.contains("positioner_tip_link"))
    c.positionerTipLink = codec::stringField(j, "positioner_tip_link", what);
  if (j.contains("T_mount_part"))
    c.T_mount_part = codec::transformFromJson(codec::field(j, "T_mount_part", what), "cell T_mount_part");
  if (j.contains("keep_build_vertical"))
    c.keepBuildVertical = codec::boolField(j, "keep_build_vertical", what);
  if (j.contains("cable_twist_limit_deg"))
    c.cableTwistLimitDeg = codec::numberField(j, "cable_twist_limit_deg", what);
  if (c.j23Coupling < -1 || c.j23Coupling > 1) badCell("j23_coupling must be -1, 0 or 1");
  return c;
}

}  // namespace spira
