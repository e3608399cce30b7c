#include "thread_limit.h"

#include <cstdlib>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "cli_common.h"

namespace spira::cli {

namespace {

constexpr int kMaxThreads = 256;

int parseThreadCount(const std::string& text, const std::string& source)
{
  return static_cast<int>(wholeNumberFlag(source, text, 1, kMaxThreads,
                                          "a whole number of threads, e.g. --threads 1 (SPIRA_THREADS=1), or "
                                          "leave it out to use every core"));
}

}  // namespace

int takeThreadCount(std::vector<std::string>& args)
{
  Args a;
  a.rest = std::move(args);
  const std::string option = a.takeOption("--threads");
  args = std::move(a.rest);
  if (!option.empty()) return parseThreadCount(option, "--threads");
  const char* env = std::getenv("SPIRA_THREADS");
  if (env && *env) return parseThreadCount(env, "SPIRA_THREADS");
  return 0;
}

int runWithThreads(int threads, const std::function<int()>& body)
{
  if (threads <= 0) return body();
  // The global limit caps TBB's worker pool (and may raise it above the core count, for tests);
  // the arena gives the run exactly that many slots, the calling thread included.
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
  tbb::task_arena arena(threads);
  return arena.execute([&] { return body(); });
}

}  // namespace spira::cli
