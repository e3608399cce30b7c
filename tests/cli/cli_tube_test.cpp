// spira-cli plans the bundled bent tube with the constant-distance strategy and writes its layer figures to
// report.json; a layer taller than the tube is wide, or a guide file that is not there, is bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

constexpr int kBadInput = 3;

fs::path bentTube(const TempDir& dir)
{
  const fs::path part = dir / "bent.stl";
  const CliRun made = runCli({"sample", "bent-tube", "-o", part.string()});
  EXPECT_EQ(made.exitCode, 0) << made.err;
  return part;
}

std::vector<std::string> tubePlan(const fs::path& part, const fs::path& out)
{
  return {"plan", part.string(), "-o",      out.string(), "--strategy", "constant_distance",
          "--h",  "5",           "--h-min", "4.5",        "--h-max",    "5.5"};
}

// The source's quarter torus: 16 layers at 5 mm, whose kinks fold the top layers over themselves (a
// handful of beads under the same layer's); the plan is written and called infeasible there.
TEST(CliTube, TheBentTubeIsPlannedInLayersAtTheDepositHeight)
{
  TempDir dir;
  const fs::path part = bentTube(dir);
  std::vector<std::string> args = tubePlan(part, dir / "layers");
  args.insert(args.end(), {"--output", "layers", "--stagger", "golden"});
  const CliRun r = runCli(args);
  ASSERT_EQ(r.exitCode, 4) << r.err << r.out;
  EXPECT_NE(r.out.find("under material already laid"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("16 layers at 5.000 .. 5.000 mm from the layer below"), std::string::npos) << r.out;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir / "layers" / "report.json"));
  EXPECT_EQ(report.at("strategy"), "constant_distance");
  EXPECT_EQ(report.at("n_layers"), 16);
  EXPECT_NEAR(report.at("delta_min").get<double>(), 5.0, 1e-3);
  EXPECT_NEAR(report.at("delta_max").get<double>(), 5.0, 1e-3);
  EXPECT_GT(report.at("max_kink_deg").get<double>(), 100.0);
  EXPECT_EQ(report.at("layer_kinks_deg").size(), 16u);
  EXPECT_GE(report.at("n_arc_starts").get<int>(), 16);
  EXPECT_EQ(report.at("layer_output"), "layers");
  EXPECT_EQ(report.at("part_end"), "truncate");
  EXPECT_FALSE(report.at("feasible").get<bool>());
  const nlohmann::json& counts = report.at("deposit_check").at("counts");
  EXPECT_GT(counts.at("below_deposit").get<int>(), 0);
  EXPECT_EQ(counts.at("thin").get<int>() + counts.at("thick").get<int>() +
                counts.at("unsupported").get<int>() + counts.at("jump").get<int>(),
            0);
}

// An elbow of bend radius 100 mm (6.7 tube radii) folds no layer: one spiral, feasible.
TEST(CliTube, OneSpiralThroughTheLayersIsTheDefaultPath)
{
  TempDir dir;
  const double pi = 3.14159265358979323846;
  writeMesh(makeBentTube(100.0, 15.0, 0.5 * pi, 47, 78), dir / "elbow.stl");
  std::vector<std::string> args = tubePlan(dir / "elbow.stl", dir / "spiral");
  args[7] = "2", args[9] = "1.8", args[11] = "2.2";
  const CliRun r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir / "spiral" / "report.json"));
  EXPECT_EQ(report.at("layer_output"), "spiral");
  EXPECT_TRUE(report.at("feasible").get<bool>());
  EXPECT_GE(report.at("height_min").get<double>(), 1.8);
  EXPECT_LE(report.at("height_max").get<double>(), 2.2);
  // The end face cuts the last revolutions: fewer arcs than a layer-by-layer path has.
  EXPECT_GE(report.at("n_arc_starts").get<int>(), 1);
  EXPECT_LT(report.at("n_arc_starts").get<int>(), report.at("n_layers").get<int>());
}

TEST(CliTube, BadTubeInputIsRefusedWithExitCode3AndNothingWritten)
{
  TempDir dir;
  const fs::path part = bentTube(dir);
  std::vector<std::string> tall = tubePlan(part, dir / "tall");
  tall[7] = "16", tall[9] = "15", tall[11] = "17";
  CliRun r = runCli(tall);
  EXPECT_EQ(r.exitCode, kBadInput) << r.err;
  EXPECT_NE(r.err.find("not smaller than the tube's radius"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "tall" / "trajectory.csv"));

  std::vector<std::string> missing = tubePlan(part, dir / "missing");
  missing.insert(missing.end(), {"--guide", (dir / "nowhere.csv").string()});
  r = runCli(missing);
  EXPECT_EQ(r.exitCode, kBadInput) << r.err;
  EXPECT_NE(r.err.find("nowhere.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "missing" / "trajectory.csv"));

  r = runCli({"plan", part.string(), "-o", (dir / "bad").string(), "--strategy", "constant_distance", "--end",
              "sideways"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("truncate"), std::string::npos) << r.err;
}

// The source's torus feature on a 64 mm pipe: planned on the pipe, its first beads measured down to it.
TEST(CliTube, AFeatureIsPlannedOnAPipe)
{
  TempDir dir;
  const fs::path part = dir / "feature.stl";
  ASSERT_EQ(runCli({"sample", "torus-on-pipe", "-o", part.string()}).exitCode, 0);
  std::vector<std::string> args = tubePlan(part, dir / "pipe");
  args[7] = "2", args[9] = "1.8", args[11] = "2.2";
  args.insert(args.end(), {"--substrate", "cylinder:32,y"});
  const CliRun r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir / "pipe" / "report.json"));
  EXPECT_EQ(report.at("substrate").at("kind"), "mesh");
  EXPECT_TRUE(report.at("feasible").get<bool>());
  EXPECT_GE(report.at("deposit_check").at("height_min").get<double>(), 1.8 - 0.01);

  // On the plate instead, its base edge lies 22 to 31 mm up and is not level.
  const CliRun plate = runCli(tubePlan(part, dir / "plate"));
  EXPECT_EQ(plate.exitCode, kBadInput) << plate.err;

  // A pipe it does not touch, or a malformed one, is refused, nothing written.
  args = tubePlan(part, dir / "thin");
  args.insert(args.end(), {"--substrate", "cylinder:30,y"});
  const CliRun off = runCli(args);
  EXPECT_EQ(off.exitCode, kBadInput) << off.err;
  EXPECT_NE(off.err.find("does not stand on the substrate mesh"), std::string::npos) << off.err;
  EXPECT_FALSE(fs::exists(dir / "thin" / "trajectory.csv"));
  args.back() = "cylinder:32,w";
  EXPECT_EQ(runCli(args).exitCode, 2);
  args.back() = (dir / "missing.stl").string();
  EXPECT_EQ(runCli(args).exitCode, kBadInput);
}

}  // namespace
}  // namespace spira::test
