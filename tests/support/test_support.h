#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

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

// A project file's bytes: `payload` framed, or the project JSON `j` framed as project_file.h documents it
// (written independently of the implementation), and the JSON inside a project file's bytes: for
// tests that damage a project or read what an earlier version stored.
std::string projectFrame(std::uint32_t version, const std::string& payload, std::uint32_t crc);
std::string projectBytesOf(const nlohmann::json& j);
nlohmann::json projectJsonOf(const std::string& file);

}  // namespace spira::test
