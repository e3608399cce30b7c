#include "spira/scan/scan_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <vector>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/io/import_service.h"
#include "spira/io/mapped_file.h"
#include "spira/io/ply_reader.h"

namespace spira {
namespace {

const char* const kTextHint =
    "write one point per line as x y z (optionally nx ny nz), in mm, separated by spaces or commas";

std::string lowerCase(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// The fields of one text line, split at spaces, tabs, commas and semicolons.
std::vector<std::string_view> fieldsOf(std::string_view line)
{
  std::vector<std::string_view> out;
  size_t i = 0;
  const auto separator = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; };
  while (i < line.size()) {
    while (i < line.size() && separator(line[i])) ++i;
    size_t j = i;
    while (j < line.size() && !separator(line[j])) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

bool number(std::string_view text, double& value)
{
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

// Which column holds x, y, z and nx, ny, nz (-1: none), from a header line's names.
struct Columns {
  int at[6] = {0, 1, 2, -1, -1, -1};
};

bool columnsFromNames(const std::vector<std::string_view>& names, Columns& c)
{
  static const char* const kNames[6][2] = {{"x", "x"},         {"y", "y"},         {"z", "z"},
                                           {"nx", "normal_x"}, {"ny", "normal_y"}, {"nz", "normal_z"}};
  Columns found;
  std::fill(std::begin(found.at), std::end(found.at), -1);
  for (size_t k = 0; k < names.size(); ++k) {
    const std::string name = lowerCase(std::string(names[k]));
    for (int f = 0; f < 6; ++f)
      if (name == kNames[f][0] || name == kNames[f][1] || name == "//" + std::string(kNames[f][0]))
        found.at[f] = int(k);
  }
  if (found.at[0] < 0 || found.at[1] < 0 || found.at[2] < 0) return false;
  if (found.at[3] < 0 || found.at[4] < 0 || found.at[5] < 0) found.at[3] = found.at[4] = found.at[5] = -1;
  c = found;
  return true;
}

std::string lineAt(const std::string& source, size_t line)
{
  return "'" + source + "' line " + std::to_string(line);
}

void requirePoints(const PointCloud& cloud, const std::string& source, const char* hint)
{
  if (cloud.empty()) throw InputError("'" + source + "' holds no point", hint);
}

// Normals given in a file are unit vectors; a zero one (a scanner's "none") is refused with its place.
void normaliseNormals(PointCloud& cloud, const std::string& source)
{
  for (size_t i = 0; i < cloud.normals.size(); ++i) {
    const double n = cloud.normals[i].norm();
    if (!(n > 1e-9))
      throw InputError("'" + source + "': point " + std::to_string(i) + " has a zero normal",
                       "export the scan with estimated normals, or without normals (Spira then needs none)");
    cloud.normals[i] /= n;
  }
}

}  // namespace

PointCloud parseXyzText(std::string_view text, const std::string& source)
{
  PointCloud cloud;
  Columns columns;
  bool decided = false;  // whether the columns are known (a header line, or the first data line)
  size_t lineNo = 0, pos = 0, width = 0;
  std::vector<std::array<double, 3>> sixth;  // columns 4..6 of a 6-column file without a header
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++lineNo;
    const size_t comment = std::min(line.find('#'), line.find("//") == 0 ? 0 : std::string_view::npos);
    if (comment != std::string_view::npos && comment == 0) {
      // A commented header ("//X,Y,Z" as CloudCompare writes it) still names the columns.
      if (!decided && line.rfind("//", 0) == 0 && columnsFromNames(fieldsOf(line.substr(2)), columns))
        decided = true, width = fieldsOf(line.substr(2)).size();
      continue;
    }
    line = line.substr(0, std::min(line.find('#'), line.size()));
    const std::vector<std::string_view> fields = fieldsOf(line);
    if (fields.empty()) continue;
    double v[64];
    const size_t n = std::min<size_t>(fields.size(), 64);
    bool numeric = true;
    for (size_t k = 0; k < n && numeric; ++k) numeric = number(fields[k], v[k]);
    if (!numeric) {
      if (!decided && cloud.empty() && columnsFromNames(fields, columns)) {
        decided = true, width = fields.size();
        continue;
      }
      size_t bad = 0;
      while (bad < n && number(fields[bad], v[bad])) ++bad;
      throw InputError(
          lineAt(source, lineNo) + ": '" + clippedText(fields[std::min(bad, n - 1)]) + "' is not a number",
          kTextHint);
    }
    if (!decided) {
      if (n < 3)
        throw InputError(lineAt(source, lineNo) + ": " + std::to_string(n) + " value(s), a point needs x y z",
                         kTextHint);
      decided = true, width = n;
    }
    if (n != width)
      throw InputError(lineAt(source, lineNo) + ": " + std::to_string(n) +
                           " values where the file's lines hold " + std::to_string(width),
                       kTextHint);
    const Vec3 p(v[columns.at[0]], v[columns.at[1]], v[columns.at[2]]);
    if (!p.allFinite()) throw InputError(lineAt(source, lineNo) + ": the point is not finite", kTextHint);
    cloud.points.push_back(p);
    if (columns.at[3] >= 0)
      cloud.normals.emplace_back(v[columns.at[3]], v[columns.at[4]], v[columns.at[5]]);
    else if (width == 6)
      sixth.push_back({v[3], v[4], v[5]});
  }
  requirePoints(cloud, source, kTextHint);
  // Six unnamed columns: x y z nx ny nz when the last three are unit vectors throughout.
  if (!sixth.empty() && sixth.size() == cloud.size() &&
      std::all_of(sixth.begin(), sixth.end(), [](const std::array<double, 3>& a) {
        return std::abs(std::hypot(a[0], a[1], a[2]) - 1.0) < 1e-3;
      }))
    for (const auto& a : sixth) cloud.normals.emplace_back(a[0], a[1], a[2]);
  normaliseNormals(cloud, source);
  return cloud;
}

PointCloud parsePcd(std::string_view bytes, const std::string& source)
{
  const char* const hint = "save the cloud again with pcl_convert_pcd_ascii_binary (ascii or binary)";
  std::vector<std::string> fields;
  std::vector<int> sizes, counts;
  std::vector<char> types;
  size_t points = 0, pos = 0, lineNo = 0;
  std::string data;
  while (data.empty()) {
    if (pos >= bytes.size())
      throw InputError("'" + source + "' ends before its PCD header's DATA line", hint);
    size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    const std::string_view line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++lineNo;
    const std::vector<std::string_view> f = fieldsOf(line);
    if (f.empty() || f[0].front() == '#') continue;
    const std::string key = lowerCase(std::string(f[0]));
    const auto numbers = [&](std::vector<int>& out) {
      for (size_t k = 1; k < f.size(); ++k) {
        double v = 0.0;
        if (!number(f[k], v) || v < 1 || v != std::floor(v) || v > 1e6)
          throw InputError(lineAt(source, lineNo) + ": '" + clippedText(f[k]) + "' is not a positive count",
                           hint);
        out.push_back(int(v));
      }
    };
    if (key == "fields") {
      for (size_t k = 1; k < f.size(); ++k) fields.push_back(lowerCase(std::string(f[k])));
    } else if (key == "size") {
      numbers(sizes);
    } else if (key == "count") {
      numbers(counts);
    } else if (key == "type") {
      for (size_t k = 1; k < f.size(); ++k) types.push_back(char(std::toupper(f[k].front())));
    } else if (key == "points") {
      double v = 0.0;
      if (f.size() < 2 || !number(f[1], v) || v < 0 || v != std::floor(v))
        throw InputError(lineAt(source, lineNo) + ": POINTS is not a count", hint);
      points = size_t(v);
    } else if (key == "data") {
      data = f.size() > 1 ? lowerCase(std::string(f[1])) : "?";
    }
  }
  if (counts.empty()) counts.assign(fields.size(), 1);
  if (fields.empty() || sizes.size() != fields.size() || types.size() != fields.size() ||
      counts.size() != fields.size())
    throw InputError("'" + source + "': the PCD header's FIELDS, SIZE, TYPE and COUNT lines do not match",
                     hint);
  const auto find = [&](const char* name) {
    return int(std::find(fields.begin(), fields.end(), name) - fields.begin());
  };
  int at[6] = {find("x"), find("y"), find("z"), find("normal_x"), find("normal_y"), find("normal_z")};
  for (int k = 0; k < 3; ++k)
    if (at[k] >= int(fields.size()))
      throw InputError(
          "'" + source + "': the PCD header has no field '" + std::string(1, char('x' + k)) + "'", hint);
  const bool normals = at[3] < int(fields.size()) && at[4] < int(fields.size()) && at[5] < int(fields.size());
  // Value offsets within a record (binary) and value indices within a line (ascii).
  std::vector<size_t> offset(fields.size()), index(fields.size());
  size_t record = 0, values = 0;
  for (size_t k = 0; k < fields.size(); ++k) {
    offset[k] = record, index[k] = values;
    record += size_t(sizes[k]) * size_t(counts[k]);
    values += size_t(counts[k]);
  }
  PointCloud cloud;
  const auto store = [&](const double* v) {
    const Vec3 p(v[0], v[1], v[2]);
    if (!p.allFinite()) return;  // PCL marks missing returns as NaN: not points
    cloud.points.push_back(p);
    if (normals) cloud.normals.emplace_back(v[3], v[4], v[5]);
  };
  const int used = normals ? 6 : 3;
  if (data == "ascii") {
    std::vector<std::string_view> f;
    for (size_t k = 0; k < points; ++k) {
      if (pos >= bytes.size())
        throw InputError("'" + source + "' ends after " + std::to_string(k) + " of its " +
                             std::to_string(points) + " points",
                         hint);
      size_t end = bytes.find('\n', pos);
      if (end == std::string_view::npos) end = bytes.size();
      f = fieldsOf(bytes.substr(pos, end - pos));
      pos = end + 1;
      ++lineNo;
      if (f.size() != values)
        throw InputError(lineAt(source, lineNo) + ": " + std::to_string(f.size()) +
                             " values, the header declares " + std::to_string(values),
                         hint);
      double v[6];
      for (int u = 0; u < used; ++u) {
        const std::string_view text = f[index[size_t(at[u])]];
        if (!number(text, v[u]) && lowerCase(std::string(text)) != "nan")
          throw InputError(lineAt(source, lineNo) + ": '" + clippedText(text) + "' is not a number", hint);
        if (lowerCase(std::string(text)) == "nan") v[u] = NAN;
      }
      store(v);
    }
  } else if (data == "binary") {
    if (record == 0 || (bytes.size() - std::min(pos, bytes.size())) / record < points)
      throw InputError("'" + source + "': the PCD header declares " + std::to_string(points) +
                           " points, more than its bytes hold",
                       hint);
    for (int u = 0; u < used; ++u) {
      const size_t k = size_t(at[u]);
      if (!((types[k] == 'F' && (sizes[k] == 4 || sizes[k] == 8)) ||
            ((types[k] == 'I' || types[k] == 'U') && sizes[k] <= 8)))
        throw InputError("'" + source + "': field '" + fields[k] + "' has type " + std::string(1, types[k]) +
                             std::to_string(sizes[k]) + ", not a number type",
                         hint);
    }
    for (size_t i = 0; i < points; ++i) {
      const char* rec = bytes.data() + pos + i * record;
      double v[6];
      for (int u = 0; u < used; ++u) {
        const size_t k = size_t(at[u]);
        const char* p = rec + offset[k];
        if (types[k] == 'F' && sizes[k] == 4) {
          float x;
          std::memcpy(&x, p, 4);
          v[u] = x;
        } else if (types[k] == 'F') {
          std::memcpy(&v[u], p, 8);
        } else {
          std::int64_t x = 0;
          std::memcpy(&x, p, size_t(sizes[k]));
          v[u] = double(x);
        }
      }
      store(v);
    }
  } else if (data == "binary_compressed") {
    throw InputError(
        "'" + source + "' is a compressed PCD (DATA binary_compressed), which Spira does not read", hint);
  } else {
    throw InputError(
        "'" + source + "': DATA '" + clippedText(data) + "' is not ascii, binary or binary_compressed", hint);
  }
  requirePoints(cloud, source, hint);
  normaliseNormals(cloud, source);
  return cloud;
}

PointCloud readScan(const PluginRegistry& registry, const std::filesystem::path& file, Progress& progress)
{
  const std::string ext = lowerCase(file.extension().string());
  const std::string name = file.filename().string();
  if (ext == ".ply") {
    PlyData ply = readPlyPoints(file, progress);
    PointCloud cloud;
    cloud.points = std::move(ply.mesh.vertices);
    cloud.normals = std::move(ply.normals);
    for (size_t i = 0; i < cloud.size(); ++i)
      if (!cloud.points[i].allFinite())
        throw InputError("'" + name + "': vertex " + std::to_string(i) + " is not finite",
                         "export the scan again without invalid returns");
    normaliseNormals(cloud, name);
    return cloud;
  }
  if (ext == ".pcd") {
    const MappedFile mapped(file);
    return parsePcd(mapped.bytes(), name);
  }
  if (ext == ".xyz" || ext == ".csv" || ext == ".txt" || ext == ".asc" || ext == ".pts") {
    const MappedFile mapped(file);
    return parseXyzText(mapped.bytes(), name);
  }
  ImportedPart mesh = importPart(registry, file, nullptr, progress);
  PointCloud cloud;
  cloud.normals = mesh.mesh.vertexNormals();
  cloud.points = std::move(mesh.mesh.vertices);
  // An isolated vertex has no normal: then the mesh's normals are not used at all.
  if (std::any_of(cloud.normals.begin(), cloud.normals.end(),
                  [](const Vec3& n) { return n.squaredNorm() < 0.5; }))
    cloud.normals.clear();
  return cloud;
}

}  // namespace spira
