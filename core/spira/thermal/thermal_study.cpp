#include "spira/thermal/thermal_study.h"

#include <chrono>

namespace spira {

ThermalStudy runThermalStudy(const Trajectory& trajectory, const ThermalStudySettings& settings,
                             Progress& progress)
{
  ThermalStudy study;
  const auto clock0 = std::chrono::steady_clock::now();
  study.mesh = buildThermalMesh(trajectory, settings.mesh);
  study.meshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();

  ThermalSettings solver = settings.solver;
  const double duration = study.mesh.buildTime() + solver.coolingTime;
  ThermalFrameRecorder frames(settings.frames > 0 ? frameIntervalFor(duration, settings.frames) : -1.0);
  MeltPoolTracker pool(study.mesh, trajectory, solver.material.meltingTemperature);
  solver.onStep = [&](const ThermalStep& step) {
    if (settings.frames > 0) frames(step);
    pool(step);
  };
  study.result = simulateThermal(study.mesh, solver, progress);
  if (settings.frames > 0) study.frames = frames.take(study.result);

  study.poolLength = pool.lengths();
  const size_t n = trajectory.points.size();
  study.bond.assign(n, 0.0);
  study.risk.assign(n, 0);
  const double solidus = solver.material.solidusTemperature;
  for (size_t p = 0; p < n; ++p) {
    study.bond[p] = weightedBondNumber(solver.material, study.poolLength[p], trajectory.points[p].normal);
    // The pool always reaches into the layer below as the torch arrives (that is how it fuses):
    // the risk is that layer never solidifying between the passes.
    const bool liquidBelow = study.mesh.pointBelowNode[p] >= 0 && study.result.interpass[p] > solidus &&
                             trajectory.points[p].revolution > 0;
    study.risk[p] = char(study.bond[p] > settings.bondThreshold || liquidBelow);
    study.riskPoints += study.risk[p];
  }
  return study;
}

}  // namespace spira
