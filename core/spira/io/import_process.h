#pragma once

#include <sys/types.h>

#include <memory>
#include <string>
#include <utility>

// How readIsolated (isolated_import.h) gets an importer running in another process. The first
// import of a session starts a warm server, `spira-import --serve`, which has loaded the
// third-party libraries once and forks one child per import: starting a fresh helper costs tens of
// milliseconds of loading and relocating OpenCASCADE, a fork a few. When the server is busy with
// another thread's import, or cannot be reached, a one-shot helper is spawned instead.
namespace spira::import_process {

struct Request {
  std::string importer;  // the importer's id in the helper's registry
  std::string file;
  std::string params;  // ParamSet JSON
  size_t memoryBytes = 0;
  long cpuSeconds = 0;
};

// Both ends close-on-exec, numbered 10 or above.
struct Pipe {
  int read = -1, write = -1;
  Pipe();
  ~Pipe();
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  void closeRead();
  void closeWrite();
};

// A running importer. Destroying it before wait() kills and reaps it.
class Helper {
 public:
  virtual ~Helper() = default;
  // Resident memory now (bytes), 0 once unknown. Watched as well as the helper's own address-space
  // limit, which builds with AddressSanitizer cannot set.
  virtual size_t residentBytes() const = 0;
  // The wait status and the peak resident memory (bytes) once it has ended.
  virtual std::pair<int, size_t> wait() = 0;
};

// Waits for child `pid` to end: its wait status and peak resident memory (bytes).
std::pair<int, size_t> reap(pid_t pid);

// Starts `request` with its result on `result.write` and its messages on `log.write`.
std::unique_ptr<Helper> start(const Request& request, const Pipe& result, const Pipe& log);

// Starts the warm server now, without waiting for it, so that the first import finds it ready.
void prestartServer();

// The server's process id, or -1 when none is running (for tests).
pid_t serverPid();

// Ends the server; the next import starts a new one (for benchmarks of the first import).
void stopServer();

}  // namespace spira::import_process
