// Runs a fuzz target without libFuzzer (GCC builds, the test suite): every seed and regression
// input once, then a fixed number of inputs made by deterministic mutations of them. A crash, an
// abort, an escaped exception or an input that runs longer than the timeout stops the run and
// leaves that input in the working folder, so that the finding can be replayed and kept.
//
//   fuzz_<target> [-runs=N] [-seed=S] [-max_len=BYTES] [-timeout=SECONDS] FILE_OR_FOLDER...

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "mutator.h"

namespace fs = std::filesystem;

namespace {

// What the signal handler writes out: the input being run. Set before each run.
const std::string* g_current = nullptr;
char g_crashFile[512] = "fuzz-crash.bin";

void writeAll(int fd, const char* p, size_t n)
{
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w <= 0) return;
    p += w;
    n -= static_cast<size_t>(w);
  }
}

void say(const char* text)
{
  writeAll(2, text, std::strlen(text));
}

// Only async-signal-safe calls: the process may be in any state.
void onFatalSignal(int sig)
{
  say(sig == SIGALRM ? "\nfuzz: the input ran past the timeout (a hang)\n" : "\nfuzz: the target crashed\n");
  if (g_current) {
    const int fd = ::open(g_crashFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      writeAll(fd, g_current->data(), g_current->size());
      ::close(fd);
      say("fuzz: the input is in ");
      say(g_crashFile);
      say("; keep it in fuzz/regressions/<target>/ once fixed\n");
    }
  }
  ::signal(SIGABRT, SIG_DFL);
  std::abort();
}

void installHandlers(const char* program)
{
  std::snprintf(g_crashFile, sizeof g_crashFile, "%s-crash.bin", fs::path(program).filename().c_str());
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM}) ::signal(sig, onFatalSignal);
}

// Without AddressSanitizer (whose shadow memory needs the address space) a memory blow-up becomes
// std::bad_alloc, which the targets do not allow, instead of taking the machine down.
void limitMemory()
{
#ifndef __SANITIZE_ADDRESS__
  rlimit limit{};
  limit.rlim_cur = limit.rlim_max = rlim_t{4} << 30;
  ::setrlimit(RLIMIT_AS, &limit);
#endif
}

std::string readBytes(const fs::path& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

bool parseFlag(const std::string& arg, const char* name, unsigned long long& value)
{
  const std::string prefix = std::string("-") + name + "=";
  if (arg.rfind(prefix, 0) != 0) return false;
  char* end = nullptr;
  value = std::strtoull(arg.c_str() + prefix.size(), &end, 10);
  if (*end != '\0') {
    std::fprintf(stderr, "fuzz: '%s' needs a whole number\n", arg.c_str());
    std::exit(2);
  }
  return true;
}

void run(const std::string& input, unsigned timeout)
{
  g_current = &input;
  ::alarm(timeout);
  LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(input.data()), input.size());
  ::alarm(0);
}

}  // namespace

int main(int argc, char** argv)
{
  unsigned long long runs = 0, seed = 1, maxLen = 1 << 16, timeout = 10;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (parseFlag(arg, "runs", runs) || parseFlag(arg, "seed", seed) || parseFlag(arg, "max_len", maxLen) ||
        parseFlag(arg, "timeout", timeout))
      continue;
    if (arg.rfind('-', 0) == 0) {
      std::fprintf(stderr, "fuzz: unknown option '%s'\n", arg.c_str());
      return 2;
    }
    if (fs::is_directory(arg)) {
      std::vector<fs::path> inDir;
      for (const auto& e : fs::directory_iterator(arg))
        if (e.is_regular_file()) inDir.push_back(e.path());
      std::sort(inDir.begin(), inDir.end());
      files.insert(files.end(), inDir.begin(), inDir.end());
    } else if (fs::is_regular_file(arg)) {
      files.emplace_back(arg);
    } else {
      std::fprintf(stderr, "fuzz: '%s' is neither a file nor a folder\n", arg.c_str());
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "fuzz: no inputs; give the seed corpus and regression folders\n");
    return 2;
  }
  installHandlers(argv[0]);
  limitMemory();

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> inputs;
  for (const fs::path& f : files) inputs.push_back(readBytes(f));
  for (const std::string& input : inputs) run(input, static_cast<unsigned>(timeout));

  spira::fuzz::Mutator mutator(seed, static_cast<size_t>(maxLen));
  std::string input;
  for (unsigned long long r = 0; r < runs; ++r) {
    input = mutator.mutate(inputs);
    run(input, static_cast<unsigned>(timeout));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("fuzz: %zu inputs and %llu mutations ran without a finding in %.1f s\n", inputs.size(), runs,
              seconds);
  return 0;
}
