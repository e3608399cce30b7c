#include "spira/robotcell/cell_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/units.h"
#include "spira/io/json_read.h"

namespace spira {

namespace {

constexpr int kCellFileVersion = 1;

class CellReader {
 public:
  CellReader(std::string what, std::filesystem::path baseDir)
      : what_(std::move(what)), base_(std::move(baseDir))
  {
  }

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const
  {
    throw InputError(what_ + ": " + where + ": " + problem,
                     "fix the cell file (its format is described in docs/cell-format.md)");
  }

  const nlohmann::json& need(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    if (!j.is_object() || !j.contains(key)) fail(where, std::string("'") + key + "' is missing");
    return j.at(key);
  }

  std::string text(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    const auto& v = need(j, key, where);
    if (!v.is_string()) fail(where, std::string("'") + key + "' must be a string");
    return v.get<std::string>();
  }

  std::string text(const nlohmann::json& j, const char* key, const std::string& where, const char* def) const
  {
    return j.contains(key) ? text(j, key, where) : def;
  }

  double number(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    const auto& v = need(j, key, where);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      fail(where, std::string("'") + key + "' must be a finite number");
    return v.get<double>();
  }

  double number(const nlohmann::json& j, const char* key, const std::string& where, double def) const
  {
    return j.contains(key) ? number(j, key, where) : def;
  }

  Vec3 triple(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    if (!j.contains(key)) return Vec3::Zero();
    const auto& v = j.at(key);
    if (!v.is_array() || v.size() != 3) fail(where, std::string("'") + key + "' must be 3 numbers");
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
        fail(where, std::string("'") + key + "' must be 3 finite numbers");
      out[i] = v[i].get<double>();
    }
    return out;
  }

  Transform pose(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    if (!j.contains(key)) return Transform::Identity();
    const auto& p = j.at(key);
    const std::string w = where + "." + key;
    if (!p.is_object()) fail(w, "must be an object with xyz_mm and rpy_deg");
    return transformFromXyzRpy(triple(p, "xyz_mm", w), triple(p, "rpy_deg", w) * (kPi / 180.0));
  }

  std::string path(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    const std::filesystem::path p = text(j, key, where);
    if (p.empty()) fail(where, std::string("'") + key + "' is empty");
    return (p.is_absolute() ? p : (base_ / p).lexically_normal()).string();
  }

  std::vector<CellAxis> axes(const nlohmann::json& j, const std::string& where) const
  {
    const auto& arr = need(j, "axes", where);
    if (!arr.is_array() || arr.empty()) fail(where, "'axes' must be a non-empty array");
    std::vector<CellAxis> out;
    for (size_t i = 0; i < arr.size(); ++i) {
      const std::string w = where + ".axes[" + std::to_string(i) + "]";
      CellAxis a;
      a.urdfJoint = text(arr[i], "joint", w);
      const double sign = number(arr[i], "sign", w, 1.0);
      if (sign != 1.0 && sign != -1.0) fail(w, "'sign' must be 1 or -1");
      a.sign = static_cast<int>(sign);
      a.offsetDeg = number(arr[i], "offset_deg", w, 0.0);
      a.minDeg = number(arr[i], "min_deg", w);
      a.maxDeg = number(arr[i], "max_deg", w);
      a.maxSpeedDegPerS = number(arr[i], "max_speed_deg_s", w);
      if (a.minDeg >= a.maxDeg) fail(w, "min_deg must be below max_deg");
      if (a.maxSpeedDegPerS <= 0.0) fail(w, "max_speed_deg_s must be positive");
      out.push_back(a);
    }
    return out;
  }

 private:
  std::string what_;
  std::filesystem::path base_;
};

nlohmann::json poseJson(const Transform& T)
{
  const Mat3 R = T.linear();
  // URDF rpy: R = Rz(yaw) Ry(pitch) Rx(roll).
  const double pitch = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0)));
  double roll = 0.0, yaw = 0.0;
  if (std::hypot(R(0, 0), R(1, 0)) > 1e-12) {
    roll = std::atan2(R(2, 1), R(2, 2));
    yaw = std::atan2(R(1, 0), R(0, 0));
  } else {
    yaw = std::atan2(-R(0, 1), R(1, 1));
  }
  const Vec3 t = T.translation();
  return {{"xyz_mm", {t.x(), t.y(), t.z()}},
          {"rpy_deg", {roll * 180.0 / kPi, pitch * 180.0 / kPi, yaw * 180.0 / kPi}}};
}

