#pragma once

#include <exception>
#include <string>

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

// What a command that threw `error` exits with, and the one line that says why: Spira's error kinds
// map to the codes above here and nowhere else. A part Spira cannot plan (AlgorithmError) and
// running out of memory are for the user to change, not bugs; only a broken invariant
// (InternalError) or a foreign exception is reported as a bug.
struct Failure {
  int exitCode = kExitInternal;
  std::string message;
};
Failure failureOf(std::exception_ptr error);

}  // namespace spira
