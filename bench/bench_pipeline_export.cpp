// The whole export of a planned path, as `spira-cli plan --export` runs it: path preparation
// (C2 quintic smoothing and decimation under chord and attribute tolerances), inverse kinematics of
// the prepared points on a bundled cell, and the program files. A 100,000-point spiral (200
// revolutions of 500 points, R = 50 mm, deposit-height modulated) on the KUKA KR 16-2 table cell
// and on the FANUC + positioner cell. Target (issue 5): < 1 s per format.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "builtin_plugins.h"
#include "spira/base/units.h"
#include "spira/pipeline/export_job.h"
#include "spira/robotcell/cell_file.h"

using namespace spira;
namespace fs = std::filesystem;

namespace {

Trajectory spiral(int revolutions, int perRev)
{
  Trajectory t;
  const double radius = 50.0, pitch = 2.0;
  for (int i = 0; i < revolutions * perRev; ++i) {
    const double a = 2.0 * kPi * i / perRev;
    TrajectoryPoint p;
    p.position = Vec3(radius * std::cos(a), radius * std::sin(a), 2.0 + pitch * i / perRev);
    p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), pitch / (2.0 * kPi * radius)).normalized();
    p.build = p.normal.cross(p.tangent).normalized();
    p.height = 2.0 + 0.1 * std::sin(3.0 * a);
    p.travelSpeed = 5.0 / (p.height / 2.0);
    p.wireFeed = 2300.0 / 60.0;
    p.revolution = i / perRev;
    p.generatrix = i % perRev;
    t.points.push_back(p);
  }
  return t;
}

}  // namespace

int main()
{
  const fs::path cells = fs::path(SPIRA_SOURCE_DIR) / "resources" / "cells";
  const Trajectory plan = spiral(200, 500);
  const fs::path out = fs::temp_directory_path() / "spira_bench_pipeline_export";
  std::printf("plan: %zu points, path %.0f mm\n", plan.size(), plan.length());
  for (const auto& [format, cellName] : {std::pair{"export.krl", "kuka_kr16_2_table.cell"},
                                         std::pair{"export.fanuc_tp", "fanuc_m20ia_positioner.cell"}}) {
    const RobotCell cell(readCellFile(cells / cellName));
    ExportJob job;
    job.exporterId = format;
    job.exporterParams.set("force", true);  // constant torch spin: the KUKA's A6 winds past its limits
    job.cell = &cell;
    job.header = {{"part", "bench spiral"}, {"cell", cell.record().name}};
    double best = 1e9;
    ExportOutcome last;
    for (int run = 0; run < 3; ++run) {
      fs::remove_all(out);
      fs::create_directories(out);
      NullProgress progress;
      const auto t0 = std::chrono::steady_clock::now();
      last = exportTrajectory(builtinRegistry(), plan, job, out, progress);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::printf("%-16s %-30s %zu -> %zu targets (chord %.4f mm), %zu files, best of 3: %.3f s\n", format,
                cellName, last.prep.pointsIn, last.robotTargets, last.prep.maxChordDeviation,
                last.result.files.size(), best);
  }
  fs::remove_all(out);
  return 0;
}
