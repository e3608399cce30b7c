#pragma once

#include <array>
#include <filesystem>
#include <string>

#include "spira/base/transform.h"

namespace spira {

// A gantry or CNC machine with a two-axis tilting head, as the G-code exporter drives it; read from a
// .machine file (docs/machine-format.md). Lengths mm, angles degrees, feeds mm/min.
struct LinearAxis {
  std::string letter;  // the word the program writes, e.g. "X"
  double minMm = 0.0;
  double maxMm = 0.0;
};

struct RotaryAxis {
  std::string letter;          // "A", "B" or "C"
  Vec3 about = Vec3::UnitZ();  // unit direction it turns about, in machine axes at zero angles
  double minDeg = 0.0;
  double maxDeg = 0.0;
};

struct GcodeMachine {
  std::string name;
  std::array<LinearAxis, 3> linear;  // along the machine's X, Y and Z
  // [0] is carried by the gantry, [1] by [0]. The gantry's linear axes place the point of the
  // first axis' line that the offsets start from.
  std::array<RotaryAxis, 2> rotary;
  Vec3 firstToSecond = Vec3::Zero();          // from the first rotary axis to the second, zero angles
  Vec3 secondToTip = Vec3(0.0, 0.0, -150.0);  // from the second rotary axis to the tool tip, zero angles
  Vec3 toolDirection = -Vec3::UnitZ();        // the torch axis towards the deposit, zero angles (unit)
  Vec3 partOrigin = Vec3::Zero();             // the part frame's origin in machine coordinates
  double maxFeed = 6000.0;                    // mm/min of a G1 move
  std::string arcOn = "M3";
  std::string arcOff = "M5";
  std::string wireFeed = "S{wfs}";      // {wfs} becomes the wire-feed speed in wireFeedUnit
  std::string wireFeedUnit = "mm/min";  // "mm/min", "m/min" or "mm/s"
  std::string dwell = "G4 P{s}";        // {s} becomes the wait in seconds
  std::string programEnd = "M30";
};

// Reads and checks a machine file; InputError naming the file, the axis and the field for anything
// that cannot drive a head (a letter used twice, a rotary letter other than A/B/C, a zero or
// parallel pair of rotary axes, a limit whose min is not below its max...), IoError when unreadable.
GcodeMachine readMachineFile(const std::filesystem::path& file);
// The same from the file's text; `what` names it in messages ("machine file gantry.machine").
GcodeMachine machineFromText(const std::string& text, const std::string& what);

}  // namespace spira
