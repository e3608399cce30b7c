// Layer-wise spin optimisation and motion checks on the KUKA KR 16-2 cell of
// resources/cells/kuka_kr16_2_table.cell (part frame 1100 mm in front of the robot, 400 mm up):
// 100-revolution, 36,000-point plans (360 points a revolution, 10 mm/s):
//   a hemisphere R 150 mm from its equator up to 50 deg from the pole (the torch tilts up to 40 deg),
//   once with the cell's straight torch (TCP 350 mm along tool0 z) and once with a 36 deg gooseneck;
//   a cylinder R 100 mm climbing 2 mm a revolution with the straight torch.
// For each: the constant-spin solve (optimisation off) and the full solve with the optimisation
// (which includes the constant-spin plan it is compared with). Best of 3 runs, wall and CPU time.
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
#include "spira/motion/motion_solver.h"
#include "spira/path/tool_frame.h"

using namespace spira;

namespace {

Trajectory cylinder(double r, double pitch, int turns, int perTurn)
{
  Trajectory path;
  for (int k = 0; k < turns * perTurn; ++k) {
    const double a = 2 * kPi * k / perTurn;
    TrajectoryPoint p;
    p.normal = Vec3(std::cos(a), std::sin(a), 0);
    p.position = r * p.normal + Vec3(0, 0, pitch * a / (2 * kPi));
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0);
    p.build = p.normal.cross(p.tangent);
    p.revolution = k / perTurn;
    p.travelSpeed = 10.0;
    path.points.push_back(p);
  }
  return path;
}

struct Timing {
  double wall = 1e30, cpu = 1e30;
};

MotionResult timed(const ArmIk& ik, const ControllerConvention& c, const Trajectory& path,
                   const JointPathSetup& s, const MotionParams& p, Timing& t)
{
  MotionResult r;
  for (int run = 0; run < 3; ++run) {
    NullProgress progress;
    const auto w0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    r = solveMotion(ik, c, path, s, p, progress);
    t.cpu = std::min(t.cpu, 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    t.wall = std::min(
        t.wall, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count());
  }
  return r;
}

void describe(const char* label, const MotionReport& m)
{
  std::printf(
      "    %-9s buildable %-3s (unreachable %zu, outside limits %zu, twist %.1f deg %s), min margin %.1f deg "
      "(%s), "
      "min dexterity %.3f, max speed ratio %.2f (%s), Phi %.1f\n",
      label, m.reachable && m.withinCableTwistLimit ? "yes" : "no", m.unreachable.size(),
      m.outsideLimits.size(), m.maxCableTwistDeg, m.withinCableTwistLimit ? "ok" : "over",
      m.minLimitMarginDeg, m.minLimitMarginAxis.c_str(), m.minDexterity, m.maxSpeedRatio,
      m.maxSpeedRatioAxis.c_str(), m.objectiveResult);
}

bool runCase(const char* name, const ArmIk& ik, const ControllerConvention& c, const Trajectory& path,
             JointPathSetup setup)
{
  const Transform tip =
      setup.basePart * toolFrame(path.points.front(), setup.spinRad) * setup.flangeTcp.inverse();
  const std::optional<IkSolution> seed = ik.solve(tip, ArmConfiguration{}, JointVector::Zero());
  if (!seed) {
    std::printf("bench_motion: %s: first point out of reach\n", name);
    return false;
  }
  setup.seed = seed->q;
  MotionParams params;
  params.cableTwistLimitDeg = 120.0;
  params.optimiseSpin = false;
  Timing constantTime, optimisedTime;
  const MotionResult constant = timed(ik, c, path, setup, params, constantTime);
  params.optimiseSpin = true;
  const MotionResult optimised = timed(ik, c, path, setup, params, optimisedTime);
  size_t polished = 0;
  for (const LayerSpin& l : optimised.report.layers) polished += l.polished ? 1 : 0;
  std::printf("  %s, %zu points, %zu layers\n", name, path.size(), optimised.report.layers.size());
  std::printf(
      "    constant spin: %.0f ms wall, %.0f ms CPU; with optimisation: %.0f ms wall, %.0f ms CPU "
      "(%d poses solved by the optimiser, %.1f per point; %zu layers polished)\n",
      constantTime.wall, constantTime.cpu, optimisedTime.wall, optimisedTime.cpu,
      optimised.report.posesSolved,
      static_cast<double>(optimised.report.posesSolved) / static_cast<double>(path.size()), polished);
  describe("constant", constant.report);
  describe("optimised", optimised.report);
  std::printf("    Phi constant %.2f -> returned %.2f (optimised plan %s)\n",
              optimised.report.objectiveConstant, optimised.report.objectiveResult,
              optimised.report.optimised ? "kept" : "lost to the constant one");
  return optimisedTime.cpu < 3000.0;
}

}  // namespace

int main()
{
  ArmIk ik(KinematicChain::fromUrdfFile(test::motionRobotUrdf("kuka_kr16_2"), "base_link", "tool0"));
  const ControllerConvention convention(Controller::KukaKrc4, ik.chain());
  convention.applyTo(ik);
  JointPathSetup setup;
  setup.cellName = "KUKA KR 16-2 on a fixed table";
  setup.basePart.translation() = Vec3(1100, 0, 400);
  setup.flangeTcp.translation() = Vec3(0, 0, 350);
  JointPathSetup gooseneck = setup;
  gooseneck.flangeTcp.linear() = Eigen::AngleAxisd(degToRad(-36.0), Vec3::UnitY()).toRotationMatrix();
  gooseneck.flangeTcp.translation() = Vec3(-86, 0, 406);

  std::printf(
      "bench_motion: KUKA KR 16-2, 100 revolutions x 360 points, cable twist limit 120 deg, defaults "
      "otherwise\n");
  bool met = true;
  met &=
      runCase("hemisphere R150, straight torch", ik, convention, test::domeSpiral(150, 50, 100, 360), setup);
  met &= runCase("hemisphere R150, 36 deg gooseneck", ik, convention, test::domeSpiral(150, 50, 100, 360),
                 gooseneck);
  met &= runCase("cylinder R100, straight torch", ik, convention, cylinder(100, 2, 100, 360), setup);
  std::printf("  target: optimised solve under 3 s CPU on every plan -> %s\n", met ? "met" : "NOT met");
  return 0;
}