nlohmann::json axesJson(const std::vector<CellAxis>& axes)
{
  nlohmann::json arr = nlohmann::json::array();
  for (const CellAxis& a : axes)
    arr.push_back({{"joint", a.urdfJoint},
                   {"sign", a.sign},
                   {"offset_deg", a.offsetDeg},
                   {"min_deg", a.minDeg},
                   {"max_deg", a.maxDeg},
                   {"max_speed_deg_s", a.maxSpeedDegPerS}});
  return arr;
}

}  // namespace

std::string relativeTo(const std::string& file, const std::filesystem::path& baseDir)
{
  const std::filesystem::path p(file);
  if (baseDir.empty() || !p.is_absolute()) return file;
  const std::filesystem::path rel = p.lexically_relative(baseDir);
  return rel.empty() ? file : rel.generic_string();
}

CellRecord cellFromText(const std::string& text, const std::filesystem::path& baseDir,
                        const std::string& what)
{
  const CellReader r(what, baseDir);
  const nlohmann::json j =
      json_read::parse(text, what, "fix the syntax (docs/cell-format.md shows the format)");
  if (!j.is_object()) r.fail("top level", "must be a JSON object");
  const double version = r.number(j, "spira_cell", "top level");
  if (version != kCellFileVersion)
    r.fail("top level", "format version " + significantText(version, 6) +
                            " is not supported (this Spira reads version 1)");
  CellRecord c;
  c.name = r.text(j, "name", "top level");
  const std::string controller = r.text(j, "controller", "top level");
  if (controller == controllerFamilyName(ControllerFamily::KukaKrc4)) {
    c.controller = ControllerFamily::KukaKrc4;
  } else if (controller == controllerFamilyName(ControllerFamily::FanucR30iB)) {
    c.controller = ControllerFamily::FanucR30iB;
  } else if (controller == controllerFamilyName(ControllerFamily::AbbIrc5)) {
    c.controller = ControllerFamily::AbbIrc5;
  } else {
    r.fail("controller", "'" + controller + "' is unknown (use kuka_krc4, fanuc_r30ib or abb_irc5)");
  }

  const auto& robot = r.need(j, "robot", "top level");
  c.robotUrdf = r.path(robot, "urdf", "robot");
  c.robotBaseLink = r.text(robot, "base_link", "robot", "base_link");
  c.robotTipLink = r.text(robot, "tip_link", "robot", "tool0");
  c.T_world_robotbase = r.pose(robot, "pose", "robot");
  const double coupling = r.number(robot, "j23_coupling", "robot", 0.0);
  if (coupling != 0.0 && coupling != 1.0 && coupling != -1.0)
    r.fail("robot", "'j23_coupling' must be -1, 0 or 1");
  c.j23Coupling = static_cast<int>(coupling);
  c.robotAxes = r.axes(robot, "robot");
  if (c.robotAxes.size() != 6)
    r.fail("robot.axes", "a robot has 6 axes, found " + std::to_string(c.robotAxes.size()));

  const auto& tool = r.need(j, "tool", "top level");
  c.tool.T_flange_tcp = r.pose(tool, "tcp", "tool");
  c.tool.nozzleRadius = r.number(tool, "nozzle_radius_mm", "tool", c.tool.nozzleRadius);
  c.tool.nozzleLength = r.number(tool, "nozzle_length_mm", "tool", c.tool.nozzleLength);
  c.tool.torchBodyRadius = r.number(tool, "body_radius_mm", "tool", c.tool.torchBodyRadius);
  c.tool.torchBodyLength = r.number(tool, "body_length_mm", "tool", c.tool.torchBodyLength);
  if (c.tool.nozzleRadius <= 0 || c.tool.nozzleLength <= 0 || c.tool.torchBodyRadius <= 0 ||
      c.tool.torchBodyLength <= 0)
    r.fail("tool", "torch sizes must be positive");

  if (j.contains("positioner") && !j.at("positioner").is_null()) {
    const auto& pos = j.at("positioner");
    c.positionerUrdf = r.path(pos, "urdf", "positioner");
    c.positionerBaseLink = r.text(pos, "base_link", "positioner", "base_link");
    c.positionerTipLink = r.text(pos, "tip_link", "positioner", "table_top");
    c.T_world_positioner = r.pose(pos, "pose", "positioner");
    if (pos.contains("keep_build_vertical")) {
      if (!pos.at("keep_build_vertical").is_boolean())
        r.fail("positioner", "'keep_build_vertical' must be true or false");
      c.keepBuildVertical = pos.at("keep_build_vertical").get<bool>();
    }
    c.positionerAxes = r.axes(pos, "positioner");
    if (c.positionerAxes.size() != 2)
      r.fail("positioner.axes",
             "a tilt-rotate positioner has 2 axes, found " + std::to_string(c.positionerAxes.size()));
  }

  const auto& part = r.need(j, "part", "top level");
  const std::string mount = r.text(part, "mount", "part", "fixed_table");
  if (mount == partMountingName(PartMounting::FixedTable)) {
    c.mounting = PartMounting::FixedTable;
  } else if (mount == partMountingName(PartMounting::Positioner)) {
    if (!c.hasPositioner()) r.fail("part", "mount is 'positioner' but the cell has no positioner");
    c.mounting = PartMounting::Positioner;
  } else {
    r.fail("part", "mount '" + mount + "' is unknown (use fixed_table or positioner)");
  }
  c.T_mount_part = r.pose(part, "pose", "part");
  c.cableTwistLimitDeg = r.number(j, "cable_twist_limit_deg", "top level", c.cableTwistLimitDeg);
  if (c.cableTwistLimitDeg < 0.0) r.fail("cable_twist_limit_deg", "must be 0 (no limit) or positive");
  return c;
}

