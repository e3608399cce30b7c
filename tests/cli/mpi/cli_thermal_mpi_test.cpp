// spira-cli thermal on two MPI ranks (mpiexec -n 2 ... --backend petsc) against the in-process backend
// on a planned open cylinder: the same thermal.json figures, points and probe histories to the solver's
// tolerance, written and printed once, by rank 0; the same in one process without mpiexec; petsc is
// the backend of an MPI launch unless told, eigen is refused there, re-planning gives the in-process
// path, bad input exits 3 once, and so do PETSc's own failures.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

// The 1e-6 relative residual of the solves moved temperatures by < 0.01 C against 1e-10 (docs/thermal.md).
constexpr double kTemperatureTolerance = 0.01;  // C

class CliThermalMpi : public ::testing::Test {
 protected:
  static void SetUpTestSuite()
  {
    dir_ = new TempDir;
    const CliRun plan = runCli({"plan", (sourceDir() / "resources/samples/open_cylinder.stl").string(), "-o",
                                (*dir_ / "plan").string(), "--points-per-rev", "36"});
    ASSERT_EQ(plan.exitCode, 0) << plan.err;
    const CliRun eigen = runCli(thermalArgs(*dir_ / "eigen", "eigen"));
    ASSERT_EQ(eigen.exitCode, 0) << eigen.err;
  }
  static void TearDownTestSuite()
  {
    delete dir_;
    dir_ = nullptr;
  }
  static std::vector<std::string> thermalArgs(const fs::path& out, const std::string& backend)
  {
    std::vector<std::string> args = {
        "thermal", (*dir_ / "plan").string(), "-o", out.string(), "--probe", "50,0,2", "--probe", "50,0,40"};
    if (!backend.empty()) args.insert(args.end(), {"--backend", backend});
    return args;
  }
  // mpiexec -n 2 spira-cli ARGS
  static CliRun onTwoRanks(const std::vector<std::string>& args)
  {
    std::vector<std::string> all;
    std::istringstream flags(SPIRA_MPIEXEC_FLAGS);
    for (std::string f; flags >> f;) all.push_back(f);
    all.insert(all.end(), {"-n", "2", SPIRA_CLI});
    all.insert(all.end(), args.begin(), args.end());
    return runProgram(SPIRA_MPIEXEC, all);
  }
  static fs::path eigen() { return *dir_ / "eigen"; }
  TempDir tmp_;
  static TempDir* dir_;
};
TempDir* CliThermalMpi::dir_ = nullptr;

