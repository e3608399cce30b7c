// Export speed: a 100,000-point spiral (200 revolutions of 500 points on a 50 mm cylinder, a
// solved cell with a positioner) written as KUKA KRL and FANUC TP, as single programs and split
// at the default points per file. Times are for the whole ExporterPlugin::write(): checks,
// angle conversion (the head's inverse kinematics for G-code), text and the synced, atomic file
// writes. Target: < 1 s each.
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "builtin_plugins.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/path/tool_frame.h"
#include "spira/plugin/plugin_registry.h"

using namespace spira;
namespace fs = std::filesystem;

namespace {

Trajectory spiral(int revolutions, int perRev)
{
  Trajectory t;
  const double radius = 50.0, pitch = 2.0;
  for (int i = 0; i <= revolutions * perRev; ++i) {
    const double a = 2.0 * kPi * i / perRev;
    TrajectoryPoint p;
    p.position = Vec3(radius * std::cos(a), radius * std::sin(a), pitch * i / perRev);
    p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), pitch / (2.0 * kPi * radius)).normalized();
    p.build = p.normal.cross(p.tangent).normalized();
    p.travelSpeed = 8.0 + 2.0 * std::sin(0.01 * i);
    p.wireFeed = 50.0 + 5.0 * std::sin(a);
    t.points.push_back(p);
  }
  return t;
}

JointTrajectory solved(const Trajectory& plan, const std::string& controller)
{
  JointTrajectory j;
  j.controller = controller;
  j.hasPositioner = true;
  const Transform basePart(Eigen::Translation3d(1200.0, 0.0, 600.0));
  for (size_t i = 0; i < plan.size(); ++i) {
    const double s = static_cast<double>(i);
    JointPoint p;
    p.robotDeg = {10.0 + 1e-4 * s, -60.0, 80.0, 5.0 * std::sin(1e-3 * s), 45.0, -1e-3 * s};
    p.externalDeg = {-30.0, std::fmod(0.72 * s, 360.0)};
    p.baseTcp = basePart * toolFrame(plan.points[i], 0.1 * std::sin(1e-3 * s));
    p.kukaStatus = 2;
    p.kukaTurn = 35;
    p.fanucConfig = "N U T, 0, 0, 0";
    j.points.push_back(p);
  }
  return j;
}

uintmax_t folderBytes(const fs::path& dir, size_t& count)
{
  uintmax_t bytes = 0;
  count = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    bytes += e.file_size();
    ++count;
  }
  return bytes;
}

void run(const char* label, const std::string& id, const Trajectory& plan, const JointTrajectory* joints,
         const ParamSet& params)
{
  const fs::path dir = fs::temp_directory_path() / ("spira-bench-export-" + std::to_string(::getpid()));
  std::vector<double> times;
  size_t files = 0;
  uintmax_t bytes = 0;
  for (int rep = 0; rep < 5; ++rep) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    NullProgress progress;
    ExportInput input{plan, joints, {{"part", "bench spiral"}, {"date", "2024-05-01"}}};
    const auto t0 = std::chrono::steady_clock::now();
    builtinRegistry().exporter(id).write(input, params, dir, progress);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    bytes = folderBytes(dir, files);
  }
  fs::remove_all(dir);
  std::sort(times.begin(), times.end());
  std::printf("%-34s %8zu points  %3zu files  %6.1f MB   best %6.3f s  median %6.3f s\n", label, plan.size(),
              files, static_cast<double>(bytes) / 1e6, times.front(), times[times.size() / 2]);
}

void run(const char* label, const std::string& id, const Trajectory& plan, const JointTrajectory& joints,
         const ParamSet& params)
{
  run(label, id, plan, &joints, params);
}

// G-code has no cell: the head of resources/machines/gantry_ca_head.machine, its C axis unlimited so
// that the exact torch axis (a slight lean turning with the spiral) can be followed over 200 turns.
ParamSet gcodeParams(double uprightDeg)
{
  const fs::path file =
      fs::temp_directory_path() / ("spira-bench-" + std::to_string(::getpid()) + ".machine");
  std::ofstream(file) << R"({"spira_machine": 1, "linear_axes": [{"min_mm": -1000, "max_mm": 1000},
    {"min_mm": -1000, "max_mm": 1000}, {"min_mm": -1000, "max_mm": 1000}],
    "rotary_axes": [{"letter": "C", "about": "Z", "min_deg": -1e6, "max_deg": 1e6},
                    {"letter": "A", "about": "X", "min_deg": -95, "max_deg": 95}],
    "second_to_tip_mm": [0, 0, -150], "process": {"wire_feed": "M67 E0 Q{wfs}", "wire_feed_unit": "m/min"}})";
  ParamSet p;
  p.set("machine", file.string());
  p.set("upright_tolerance", uprightDeg);
  return p;
}

}  // namespace

int main()
{
  const Trajectory plan = spiral(200, 500);
  const JointTrajectory kuka = solved(plan, "kuka_krc4");
  const JointTrajectory fanuc = solved(plan, "fanuc_r30ib");
  const JointTrajectory abb = solved(plan, "abb_irc5");
  ParamSet single;
  single.set("max_points", std::int64_t{100000});  // the KRL maximum
  single.set("process_command", std::string("speed_analog"));
  ParamSet split;
  split.set("process_command", std::string("speed_analog"));
  ParamSet tpSingle = single;
  tpSingle.set("max_points", std::int64_t{15000});  // the R-30iB maximum: 7 parts
  run("KRL, split at 5000 (default)", "export.krl", plan, kuka, split);
  run("KRL, split at 100000 (1 part)", "export.krl", plan, kuka, single);
  run("FANUC TP, split at 9000 (default)", "export.fanuc_tp", plan, fanuc, split);
  run("FANUC TP, split at 15000", "export.fanuc_tp", plan, fanuc, tpSingle);
  run("G-code, exact torch axis", "export.gcode", plan, nullptr, gcodeParams(0.0));
  run("G-code, upright within 1 deg", "export.gcode", plan, nullptr, gcodeParams(1.0));
  run("ABB RAPID, split at 5000 (default)", "export.rapid", plan, abb, split);
  return 0;
}
