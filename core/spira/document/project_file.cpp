#include "spira/document/project_file.h"

#include <array>

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/version.h"
#include "spira/io/json_codec.h"
#include "spira/io/json_read.h"
#include "spira/robotcell/cell_file.h"

namespace spira {

namespace {

constexpr std::size_t kHeaderSize = 8 + 4 + 8;
constexpr std::size_t kTrailerSize = 4;
const char* kNotProject = "not a Spira project";
const char* kDamaged = "file is truncated or damaged";
const char* kDamagedHint = "open a backup copy of the project, or re-import the part and plan again";

std::array<std::uint32_t, 256> makeCrcTable()
{
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}

void putLe(std::string& out, std::uint64_t v, int bytes)
{
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

std::uint64_t getLe(std::string_view in, std::size_t offset, int bytes)
{
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= std::uint64_t{static_cast<unsigned char>(in[offset + i])} << (8 * i);
  return v;
}

// The cell's files relative to the project's folder, next to the absolute paths the cell holds: a
// project moved together with them (or shipped with Spira) finds them through these, a project
// moved alone through the absolute ones.
constexpr const char* kRelativePaths = "relative_paths";

nlohmann::json relativePaths(const CellRecord& c, const std::filesystem::path& dir)
{
  nlohmann::json j = nlohmann::json::object();
  // Only paths that relativeTo changes: a relative path already is one, an empty one names no file.
  if (const std::string r = relativeTo(c.robotUrdf, dir); r != c.robotUrdf) j["robot_urdf"] = r;
  if (const std::string r = relativeTo(c.positionerUrdf, dir); r != c.positionerUrdf)
    j["positioner_urdf"] = r;
  return j;
}

// `file` as the relative path stored under `key` finds it from `dir`, when that file exists.
void resolveRelative(const nlohmann::json& paths, const char* key, const std::filesystem::path& dir,
                     std::string& file)
{
  if (!paths.contains(key)) return;
  const std::filesystem::path candidate =
      (dir / codec::stringField(paths, key, "project relative_paths")).lexically_normal();
  std::error_code ec;
  if (std::filesystem::is_regular_file(candidate, ec)) file = candidate.string();
}

nlohmann::json toProjectJson(const DocumentState& s, const std::filesystem::path& dir)
{
  nlohmann::json j;
  j["application"] = kApplicationName;
  j["spira_version"] = kVersion;
  j["part"] = s.part ? partToJson(*s.part) : nlohmann::json(nullptr);
  j["substrate"] = substrateToJson(s.substrate ? *s.substrate : Substrate());
  j["cell"] = s.cell ? cellRecordToJson(*s.cell) : nlohmann::json(nullptr);
  if (s.cell && !dir.empty()) j[kRelativePaths] = relativePaths(*s.cell, dir);
  if (s.scan) {
    j["scan"] = scanRecordToJson(*s.scan);
    if (!dir.empty())
      if (const std::string r = relativeTo(s.scan->file, dir); r != s.scan->file)
        j["scan"]["relative_file"] = r;
  }
  j["plan"] = planSettingsToJson(s.settings ? *s.settings : PlanSettings());
  j["results"] = resultsToJson(s.results);
  return j;
}

DocumentState fromProjectJson(const nlohmann::json& j, const std::filesystem::path& dir)
{
  const std::string what = "project";
  codec::stringField(j, "spira_version", what);
  DocumentState s;
  const auto& part = codec::field(j, "part", what);
  if (!part.is_null()) s.part = std::make_shared<const Part>(partFromJson(part));
  s.substrate = std::make_shared<const Substrate>(substrateFromJson(codec::field(j, "substrate", what)));
  const auto& cell = codec::field(j, "cell", what);
  if (!cell.is_null()) {
    CellRecord record = cellRecordFromJson(cell);
    if (j.contains(kRelativePaths) && !dir.empty()) {
      const nlohmann::json& paths = j[kRelativePaths];
      if (!paths.is_object())
        throw InputError("the project's relative_paths is not an object", "save the project again in Spira");
      resolveRelative(paths, "robot_urdf", dir, record.robotUrdf);
      resolveRelative(paths, "positioner_urdf", dir, record.positionerUrdf);
    }
    s.cell = std::make_shared<const CellRecord>(std::move(record));
  }
  s.settings = std::make_shared<const PlanSettings>(planSettingsFromJson(codec::field(j, "plan", what)));
  if (j.contains("scan") && !j["scan"].is_null()) {
    ScanRecord scan = scanRecordFromJson(j["scan"]);
    if (!dir.empty()) resolveRelative(j["scan"], "relative_file", dir, scan.file);
    s.scan = std::make_shared<const ScanRecord>(std::move(scan));
  }
  s.results = resultsFromJson(codec::field(j, "results", what));
  return s;
}

}  // namespace

std::uint32_t crc32(std::string_view bytes)
{
  static const auto table = makeCrcTable();
  std::uint32_t c = 0xFFFFFFFFu;
  for (char ch : bytes) c = table[(c ^ static_cast<unsigned char>(ch)) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::string encodeProject(const DocumentState& state, const std::filesystem::path& projectDir)
{
  const std::vector<std::uint8_t> cbor = nlohmann::json::to_cbor(toProjectJson(state, projectDir));
  const std::string_view payload(reinterpret_cast<const char*>(cbor.data()), cbor.size());
  std::string out;
  out.reserve(kHeaderSize + payload.size() + kTrailerSize);
  out.append(kProjectMagic);
  putLe(out, kProjectFormatVersion, 4);
  putLe(out, payload.size(), 8);
  out.append(payload);
  putLe(out, crc32(payload), 4);
  return out;
}

DocumentState decodeProject(std::string_view bytes, const std::filesystem::path& projectDir)
{
  if (bytes.empty())
    throw InputError(std::string(kNotProject) + " (the file is empty)", "choose a .spira file");
  if (bytes.size() < kProjectMagic.size() && kProjectMagic.substr(0, bytes.size()) == bytes)
    throw InputError(kDamaged, kDamagedHint);
  if (bytes.size() < kProjectMagic.size() || bytes.substr(0, kProjectMagic.size()) != kProjectMagic)
    throw InputError(kNotProject, "choose a .spira file saved by Spira");
  if (bytes.size() < kHeaderSize + kTrailerSize) throw InputError(kDamaged, kDamagedHint);
  const auto version = static_cast<std::uint32_t>(getLe(bytes, 8, 4));
  if (version > kProjectFormatVersion)
    throw InputError("the project was saved in format version " + std::to_string(version) + ", this Spira " +
                         kVersion + " reads up to version " + std::to_string(kProjectFormatVersion),
                     "update Spira to open this project");
  if (version == 0) throw InputError(std::string(kDamaged) + " (format version 0)", kDamagedHint);
  const std::uint64_t size = getLe(bytes, 12, 8);
  if (size != bytes.size() - kHeaderSize - kTrailerSize) throw InputError(kDamaged, kDamagedHint);
  const std::string_view payload = bytes.substr(kHeaderSize, static_cast<std::size_t>(size));
  if (crc32(payload) != static_cast<std::uint32_t>(getLe(bytes, kHeaderSize + payload.size(), 4)))
    throw InputError(std::string(kDamaged) + " (checksum mismatch)", kDamagedHint);
  return fromProjectJson(json_read::parseCbor(payload, "the project content", kDamagedHint), projectDir);
}

namespace {

std::filesystem::path folderOf(const std::filesystem::path& project)
{
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(project, ec);
  return ec ? std::filesystem::path() : absolute.parent_path();
}

}  // namespace

void saveProject(const DocumentState& state, const std::filesystem::path& path)
{
  writeFileAtomically(path, encodeProject(state, folderOf(path)));
}

DocumentState loadProject(const std::filesystem::path& path)
{
  const std::string bytes = readFile(path);
  try {
    return decodeProject(bytes, folderOf(path));
  } catch (const InputError& e) {
    throw InputError(path.filename().string() + ": " + e.what(), e.hint());
  }
}

}  // namespace spira
