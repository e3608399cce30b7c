#pragma once

#include <filesystem>
#include <string>

namespace spira::test {

// A fresh, empty folder for one test, removed when the object goes away.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

std::filesystem::path sourceDir();
std::filesystem::path binaryDir();
// Writes `bytes` to `path` as is (test inputs, including deliberately broken ones).
void writeBytes(const std::filesystem::path& path, const std::string& bytes);
// The whole file as is; empty when it cannot be read.
std::string readBytes(const std::filesystem::path& path);

}  // namespace spira::test
