#pragma once

namespace spira {

// The exit codes of spira-cli and spira (documented in README.md). 1 is for bugs only: whatever the
// user can fix (a file, a flag, an unwritable folder, no display to render on) is 2 or 3.
enum ExitCode : int {
  kExitOk = 0,
  kExitInternal = 1,     // a bug in Spira: please report
  kExitUsage = 2,        // a malformed command line
  kExitBadInput = 3,     // input or environment the user can fix
  kExitInfeasible = 4,   // planned, but the plan is not feasible
  kExitCancelled = 130,  // interrupted (SIGINT)
};

}  // namespace spira
