// The import server started by spira-cli ends with it: killed in the middle of a STEP import, the
// program leaves neither the server nor the importer it forked running.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.h"

extern char** environ;

namespace spira::test {
namespace {

struct ProcessInfo {
  std::string name;
  pid_t parent = 0;
  char state = '?';
};

ProcessInfo infoOf(pid_t pid)
{
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  ProcessInfo info;
  if (!std::getline(stat, text)) return info;
  const size_t open = text.find('('), close = text.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close + 4 > text.size()) return info;
  info.name = text.substr(open + 1, close - open - 1);
  info.state = text[close + 2];
  info.parent = static_cast<pid_t>(std::stol(text.substr(close + 4)));
  return info;
}

std::vector<pid_t> childrenOf(pid_t parent, const std::string& name)
{
  std::vector<pid_t> out;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string dir = entry.path().filename().string();
    if (dir.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(dir));
    const ProcessInfo info = infoOf(pid);
    if (info.parent == parent && info.name == name && info.state != 'Z') out.push_back(pid);
  }
  return out;
}

bool running(pid_t pid)
{
  const ProcessInfo info = infoOf(pid);
  return !info.name.empty() && info.state != 'Z';
}

TEST(CliImportServer, ServerAndImporterEndWhenTheProgramIsKilled)
{
  // Orphans of the killed program become this process's children, so they can be watched and reaped.
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
  const std::string step = (sourceDir() / "tests/data/real/hepa_filter_assembly.step").string();
  std::vector<std::string> args = {SPIRA_CLI, "info", step};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t cli = 0;
  ASSERT_EQ(::posix_spawn(&cli, SPIRA_CLI, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);

  // The server is the program's spira-import child; the importer reading the file is the server's.
  pid_t server = 0, importer = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (importer == 0 && std::chrono::steady_clock::now() < deadline) {
    for (pid_t s : childrenOf(cli, "spira-import"))
      for (pid_t i : childrenOf(s, "spira-import")) {
        server = s;
        importer = i;
      }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(cli, SIGKILL);
  ::waitpid(cli, nullptr, 0);
  ASSERT_GT(importer, 0) << "no importer was seen running under spira-cli's import server";

  // Reading the file takes seconds; ending the server and its importer takes milliseconds.
  const auto gone = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while ((running(server) || running(importer)) && std::chrono::steady_clock::now() < gone) {
    while (::waitpid(-1, nullptr, WNOHANG) > 0) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_FALSE(running(server)) << "the import server outlived spira-cli";
  EXPECT_FALSE(running(importer)) << "the importer outlived spira-cli";
  while (::waitpid(-1, nullptr, WNOHANG) > 0) {
  }
}

}  // namespace
}  // namespace spira::test
