#pragma once

#include <functional>
#include <string>
#include <vector>

namespace spira::cli {

// The number of threads a spira-cli run may use: "--threads N" anywhere on the command line
// (taken out of `args`), else the SPIRA_THREADS environment variable, else 0 (one per core).
// Throws UsageError for a value that is not a whole number from 1 to 256.
int takeThreadCount(std::vector<std::string>& args);

// Runs `body` with `threads` TBB threads (0: TBB's default, one per core) and returns its result;
// exceptions pass through. A plan is the same whatever the count: it only changes the speed.
int runWithThreads(int threads, const std::function<int()>& body);

}  // namespace spira::cli
