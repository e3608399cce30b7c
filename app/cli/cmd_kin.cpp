#include <iomanip>
#include <iostream>

#include "cli_common.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/export/euler_angles.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"

namespace spira::cli {
namespace {

std::array<double, 6> sixNumbers(const std::vector<std::string>& words, const std::string& flag)
{
  if (words.size() != 6) throw UsageError(flag + " takes six numbers", "e.g. " + flag + " 0 -90 90 0 0 0");
  std::array<double, 6> v{};
  for (size_t i = 0; i < 6; ++i) v[i] = finiteNumberFlag(flag, words[i], "give six numbers");
  return v;
}

// A pose in the controller's notation: X Y Z in mm, then A B C (KUKA) or W P R (FANUC) in degrees.
void printPose(const std::string& what, const Transform& T, bool kuka, std::ostream& out)
{
  const Vec3 p = T.translation();
  out << what << ": X " << p.x() << "  Y " << p.y() << "  Z " << p.z();
  if (kuka) {
    const KukaAbc abc = kukaAbcFromRotation(T.linear());
    out << "  A " << radToDeg(abc.a) << "  B " << radToDeg(abc.b) << "  C " << radToDeg(abc.c) << "\n";
  } else {
    const FanucWpr wpr = fanucWprFromRotation(T.linear());
    out << "  W " << radToDeg(wpr.w) << "  P " << radToDeg(wpr.p) << "  R " << radToDeg(wpr.r) << "\n";
  }
}

Transform poseFrom(const std::array<double, 6>& v, bool kuka)
{
  Transform T = Transform::Identity();
  T.translation() = Vec3(v[0], v[1], v[2]);
  T.linear() = kuka ? rotationFromKukaAbc({degToRad(v[3]), degToRad(v[4]), degToRad(v[5])})
                    : rotationFromFanucWpr({degToRad(v[3]), degToRad(v[4]), degToRad(v[5])});
  return T;
}

void printJoints(const RobotCell& cell, const JointVector& q, std::ostream& out)
{
  JointPoint jp;
  cell.convention().describe(cell.ik().model(), q, jp);
  const auto& limits = cell.convention().axisLimits();
  for (size_t k = 0; k < 6; ++k) out << "  " << limits[k].name << " " << jp.robotDeg[k];
  if (cell.convention().controller() == Controller::KukaKrc4)
    out << "  S " << jp.kukaStatus << "  T " << jp.kukaTurn;
  else if (cell.convention().controller() == Controller::AbbIrc5)
    out << "  confdata [" << jp.abbConf[0] << "," << jp.abbConf[1] << "," << jp.abbConf[2] << ","
        << jp.abbConf[3] << "]";
  else
    out << "  CONFIG '" << jp.fanucConfig << "'";
}

}  // namespace

int cmdKin(const std::vector<std::string>& argv)
{
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout << "usage: spira-cli kin CELL --fk J1 J2 J3 J4 J5 J6\n"
                 "       spira-cli kin CELL --ik X Y Z A B C\n\n"
                 "Forward kinematics: the flange and TCP poses of the cell's robot for six axis values in\n"
                 "the controller's convention (degrees). Inverse kinematics: every joint solution, with its\n"
                 "configuration, that puts the TCP at the pose X Y Z (mm) A B C (KUKA, degrees) or W P R\n"
                 "(FANUC and ABB: R = Rz(R) Ry(P) Rx(W), degrees), in the robot's base frame\n"
                 "($ROBROOT / World / ABB base).\n";
    return kExitOk;
  }
  const bool fk = args.takeSwitch("--fk");
  const bool ik = args.takeSwitch("--ik");
  if (fk == ik) throw UsageError("'kin' needs exactly one of --fk and --ik", "see spira-cli kin --help");
  std::vector<std::string> words = args.rest;
  if (words.size() != 7)
    throw UsageError("'kin' takes a cell file and six numbers",
                     "e.g. spira-cli kin cell.cell --fk 0 -90 90 0 0 0");
  const std::string cellFile = words.front();
  words.erase(words.begin());
  const std::array<double, 6> v = sixNumbers(words, fk ? "--fk" : "--ik");

  const RobotCell cell(readCellFile(cellFile));
  const bool kuka = cell.convention().controller() == Controller::KukaKrc4;
  const Transform flangeTcp = cell.record().tool.T_flange_tcp;
  std::cout << std::fixed << std::setprecision(4);
  std::cout << "cell: " << cell.record().name << " (" << cell.convention().id() << ")\n";
  if (fk) {
    const JointVector q = cell.convention().fromControllerDeg(v);
    const Transform flange = cell.arm().forward(q);
    printPose("flange", flange, kuka, std::cout);
    printPose("tcp   ", flange * flangeTcp, kuka, std::cout);
    if (cell.canSolve()) {
      std::cout << "configuration:";
      printJoints(cell, q, std::cout);
      std::cout << "  dexterity " << cell.ik().dexterity(q) << "\n";
    }
    return kExitOk;
  }
  const Transform tcp = poseFrom(v, kuka);
  const auto solutions = cell.ik().solveAll(tcp * flangeTcp.inverse());
  if (solutions.empty()) {
    std::cout << "no solution: the pose is out of the robot's reach\n";
    return kExitInfeasible;
  }
  size_t within = 0;
  for (const IkSolution& s : solutions) {
    std::cout << (s.withinLimits ? "  ok    " : "  limit ") << s.configuration.label() << ":";
    printJoints(cell, s.q, std::cout);
    std::cout << "  dexterity " << s.dexterity << "\n";
    within += s.withinLimits;
  }
  std::cout << solutions.size() << " solution(s), " << within << " within the controller limits\n";
  return within ? kExitOk : kExitInfeasible;
}

}  // namespace spira::cli
