// A named pipe (or any path that is not a regular file) given where Spira reads a file is refused
// before it is opened, naming it: opening a pipe with no writer would block forever.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cell_variant.h"
#include "cli_runner.h"
#include "spira/base/output_set.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

// A named pipe at `path` for the length of a test. Should the program under test open it (the bug
// this guards against), a watcher opens the writing end and closes it at once, so the reader sees an
// empty file instead of blocking the test forever.
class Fifo {
 public:
  explicit Fifo(fs::path path) : path_(std::move(path))
  {
    if (::mkfifo(path_.c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
    watcher_ = std::thread([this] {
      while (!stop_) {
        const int fd = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK);  // fails (ENXIO) while no reader
        if (fd >= 0) {
          ::close(fd);
          opened_ = true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
  }
  ~Fifo()
  {
    stop_ = true;
    watcher_.join();
  }
  const fs::path& path() const { return path_; }
  bool wasOpened() const { return opened_; }

 private:
  fs::path path_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> opened_{false};
  std::thread watcher_;
};

void expectRefused(const CliRun& r, const Fifo& fifo)
{
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("'" + fifo.path().string() + "' is not a regular file"), std::string::npos) << r.err;
  EXPECT_FALSE(fifo.wasOpened());
}

TEST(HostileFifo, PartIsRefused)
{
  TempDir dir;
  const Fifo part(dir / "part.stl");
  expectRefused(runCli({"plan", part.path().string(), "-o", (dir / "out").string()}), part);
}

TEST(HostileFifo, CellIsRefused)
{
  TempDir dir;
  const Fifo cell(dir / "robot.cell");
  expectRefused(runCli({"plan", cylinderPart(dir.path(), 30.0, 50.0).string(), "-o", (dir / "out").string(),
                        "--cell", cell.path().string()}),
                cell);
}

TEST(HostileFifo, CalibrationIsRefused)
{
  TempDir dir;
  const Fifo table(dir / "beads.csv");
  expectRefused(runCli({"plan", cylinderPart(dir.path(), 30.0, 50.0).string(), "-o", (dir / "out").string(),
                        "--calibration", table.path().string()}),
                table);
}

TEST(HostileFifo, PlanFoldersCellFileIsRefused)
{
  TempDir dir;
  const fs::path plan = dir / "plan";
  const CliRun planned = runCli(
      {"plan", cylinderPart(dir.path(), 30.0, 50.0).string(), "-o", plan.string(), "--points-per-rev", "36"});
  ASSERT_EQ(planned.exitCode, 0) << planned.err;
  const Fifo cell(dir / "robot.cell");
  std::ifstream in(plan / "report.json");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json report = nlohmann::json::parse(text.str());
  report["cell_file"] = cell.path().string();
  writeBytes(plan / "report.json", report.dump(2));
  fs::remove(plan / kOutputManifest);  // as an older Spira wrote it: the report is read as it is
  expectRefused(runCli({"export", plan.string(), "--format", "krl", "-o", (dir / "program").string()}), cell);
}

TEST(HostileFifo, UrdfNamedByACellIsRefused)
{
  TempDir dir;
  const Fifo urdf(dir / "robot.urdf");
  const fs::path cell = bundledCellVariant("kuka_kr16_2_table.cell", dir.path(), [&](nlohmann::json& c) {
    c["robot"]["urdf"] = urdf.path().string();
  });
  expectRefused(runCli({"kin", cell.string(), "--fk", "0", "-90", "90", "0", "0", "0"}), urdf);
}

}  // namespace
}  // namespace spira::test
