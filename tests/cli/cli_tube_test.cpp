// spira-cli plans the bundled bent tube with the constant-distance strategy and writes its layer figures to
// report.json; a layer taller than the tube is wide, or a guide file that is not there, is bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_runner.h"
#include "export/krl_reader.h"
#include "spira/base/units.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/robotcell/cell_file.h"
#include "spira/robotcell/robot_cell.h"
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
  // The advice names the cause: the layers fold at their kinks.
  EXPECT_NE(r.out.find("folds the layer over itself"), std::string::npos) << r.out;
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

// The columns `names` of a CSV file with a header line, per row.
std::vector<std::vector<double>> columns(const fs::path& file, const std::vector<std::string>& names)
{
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::istringstream h(line);
  for (std::string cell; std::getline(h, cell, ',');) header.push_back(cell);
  std::vector<size_t> at;
  for (const std::string& n : names)
    at.push_back(size_t(std::find(header.begin(), header.end(), n) - header.begin()));
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = csvCells(line);
    std::vector<double> row;
    for (size_t k : at) row.push_back(k < cells.size() ? std::atof(cells[k].c_str()) : NAN);
    rows.push_back(row);
  }
  return rows;
}

// The largest angle (deg) between a planned build direction, turned by the positioner's joints, and the
// vertical, and the largest tilt (deg) of the positioner.
std::pair<double, double> leanOnThePositioner(const fs::path& plan, const RobotCell& cell)
{
  const auto b = columns(plan / "trajectory.csv", {"bx", "by", "bz"});
  const auto e = columns(plan / "joints.csv", {"e1", "e2"});
  EXPECT_EQ(b.size(), e.size());
  const Transform tablePart = cell.setup().tablePart;
  double worst = 0.0, tiltMax = 0.0;
  for (size_t i = 0; i < std::min(b.size(), e.size()); ++i) {
    const TiltRotatePositioner::Axes axes(degToRad(e[i][0]), degToRad(e[i][1]));
    const Vec3 up = (cell.positioner()->forward(axes) * tablePart).linear() * Vec3(b[i][0], b[i][1], b[i][2]);
    worst = std::max(worst, radToDeg(std::acos(std::clamp(up.normalized().z(), -1.0, 1.0))));
    tiltMax = std::max(tiltMax, std::abs(e[i][0]));
  }
  return {worst, tiltMax};
}

// The plan of a gentle bend (R 200, r 15, 0.3 rad) written into `dir`, at 2 mm in 1.8 .. 2.2 mm on `cell`,
// into dir / out, written for `exporter`.
std::vector<std::string> bendOnCell(const TempDir& dir, const fs::path& cell, const std::string& out,
                                    const std::string& exporter)
{
  writeMesh(makeBentTube(200.0, 15.0, 0.3, 47, 30), dir / "bend.stl");
  std::vector<std::string> args = tubePlan(dir / "bend.stl", dir / out);
  args[7] = "2", args[9] = "1.8", args[11] = "2.2";
  args.insert(args.end(), {"--cell", cell.string(), "--export", exporter});
  return args;
}

// A bend on the bundled positioner cell: the positioner tilts the part so that every bead is laid with
// the build direction within its tolerance of the vertical, the joints are solved and the FANUC program
// written.
TEST(CliTube, ABendOnThePositionerCellIsBuiltUpright)
{
  TempDir dir;
  const fs::path cellFile = sourceDir() / "resources/cells/fanuc_m20ia_positioner.cell";
  const RobotCell cell(readCellFile(cellFile));
  ASSERT_NE(cell.positioner(), nullptr);
  std::vector<std::string> args = bendOnCell(dir, cellFile, "cell", "fanuc_tp");
  const CliRun r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  EXPECT_TRUE(fs::exists(dir / "cell" / "SPIRA_PART.ls"));
  const auto [lean, tilt] = leanOnThePositioner(dir / "cell", cell);
  EXPECT_LE(lean, 2.0 + 1e-6);  // the default positioner tolerance
  EXPECT_GT(tilt, 10.0);        // the 17-degree bend is followed by the tilt axis

  // Within 1 degree the table's rotation has to follow the spiral's climb (1.2 deg per turn here): the
  // beads are as level as asked, and the rotation passes its speed limit at a few points.
  args[3] = (dir / "level").string();
  args.insert(args.end(), {"--positioner-tolerance", "1"});
  const CliRun level = runCli(args);
  EXPECT_EQ(level.exitCode, 4) << level.err << level.out;
  EXPECT_NE(level.out.find("E2"), std::string::npos) << level.out;
  EXPECT_LE(leanOnThePositioner(dir / "level", cell).first, 1.0 + 1e-6);
  // A slower process (2 mm/s) leaves the rotation time to follow: the TP program is written.
  args[3] = (dir / "slow").string();
  args.insert(args.end(), {"--wfs", "1.6"});
  const CliRun slow = runCli(args);
  ASSERT_EQ(slow.exitCode, 0) << slow.err << slow.out;
  EXPECT_TRUE(fs::exists(dir / "slow" / "SPIRA_PART.ls"));
  EXPECT_LE(leanOnThePositioner(dir / "slow", cell).first, 1.0 + 1e-6);
  std::printf("bend on the positioner: build direction within %.3f deg of vertical, tilt up to %.1f deg\n",
              lean, tilt);
}

