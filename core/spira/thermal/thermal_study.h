#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/path/trajectory.h"
#include "spira/thermal/thermal_frames.h"
#include "spira/thermal/thermal_mesh.h"
#include "spira/thermal/thermal_pool.h"
#include "spira/thermal/thermal_solver.h"

namespace spira {

// Everything one thermal run of a planned path needs (the CLI's flags, the project's thermal
// settings).
struct ThermalStudySettings {
  ThermalMeshSettings mesh;
  ThermalSettings solver;  // its onStep is the study's
  int frames = 200;        // frames of the field kept over the simulated time; 0 = none
  double bondThreshold = kDefaultBondThreshold;
};

// A thermal run of a path and what is derived from it per trajectory point: the melt pool's
// length, the weighted Bond number and the collapse-risk flag.
struct ThermalStudy {
  ThermalMesh mesh;
  ThermalResult result;
  ThermalFrames frames;
  std::vector<double> poolLength;  // mm
  std::vector<double> bond;
  // A point is at risk when its pool's weighted Bond number exceeds the threshold, or when the
  // deposit below it stayed above the solidus between the passes (the pool cannot rest on it).
  std::vector<char> risk;
  int riskPoints = 0;
  double meshSeconds = 0.0;  // wall time of building the shell
};

// Builds the shell from the trajectory and simulates it. Throws InputError for bad settings or a
// path without process channels; Cancelled from `progress`.
ThermalStudy runThermalStudy(const Trajectory& trajectory, const ThermalStudySettings& settings,
                             Progress& progress);

}  // namespace spira