std::vector<std::vector<double>> readCsv(const fs::path& file, std::string* header)
{
  std::ifstream in(file);
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::stringstream s(line);
    rows.emplace_back();
    for (std::string cell; std::getline(s, cell, ',');) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

void expectSameCsv(const fs::path& a, const fs::path& b, double tolerance)
{
  std::string headerA, headerB;
  const auto rowsA = readCsv(a, &headerA), rowsB = readCsv(b, &headerB);
  EXPECT_EQ(headerA, headerB) << b;
  ASSERT_EQ(rowsA.size(), rowsB.size()) << b;
  ASSERT_GT(rowsA.size(), 100u) << a;
  double largest = 0.0;
  for (size_t r = 0; r < rowsA.size(); ++r) {
    ASSERT_EQ(rowsA[r].size(), rowsB[r].size()) << b << " row " << r;
    for (size_t c = 0; c < rowsA[r].size(); ++c)
      largest = std::max(largest, std::abs(rowsA[r][c] - rowsB[r][c]));
  }
  EXPECT_LE(largest, tolerance) << b;
}

// A thermal.json value and its counterpart: temperatures (and every other figure) to the solver's
// tolerance, energies to 1e-6 of the input, counts, names and flags exactly; the wall times are left out.
void expectSameJson(const nlohmann::json& a, const nlohmann::json& b, const std::string& key, double in)
{
  if (a.is_object()) {
    ASSERT_TRUE(b.is_object()) << key;
    for (const auto& [name, value] : a.items()) {
      if (name == "timings_s") continue;
      ASSERT_TRUE(b.contains(name)) << key << "/" << name;
      expectSameJson(value, b.at(name), key + "/" + name, in);
    }
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << key;
    for (size_t i = 0; i < a.size(); ++i) expectSameJson(a[i], b[i], key + "[" + std::to_string(i) + "]", in);
  } else if (a.is_number_float()) {
    const bool energy = key.rfind("/energy_", 0) == 0;
    EXPECT_NEAR(a.get<double>(), b.get<double>(), energy ? 1e-6 * in : kTemperatureTolerance) << key;
  } else {
    EXPECT_EQ(a, b) << key;
  }
}

void expectSameReport(const fs::path& a, const fs::path& b)
{
  const auto ja = nlohmann::json::parse(readBytes(a / "thermal.json")),
             jb = nlohmann::json::parse(readBytes(b / "thermal.json"));
  const double in = ja.at("energy_in_J").get<double>();
  ASSERT_GT(in, 0.0);
  expectSameJson(ja, jb, "", in);
}

void expectSameResults(const fs::path& a, const fs::path& b)
{
  expectSameReport(a, b);
  expectSameCsv(a / "thermal_points.csv", b / "thermal_points.csv", kTemperatureTolerance);
  expectSameCsv(a / "probes.csv", b / "probes.csv", kTemperatureTolerance);
}

size_t countOf(const std::string& text, const std::string& word)
{
  size_t n = 0;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

TEST_F(CliThermalMpi, TwoRanksGiveTheInProcessResultsWrittenOnce)
{
  const fs::path out = tmp_ / "two";
  const CliRun r = onTwoRanks(thermalArgs(out, "petsc"));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(countOf(r.out, "wrote "), 1u) << r.out;
  EXPECT_EQ(countOf(r.out, "thermal: "), 1u) << r.out;
  EXPECT_EQ(countOf(r.out, "backend: PETSc on 2 MPI processes\n"), 1u) << r.out;
  expectSameResults(eigen(), out);
}

TEST_F(CliThermalMpi, OneProcessWithoutMpiexecGivesTheInProcessResults)
{
  const fs::path out = tmp_ / "one";
  const CliRun r = runCli(thermalArgs(out, "petsc"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("backend: PETSc on 1 MPI process\n"), std::string::npos) << r.out;
  expectSameResults(eigen(), out);
}

TEST_F(CliThermalMpi, AnMpiLaunchRunsPetscUnlessToldAndRefusesEigen)
{
  const fs::path out = tmp_ / "default";
  CliRun r = onTwoRanks(thermalArgs(out, ""));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("backend: PETSc on 2 MPI processes\n"), std::string::npos) << r.out;
  expectSameResults(eigen(), out);

  const fs::path refused = tmp_ / "refused";
  r = onTwoRanks(thermalArgs(refused, "eigen"));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--backend eigen solves in one process, but this is one of 2 processes"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(refused / "thermal.json"));
}

TEST_F(CliThermalMpi, BadInputOnTwoRanksExitsThreeAndSaysSoOnce)
{
  const fs::path out = tmp_ / "bad";
  std::vector<std::string> args = thermalArgs(out, "petsc");
  args.insert(args.end(), {"--power", "-5"});
  const CliRun r = onTwoRanks(args);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_EQ(countOf(r.err, "spira-cli: "), 1u) << r.err;
  EXPECT_FALSE(fs::exists(out / "thermal.json"));
}

// Re-planning to an interpass limit runs on every rank alike, each simulation on PETSc: the in-process
// re-planned path and report. With the point source: the re-planned speeds of the two backends differ
// by 1e-15, and the Gaussian arc's load jumps when a sample falls on a segment's middle (the search for
// the nodes it heats starts at the nearer end), which moved peaks by up to 600 C.
TEST_F(CliThermalMpi, ReplanningOnTwoRanksGivesTheInProcessPath)
{
  const auto args = [](const fs::path& out, const std::string& backend) {
    std::vector<std::string> a = thermalArgs(out, backend);
    a.insert(a.end(),
             {"--interpass-max", "200", "--remedy", "heat", "--frames", "0", "--source-radius", "0"});
    return a;
  };
  const fs::path inProcess = tmp_ / "replan_eigen", two = tmp_ / "replan_two";
  const CliRun e = runCli(args(inProcess, "eigen"));
  ASSERT_EQ(e.exitCode, 0) << e.err;
  const CliRun r = onTwoRanks(args(two, "petsc"));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(countOf(r.out, "re-planned for an interpass limit"), 1u) << r.out;
  expectSameResults(inProcess, two);
  expectSameCsv(inProcess / "trajectory.csv", two / "trajectory.csv", 1e-6);
}

// PETSc's own failures (here asked for through its options) exit 3 with PETSc's message, nothing written.
TEST_F(CliThermalMpi, PetscFailuresExitThreeWithPetscsMessage)
{
  const fs::path out = tmp_ / "failed";
  CliRun r = runCli(thermalArgs(out, "petsc"), {"PETSC_OPTIONS=-thermal_ksp_type nosuch"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("the PETSc thermal solve failed in KSPSetFromOptions"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nosuch"), std::string::npos) << r.err;
  r = runCli(
      thermalArgs(out, "petsc"),
      {"PETSC_OPTIONS=-thermal_ksp_type richardson -thermal_pc_type none -thermal_ksp_richardson_scale 100"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("the thermal solve did not converge (PETSc: DIVERGED_"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "thermal.json"));
}

}  // namespace
}  // namespace spira::test
