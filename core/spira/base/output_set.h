#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace spira {

// One file of an output set: its name inside the output folder and its whole content.
struct OutputFile {
  std::string name;
  std::string bytes;
  // In a plan set: a file of the plan's thermal history, which the next thermal set replaces.
  bool thermal = false;
};

// A plan (trajectory.csv, joints.csv, report.json), a robot program (its .src/.dat/.ls files), the
// thermal history of the plan (thermal.json, its CSVs and its ParaView series) or a scan's comparison
// with the part (the aligned scan, deviation.csv, deviation.json).
enum class OutputKind { Plan, Program, Thermal, Scan };

// The hidden file in an output folder that lists the files of Spira's sets there, with their sizes
// and checksums.
inline constexpr const char* kOutputManifest = ".spira-set.json";

// Replaces Spira's files of one kind in `dir` by `files`, as one set: a reader sees the old set or
// the new one, never a mix, and a failure at any point leaves the old set as it was. A plan set
// drops every file of the previous plan and its programs (a program belongs to the plan it was made
// from); a program set (named by its first file's stem, the main program) drops the previous files
// of that program and keeps the plan and other programs; a thermal set replaces the previous thermal
// files and keeps the plan and the programs. Files that are not Spira's are kept.
//
// The new folder content is staged in full in a hidden sibling folder (new files written and
// synced, kept files hard-linked, the manifest last) and swapped with `dir` in one rename
// (renameat2 RENAME_EXCHANGE; where the file system has no exchange, two renames, the second undone
// on failure). Where `dir` cannot be swapped (the working directory, a mount point, a folder with
// sub-folders) the files are renamed in one by one under a manifest that marks the set incomplete
// until the last rename, which verifyOutputSet refuses. Leftovers of a killed run are removed.
// Throws IoError naming the file and the reason. Returns the written paths, in order.
std::vector<std::filesystem::path> replaceOutputSet(const std::filesystem::path& dir, OutputKind kind,
                                                    const std::vector<OutputFile>& files);

// Checks the files `dir`'s manifest lists against their sizes and checksums. Throws InputError
// naming the first file that is missing or differs (an interrupted run, or a file changed by
// hand), with what to do. A folder without a manifest (written by an older Spira) passes.
void verifyOutputSet(const std::filesystem::path& dir);

}  // namespace spira
