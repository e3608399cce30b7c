// The warm import server (spira/io/import_process.h): imports are forked from one server that
// outlives a crashing import and a cancelled one, a killed server is replaced, and imports from
// several threads at once all finish.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <thread>
#include <vector>

#include "io_test_util.h"
#include "spira/io/import_process.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

// A 10 x 20 x 30 box, 12 triangles, with one harmless unresolved reference.
fs::path box()
{
  return sourceDir() / "tests/data/hostile/step/unresolved_point.step";
}

bool isZombieOrGone(pid_t pid)
{
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return true;
  const size_t close = text.rfind(')');
  return close == std::string::npos || text.substr(close + 2, 1) == "Z";
}

TEST(ImportServer, SuccessiveImportsShareOneServerThatOutlivesACrash)
{
  EXPECT_EQ(importFile(box()).mesh.faces.size(), 12u);
  const pid_t server = import_process::serverPid();
  ASSERT_GT(server, 0);
  EXPECT_TRUE(throwsOneLine<InputError>(
      [] { importFile(sourceDir() / "tests/data/hostile/step/wrong_type_crash.step"); },
      "the STEP reader crashed on 'wrong_type_crash.step' (signal 11"));
  EXPECT_EQ(import_process::serverPid(), server);
  EXPECT_EQ(importFile(box()).mesh.faces.size(), 12u);
  EXPECT_EQ(import_process::serverPid(), server);
}

TEST(ImportServer, CancelledImportLeavesTheServerReady)
{
  EXPECT_EQ(importFile(box()).mesh.faces.size(), 12u);
  const pid_t server = import_process::serverPid();
  CallbackProgress* self = nullptr;
  CallbackProgress progress([&](double, std::string_view) { self->cancel(); });
  self = &progress;
  EXPECT_THROW(
      importPart(ioRegistry(), sourceDir() / "tests/data/real/hepa_filter_assembly.step", nullptr, progress),
      Cancelled);
  EXPECT_EQ(import_process::serverPid(), server);
  EXPECT_EQ(importFile(box()).mesh.faces.size(), 12u);
}

TEST(ImportServer, KilledServerIsReplaced)
{
  EXPECT_EQ(importFile(box()).mesh.faces.size(), 12u);
  const pid_t old = import_process::serverPid();
  ASSERT_GT(old, 0);
  ASSERT_EQ(::kill(old, SIGKILL), 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!isZombieOrGone(old) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(isZombieOrGone(old));
  EXPECT_EQ(importFile(box()).mesh.faces.size(), 12u);
  const pid_t replacement = import_process::serverPid();
  EXPECT_GT(replacement, 0);
  EXPECT_NE(replacement, old);
}

TEST(ImportServer, ImportsFromSeveralThreadsAtOnceAllFinish)
{
  // One thread holds the server; the others get helpers of their own.
  std::vector<size_t> faces(4, 0);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < faces.size(); ++i)
    threads.emplace_back([&faces, i] { faces[i] = importFile(box()).mesh.faces.size(); });
  for (std::thread& t : threads) t.join();
  for (size_t f : faces) EXPECT_EQ(f, 12u);
}

}  // namespace
}  // namespace spira::test
