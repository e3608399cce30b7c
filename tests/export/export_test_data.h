#pragma once

#include <filesystem>
#include <string>

#include "spira/path/joint_trajectory.h"
#include "spira/path/trajectory.h"
#include "spira/plugin/exporter.h"

// Plans and solved motions for the exporter tests, built in code.
namespace spira::test {

// A helix on a cylinder of radius `radius` around the part's Z axis, `pitch` mm per revolution,
// `pointsPerRev` points per revolution and `revolutions` revolutions (plus the closing point),
// outward normals, travel counter-clockwise seen from +Z. TS is 8 mm/s on the first revolution
// and 10 mm/s after; WFS = 3 + 0.5 sin(angle) m/min; the arc is on everywhere.
Trajectory cylinderPlan(int revolutions = 3, int pointsPerRev = 12, double radius = 20.0, double pitch = 2.0);

// Where the part sits in the robot base frame in the synthetic cell: T_base_part.
Transform cellBasePart();
// The free spin of the torch about its axis the synthetic solver chose at point i (radians).
double cellSpin(size_t i);

// A joint trajectory as a kinematics solver would return it for `plan`: T_base_tcp =
// cellBasePart() * toolFrame(point, cellSpin(i)), smooth made-up joint values (distinct per
// axis and point so a swapped column shows), S = 2, T = 35, CONFIG "N U T, 0, 0, 0", and with a
// positioner E1 = -30 + 0.25 i, E2 = 5 i degrees. Limits are named and wide.
JointTrajectory syntheticJoints(const Trajectory& plan, const std::string& controller, bool positioner);

// The header an application would pass: part, cell, date and two plan parameters.
std::map<std::string, std::string> testHeader();

// Runs the built-in exporter `id` on `plan` (and `joints`, may be null) into `dir`.
ExportResult runExporter(const std::string& id, const Trajectory& plan, const JointTrajectory* joints,
                         const ParamSet& params, const std::filesystem::path& dir);

// Distance between the positions (mm) and angle between the orientations (degrees) of two poses.
double positionError(const Transform& a, const Transform& b);
double orientationErrorDeg(const Transform& a, const Transform& b);

// Names of the regular files in `dir`, sorted, without the manifest of its output sets.
std::vector<std::string> filesIn(const std::filesystem::path& dir);

}  // namespace spira::test
