// spira-cli thermal on a planned open cylinder: the heat put in is the arc power times the arc-on
// time read from the plan itself, in = stored + lost, one row per planned point, twice the power
// gives twice the rise (the model is linear), a probe stays at ambient until the deposit reaches it;
// bad input exits 3 with nothing written, and the time step the message proposes works.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "spira/path/dwell.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

class CliThermal : public ::testing::Test {
 protected:
  static void SetUpTestSuite()
  {
    dir_ = new TempDir;
    const CliRun r = runCli({"plan", (sourceDir() / "resources/samples/open_cylinder.stl").string(), "-o",
                             (*dir_ / "plan").string(), "--points-per-rev", "90"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  static void TearDownTestSuite()
  {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path plan() { return *dir_ / "plan"; }
  static nlohmann::json thermal(const fs::path& out)
  {
    return nlohmann::json::parse(readBytes(out / "thermal.json"));
  }
  TempDir tmp_;
  static TempDir* dir_;
};
TempDir* CliThermal::dir_ = nullptr;

// The arc-on time of the plan, from its own channels: each arc-on segment at its first point's speed.
double arcOnSeconds(const Trajectory& t)
{
  double s = 0.0;
  for (size_t i = 0; i + 1 < t.size(); ++i)
    if (t.points[i].arcOn && t.points[i + 1].arcOn)
      s += (t.points[i + 1].position - t.points[i].position).norm() / t.points[i].travelSpeed;
  return s;
}

std::vector<std::vector<double>> readCsv(const fs::path& file, std::string* header)
{
  std::ifstream in(file);
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell;
    rows.emplace_back();
    while (std::getline(s, cell, ',')) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

TEST_F(CliThermal, EnergyPointsProbesAndLinearity)
{
  const fs::path out = tmp_ / "thermal";
  const CliRun r =
      runCli({"thermal", plan().string(), "-o", out.string(), "--probe", "50,0,2", "--probe", "50,0,55"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = thermal(out);
  const Trajectory path = readTrajectoryCsv(plan() / "trajectory.csv");
  const double in = j.at("energy_in_J").get<double>();
  EXPECT_NEAR(in, 1000.0 * arcOnSeconds(path), 1e-6 * in);  // 1000 W, the default
  EXPECT_NEAR(j.at("energy_stored_J").get<double>() + j.at("energy_lost_J").get<double>(), in, 0.01 * in);
  EXPECT_EQ(j.at("substrate_z_mm"), 0.0);  // the sample stands on z = 0
  std::string header;
  const auto points = readCsv(out / "thermal_points.csv", &header);
  EXPECT_EQ(header, "index,peak_C,interpass_C,time_above_melt_s,bond,risk,below_at_arrival_C,pool_mm");
  ASSERT_EQ(points.size(), path.size());
  // Eq. 5.31 with G3Si1's liquid density 7200 kg/m3 and surface tension 1.6 N/m, g = 9.81: Bo / L^2
  // lies between the vertical wall's weight 1 and the horizontal surface's e^(pi/4), per mm^2.
  const double perSquareMm = 7200.0 * 9.81 / 1.6 * 1e-6;
  int risky = 0;
  for (const auto& row : points) {
    EXPECT_GT(row[1], 1500.0) << "point " << row[0] << " never melted";
    const double pool = row[7], bond = row[4];
    // The arc strikes on the first point: nothing has melted yet.
    if (row[0] > 0) {
      EXPECT_GT(pool, 0.0) << "point " << row[0];
    }
    EXPECT_GE(bond, perSquareMm * pool * pool * (1.0 - 1e-9)) << "point " << row[0];
    EXPECT_LE(bond, perSquareMm * pool * pool * std::exp(M_PI / 4.0) * (1.0 + 1e-9)) << "point " << row[0];
    const bool liquidBelow = row[2] > 1450.0 && path.points[size_t(row[0])].revolution > 0;  // solidus
    EXPECT_EQ(row[5], (bond > j.at("bond_threshold").get<double>() || liquidBelow) ? 1.0 : 0.0)
        << "point " << row[0];
    risky += int(row[5]);
  }
  EXPECT_EQ(j.at("n_risk_points"), risky);
  const auto probes = readCsv(out / "probes.csv", &header);
  ASSERT_TRUE(std::regex_match(header, std::regex(R"(t,node_\d+_C,node_\d+_C)"))) << header;
  ASSERT_GT(probes.size(), 10u);
  // The probe at the top stays at ambient until the torch comes near, long after the start.
  EXPECT_DOUBLE_EQ(probes[probes.size() / 2][2], 20.0);
  double topPeak = 0.0;
  for (const auto& row : probes) topPeak = std::max(topPeak, row[2]);
  EXPECT_GT(topPeak, 1500.0);

  // A synergic line's energy per mm of wire: the plan feeds a constant 2.3 m/min, so 1000 W is
  // 1000 / (2300 / 60) J/mm, and the energy in is the same.
  const fs::path perWire = tmp_ / "per_wire";
  ASSERT_EQ(runCli({"thermal", plan().string(), "-o", perWire.string(), "--energy-per-wire",
                    std::to_string(1000.0 / (2300.0 / 60.0))})
                .exitCode,
            0);
  EXPECT_NEAR(thermal(perWire).at("energy_in_J").get<double>(), in, 1e-5 * in);

  // A calibration table flat at 1000 W is the default's power; a row out of order is refused by line.
  writeBytes(tmp_ / "flat.csv", "wfs_m_min,power_W\n1.0,1000\n12.0,1000\n");
  const fs::path tabled = tmp_ / "tabled";
  ASSERT_EQ(runCli({"thermal", plan().string(), "-o", tabled.string(), "--power-table",
                    (tmp_ / "flat.csv").string()})
                .exitCode,
            0);
  EXPECT_NEAR(thermal(tabled).at("energy_in_J").get<double>(), in, 1e-9 * in);
  writeBytes(tmp_ / "unsorted.csv", "wfs_m_min,power_W\n3.0,1200\n2.0,900\n");
  CliRun bad = runCli(
      {"thermal", plan().string(), "-o", tabled.string(), "--power-table", (tmp_ / "unsorted.csv").string()});
  EXPECT_EQ(bad.exitCode, 3) << bad.err;
  EXPECT_NE(bad.err.find("row 2 of the power table does not feed more wire than row 1"), std::string::npos)
      << bad.err;
  writeBytes(tmp_ / "text.csv", "wfs_m_min,power_W\n2.3,lots\n");
  bad = runCli(
      {"thermal", plan().string(), "-o", tabled.string(), "--power-table", (tmp_ / "text.csv").string()});
  EXPECT_EQ(bad.exitCode, 3) << bad.err;
  EXPECT_NE(bad.err.find("line 2 of"), std::string::npos) << bad.err;

  // Radiation only takes heat away.
  const fs::path radiating = tmp_ / "radiating";
  ASSERT_EQ(runCli({"thermal", plan().string(), "-o", radiating.string(), "--emissivity", "0.8"}).exitCode,
            0);
  EXPECT_LT(thermal(radiating).at("max_peak_C").get<double>(), j.at("max_peak_C").get<double>() - 100.0);
  EXPECT_EQ(thermal(radiating).at("material").at("emissivity"), 0.8);

  const fs::path twice = tmp_ / "twice";
  ASSERT_EQ(runCli({"thermal", plan().string(), "-o", twice.string(), "--power", "2000"}).exitCode, 0);
  const double rise = j.at("max_peak_C").get<double>() - 20.0;
  EXPECT_NEAR(thermal(twice).at("max_peak_C").get<double>() - 20.0, 2.0 * rise, 1e-6 * rise);
}

// A saved project is simulated on the path its robot was solved for, with its bead width.
TEST_F(CliThermal, PlannedProject)
{
  const fs::path out = tmp_ / "project";
  const CliRun r =
      runCli({"thermal", (sourceDir() / "tests/data/projects/open_cylinder_227a109.spira").string(), "-o",
              out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::string header;
  EXPECT_EQ(readCsv(out / "thermal_points.csv", &header).size(), 720u);
  EXPECT_EQ(thermal(out).at("shell_thickness_mm"), 5.2);
  EXPECT_NEAR(thermal(out).at("substrate_z_mm").get<double>(), 0.0, 1e-6);
}

TEST_F(CliThermal, BadInputExitsThreeWithNothingWritten)
{
  const fs::path out = tmp_ / "bad";
  CliRun r = runCli({"thermal", plan().string(), "-o", out.string(), "--material", "Inconel"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("unknown material 'Inconel' (use one of: G3Si1, 316L, Ti-6Al-4V, AlMg5)"),
            std::string::npos)
      << r.err;
  r = runCli({"thermal", plan().string(), "-o", out.string(), "--power", "0"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  r = runCli({"thermal", plan().string(), "-o", out.string(), "--voltage", "18"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  r = runCli({"thermal", plan().string(), "-o", out.string(), "--energy-per-wire", "30", "--power", "900"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  r = runCli({"thermal", plan().string(), "-o", out.string(), "--energy-per-wire", "-1"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  r = runCli({"thermal", plan().string(), "-o", out.string(), "--emissivity", "1.5"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("emissivity must be in [0, 1]"), std::string::npos) << r.err;
  r = runCli({"thermal", plan().string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  // A step the torch outruns: refused, with the longest that resolves it, which then works.
  r = runCli({"thermal", plan().string(), "-o", out.string(), "--dt", "5"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(use at most ([0-9.]+) s)"))) << r.err;
  EXPECT_FALSE(fs::exists(out / "thermal.json"));
  r = runCli({"thermal", plan().string(), "-o", out.string(), "--dt", m[1].str()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "thermal.json"));
}

// Re-planned to a limit the plain plan exceeds, the path written is the plan's with slower
// speeds, and simulated again on its own (a plain run on the written folder) it meets the limit.
TEST_F(CliThermal, ReplansToAnInterpassLimit)
{
  const fs::path plain = tmp_ / "plain", out = tmp_ / "replanned";
  ASSERT_EQ(runCli({"thermal", plan().string(), "-o", plain.string(), "--frames", "0"}).exitCode, 0);
  const double hottest = thermal(plain).at("max_interpass_C").get<double>();
  const double limit = 20.0 + 0.8 * (hottest - 20.0);
  const std::string limitText = std::to_string(limit);
  CliRun r = runCli({"thermal", plan().string(), "-o", out.string(), "--interpass-max", limitText, "--remedy",
                     "heat", "--frames", "3"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = thermal(out);
  EXPECT_EQ(j.at("replan").at("limit_met"), true);
  EXPECT_EQ(j.at("replan").at("revolutions_added"), 0);
  EXPECT_GT(j.at("replan").at("build_time_added_s").get<double>(), 0.0);
  EXPECT_LE(j.at("max_interpass_C").get<double>(), limit);
  const Trajectory before = readTrajectoryCsv(plan() / "trajectory.csv");
  const Trajectory after = readTrajectoryCsv(out / "trajectory.csv");
  ASSERT_EQ(after.size(), before.size());
  for (size_t i = 0; i < after.size(); ++i) {
    EXPECT_EQ(after.points[i].position, before.points[i].position);
    EXPECT_LE(after.points[i].travelSpeed, before.points[i].travelSpeed);
  }
  const nlohmann::json report = nlohmann::json::parse(readBytes(out / "report.json"));
  EXPECT_NEAR(report.at("build_time_s").get<double>(),
              nlohmann::json::parse(readBytes(plan() / "report.json")).at("build_time_s").get<double>() +
                  j.at("replan").at("build_time_added_s").get<double>(),
              1e-6);
  EXPECT_EQ(report.at("thermal_replan").at("limit_met"), true);
  EXPECT_TRUE(fs::exists(out / "thermal.pvd"));
  EXPECT_TRUE(fs::exists(out / "thermal_0003.vtu"));

  // The plain run on the re-planned folder replaces only the thermal files.
  r = runCli(
      {"thermal", out.string(), "-o", out.string(), "--frames", "0", "--power", std::to_string(1000.0)});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "trajectory.csv"));
  EXPECT_FALSE(fs::exists(out / "thermal_0000.vtu"));
  // A fixed power over the slowed revolutions puts more heat in than the wire-fed one: the
  // re-planned path is judged at the power the re-planning assumed, the power per unit wire.
  EXPECT_GT(thermal(out).at("max_interpass_C").get<double>(), 0.0);

  // A limit nothing can reach: exit 4, the best path still written, with why.
  const fs::path hopeless = tmp_ / "hopeless";
  r = runCli({"thermal", plan().string(), "-o", hopeless.string(), "--interpass-max", "25", "--frames", "0"});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("the interpass limit cannot be met"), std::string::npos) << r.err;
  EXPECT_EQ(thermal(hopeless).at("replan").at("limit_met"), false);
  EXPECT_TRUE(fs::exists(hopeless / "trajectory.csv"));

  EXPECT_EQ(runCli({"thermal", plan().string(), "-o", hopeless.string(), "--remedy", "heat"}).exitCode, 2);
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--remedy", "cool"},
                                              {"--remedy", "heat,heat"},
                                              {"--remedy", ","},
                                              {"--remedy", "heat", "--max-dwell", "60"},
                                              {"--remedy", "dwell", "--max-dwell", "0"}}) {
    std::vector<std::string> args{"thermal",         plan().string(),   "-o",
                                  hopeless.string(), "--interpass-max", "300"};
    args.insert(args.end(), bad.begin(), bad.end());
    r = runCli(args);
    EXPECT_EQ(r.exitCode, bad.back() == "0" ? 3 : 2) << bad[1] << ": " << r.err;
    EXPECT_NE(r.err.find(bad.size() == 2 ? "--remedy " : "--max-dwell "), std::string::npos) << r.err;
  }
}

// Re-planned with dwells: the plan folder written carries them in trajectory.csv's dwell_s column
// and report.json, simulated again on its own it meets the limit, and the robot program exported
// from it stops the arc, waits and strikes again once per dwell.
TEST_F(CliThermal, DwellsReachTheRobotProgram)
{
  const fs::path plain = tmp_ / "plain", out = tmp_ / "dwelled";
  ASSERT_EQ(runCli({"thermal", plan().string(), "-o", plain.string(), "--frames", "0"}).exitCode, 0);
  const double limit = 20.0 + 0.8 * (thermal(plain).at("max_interpass_C").get<double>() - 20.0);
  CliRun r = runCli({"thermal", plan().string(), "-o", out.string(), "--interpass-max", std::to_string(limit),
                     "--remedy", "dwell", "--max-dwell", "300", "--frames", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = thermal(out).at("replan");
  EXPECT_EQ(j.at("limit_met"), true);
  EXPECT_EQ(j.at("applied"), nlohmann::json::array({"dwell"}));
  const long long dwells = j.at("dwells").get<long long>();
  ASSERT_GT(dwells, 0);
  EXPECT_EQ(j.at("arc_starts_added"), dwells);
  EXPECT_NE(r.out.find(std::to_string(dwells) + " dwell(s)"), std::string::npos) << r.out;

  const Trajectory written = readTrajectoryCsv(out / "trajectory.csv");
  const DwellTotals totals = dwellTotals(written);
  EXPECT_EQ(totals.count, dwells);
  EXPECT_NEAR(totals.seconds, j.at("dwell_time_s").get<double>(), 1e-6 * totals.seconds);
  const nlohmann::json report = nlohmann::json::parse(readBytes(out / "report.json"));
  EXPECT_EQ(report.at("n_dwells"), dwells);
  EXPECT_NEAR(report.at("build_time_s").get<double>(),
              nlohmann::json::parse(readBytes(plan() / "report.json")).at("build_time_s").get<double>() +
                  totals.seconds,
              1e-3);

  // Simulated again from the folder alone, at the power per unit wire the re-planning used.
  const fs::path again = tmp_ / "again";
  r = runCli({"thermal", out.string(), "-o", again.string(), "--frames", "0", "--interpass-max",
              std::to_string(limit), "--remedy", "dwell"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(thermal(again).at("replan").at("re_simulations"), 0);

  const fs::path krl = tmp_ / "krl";
  r = runCli({"export", out.string(), "--format", "krl", "-o", krl.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  std::string src;
  for (const auto& f : fs::directory_iterator(krl))
    if (f.path().extension() == ".src") src += readBytes(f.path());
  size_t waits = 0;
  for (size_t at = src.find("WAIT SEC"); at != std::string::npos; at = src.find("WAIT SEC", at + 1)) ++waits;
  EXPECT_EQ(waits, size_t(dwells));
}

// The bundled dome overheats near its closure. Planned from the part and re-planned to 600 C, the
// path written meets the limit when simulated again on its own, from the folder alone.
TEST_F(CliThermal, BundledDomeReplannedMeetsTheLimitWhenSimulatedAgain)
{
  const fs::path out = tmp_ / "dome", again = tmp_ / "dome_again";
  const std::string part = (sourceDir() / "resources/samples/dome.stl").string();
  CliRun r = runCli({"thermal", part, "-o", out.string(), "--interpass-max", "600", "--frames", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = thermal(out).at("replan");
  EXPECT_GT(j.at("planned_max_interpass_C").get<double>(), 800.0);
  EXPECT_EQ(j.at("limit_met"), true);
  EXPECT_GE(j.at("re_simulations").get<int>(), 1);
  EXPECT_LE(j.at("final_max_interpass_C").get<double>(), 600.0);
  r = runCli({"thermal", out.string(), "-o", again.string(), "--interpass-max", "600", "--frames", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(thermal(again).at("replan").at("re_simulations"), 0);
  EXPECT_LE(thermal(again).at("max_interpass_C").get<double>(), 600.0);
  std::printf("bundled dome: interpass %.0f C planned, %.0f C re-planned, %.0f C simulated again\n",
              j.at("planned_max_interpass_C").get<double>(), j.at("final_max_interpass_C").get<double>(),
              thermal(again).at("max_interpass_C").get<double>());
}

// A part file is planned as 'plan' plans it (same flags, same path) and simulated; the plan is
// written with its thermal history.
TEST_F(CliThermal, PlansAPartFileFirst)
{
  const fs::path out = tmp_ / "part";
  const std::string part = (sourceDir() / "resources/samples/open_cylinder.stl").string();
  CliRun r = runCli({"thermal", part, "--points-per-rev", "90", "-o", out.string(), "--frames", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("planned open_cylinder.stl: 4500 points, feasible"), std::string::npos) << r.out;
  EXPECT_EQ(readBytes(out / "trajectory.csv"), readBytes(plan() / "trajectory.csv"));
  EXPECT_EQ(nlohmann::json::parse(readBytes(out / "report.json")).at("n_points"), 4500);
  const fs::path fromPlan = tmp_ / "from_plan";
  ASSERT_EQ(runCli({"thermal", plan().string(), "-o", fromPlan.string(), "--frames", "0"}).exitCode, 0);
  EXPECT_EQ(readBytes(out / "thermal_points.csv"), readBytes(fromPlan / "thermal_points.csv"));

  r = runCli({"thermal", part, "--points-per-rev", "zero", "-o", out.string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("points_per_rev"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace spira::test
