#include "spira/io/import_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
// glibc 2.36's header lacks the C++ linkage guards.
extern "C" {
#include <sys/pidfd.h>
}
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <optional>
#include <vector>

#include "spira/base/error.h"
#include "spira/io/import_server_protocol.h"
#include "spira/io/isolated_import.h"

extern char** environ;

namespace spira::import_process {
namespace {

const char* const kReinstall = "reinstall Spira: spira-import must sit next to spira-cli";

size_t residentBytesOf(pid_t pid)
{
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  size_t pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return resident * static_cast<size_t>(::sysconf(_SC_PAGE_SIZE));
}

// `args` with descriptors 0 to 3 of the new process taken from `fds` (-1: /dev/null), signals at
// their defaults and none blocked.
pid_t spawn(const std::vector<std::string>& args, const int (&fds)[4])
{
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  for (int target = 0; target < 4; ++target) {
    if (fds[target] >= 0)
      posix_spawn_file_actions_adddup2(&actions, fds[target], target);
    else
      posix_spawn_file_actions_addopen(&actions, target, "/dev/null", target == 0 ? O_RDONLY : O_WRONLY, 0);
  }
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGXCPU, SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGCHLD})
    sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, args[0].c_str(), &actions, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (rc != 0)
    throw IoError("cannot start the import helper '" + args[0] + "': " + std::strerror(rc), kReinstall);
  return pid;
}

// A helper started for one import: `spira-import IMPORTER FILE PARAMS MEMORY CPU`.
class SpawnedHelper final : public Helper {
 public:
  SpawnedHelper(const Request& r, const Pipe& result, const Pipe& log)
      : pid_(spawn({importHelperPath().string(), r.importer, r.file, r.params, std::to_string(r.memoryBytes),
                    std::to_string(r.cpuSeconds)},
                   {-1, log.write, log.write, result.write}))
  {
  }
  ~SpawnedHelper() override
  {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  size_t residentBytes() const override { return residentBytesOf(pid_); }
  std::pair<int, size_t> wait() override
  {
    const auto ended = reap(pid_);
    pid_ = -1;
    return ended;
  }

 private:
  pid_t pid_;
};

// The warm server and the socket to it. One import at a time: the caller holds `mutex`.
struct Server {
  std::mutex mutex;
  int socket = -1;
  pid_t pid = -1;

  bool running() const { return socket >= 0; }

  void launch()
  {
    int ends[2];
    if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, ends) != 0) return;
    const int mine = import_server::highDescriptor(ends[0]);
    const int theirs = import_server::highDescriptor(ends[1]);
    try {
      if (mine >= 0 && theirs >= 0)
        pid = spawn({importHelperPath().string(), "--serve"}, {-1, -1, -1, theirs});
    } catch (const Error&) {
      pid = -1;
    }
    if (theirs >= 0) ::close(theirs);
    if (pid > 0)
      socket = mine;
    else if (mine >= 0)
      ::close(mine);
  }

  // Closing the socket ends an idle server; a stuck one is killed.
  void stop()
  {
    if (socket >= 0) ::close(socket);
    socket = -1;
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      reap(pid);
    }
    pid = -1;
  }
};

// Never destroyed: at exit the process's descriptors close and the server ends by itself.
Server& server()
{
  static Server* s = new Server;
  return *s;
}

// An importer the warm server forked. Holds the server for as long as it runs.
class ServedHelper final : public Helper {
 public:
  ServedHelper(std::unique_lock<std::mutex> lock, pid_t pid, int pidfd)
      : lock_(std::move(lock)), pid_(pid), pidfd_(pidfd)
  {
  }
  ~ServedHelper() override
  {
    if (!ended_) {
      ::pidfd_send_signal(pidfd_, SIGKILL, nullptr, 0);
      wait();
    }
    ::close(pidfd_);
  }
  size_t residentBytes() const override { return ended_ ? 0 : residentBytesOf(pid_); }
  std::pair<int, size_t> wait() override
  {
    ended_ = true;
    const std::optional<import_server::Message> m = import_server::receive(server().socket);
    if (m && m->body.contains("status") && m->body["status"].is_number_integer() &&
        m->body.contains("maxrss") && m->body["maxrss"].is_number_unsigned() && m->fds.empty())
      return {m->body["status"].get<int>(), m->body["maxrss"].get<size_t>()};
    // The server died with its child (which it takes down with it): report a killed helper.
    server().stop();
    return {SIGKILL, 0};
  }

