#pragma once

#include <filesystem>
#include <string>

#include "spira/robotcell/cell_record.h"

namespace spira {

// The stand-alone cell file (.cell): JSON written for people (poses as xyz in mm and URDF rpy in
// degrees, named sections), documented in docs/cell-format.md. Relative URDF paths are resolved
// against the cell file's folder, so a cell and its robots can move together.
//
// Frames (all "pose" entries are child -> parent, p_parent = T * p_child):
//   robot.pose       the robot URDF's root link (its foot) in the cell's world frame;
//   positioner.pose  the positioner URDF's root link in the world;
//   part.pose        the part's mesh frame in the mount frame (world for a fixed table, the
//                    positioner's tip link when mounted on it);
//   tool.tcp         the TCP in the flange (the robot chain's tip link).
//
// Throws InputError naming the file and the field for anything unreadable or inconsistent, and
// IoError when the file cannot be read.
CellRecord readCellFile(const std::filesystem::path& file);
CellRecord cellFromText(const std::string& text, const std::filesystem::path& baseDir,
                        const std::string& what = "cell file");

// The .cell text of a record; URDF paths are written relative to `baseDir` when they lie under it.
std::string cellFileText(const CellRecord& cell, const std::filesystem::path& baseDir);

// `file` relative to `baseDir` when it is absolute; else, or when `baseDir` is empty, unchanged.
std::string relativeTo(const std::string& file, const std::filesystem::path& baseDir);

}  // namespace spira