CellRecord readCellFile(const std::filesystem::path& file)
{
  return cellFromText(readFile(file), file.parent_path(), "cell file " + file.string());
}

std::string cellFileText(const CellRecord& c, const std::filesystem::path& baseDir)
{
  nlohmann::ordered_json j;
  j["spira_cell"] = kCellFileVersion;
  j["name"] = c.name;
  j["controller"] = controllerFamilyName(c.controller);
  j["robot"] = {{"urdf", relativeTo(c.robotUrdf, baseDir)},
                {"base_link", c.robotBaseLink},
                {"tip_link", c.robotTipLink},
                {"pose", poseJson(c.T_world_robotbase)},
                {"j23_coupling", c.j23Coupling},
                {"axes", axesJson(c.robotAxes)}};
  j["tool"] = {{"tcp", poseJson(c.tool.T_flange_tcp)},
               {"nozzle_radius_mm", c.tool.nozzleRadius},
               {"nozzle_length_mm", c.tool.nozzleLength},
               {"body_radius_mm", c.tool.torchBodyRadius},
               {"body_length_mm", c.tool.torchBodyLength}};
  if (c.hasPositioner()) {
    j["positioner"] = {{"urdf", relativeTo(c.positionerUrdf, baseDir)},
                       {"base_link", c.positionerBaseLink},
                       {"tip_link", c.positionerTipLink},
                       {"pose", poseJson(c.T_world_positioner)},
                       {"keep_build_vertical", c.keepBuildVertical},
                       {"axes", axesJson(c.positionerAxes)}};
  } else {
    j["positioner"] = nullptr;
  }
  j["part"] = {{"mount", partMountingName(c.mounting)}, {"pose", poseJson(c.T_mount_part)}};
  j["cable_twist_limit_deg"] = c.cableTwistLimitDeg;
  return j.dump(2) + "\n";
}

}  // namespace spira
