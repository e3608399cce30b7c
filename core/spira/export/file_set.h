#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace spira {

// One file of an export: its name inside the output folder and its whole content.
struct OutputFile {
  std::string name;
  std::string bytes;
};

// Writes all `files` into `dir`, or none of them. Every file is first written in full to a
// hidden temporary file beside its target and synced; only when all of them are on disk are
// they renamed over their targets. A failure while staging (disk full, permissions) removes the
// temporary files and leaves the folder as it was. The rename step cannot leave a half-written
// file; should a rename itself fail, the files already renamed by this call are removed again.
// Throws IoError naming the file and the reason. Returns the written paths, in order.
std::vector<std::filesystem::path> writeFileSet(const std::filesystem::path& dir,
                                                const std::vector<OutputFile>& files);

}  // namespace spira
