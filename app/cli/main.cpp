// spira-cli: Spira's headless entry point. Every sub-command maps errors to documented exit
// codes and prints one line on stderr that says what is wrong and what to do.
#include <iostream>
#include <string>
#include <vector>

#include "cli_common.h"
#include "spira/base/exit_code.h"
#include "spira/base/version.h"
#include "thread_limit.h"

namespace {

constexpr const char* kUsageText =
    "usage: spira-cli <command> [options]\n"
    "\n"
    "commands:\n"
    "  info PART        mesh statistics, validation findings, boundary loops, open/closed class\n"
    "  plugins          list plugins and their parameter schemas\n"
    "  field PART --kind geodesic|harmonic -o FILE   per-vertex scalar field as .csv or .vtp\n"
    "  plan PART -o DIR   plan one continuous spiral: DIR/trajectory.csv and DIR/report.json\n"
    "  compare PART -o DIR   every strategy and the planar 2.5D baseline: DIR/compare.json, .csv\n"
    "  thermal PLAN_DIR|PROJECT -o DIR   heat of the build: DIR/thermal.json, thermal_points.csv, "
    "probes.csv\n"
    "  kin CELL --fk J1..J6 | --ik X Y Z A B C   forward / inverse kinematics of a cell's robot\n"
    "  export PLAN_DIR --format krl|fanuc_tp|rapid|gcode -o DIR   robot or machine program\n"
    "  scan-compare PART SCAN -o DIR   a scan aligned to the part and its deviation map\n"
    "  scan-sim PART|PLAN_DIR -o SCAN.ply   a simulated scan of a part, or of a plan built part way\n"
    "  resume PLAN_DIR --scan SCAN --at INDEX -o DIR   the rest of a build re-planned from a scan\n"
    "  sample NAME -o FILE   write a bundled sample part (open-cylinder, dome, cone) made in code\n"
    "\n"
    "options: --help (also after a command), --version, --threads N (at most N threads; also the\n"
    "         SPIRA_THREADS environment variable; the results are the same with any count)\n"
    "exit codes: 0 success, 2 usage error, 3 bad input, 4 infeasible plan, 1 internal error\n";

int dispatch(const std::string& command, const std::vector<std::string>& rest)
{
  using namespace spira;
  using namespace spira::cli;
  if (command == "info") return cmdInfo(rest);
  if (command == "plugins") return cmdPlugins(rest);
  if (command == "sample") return cmdSample(rest);
  if (command == "plan") return cmdPlan(rest);
  if (command == "field") return cmdField(rest);
  if (command == "kin") return cmdKin(rest);
  if (command == "export") return cmdExport(rest);
  if (command == "compare") return cmdCompare(rest);
  if (command == "thermal") return cmdThermal(rest);
  if (command == "scan-compare") return cmdScanCompare(rest);
  if (command == "scan-sim") return cmdScanSim(rest);
  if (command == "resume") return cmdResume(rest);
  throw UsageError("unknown command '" + command + "'", "run 'spira-cli --help' for the list of commands");
}

}  // namespace

int main(int argc, char** argv)
{
  using namespace spira;
  using namespace spira::cli;
  std::vector<std::string> args(argv + 1, argv + argc);
  int threads = 0;
  try {
    threads = takeThreadCount(args);
  } catch (const UsageError& e) {
    std::cerr << "spira-cli: " << e.what() << " (" << e.hint() << ")\n";
    return kExitUsage;
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << kUsageText;
    return args.empty() ? kExitUsage : kExitOk;
  }
  if (args[0] == "--version") {
    std::cout << "spira-cli " << spira::kVersion << "\n";
    return kExitOk;
  }
  try {
    const std::string command = args[0];
    args.erase(args.begin());
    return runWithThreads(threads, [&] { return dispatch(command, args); });
  } catch (const UsageError& e) {
    std::cerr << "spira-cli: " << e.what() << " (" << e.hint() << ")\n";
    return kExitUsage;
  } catch (...) {
    const Failure failure = failureOf(std::current_exception());
    std::cerr << "spira-cli: " << failure.message << "\n";
    return failure.exitCode;
  }
}
