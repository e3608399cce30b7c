// The thermal history of the bundled dome (resources/samples/dome.stl planned with the defaults, or a
// trajectory.csv given as the first argument): the whole build, G3Si1 at 1000 W, the source's films,
// Crank-Nicolson on the automatic step (one sub-segment of torch travel). Prints the mesh, the steps,
// the time per step and where it goes, the hottest peak and interpass temperatures and the energy
// balance. Then, for the record, what one direct (CHOLMOD) factorisation of the same-size system costs:
// element birth changes the matrix at every step, so a direct solver would pay it every step.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "builtin_plugins.h"
#include "spira/base/progress.h"
#include "spira/field/sparse_cholesky.h"
#include "spira/io/import_service.h"
#include "spira/planning/planner.h"
#include "spira/planning/trajectory_csv_reader.h"
#include "spira/thermal/thermal_solver.h"

using namespace spira;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Trajectory domeTrajectory(int argc, char** argv)
{
  if (argc > 1) return readTrajectoryCsv(argv[1]);
  NullProgress progress;
  const std::filesystem::path root(SPIRA_SOURCE_DIR);
  const ImportedPart part =
      importPart(builtinRegistry(), root / "resources/samples/dome.stl", nullptr, progress);
  return planPart(builtinRegistry(), PlanRequest(part.mesh, part.report), progress).spiral.trajectory;
}

// The whole system C + dt/2 K with every element active, in CHOLMOD's layout (lower triangle by columns).
SymmetricSparseMatrix stepMatrix(const ThermalMesh& mesh, const ThermalSettings& s, double dt)
{
  ThermalSystem system(mesh, s.material, s.films, true);
  for (int e = 0; e < int(mesh.elementCount()); ++e) system.activate(e);
  SymmetricSparseMatrix m;
  m.size = system.size();
  m.columnStart.push_back(0);
  for (int j = 0; j < m.size; ++j) {
    for (int p = system.rowStart[size_t(j)]; p < system.rowStart[size_t(j) + 1]; ++p)
      if (system.column[size_t(p)] >= j) {
        m.rowIndex.push_back(system.column[size_t(p)]);
        m.values.push_back(system.capacity[size_t(p)] + 0.5 * dt * system.conductance[size_t(p)]);
      }
    m.columnStart.push_back(int(m.rowIndex.size()));
  }
  return m;
}

}  // namespace

int main(int argc, char** argv)
{
  auto t0 = std::chrono::steady_clock::now();
  const Trajectory trajectory = domeTrajectory(argc, argv);
  std::printf("trajectory: %zu points, path %.1f m (%s %.2f s)\n", trajectory.size(),
              trajectory.length() / 1000.0, argc > 1 ? "read in" : "planned in", secondsSince(t0));

  t0 = std::chrono::steady_clock::now();
  ThermalMeshSettings ms;
  ms.thickness = 5.0;
  const ThermalMesh mesh = buildThermalMesh(trajectory, ms);
  std::printf(
      "mesh (k = 1, f = 1, tau = 5 mm): %zu nodes, %zu triangles, %zu substrate nodes, build time %.1f min "
      "(%.3f s)\n",
      mesh.nodeCount(), mesh.elementCount(), mesh.substrateNodes.size(), mesh.buildTime() / 60.0,
      secondsSince(t0));

  ThermalSettings s;
  s.power = 1000.0;
  NullProgress progress;
  const ThermalResult r = simulateThermal(mesh, s, progress);
  const double maxPeak = *std::max_element(r.peak.begin(), r.peak.end());
  const double maxInterpass = *std::max_element(r.interpass.begin(), r.interpass.end());
  size_t hottest = size_t(std::max_element(r.interpass.begin(), r.interpass.end()) - r.interpass.begin());
  std::printf(
      "simulation: %d steps over %.1f min simulated in %.2f s (%.3f ms per step, %.0fx faster than the "
      "weld)\n",
      r.steps, r.simulatedTime / 60.0, r.seconds, 1000.0 * r.seconds / r.steps, r.simulatedTime / r.seconds);
  std::printf(
      "  conjugate gradient %.2f s (%.1f iterations per step on %.0f unknowns on average), the rest %.2f s\n",
      r.solverSeconds, r.solverIterations, r.meanWindow, r.seconds - r.solverSeconds);
  std::printf(
      "  max peak %.0f C, max interpass %.0f C (point %zu, revolution %d of %d), max below-at-arrival %.0f "
      "C\n",
      maxPeak, maxInterpass, hottest, trajectory.points[hottest].revolution,
      trajectory.points.back().revolution + 1,
      *std::max_element(r.belowAtArrival.begin(), r.belowAtArrival.end()));
  std::printf("  energy in %.1f kJ, stored %.1f kJ, lost %.1f kJ, imbalance %.2g of the input\n",
              r.energy.in / 1e3, r.energy.stored / 1e3, r.energy.lost / 1e3,
              r.energy.imbalance() / r.energy.in);

  // Interpass by revolution: the rise towards the closure the issue is about.
  std::printf("  interpass by revolution (max):");
  for (int rev = 0; rev <= trajectory.points.back().revolution; rev += 4) {
    double m = 0.0;
    for (size_t i = 0; i < trajectory.size(); ++i)
      if (trajectory.points[i].revolution == rev) m = std::max(m, r.interpass[i]);
    std::printf(" %d:%.0f", rev, m);
  }
  std::printf("\n");

  const double dt = mesh.buildTime() / r.steps;
  const SymmetricSparseMatrix a = stepMatrix(mesh, s, dt);
  t0 = std::chrono::steady_clock::now();
  const CholeskyAnalysis analysis(a, CholmodOrdering::Amd);
  const double analyse = secondsSince(t0);
  t0 = std::chrono::steady_clock::now();
  const CholeskyFactor factor(analysis, a);
  const double factorise = secondsSince(t0);
  std::printf(
      "CHOLMOD on the whole %d-node system: analysis %.1f ms, one factorisation %.1f ms (%.0f x %d steps = "
      "%.0f s if refactorised at every step)\n",
      a.size, 1000.0 * analyse, 1000.0 * factorise, 1000.0 * factorise, r.steps, factorise * r.steps);
  return 0;
}
