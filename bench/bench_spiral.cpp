// Spiral building and process mapping on analytic generatrices: an open part of radius 50 mm whose
// upper edge undulates between 97 and 113 mm, one straight generatrix per degree (or half degree),
// 200 points each. Prints the best and median of several runs, wall clock and CPU time (the CPU time
// is the fairer number on a shared machine).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/path/process_model.h"
#include "spira/path/spiral_builder.h"

using namespace spira;

namespace {

Generatrices undulatingWall(int n, int points)
{
  Generatrices g;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    const Vec3 radial(std::cos(a), std::sin(a), 0.0);
    const double top = 105.0 + 8.0 * std::sin(2.0 * a);
    Polyline line;
    std::vector<Vec3> normals;
    for (int k = 0; k < points; ++k) {
      line.push_back(50.0 * radial + Vec3(0, 0, top * k / (points - 1)));
      normals.push_back(radial);
    }
    g.lines.push_back(std::move(line));
    g.normals.push_back(std::move(normals));
  }
  return g;
}

double millis(std::chrono::steady_clock::duration d)
{
  return std::chrono::duration<double, std::milli>(d).count();
}

void run(int n, double h, int repeats)
{
  const Generatrices g = undulatingWall(n, 200);
  SpiralSettings s;
  s.h = h;
  s.hMin = 0.9 * h;
  s.hMax = 1.1 * h;
  s.layerMode = LayerMode::Centered;
  ProcessSettings ps;
  ps.wireFeed = 2.3 * toInternalFactor("m/min");
  NullProgress progress;
  std::vector<double> build, process, cpu;
  SpiralResult result;
  ProcessReport pr;
  for (int r = 0; r < repeats; ++r) {
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    result = buildSpiral(g, s, progress);
    const auto t1 = std::chrono::steady_clock::now();
    pr = applyProcess(result.trajectory, ps);
    const auto t2 = std::chrono::steady_clock::now();
    cpu.push_back(1000.0 * (std::clock() - c0) / CLOCKS_PER_SEC);
    build.push_back(millis(t1 - t0));
    process.push_back(millis(t2 - t1));
  }
  std::sort(build.begin(), build.end());
  std::sort(process.begin(), process.end());
  std::sort(cpu.begin(), cpu.end());
  const SpiralReport& rep = result.report;
  std::printf(
      "%d generatrices x 200 points, h = %.2f mm +/-10%%: %d revolutions (%d start-up, %d modulated, "
      "%d end), %zu points, path %.1f m, heights %.3f..%.3f mm, %s\n",
      n, h, rep.nRevolutions, rep.nStartupRevolutions, rep.nLayers, rep.nEndRevolutions, rep.nPoints,
      rep.pathLength / 1000.0, rep.heightMin, rep.heightMax, rep.feasible ? "feasible" : "infeasible");
  std::printf("  buildSpiral : best %7.2f ms, median %7.2f ms\n", build.front(), build[build.size() / 2]);
  std::printf("  applyProcess: best %7.2f ms, median %7.2f ms (build time %.0f s, TS %.2f..%.2f mm/s)\n",
              process.front(), process[process.size() / 2], pr.buildTime, pr.travelSpeedMin,
              pr.travelSpeedMax);
  std::printf("  both, CPU time: best %7.2f ms, median %7.2f ms\n", cpu.front(), cpu[cpu.size() / 2]);
}

}  // namespace

int main()
{
  run(360, 1.0, 21);
  run(720, 0.5, 11);
  return 0;
}
