#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace spira {

// A whole file viewed read-only in memory. Large files are memory-mapped with their pages
// populated up front (no copy, no zero-filled buffer); when mapping is not possible the file is
// read into a string instead. Throws IoError when the file cannot be opened or read.
class MappedFile {
 public:
  explicit MappedFile(const std::filesystem::path& file);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return view_; }

 private:
  void* map_ = nullptr;
  size_t mapSize_ = 0;
  std::string copy_;
  std::string_view view_;
};

}  // namespace spira
