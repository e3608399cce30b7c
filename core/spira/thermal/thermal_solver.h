#pragma once

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "spira/base/progress.h"
#include "spira/base/transform.h"
#include "spira/thermal/thermal_linear_solver.h"
#include "spira/thermal/thermal_material.h"
#include "spira/thermal/thermal_mesh.h"
#include "spira/thermal/thermal_system.h"

namespace spira {

enum class ThermalScheme { CrankNicolson, ImplicitEuler };

// The state after one step, for observers that record more than ThermalResult keeps (frames of the
// field, the melt pool). Temperatures in C; a node not yet deposited holds what the inactive filler
// conducted into it, not material heat.
struct ThermalStep {
  double time = 0.0;  // s
  const std::vector<double>& temperature;
  const std::vector<char>& deposited;
};

// The transient model of 000_dbb97c2716e10cc3.txt chapter 5: a moving point source along the heat
// path, element birth that follows it, conduction and convection, the theta scheme. SI units but
// positions (mm, as the mesh) and temperatures (C).
struct ThermalSettings {
  ThermalMaterial material = thermalMaterialPreset("G3Si1");
  double power = 1000.0;  // W reaching the part while the arc is on (see arcPower); 0 = no source
  // J per mm of wire: when positive, the power follows the wire feed (a synergic line's energy per
  // unit wire, power = powerPerWireFeed x WFS) instead of `power`.
  double powerPerWireFeed = 0.0;
  // A measured calibration of the arc: (wire feed mm/s, power W) rows in increasing wire feed; when
  // given, each segment's power is interpolated at its wire feed (held at the ends) instead.
  std::vector<std::array<double, 2>> powerTable;
  // mm: the radius of a Gaussian surface flux around the torch (thermal_source.h); 0 = the source's
  // point load, whose peak temperatures and pool grow without bound as the mesh is refined.
  double sourceRadius = 0.0;
  ThermalFilms films;
  double initialTemperature = 20.0;  // C, every node at t = 0
  ThermalScheme scheme = ThermalScheme::CrankNicolson;
  // s; 0 = one sub-segment of torch travel per step (the steps fall on the heat path's points).
  double timeStep = 0.0;
  double coolingTime = 0.0;  // s simulated after the torch's last point, arc off
  bool activateAll = false;  // every element born at t = 0 (verification cases)
  // The exactly integrated consistent capacity instead of the lumped one. Under Crank-Nicolson the
  // consistent one rings after the point source passes: halving the step and the sub-segment moved
  // temperatures 20 mm behind the torch by 4.8 % (lumped: 0.6 %); see docs/thermal.md.
  bool consistentCapacity = false;
  // Relative residual of the conjugate gradient: 1e-6 moved temperatures by < 0.01 C against 1e-10 on
  // twelve revolutions of the dome, in 23 iterations per step instead of 40.
  double tolerance = 1e-6;
  // The backend of the linear solves: empty = the in-process conjugate gradient; PETSc over MPI with
  // petscThermalSolver() (spira/thermal/petsc/thermal_petsc.h). Both meet `tolerance`.
  ThermalSolverFactory linearSolver;
  std::vector<int> probeNodes;
  std::vector<Vec3> probePositions;                // mm; the nearest node is recorded
  std::function<void(const ThermalStep&)> onStep;  // after t = 0 and after every step
};

// The power of `table` (ThermalSettings::powerTable) at wire feed `wireFeed` (mm/s), W.
double tablePower(const std::vector<std::array<double, 2>>& table, double wireFeed);
// Throws InputError naming the first row (1-based) that is not finite, not positive, or not above
// the previous row's wire feed, or a table of fewer than two rows.
void validatePowerTable(const std::vector<std::array<double, 2>>& table);

// The arc power reaching the part, efficiency x U x I, in W. InputError for a non-positive voltage
// or current or an efficiency outside (0, 1].
double arcPower(double voltage, double current, double efficiency);

// Energy in joules since t = 0: in = stored + lost up to the solver tolerance (newly born material
// takes its energy from the source, not from nothing; see simulateThermal).
struct ThermalEnergy {
  double in = 0.0;
  double stored = 0.0;  // 1^T C (T - T_initial) at the end
  double lost = 0.0;    // to the air and the substrate
  double imbalance() const { return in - stored - lost; }
};

struct ThermalResult {
  // Per trajectory point: its node's highest temperature; the interpass temperature, the lowest the
  // node below it (previous layer, or substrate) reached between its own pass and the torch's arrival
  // over the point; the temperature of that node at the arrival itself, already preheated by the
  // approaching torch (a point source heats about alpha / v ahead of itself); and the time the point's
  // node spends above melting.
  std::vector<double> peak, interpass, belowAtArrival, timeAboveMelt;
  // Per node: highest and final temperature.
  std::vector<double> nodePeak, finalTemperature;
  std::vector<int> probeNodes;  // the settings' probe nodes, then the nodes nearest its positions
  std::vector<double> probeTimes;
  std::vector<std::vector<double>> probeTemperatures;  // [probe][time]
  ThermalEnergy energy;
  int nodes = 0, elements = 0, steps = 0;
  double simulatedTime = 0.0;     // s
  double seconds = 0.0;           // wall time of the simulation
  double solverSeconds = 0.0;     // of which in the conjugate gradient
  double solverIterations = 0.0;  // mean conjugate-gradient iterations per step
  double meanWindow = 0.0;        // mean unknowns solved per step (the deposited prefix and its fringe)
};

// Throws InputError for bad settings (material, negative power, a time step longer than the torch
// needs to cross one shell thickness: the message gives the longest that resolves the source).
// Progress is reported through `progress`; cancellation throws Cancelled between steps.
ThermalResult simulateThermal(const ThermalMesh& mesh, const ThermalSettings& settings, Progress& progress);

// The steady state of the whole (fully active) shell with the given nodes held at given temperatures
// and the settings' films (zero films = insulated faces), without the source. Returns node temperatures, C.
std::vector<double> solveSteadyThermal(const ThermalMesh& mesh, const ThermalSettings& settings,
                                       const std::vector<std::pair<int, double>>& fixed);

}  // namespace spira
