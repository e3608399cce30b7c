// Inverse kinematics with configuration tracking on the KUKA KR 16-2: a 100,000-point spiral
// (50 turns, 2,000 points a turn) climbing a 150 mm-radius cylinder 1.1 m in front of the robot,
// torch straight down 300 mm from tool0, its free spin chosen to keep the torch x fixed in space.
// Prints the best and median of several runs, wall clock and CPU time (the CPU time is the fairer
// number on a shared machine), and the tracking's quality numbers.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "motion/motion_fixtures.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/path_tracker.h"
#include "spira/path/tool_frame.h"

using namespace spira;

namespace {

std::vector<Transform> spiralPoses(int points, int perTurn)
{
  const Vec3 centre(1100, 0, 250);
  const double radius = 150, pitch = 3.0;
  std::vector<Transform> out;
  out.reserve(static_cast<size_t>(points));
  for (int k = 0; k < points; ++k) {
    const double a = 2.0 * kPi * k / perTurn;
    TrajectoryPoint p;
    p.normal = Vec3(std::cos(a), std::sin(a), 0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
    p.build = p.normal.cross(p.tangent);
    p.position = centre + radius * p.normal + Vec3(0, 0, pitch * a / (2 * kPi));
    // The spin about the torch axis (-Z) undoes the travel direction's turn: torch x stays +Y.
    out.push_back(toolFrame(p, a));
  }
  return out;
}

double millis(std::chrono::steady_clock::duration d)
{
  return std::chrono::duration<double, std::milli>(d).count();
}

}  // namespace

int main(int argc, char** argv)
{
  const std::string urdf = argc > 1 ? argv[1] : test::motionRobotUrdf("kuka_kr16_2");
  const ArmIk ik(KinematicChain::fromUrdfFile(urdf, "base_link", "tool0"));
  const int points = 100000;
  const std::vector<Transform> poses = spiralPoses(points, 2000);
  Transform flangeTcp = Transform::Identity();
  flangeTcp.translation() = Vec3(0, 0, 300);
  const std::optional<IkSolution> seed =
      ik.solve(poses[0] * flangeTcp.inverse(), ArmConfiguration{}, JointVector::Zero());
  if (!seed) {
    std::printf("bench_ik: the first pose is out of reach\n");
    return 1;
  }

  std::vector<double> wall, cpu;
  PathTrack track;
  for (int run = 0; run < 7; ++run) {
    NullProgress progress;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    track = trackPath(ik, poses, flangeTcp, seed->q, ArmConfiguration{}, progress);
    cpu.push_back(1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    wall.push_back(millis(std::chrono::steady_clock::now() - t0));
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  std::printf("bench_ik: KUKA KR 16-2, %d poses, configuration %s\n", points,
              track.configuration.label().c_str());
  std::printf(
      "  trackPath (IK + Newton check + unwrapping + dexterity): best %.1f ms, median %.1f ms wall; "
      "best %.1f ms CPU (%.2f us/pose)\n",
      wall.front(), wall[wall.size() / 2], cpu.front(), 1000.0 * cpu.front() / points);
  std::printf(
      "  unreachable %zu, outside limits %zu, max joint step %.4f deg, min dexterity %.3f, min limit margin "
      "%.1f deg\n",
      track.unreachable, track.outsideLimits, radToDeg(track.maxJointStep), track.minDexterity,
      radToDeg(track.minLimitMargin));

  // All solutions of 10,000 of the poses, for comparison.
  const auto t0 = std::chrono::steady_clock::now();
  size_t solutions = 0;
  for (int k = 0; k < points; k += 10)
    solutions += ik.solveAll(poses[static_cast<size_t>(k)] * flangeTcp.inverse()).size();
  std::printf("  solveAll on 10,000 poses: %.1f ms wall (%zu solutions with the +-360 deg turns)\n",
              millis(std::chrono::steady_clock::now() - t0), solutions);
  std::printf("  target: trackPath under 200 ms -> %s\n", cpu.front() < 200.0 ? "met" : "NOT met");
  return 0;
}
