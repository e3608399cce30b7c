#include "spira/io/isolated_import.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "spira/base/error.h"
#include "spira/io/import_process.h"
#include "spira/io/import_wire.h"

namespace fs = std::filesystem;

namespace spira {
namespace {

constexpr size_t kMaxLogBytes = 64 * 1024;
constexpr size_t kMaxLogWarnings = 5;
constexpr double kPollSeconds = 0.05;  // how often cancel, time and memory are checked

double envNumber(const char* name, double fallback)
{
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (*end != '\0' || !(v > 0.0))
    throw InputError(
        std::string("the environment variable ") + name + "='" + text + "' is not a positive number",
        std::string("set ") + name + " to a positive number or unset it");
  return v;
}

std::string formatName(const fs::path& file)
{
  std::string ext = file.extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  for (char& c : ext) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (ext == "STP") ext = "STEP";
  if (ext == "IGS") ext = "IGES";
  return ext.empty() ? std::string("file") : ext;
}

std::string megabytes(size_t bytes)
{
  return std::to_string(bytes / (1024 * 1024)) + " MB";
}

// OpenCASCADE colours its messages with terminal escapes.
std::string withoutEscapes(const std::string& line)
{
  std::string out;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\x1b' && i + 1 < line.size() && line[i + 1] == '[') {
      i += 2;
      while (i < line.size() && !std::isalpha(static_cast<unsigned char>(line[i]))) ++i;
      continue;
    }
    if (line[i] != '\r') out.push_back(line[i]);
  }
  return out;
}

std::vector<std::string> logLines(const std::string& log)
{
  std::vector<std::string> lines;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    line = withoutEscapes(line);
    const size_t a = line.find_first_not_of(" \t*");
    if (a == std::string::npos) continue;
    const size_t b = line.find_last_not_of(" \t*");
    lines.push_back(line.substr(a, b - a + 1));
  }
  return lines;
}

[[noreturn]] void rethrow(const wire::RemoteError& e, const std::string& source, const ImportLimits& limits,
                          const std::string& reexport)
{
  switch (e.kind) {
    case wire::ErrorKind::Input:
      throw InputError(e.what, e.hint);
    case wire::ErrorKind::Io:
      throw IoError(e.what, e.hint);
    case wire::ErrorKind::Algorithm:
      throw AlgorithmError(e.what, e.hint);
    case wire::ErrorKind::Memory:
      throw InputError("reading '" + source + "' needed more than the import's memory limit of " +
                           megabytes(limits.memoryBytes),
                       "the file is probably damaged; " + reexport +
                           ", or raise SPIRA_IMPORT_MEMORY_MB if it really is that large");
    case wire::ErrorKind::Internal:
      break;
  }
  throw InternalError(e.what, e.hint);
}

std::string signalName(int sig)
{
  const char* abbrev = sigabbrev_np(sig);
  return abbrev ? std::string(", SIG") + abbrev : std::string();
}

InputError timeLimit(const std::string& source, double seconds, const char* kind, const std::string& reexport)
{
  std::ostringstream limit;
  limit << seconds;
  return InputError("reading '" + source + "' took longer than the import's " + kind + " limit of " +
                        limit.str() + " s and was stopped",
                    "the file is probably damaged; " + reexport +
                        ", or raise SPIRA_IMPORT_TIMEOUT_S if it really is that large");
}

InputError stoppedWithoutResult(const std::string& what, const std::string& source, int status,
                                const std::vector<std::string>& lines, const std::string& hint)
{
  std::string cause = WIFSIGNALED(status)
                          ? "crashed on '" + source + "' (signal " + std::to_string(WTERMSIG(status)) +
                                signalName(WTERMSIG(status)) + ")"
                          : "stopped on '" + source + "' without a result (exit code " +
                                std::to_string(WEXITSTATUS(status)) + ")";
  cause += ": the file is damaged or uses entities Spira cannot read";
  if (!lines.empty()) cause += "; the reader said: " + lines.front();
  return InputError(what + cause, hint);
}

// The helper may have been started from another working directory.
fs::path absolutePath(const fs::path& file)
{
  std::error_code ec;
  const fs::path a = fs::absolute(file, ec);
  return ec ? file : a;
}

}  // namespace

