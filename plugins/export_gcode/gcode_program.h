#pragma once

#include <string>
#include <vector>

#include "gcode_machine.h"
#include "head_kinematics.h"
#include "spira/base/progress.h"
#include "spira/export/export_path.h"

namespace spira {

struct GcodeSettings {
  int decimals = 3;              // places of the axis words and of the wire-feed value
  bool lineNumbers = false;      // N1, N2... on every block
  int programNumber = 0;         // O-word; 0 writes none
  double approachFeed = 1200.0;  // mm/min of the approach and retract moves
  // G93: F is 1 / the move's planned duration in minutes, written on every G1, so that a machine
  // without tool-tip control keeps the plan's timing whatever its rotary axes do. Off: G94, F in mm/min.
  bool inverseTime = false;
};

// The axis values of a program: one per path point, plus the approach before and the retract after
// them when the path has an approach.
struct GcodeTargets {
  HeadAxes approach;
  std::vector<HeadAxes> points;
  HeadAxes retract;
};

// The program's text: "%", the O-word, the header as ( ) comments, G21 G90 G94 (G93), a G0 to the
// approach, then one G1 per point with its feed (modal F, mm/min), the wire feed where it changes, one
// arc on and off per arc, G4 at a dwell, the retract and the machine's program end.
std::string writeGcodeProgram(const ExportPath& path, const GcodeTargets& targets, const GcodeMachine& m,
                              const GcodeSettings& s, const std::vector<std::string>& header,
                              Progress& progress);

// The wire-feed speed in the machine's unit.
double wireFeedInUnit(double wfsMmPerS, const std::string& unit);

}  // namespace spira