// The same bend on a KUKA cell with the positioner, the torch leant by the source's tilt law (10 deg
// lead, 5 deg side): the positioner keeps the build direction, not the torch, within 1 deg of the
// vertical, and the KRL program, read back, holds the torch at the tilt law's angle off the vertical.
TEST(CliTube, ABendOnAKukaPositionerIsExportedWithTheTorchLeaning)
{
  TempDir dir;
  const fs::path cellFile = sourceDir() / "resources/cells/kuka_kr16_2_positioner.cell";
  const RobotCell cell(readCellFile(cellFile));
  ASSERT_NE(cell.positioner(), nullptr);
  std::vector<std::string> args = bendOnCell(dir, cellFile, "krl", "krl");
  // A slower process (2 mm/s) keeps the table's rotation within its speed at 1 deg.
  args.insert(args.end(),
              {"--positioner-tolerance", "1", "--wfs", "1.6", "--torch-lead", "10", "--torch-side", "5"});
  const CliRun r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;

  // Up: the build direction the positioner holds; b: the torch axis.
  const auto up = columns(dir / "krl" / "trajectory.csv", {"ux", "uy", "uz", "bx", "by", "bz", "path"});
  const auto e = columns(dir / "krl" / "joints.csv", {"e1", "e2"});
  ASSERT_EQ(up.size(), e.size());
  const double lean = std::atan(std::hypot(std::tan(degToRad(10.0)), std::tan(degToRad(5.0))));
  double worstUp = 0.0, worstLean = 0.0;
  for (size_t i = 0; i < up.size(); ++i) {
    const Mat3 turn =
        (cell.positioner()->forward({degToRad(e[i][0]), degToRad(e[i][1])}) * cell.setup().tablePart)
            .linear();
    const Vec3 u = turn * Vec3(up[i][0], up[i][1], up[i][2]).normalized();
    const Vec3 b = turn * Vec3(up[i][3], up[i][4], up[i][5]).normalized();
    worstUp = std::max(worstUp, radToDeg(std::acos(std::clamp(u.z(), -1.0, 1.0))));
    worstLean = std::max(worstLean, std::abs(std::acos(std::clamp(u.dot(b), -1.0, 1.0)) - lean));
  }
  EXPECT_LE(worstUp, 1.0 + 1e-6);
  EXPECT_LT(radToDeg(worstLean), 1e-6);

  // The program as a controller runs it: every LIN target carries both external axes, and the torch,
  // the tool's z axis in the robot's base frame, leans off the vertical by the tilt law's angle give
  // or take the positioner's tolerance, except on the travel moves between sub-paths.
  const KrlRun run = runKrl(dir / "krl", "spira_part");
  EXPECT_TRUE(run.problems.empty()) << run.problems.front();
  size_t lin = 0, atLean = 0;
  for (const KrlMove& m : run.moves) {
    if (m.motion != "LIN") continue;
    ++lin;
    EXPECT_TRUE(m.pose.e1.has_value() && m.pose.e2.has_value()) << m.target;
    const Vec3 torch = krlPose(m.pose).linear().col(2);
    const double off = radToDeg(std::acos(std::clamp(-torch.z(), -1.0, 1.0)));
    // The targets are interpolated between planned points: a few hundredths of a degree more.
    if (std::abs(off - radToDeg(lean)) <= 1.05) ++atLean;
  }
  EXPECT_GT(lin, 1000u);
  // Not so: the travel between sub-paths, at most 4 targets each (travelBetween), the torch upright there.
  const size_t subPaths = size_t(up.back()[6]) + 1;
  EXPECT_LE(lin - atLean, 4 * (subPaths - 1)) << subPaths << " sub-paths";
  std::printf(
      "KUKA positioner, torch at %.3f deg: %zu of %zu LIN targets within 1 deg of it, beads within %.3f "
      "deg of vertical\n",
      radToDeg(lean), atLean, lin, worstUp);
}

// The arm is checked against a substrate mesh as well as the part: a plate with a wall standing between
// the robot and the part (in one mesh) makes the arm's links collide; the plate alone does not.
TEST(CliTube, TheArmIsCheckedAgainstASubstrateMesh)
{
  TempDir dir;
  ASSERT_EQ(runCli({"sample", "open-cylinder", "-o", (dir / "cylinder.stl").string()}).exitCode, 0);
  const auto quad = [](TriangleMesh& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const int o = int(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {a, b, c, d});
    m.faces.push_back({o, o + 1, o + 2});
    m.faces.push_back({o, o + 2, o + 3});
  };
  TriangleMesh plate;
  quad(plate, Vec3(-150, -150, 0), Vec3(150, -150, 0), Vec3(150, 150, 0), Vec3(-150, 150, 0));
  writeMesh(plate, dir / "plate.stl");
  TriangleMesh walled = plate;
  // The KUKA table cell stands the part 1100 mm in front of the robot: the wall is half way.
  quad(walled, Vec3(-550, -700, -400), Vec3(-550, 700, -400), Vec3(-550, 700, 900), Vec3(-550, -700, 900));
  writeMesh(walled, dir / "walled.stl");
  const std::string cell = (sourceDir() / "resources/cells/kuka_kr16_2_table.cell").string();
  const auto robotCollisions = [&](const std::string& substrate, const std::string& out) {
    const CliRun r = runCli({"plan", (dir / "cylinder.stl").string(), "--substrate",
                             (dir / substrate).string(), "--cell", cell, "-o", (dir / out).string()});
    std::ifstream in(dir / out / "report.json");
    EXPECT_TRUE(in.good()) << r.err << r.out;
    return nlohmann::json::parse(in)["robot_collisions"].get<long long>();
  };
  EXPECT_EQ(robotCollisions("plate.stl", "plate"), 0);
  EXPECT_GT(robotCollisions("walled.stl", "walled"), 0);
}

}  // namespace
}  // namespace spira::test
