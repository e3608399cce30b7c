#pragma once

#include <filesystem>
#include <string>

#include "spira/path/trajectory.h"

namespace spira {

// Reads a trajectory.csv written by trajectoryCsv() (plan_files.h) back into a Trajectory: the
// exact inverse (numbers are written in shortest round-trip form) but for the wire-feed speed,
// converted back from m/min to within a few units in the last place.
// Files from before the `path` column (header ending in ",arc") read as one path; a file with the
// dwell_s column fills the trajectory's dwell channel (path/dwell.h).
// Throws InputError naming the line for a wrong header, a short row or a bad number, and IoError
// when the file cannot be read.
Trajectory readTrajectoryCsv(const std::filesystem::path& file);
Trajectory trajectoryFromCsv(const std::string& text, const std::string& what = "trajectory.csv");

}  // namespace spira
