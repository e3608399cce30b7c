#pragma once

#include <string>
#include <vector>

namespace spira::test {

struct CliRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// Runs the built spira-cli with `args` (no shell: arguments are passed as they are).
CliRun runCli(const std::vector<std::string>& args);

}  // namespace spira::test
