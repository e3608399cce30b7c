// Whole-file writes: the new content or the old one, never a part, and nothing left beside it.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

size_t entriesIn(const std::filesystem::path& dir)
{
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, ReplacesTheWholeFileAndLeavesNoTemporarySibling)
{
  TempDir dir;
  const auto file = dir / "report.json";
  writeBytes(file, std::string(100000, 'o'));
  const std::string next = "{\"short\": true}\n";
  writeFileAtomically(file, next);
  EXPECT_EQ(readBytes(file), next);
  EXPECT_EQ(entriesIn(dir.path()), 1u);
}

TEST(AtomicFile, AMissingFolderIsRefusedByName)
{
  TempDir dir;
  try {
    writeFileAtomically(dir / "absent" / "plan.csv", "x");
    FAIL() << "no IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("absent"), std::string::npos) << e.what();
  }
  EXPECT_EQ(entriesIn(dir.path()), 0u);
}

// More than a pipe holds at once (64 KiB on Linux): writeAll keeps writing while the other end reads.
TEST(AtomicFile, WriteAllDeliversEveryByteThroughAPipe)
{
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  std::string bytes(1 << 20, '\0');
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7919 % 251);
  std::string received;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(fds[0]);
    ::_exit(writeAll(fds[1], bytes).empty() ? 0 : 1);
  }
  ::close(fds[1]);
  char buf[8192];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) received.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(received, bytes);
}

TEST(AtomicFile, WriteAllReportsAClosedDescriptor)
{
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ::close(fds[1]);
  EXPECT_FALSE(writeAll(fds[1], "x").empty());
  ::close(fds[0]);
}

}  // namespace
}  // namespace spira::test