 private:
  std::unique_lock<std::mutex> lock_;
  pid_t pid_;
  int pidfd_;
  bool ended_ = false;
};

// Nothing when the server is busy or cannot take the request (the caller then spawns a helper).
std::unique_ptr<Helper> startServed(const Request& r, const Pipe& result, const Pipe& log)
{
  Server& s = server();
  std::unique_lock<std::mutex> lock(s.mutex, std::try_to_lock);
  if (!lock.owns_lock()) return nullptr;
  const nlohmann::json request = {{"importer", r.importer},
                                  {"file", r.file},
                                  {"params", r.params},
                                  {"memory", r.memoryBytes},
                                  {"cpu", r.cpuSeconds}};
  bool sent = false;
  for (int attempt = 0; attempt < 2 && !sent; ++attempt) {
    if (!s.running()) s.launch();
    if (!s.running()) return nullptr;
    sent = import_server::send(s.socket, request, {result.write, log.write});
    if (!sent) s.stop();  // it ended since the last import
  }
  if (!sent) return nullptr;
  // The server holds the pipes now: from here a failure cannot fall back on the same pipes.
  std::optional<import_server::Message> m = import_server::receive(s.socket);
  const bool started =
      m && m->fds.size() == 1 && m->body.contains("pid") && m->body["pid"].is_number_integer();
  if (!started) {
    if (m)
      for (int fd : m->fds) ::close(fd);
    s.stop();
    throw IoError("the import helper could not start the importer",
                  "try again; if it keeps failing, " + std::string(kReinstall));
  }
  return std::make_unique<ServedHelper>(std::move(lock), m->body["pid"].get<pid_t>(), m->fds[0]);
}

}  // namespace

Pipe::Pipe()
{
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw IoError("cannot start the import helper: no pipe", "close other programs and try again");
  read = import_server::highDescriptor(fds[0]);
  write = import_server::highDescriptor(fds[1]);
  if (read < 0 || write < 0) {
    closeRead();
    closeWrite();
    throw IoError("cannot start the import helper: out of file descriptors", "close other files");
  }
}

Pipe::~Pipe()
{
  closeRead();
  closeWrite();
}

void Pipe::closeRead()
{
  if (read >= 0) ::close(read);
  read = -1;
}

void Pipe::closeWrite()
{
  if (write >= 0) ::close(write);
  write = -1;
}

std::pair<int, size_t> reap(pid_t pid)
{
  int status = 0;
  struct rusage usage {};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  return {status, static_cast<size_t>(usage.ru_maxrss) * 1024};
}

std::unique_ptr<Helper> start(const Request& request, const Pipe& result, const Pipe& log)
{
  if (std::unique_ptr<Helper> served = startServed(request, result, log)) return served;
  return std::make_unique<SpawnedHelper>(request, result, log);
}

void prestartServer()
{
  Server& s = server();
  std::unique_lock<std::mutex> lock(s.mutex, std::try_to_lock);
  if (lock.owns_lock() && !s.running()) s.launch();
}

pid_t serverPid()
{
  Server& s = server();
  std::lock_guard<std::mutex> lock(s.mutex);
  return s.running() ? s.pid : -1;
}

void stopServer()
{
  Server& s = server();
  std::lock_guard<std::mutex> lock(s.mutex);
  s.stop();
}

}  // namespace spira::import_process
