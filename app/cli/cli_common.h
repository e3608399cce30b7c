#pragma once

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "spira/base/exit_code.h"
#include "spira/plugin/param_cli.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::cli {

// A malformed command line (unknown flag, missing argument): exit code 2.
class UsageError : public std::runtime_error {
 public:
  UsageError(const std::string& what, std::string hint) : std::runtime_error(what), hint_(std::move(hint)) {}
  const std::string& hint() const { return hint_; }

 private:
  std::string hint_;
};

// Parsed arguments of one sub-command: positional arguments and the switches it knows.
struct Args {
  std::vector<std::string> rest;  // not yet consumed, in order

  // Removes a boolean switch such as "--json"; true when present.
  bool takeSwitch(const std::string& name);
  // Removes "--name VALUE" or "--name=VALUE"; empty when absent.
  std::string takeOption(const std::string& name);
  // The positional arguments left once every option was taken; throws UsageError naming the
  // first unknown option, or when the count is outside [minCount, maxCount].
  std::vector<std::string> finish(const std::string& command, size_t minCount, size_t maxCount) const;
};

Args splitArgs(const std::vector<std::string>& args);

// The plugin parameter flags (--h 2, --points-per-rev 360) taken from `rest` into `targets`; the rest
// returned. A missing, malformed or out-of-range value is a usage error, as for every other flag.
std::vector<std::string> takeParamFlags(const std::vector<std::string>& rest,
                                        const std::vector<FlagTarget>& targets);

// The flags of a plan: the settings sections' and every decomposer's and closure finder's, each
// target writing into its own ParamSet of `values` (keyed by section name or plugin id).
struct PlanFlags {
  std::map<std::string, ParamSet> values;
  std::vector<FlagTarget> targets;
  explicit PlanFlags(const PluginRegistry& registry);
  PlanFlags(const PlanFlags&) = delete;  // targets point into values
  PlanFlags& operator=(const PlanFlags&) = delete;
};

// The value of a numeric flag: a finite number, or a whole number in [min, max]; anything else is a
// usage error naming the flag, what is wrong and `example`.
double finiteNumberFlag(const std::string& flag, const std::string& text, const std::string& example);
// The value of a flag that is a length or count from 0 (`zeroAllowed`) or above 0; `fallback` when the
// flag was not given. Anything else is a usage error naming the flag.
double positiveFlag(const std::string& flag, const std::string& text, double fallback, bool zeroAllowed);
long long wholeNumberFlag(const std::string& flag, const std::string& text, long long min, long long max,
                          const std::string& example);

int cmdInfo(const std::vector<std::string>& args);
int cmdPlugins(const std::vector<std::string>& args);
int cmdSample(const std::vector<std::string>& args);
int cmdPlan(const std::vector<std::string>& args);
// 'plan PROJECT.spira': `args` still holds the project's path among the options.
int cmdPlanProject(Args args, const std::filesystem::path& project);
int cmdField(const std::vector<std::string>& args);
int cmdKin(const std::vector<std::string>& args);
int cmdExport(const std::vector<std::string>& args);
int cmdCompare(const std::vector<std::string>& args);
int cmdThermal(const std::vector<std::string>& args);
int cmdScanCompare(const std::vector<std::string>& args);
int cmdScanSim(const std::vector<std::string>& args);
int cmdResume(const std::vector<std::string>& args);
// scan-sim PLAN_DIR: the wall of a plan built part way (--at, --error), scanned; `args` holds the rest.
int simulatePlanScan(Args& args, const std::string& planDir, const std::filesystem::path& out, double noiseMm,
                     long long seed);

}  // namespace spira::cli
