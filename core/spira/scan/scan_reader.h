#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "spira/base/progress.h"
#include "spira/scan/point_cloud.h"

namespace spira {

class PluginRegistry;

// The scan formats read, by extension: .ply (points, with nx ny nz when present), .pcd (ascii or
// binary, with normal_x normal_y normal_z when present), .xyz .csv .txt .asc (text columns as laser
// line profilers write them), and the part mesh formats (.stl .obj ...: their vertices with the
// mesh's normals). Millimetres as stored: scanUnitHint() says when another unit is likely.
// Throws IoError for a missing or unreadable file, InputError naming the line (or byte) for a
// malformed one, a format it does not read, a non-finite coordinate or a file without points.
PointCloud readScan(const PluginRegistry& registry, const std::filesystem::path& file, Progress& progress);

// Text columns: x y z and more, separated by spaces, tabs, commas or semicolons; '#' and '//' start
// comments. A first line of names (x, y, z, nx, ny, nz, or normal_x ...) says which column is which;
// without one the first three columns are x, y, z and, in a file of exactly six, the last three the
// normal when they are unit vectors. `source` names the file in messages.
PointCloud parseXyzText(std::string_view text, const std::string& source);

// A PCL point cloud file (.pcd, DATA ascii or binary). binary_compressed is refused with the way out.
PointCloud parsePcd(std::string_view bytes, const std::string& source);

}  // namespace spira
