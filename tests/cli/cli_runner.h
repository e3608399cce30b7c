#pragma once

#include <string>
#include <vector>

namespace spira::test {

struct CliRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// Runs the built spira-cli with `args` (no shell: arguments are passed as they are), in this
// process's environment with the "NAME=VALUE" entries of `env` set on top.
CliRun runCli(const std::vector<std::string>& args, const std::vector<std::string>& env = {});

// The same for another program, given by its path (a launcher such as mpiexec running spira-cli).
CliRun runProgram(const std::string& program, const std::vector<std::string>& args,
                  const std::vector<std::string>& env = {});

// The cells of one line of a CSV file spira-cli writes: commas inside double quotes (joints.csv's
// configuration) do not split.
std::vector<std::string> csvCells(const std::string& line);

}  // namespace spira::test
