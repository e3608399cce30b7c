#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "real/deposit_check.h"

namespace spira::test::real {

// Reads the columns the check needs (x,y,z, bx,by,bz, arc, path) from a spira-cli
// trajectory.csv, by their header names. Throws std::runtime_error naming the file and line.
std::vector<PathPoint> readTrajectoryCsv(const std::filesystem::path& file);

// The window and substrate of a plan: the figures report.json states (under "deposit_check",
// "window" or at its top level: h_min, h_max, tol, bead_width, substrate_z) override `given`,
// which holds what the caller asked spira-cli for.
CheckSettings settingsFromReport(const std::filesystem::path& reportJson, CheckSettings given);

}  // namespace spira::test::real
