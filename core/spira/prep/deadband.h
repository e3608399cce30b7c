#pragma once

#include <cstddef>
#include <vector>

namespace spira {

// A process output (travel speed, wire feed, an analog value) written to the robot program only when
// it has moved by more than `threshold` from the value last written (the "NC material
// resolution" of 003_abf6ea7743219370.txt §5.4, Fig. C.2): programs are not flooded with I/O statements, and
// the value the process actually holds never differs from the planned one by more than `threshold`.
struct DeadbandResult {
  std::vector<bool> emit;    // per point: write a new setpoint here (always at the first point)
  std::vector<double> held;  // per point: the setpoint in force, i.e. the value last written
  size_t emitted = 0;        // number of setpoints written
  double maxError = 0.0;     // max |held - value|, never above the threshold
};

// threshold >= 0, in the values' unit; 0 writes every change. Throws InputError when negative.
DeadbandResult applyDeadband(const std::vector<double>& values, double threshold);

}  // namespace spira
