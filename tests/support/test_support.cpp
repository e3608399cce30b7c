#include "support/test_support.h"

#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "spira/document/project_file.h"

namespace fs = std::filesystem;

namespace spira::test {

TempDir::TempDir()
{
  std::random_device rd;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::ostringstream name;
  name << "spira-test-" << (info ? info->name() : "x") << "-" << std::hex << rd() << rd();
  path_ = fs::temp_directory_path() / name.str();
  fs::create_directories(path_);
}

TempDir::~TempDir()
{
  std::error_code ec;
  fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
  fs::remove_all(path_, ec);
}

fs::path sourceDir()
{
  return SPIRA_SOURCE_DIR;
}
fs::path binaryDir()
{
  return SPIRA_BINARY_DIR;
}

void writeBytes(const fs::path& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string readBytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string projectFrame(std::uint32_t version, const std::string& payload, std::uint32_t crc)
{
  std::string out = "SPIRAPRJ";
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((version >> (8 * i)) & 0xFF));
  const std::uint64_t n = payload.size();
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((n >> (8 * i)) & 0xFF));
  out += payload;
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((crc >> (8 * i)) & 0xFF));
  return out;
}

std::string projectBytesOf(const nlohmann::json& j)
{
  const auto cbor = nlohmann::json::to_cbor(j);
  const std::string payload(cbor.begin(), cbor.end());
  return projectFrame(kProjectFormatVersion, payload, crc32(payload));
}

nlohmann::json projectJsonOf(const std::string& file)
{
  return nlohmann::json::from_cbor(file.substr(20, file.size() - 24));
}

}  // namespace spira::test
