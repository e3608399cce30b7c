// Torch collision checking on a spiral plan against the growing deposit: a 100-revolution helix of
// 36,000 points on an R = 50 mm cylinder (4 mm bead, 1 mm layer), a substrate plane and a table.
// Times the checker set-up (deposit hierarchy), the full check-and-resolve pass (every point against
// everything laid before it, sliding window applied), and a clearance (distance) query per point.
// Then the same plan with the torch leaning 20 deg inwards (loose boxes: the exact node test works)
// and with a clamp beside the wall that forces tilts (the resolution itself). Prints wall-clock and
// CPU time (CPU is the fairer number on a shared machine; the checks run on all cores).
// Last, the bundled dome (resources/samples/dome.stl) planned with the defaults and checked with the
// KUKA cell's torch and the default bead, as `spira-cli plan --cell` does: resolution on one thread
// against all cores, and whether both give the same tilts bit for bit.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <thread>
#include <vector>

#include "builtin_plugins.h"
#include "collision/mesh_builders.h"
#include "collision/plan_builders.h"
#include "spira/base/progress.h"
#include "spira/base/units.h"
#include "spira/collision/collision_resolver.h"
#include "spira/collision/tilt_about_tangent.h"
#include "spira/io/import_service.h"
#include "spira/pipeline/plan_motion.h"
#include "spira/planning/planner.h"
#include "spira/robotcell/cell_file.h"

using namespace spira;

namespace {

struct Timer {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  std::clock_t cpu = std::clock();
  void print(const char* what) const
  {
    const double w = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
    const double c = double(std::clock() - cpu) / CLOCKS_PER_SEC;
    std::printf("  %-34s %8.3f s wall, %8.3f s CPU\n", what, w, c);
  }
};

void run(const char* title, const Trajectory& plan, const CollisionScene& scene, bool clearances)
{
  std::printf("%s: %zu points, path %.1f m\n", title, plan.size(), plan.length() / 1000.0);
  NullProgress progress;
  Timer total;
  Timer t0;
  const TorchCollisionChecker checker(plan, TorchParams(), DepositParams(), scene);
  t0.print("checker set-up (deposit BVH)");
  Timer t1;
  const CollisionResolution res = resolveTorchCollisions(plan, checker, ResolveSettings(), progress);
  t1.print("check + resolve");
  double maxTilt = 0.0, maxStep = 0.0;
  for (size_t i = 0; i < res.tiltRad.size(); ++i) {
    maxTilt = std::max(maxTilt, std::abs(res.tiltRad[i]));
    if (i > 0) maxStep = std::max(maxStep, std::abs(res.tiltRad[i] - res.tiltRad[i - 1]));
  }
  size_t tilted = std::count_if(res.tiltRad.begin(), res.tiltRad.end(), [](double t) { return t != 0.0; });
  std::printf("    %zu colliding points, %zu tilted, %zu unresolved, max tilt %.2f deg, max step %.2f deg\n",
              res.collisionCount(), tilted, res.unresolved.size(), radToDeg(maxTilt), radToDeg(maxStep));
  if (clearances) {
    Timer t2;
    std::vector<double> clearance(plan.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, plan.size(), 64),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i)
                          clearance[i] = checker.clearance(i, res.tiltRad[i]);
                      });
    t2.print("clearance per point (distance)");
    std::printf("    clearance min %.3f mm, median %.3f mm\n",
                *std::min_element(clearance.begin(), clearance.end()), [&] {
                  std::vector<double> c = clearance;
                  std::nth_element(c.begin(), c.begin() + c.size() / 2, c.end());
                  return c[c.size() / 2];
                }());
  }
  total.print("total");
}

double seconds(std::chrono::steady_clock::time_point from)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}

// The resolution of `plan` on `threads` threads (0: all), best wall time of `runs` and the CPU time
// of that run (process CPU: on a loaded machine the wall time says little).
CollisionResolution resolveOn(int threads, int runs, const Trajectory& plan,
                              const TorchCollisionChecker& checker, double& best, double& cpu)
{
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  CollisionResolution res;
  best = 1e9;
  for (int r = 0; r < runs; ++r) {
    NullProgress progress;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    arena.execute([&] { res = resolveTorchCollisions(plan, checker, ResolveSettings(), progress); });
    if (seconds(t0) < best) {
      best = seconds(t0);
      cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    }
  }
  return res;
}

