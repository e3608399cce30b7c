#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "spira/path/trajectory.h"

namespace spira::test {

// Where two trajectories differ, to the bit (every channel of every point, and the extra
// channels), with the largest position difference over the path; empty when they are identical.
std::string trajectoryDifference(const Trajectory& a, const Trajectory& b);

// Where two per-vertex fields differ, to the bit; empty when they are identical.
std::string fieldDifference(const std::vector<double>& a, const std::vector<double>& b);

// Where two generatrix sets differ, to the bit; empty when they are identical.
std::string generatricesDifference(const Generatrices& a, const Generatrices& b);

// Where the files of two folders differ (names, then bytes: the first differing line of each file
// that differs); empty when both hold the same files with the same bytes. Files named in `skip`
// are left out.
std::string folderDifference(const std::filesystem::path& a, const std::filesystem::path& b,
                             const std::vector<std::string>& skip = {});

}  // namespace spira::test
