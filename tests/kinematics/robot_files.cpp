#include "robot_files.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "support/test_support.h"

namespace spira::test {

namespace fs = std::filesystem;

std::string robotUrdf(const std::string& name)
{
  std::vector<fs::path> candidates;
  if (const char* dir = std::getenv("SPIRA_ROBOTS_DIR"))
    candidates.push_back(fs::path(dir) / name / "robot.urdf");
  candidates.push_back(sourceDir() / "resources" / "robots" / name / "robot.urdf");
  for (const fs::path& p : candidates)
    if (fs::exists(p)) return p.string();
  throw std::runtime_error("robot description " + name + " not found (set SPIRA_ROBOTS_DIR)");
}

namespace {

Transform joint(const Vec3& originMm, const Vec3& axis, double angle)
{
  Transform t = Transform::Identity();
  t.translate(originMm);
  t.rotate(Eigen::AngleAxisd(angle, axis));
  return t;
}

}  // namespace

Transform handKukaKr16(const JointVector& q)
{
  Transform t = joint({0, 0, 675}, -Vec3::UnitZ(), q[0]) * joint({260, 0, 0}, Vec3::UnitY(), q[1]) *
                joint({680, 0, 0}, Vec3::UnitY(), q[2]) * joint({670, 0, -35}, -Vec3::UnitX(), q[3]) *
                joint({0, 0, 0}, Vec3::UnitY(), q[4]) * joint({0, 0, 0}, -Vec3::UnitX(), q[5]);
  t.translate(Vec3(158, 0, 0));                          // flange
  t.rotate(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()));  // tool0 = flange turned +90 deg about Y
  return t;
}

Transform handFanucM20ia(const JointVector& q)
{
  Transform t = joint({0, 0, 525}, Vec3::UnitZ(), q[0]) * joint({150, 0, 0}, Vec3::UnitY(), q[1]) *
                joint({0, 0, 790}, -Vec3::UnitY(), q[2]) * joint({0, 0, 250}, -Vec3::UnitX(), q[3]) *
                joint({835, 0, 0}, -Vec3::UnitY(), q[4]) * joint({100, 0, 0}, -Vec3::UnitX(), q[5]);
  // tool0 = flange rpy(180, -90, 0) = Rz(0) Ry(-90) Rx(180).
  t.rotate(Eigen::AngleAxisd(-M_PI / 2, Vec3::UnitY()) * Eigen::AngleAxisd(M_PI, Vec3::UnitX()));
  return t;
}

double positionGap(const Transform& a, const Transform& b)
{
  return (a.translation() - b.translation()).norm();
}

double rotationGap(const Transform& a, const Transform& b)
{
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace spira::test