void runDome()
{
  namespace fs = std::filesystem;
  const fs::path root(SPIRA_SOURCE_DIR);
  NullProgress progress;
  auto t0 = std::chrono::steady_clock::now();
  const ImportedPart part =
      importPart(builtinRegistry(), root / "resources/samples/dome.stl", nullptr, progress);
  const PlanOutput plan = planPart(builtinRegistry(), PlanRequest(part.mesh, part.report), progress);
  const Trajectory& path = plan.spiral.trajectory;
  std::printf("dome.stl planned with the defaults: %zu points, path %.1f m (planning %.2f s)\n", path.size(),
              path.length() / 1000.0, seconds(t0));
  const RobotCell cell(readCellFile(root / "resources/cells/kuka_kr16_2_table.cell"));
  const ToolRecord& tool = cell.record().tool;
  TorchParams torch;
  torch.nozzleRadius = tool.nozzleRadius;
  torch.coneLength = tool.nozzleLength;
  torch.bodyRadius = tool.torchBodyRadius;
  torch.bodyLength = tool.torchBodyLength;
  DepositParams deposit;
  deposit.beadWidth = MotionSettings().beadWidth;
  CollisionScene scene;
  scene.setSubstratePlane(Vec3::Zero(), Vec3::UnitZ());
  t0 = std::chrono::steady_clock::now();
  const TorchCollisionChecker checker(path, torch, deposit, scene);
  std::printf("  %-34s %8.3f s wall\n", "checker set-up (deposit BVH)", seconds(t0));
  double serial = 0.0, parallel = 0.0, serialCpu = 0.0, parallelCpu = 0.0;
  const CollisionResolution one = resolveOn(1, 2, path, checker, serial, serialCpu);
  const CollisionResolution all = resolveOn(0, 3, path, checker, parallel, parallelCpu);
  std::printf("  %-34s %8.3f s wall, %8.3f s CPU (best of 2)\n", "check + resolve, 1 thread", serial,
              serialCpu);
  std::printf("  %-34s %8.3f s wall, %8.3f s CPU (best of 3), speed-up %.2fx\n",
              "check + resolve, all threads", parallel, parallelCpu, serial / parallel);
  const bool same =
      one.hits == all.hits && one.unresolved == all.unresolved && one.tiltRad.size() == all.tiltRad.size() &&
      std::memcmp(one.tiltRad.data(), all.tiltRad.data(), one.tiltRad.size() * sizeof(double)) == 0;
  std::printf("    %zu colliding points, %zu unresolved; 1-thread and parallel tilts bit-identical: %s\n",
              all.collisionCount(), all.unresolved.size(), same ? "yes" : "NO");
}

}  // namespace

int main(int argc, char** argv)
{
  std::printf("hardware threads: %u\n", std::thread::hardware_concurrency());
  if (argc > 1 && std::strcmp(argv[1], "--dome") == 0) {  // the dome alone
    runDome();
    return 0;
  }
  const Trajectory plan = test::helixPlan(50.0, 1.0, 100, 360);
  CollisionScene scene;
  scene.setSubstratePlane(Vec3::Zero(), Vec3::UnitZ());
  scene.addObstacle("table", test::boxMesh(Vec3(-400, -400, -40), Vec3(400, 400, -5)));
  run("helix R50, 100 rev x 360, torch along b", plan, scene, true);

  Trajectory leaning = plan;
  for (auto& p : leaning.points) p = tiltAboutTangent(p, degToRad(-20.0));
  run("same, torch leaning 20 deg inwards", leaning, scene, true);

  CollisionScene clamped = scene;
  clamped.addObstacle("clamp", test::boxMesh(Vec3(64, -6, 0), Vec3(90, 6, 150)));
  run("same, with a clamp beside the wall", plan, clamped, false);
  runDome();
  return 0;
}
