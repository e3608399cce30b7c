#include <cmath>
#include <limits>

#include "document_test_data.h"

namespace spira::test {

KinematicsResult sampleKinematics(int points)
{
  JointTrajectory j;
  j.controller = "fanuc_r30ib";
  j.cellName = "sample cell";
  j.hasPositioner = true;
  for (int k = 0; k < 6; ++k)
    j.robotLimits[static_cast<size_t>(k)] =
        AxisLimit{"J" + std::to_string(k + 1), -170.0 + k, 170.5 - k, 195.0 / 3.0};
  j.externalLimits = {AxisLimit{"E1", -135.0, 135.0, 90.0}, AxisLimit{"E2", -36000.0, 36000.0, 120.0}};
  for (int i = 0; i < points; ++i) {
    JointPoint p;
    for (int k = 0; k < 6; ++k) p.robotDeg[static_cast<size_t>(k)] = 0.1 * i - 3.0 * k + 1e-13;
    p.robotDeg[1] = i == 0 ? -0.0 : p.robotDeg[1];
    p.externalDeg = {-20.0 / 3.0, 1.0e3 * i + 0.1};
    p.baseTcp = Transform(Eigen::AngleAxisd(0.3 * i, Vec3(1, 2, 3).normalized()));
    p.baseTcp.translation() = Vec3(1085.0 + i, -0.1 * i, 1040.0 / 3.0);
    p.kukaStatus = i % 8;
    p.kukaTurn = 63 - i;
    p.fanucConfig = i < 3 ? "N U T, 0, 0, 0" : "F D B, -1, 0, 1";
    p.reachable = i != 2;
    p.dexterity = i == 4 ? std::numeric_limits<double>::denorm_min() : 1.0 / (i + 3);
    p.collision = i == 5;
    j.points.push_back(p);
  }
  Trajectory path = sampleTrajectory(points);
  return makeKinematicsResult(std::move(j), std::move(path));
}

}  // namespace spira::test
