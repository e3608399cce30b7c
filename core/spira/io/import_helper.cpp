// spira-import's body: runs one importer with limits on its own memory and processor time and
// streams the result to the parent (see import_wire.h), or serves imports as forked children of a
// process that has loaded the libraries once (see import_process.h).
#include <poll.h>
#include <signal.h>
// glibc 2.36's header lacks the C++ linkage guards.
extern "C" {
#include <sys/pidfd.h>
}
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <fstream>
#include <iostream>
#include <new>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "spira/base/error.h"
#include "spira/io/import_process.h"
#include "spira/io/import_server_protocol.h"
#include "spira/io/import_wire.h"
#include "spira/io/isolated_import.h"

namespace spira {
namespace {

constexpr int kResultFd = 3;

// Forwards progress to the parent, at most one frame per percent or stage change.
class WireProgress final : public Progress {
 public:
  explicit WireProgress(wire::Writer& out) : out_(out) {}
  void report(double fraction, std::string_view stage) override
  {
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (stage == stage_ && std::abs(fraction - last_) < 0.01) return;
    stage_ = stage;
    last_ = fraction;
    out_.progress(fraction, stage);
  }
  bool cancelled() const override { return false; }  // the parent cancels by killing the helper

 private:
  wire::Writer& out_;
  std::string stage_;
  double last_ = -1.0;
};

void limit(int resource, rlim_t value)
{
  const rlimit r{value, value};
  ::setrlimit(resource, &r);
}

#if defined(__SANITIZE_ADDRESS__)
// The reader's private writable memory now (VmData), in bytes; 0 when it cannot be read.
rlim_t dataBytesNow()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  unsigned long long kb = 0;
  while (status >> key)
    if (key == "VmData:" && status >> kb) return static_cast<rlim_t>(kb) * 1024;
  return 0;
}
#endif

int runImporter(const import_process::Request& r, const PluginRegistry& registry)
{
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of shadow address space before main, which the address-space
  // limit would count: the memory the reader maps beyond what it holds now is limited instead (its
  // allocator then returns null, as allocator_may_return_null in app/import/main.cpp asks).
  limit(RLIMIT_DATA, dataBytesNow() + r.memoryBytes);
#else
  limit(RLIMIT_AS, r.memoryBytes);
#endif
  limit(RLIMIT_CPU, static_cast<rlim_t>(r.cpuSeconds));
  limit(RLIMIT_CORE, 0);
  wire::Writer out(kResultFd);
  out.header();
  try {
    const ImporterPlugin& importer = registry.importer(r.importer);
    const ParamSet params = ParamSet::fromJson(nlohmann::json::parse(r.params), &importer.schema());
    WireProgress progress(out);
    out.mesh(importer.read(r.file, params, progress));
  } catch (const InputError& e) {
    out.error(wire::ErrorKind::Input, e.what(), e.hint());
  } catch (const IoError& e) {
    out.error(wire::ErrorKind::Io, e.what(), e.hint());
  } catch (const AlgorithmError& e) {
    out.error(wire::ErrorKind::Algorithm, e.what(), e.hint());
  } catch (const Error& e) {
    out.error(wire::ErrorKind::Internal, e.what(), e.hint());
  } catch (const std::bad_alloc&) {
    out.error(wire::ErrorKind::Memory, {}, {});
  } catch (const std::exception& e) {
    out.error(wire::ErrorKind::Internal, "importer '" + r.importer + "' failed: " + e.what(),
              "please report this with the file");
  }
  return 0;
}

// Runs the importer and ends the process: the result is written, and the libraries' exit handlers
// can hang once memory ran out (OpenBLAS joins a thread stuck on a failed mmap) and only cost time.
[[noreturn]] void runAndExit(const import_process::Request& r, const PluginRegistry& registry)
{
  int status = 1;  // the parent is gone or the request is not Spira's: nobody left to tell
  try {
    status = runImporter(r, registry);
  } catch (const std::exception&) {
  }
  ::_exit(status);
}

std::optional<import_process::Request> requestOf(const nlohmann::json& body)
{
  const auto text = [&](const char* key) { return body.contains(key) && body[key].is_string(); };
  const auto count = [&](const char* key) { return body.contains(key) && body[key].is_number_unsigned(); };
  if (!text("importer") || !text("file") || !text("params") || !count("memory") || !count("cpu"))
    return std::nullopt;
  return import_process::Request{body["importer"], body["file"], body["params"], body["memory"].get<size_t>(),
                                 body["cpu"].get<long>()};
}

// The forked child: the pipes become its descriptors 1 to 3, as for a spawned helper.
[[noreturn]] void serveChild(const import_process::Request& r, int result, int log, pid_t server,
                             const PluginRegistry& registry)
{
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != server) ::_exit(1);
  if (::dup2(log, 1) < 0 || ::dup2(log, 2) < 0 || ::dup2(result, kResultFd) < 0) ::_exit(1);
  ::close(result);
  ::close(log);
  runAndExit(r, registry);
}

// Waits for the child to end, or for the client to go away (then the child is killed first).
std::pair<int, size_t> awaitChild(int socket, pid_t pid, int pidfd)
{
  for (;;) {
    pollfd fds[2] = {{pidfd, POLLIN, 0}, {socket, 0, 0}};
    if (::poll(fds, 2, -1) < 0 && errno != EINTR) break;
    if (fds[0].revents) break;
    if (fds[1].revents & (POLLHUP | POLLERR)) {
      ::kill(pid, SIGKILL);
      break;
    }
  }
  return import_process::reap(pid);
}

// One request at a time (the client holds the server while its import runs); ends when the client
// closes its socket.
[[noreturn]] void serve(int socket, const PluginRegistry& registry)
{
  const pid_t self = ::getpid();
  for (;;) {
    std::optional<import_server::Message> m = import_server::receive(socket);
    if (!m) ::_exit(0);
    const std::optional<import_process::Request> r = requestOf(m->body);
    const pid_t pid = r && m->fds.size() == 2 ? ::fork() : -1;
    if (pid == 0) {
      ::close(socket);
      serveChild(*r, m->fds[0], m->fds[1], self, registry);
    }
    for (int fd : m->fds) ::close(fd);
    const int pidfd = pid > 0 ? ::pidfd_open(pid, 0) : -1;
    if (pidfd < 0) {
      if (pid > 0) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
      }
      import_server::send(socket, {{"error", "no importer started"}});
      continue;
    }
    const bool told = import_server::send(socket, {{"pid", pid}}, {pidfd});
    const auto [status, peak] = told ? awaitChild(socket, pid, pidfd) : std::pair<int, size_t>{0, 0};
    ::close(pidfd);
    if (!told) ::_exit(0);  // the child dies with this process
    import_server::send(socket, {{"status", status}, {"maxrss", peak}});
  }
}

}  // namespace

int importHelperMain(int argc, char** argv, const PluginRegistry& registry)
{
  if (argc == 2 && std::string_view(argv[1]) == "--serve") {
    const int socket = import_server::highDescriptor(kResultFd);
    if (socket < 0) ::_exit(1);
    serve(socket, registry);
  }
  // Dies with the parent: an orphaned parser must not keep running.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() == 1) return 1;
  if (argc != 6) {
    std::cerr << "usage: spira-import IMPORTER_ID FILE PARAMS_JSON MEMORY_BYTES CPU_SECONDS (run by Spira, "
                 "not by hand)\n";
    return 2;
  }
  try {
    runAndExit({argv[1], argv[2], argv[3], std::stoull(argv[4]), std::stol(argv[5])}, registry);
  } catch (const std::exception&) {
  }
  ::_exit(1);
}

}  // namespace spira