ImportLimits ImportLimits::fromEnvironment()
{
  const double physical =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  const double fallbackMb = std::min(4096.0, physical > 0 ? physical / 2 / (1024 * 1024) : 4096.0);
  ImportLimits l;
  l.memoryBytes = static_cast<size_t>(envNumber("SPIRA_IMPORT_MEMORY_MB", fallbackMb) * 1024 * 1024);
  l.wallSeconds = envNumber("SPIRA_IMPORT_TIMEOUT_S", 120.0);
  return l;
}

void prestartImportHelper()
{
  import_process::prestartServer();
}

fs::path importHelperPath()
{
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = self.parent_path() / "spira-import";
    if (fs::is_regular_file(beside, ec)) return beside;
  }
#ifdef SPIRA_IMPORT_BUILD_PATH
  if (fs::is_regular_file(SPIRA_IMPORT_BUILD_PATH, ec)) return SPIRA_IMPORT_BUILD_PATH;
#endif
  throw IoError("the import helper spira-import is missing next to '" + self.string() + "'",
                "reinstall Spira: spira-import must sit next to spira-cli");
}

ImportedMesh readIsolated(const ImporterPlugin& importer, const fs::path& file, const ParamSet& params,
                          Progress& progress)
{
  return readIsolated(importer.id(), file, params, progress,
                      "re-export the part from the CAD program (for STEP choose AP214 or AP242)");
}

ImportedMesh readIsolated(const std::string& importerId, const fs::path& file, const ParamSet& params,
                          Progress& progress, const std::string& reexport)
{
  progress.checkCancel();
  const ImportLimits limits = ImportLimits::fromEnvironment();
  const std::string source = file.filename().string();
  const auto cpuSeconds =
      static_cast<long>(limits.wallSeconds * std::max(1u, std::thread::hardware_concurrency())) + 10;
  import_process::Pipe result, log;
  const std::unique_ptr<import_process::Helper> child = import_process::start(
      {importerId, absolutePath(file).string(), params.toJson().dump(), limits.memoryBytes, cpuSeconds},
      result, log);
  result.closeWrite();
  log.closeWrite();

  wire::Reader reader;
  std::string logText;
  const auto start = std::chrono::steady_clock::now();
  std::vector<char> buffer(1 << 16);
  double nextMemoryCheck = 0.0;
  while (result.read >= 0 || log.read >= 0) {
    pollfd fds[2] = {{result.read, POLLIN, 0}, {log.read, POLLIN, 0}};
    const int ready = ::poll(fds, 2, static_cast<int>(kPollSeconds * 1000));
    if (ready < 0 && errno != EINTR) throw IoError("waiting for the import helper failed", "try again");
    if (progress.cancelled()) throw Cancelled();  // ~Helper kills the helper
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > limits.wallSeconds) throw timeLimit(source, limits.wallSeconds, "time", reexport);
    if (elapsed >= nextMemoryCheck) {
      nextMemoryCheck = elapsed + kPollSeconds;
      if (child->residentBytes() > limits.memoryBytes)
        rethrow({wire::ErrorKind::Memory, {}, {}}, source, limits, reexport);
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::read(fds[i].fd, buffer.data(), buffer.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        i == 0 ? result.closeRead() : log.closeRead();
        continue;
      }
      if (i == 0)
        reader.feed(buffer.data(), static_cast<size_t>(n), progress);
      else if (logText.size() < kMaxLogBytes)
        logText.append(buffer.data(), std::min(static_cast<size_t>(n), kMaxLogBytes - logText.size()));
    }
  }
  const auto [status, peakBytes] = child->wait();
  const std::string what = "the " + formatName(file) + " reader ";
  const std::vector<std::string> lines = logLines(logText);
  if (WIFSIGNALED(status) || !reader.complete()) {
    if (peakBytes >= limits.memoryBytes / 4 * 3)
      rethrow({wire::ErrorKind::Memory, {}, {}}, source, limits, reexport);
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
      throw timeLimit(source, cpuSeconds, "processor time", reexport);
    throw stoppedWithoutResult(what, source, status, lines, reexport);
  }
  if (reader.error()) rethrow(*reader.error(), source, limits, reexport);
  ImportedMesh mesh = std::move(*reader.mesh());
  for (size_t i = 0; i < std::min(lines.size(), kMaxLogWarnings); ++i)
    mesh.warnings.push_back(what + "said: " + lines[i]);
  if (lines.size() > kMaxLogWarnings)
    mesh.warnings.push_back(what + "said " + std::to_string(lines.size() - kMaxLogWarnings) + " more things");
  return mesh;
}

}  // namespace spira
