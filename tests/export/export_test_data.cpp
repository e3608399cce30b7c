#include "export_test_data.h"

#include <algorithm>
#include <cmath>

#include "builtin_plugins.h"
#include "spira/base/output_set.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/path/tool_frame.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::test {

Trajectory cylinderPlan(int revolutions, int pointsPerRev, double radius, double pitch)
{
  Trajectory plan;
  const int count = revolutions * pointsPerRev + 1;
  for (int i = 0; i < count; ++i) {
    const double angle = 2.0 * kPi * i / pointsPerRev;
    TrajectoryPoint p;
    p.position = Vec3(radius * std::cos(angle), radius * std::sin(angle), pitch * i / pointsPerRev);
    p.normal = Vec3(std::cos(angle), std::sin(angle), 0.0);
    p.tangent = Vec3(-radius * std::sin(angle), radius * std::cos(angle), pitch / (2.0 * kPi)).normalized();
    p.build = p.normal.cross(p.tangent).normalized();
    p.revolution = i / pointsPerRev;
    p.generatrix = i % pointsPerRev;
    p.height = pitch;
    p.travelSpeed = p.revolution == 0 ? 8.0 : 10.0;
    p.wireFeed = (3.0 + 0.5 * std::sin(angle)) * 1000.0 / 60.0;
    p.arcOn = true;
    plan.points.push_back(p);
  }
  return plan;
}

Transform cellBasePart()
{
  return Transform(Eigen::Translation3d(1000.0, -200.0, 400.0) *
                   Eigen::AngleAxisd(degToRad(30.0), Vec3::UnitZ()));
}

double cellSpin(size_t i)
{
  return 0.2 * std::sin(0.3 * static_cast<double>(i));
}

JointTrajectory syntheticJoints(const Trajectory& plan, const std::string& controller, bool positioner)
{
  JointTrajectory joints;
  joints.controller = controller;
  joints.cellName = positioner ? "test cell with positioner" : "test cell";
  joints.hasPositioner = positioner;
  const bool kuka = controller == "kuka_krc4";
  for (size_t k = 0; k < 6; ++k)
    joints.robotLimits[k] = {(kuka ? "A" : "J") + std::to_string(k + 1), -400.0, 400.0, 500.0};
  joints.externalLimits[0] = {"E1", -400.0, 400.0, 500.0};
  joints.externalLimits[1] = {"E2", -400.0, 400.0, 500.0};
  for (size_t i = 0; i < plan.size(); ++i) {
    const double s = static_cast<double>(i);
    JointPoint jp;
    jp.robotDeg = {10.0 + 0.5 * s,
                   -60.0 + 0.1 * s,
                   80.0 - 0.1 * s,
                   5.0 * std::sin(0.2 * s),
                   45.0 + 2.0 * std::cos(0.2 * s),
                   radToDeg(cellSpin(i)) - 0.25 * s};
    jp.externalDeg = {-30.0 + 0.25 * s, 5.0 * s};
    jp.baseTcp = cellBasePart() * toolFrame(plan.points[i], cellSpin(i));
    jp.kukaStatus = 2;
    jp.kukaTurn = 35;
    jp.fanucConfig = "N U T, 0, 0, 0";
    joints.points.push_back(jp);
  }
  return joints;
}

std::map<std::string, std::string> testHeader()
{
  return {{"part", "cylinder_r20.stl"},
          {"cell", "test cell"},
          {"date", "2024-05-01 12:30:00"},
          {"h", "2 mm"},
          {"decomposer", "decomposer.isovalue"}};
}

ExportResult runExporter(const std::string& id, const Trajectory& plan, const JointTrajectory* joints,
                         const ParamSet& params, const std::filesystem::path& dir)
{
  ExportInput input{plan, joints, testHeader()};
  NullProgress progress;
  return builtinRegistry().exporter(id).write(input, params, dir, progress);
}

double positionError(const Transform& a, const Transform& b)
{
  return (a.translation() - b.translation()).norm();
}

double orientationErrorDeg(const Transform& a, const Transform& b)
{
  // Independent of the library's helper: the angle of the relative rotation from its trace,
  // accurate enough here (errors above 1e-4 degrees matter).
  const double c = std::clamp(((a.linear().transpose() * b.linear()).trace() - 1.0) / 2.0, -1.0, 1.0);
  return radToDeg(std::acos(c));
}

std::vector<std::string> filesIn(const std::filesystem::path& dir)
{
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != kOutputManifest)
      names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace spira::test
