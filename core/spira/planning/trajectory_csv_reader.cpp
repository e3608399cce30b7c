#include "spira/planning/trajectory_csv_reader.h"

#include <charconv>
#include <cmath>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"

namespace spira {
namespace {

constexpr const char* kHeader = "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc,path";
// Plans written before multi-branch parts had no path column: one path.
constexpr const char* kSinglePathHeader = "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc";
constexpr int kMaxColumns = 20;

}  // namespace

Trajectory trajectoryFromCsv(const std::string& text, const std::string& what)
{
  Trajectory t;
  size_t pos = 0, lineNo = 0;
  int columns = kMaxColumns;
  const auto fail = [&](const std::string& problem) -> void {
    throw InputError(what + " line " + std::to_string(lineNo) + ": " + problem,
                     "use the trajectory.csv that 'spira-cli plan' wrote, unedited");
  };
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (lineNo == 1) {
      if (line == kSinglePathHeader)
        columns = kMaxColumns - 1;
      else if (line != kHeader)
        fail("the header is not '" + std::string(kHeader) + "'");
      continue;
    }
    if (line.empty()) continue;
    double v[kMaxColumns] = {};
    int col = 0;
    size_t at = 0;
    while (col < columns) {
      const size_t comma = std::min(line.find(',', at), line.size());
      const char* first = line.data() + at;
      const char* last = line.data() + comma;
      const auto res = std::from_chars(first, last, v[col]);
      if (res.ec != std::errc() || res.ptr != last || !std::isfinite(v[col]))
        fail("column " + std::to_string(col + 1) + " is not a number");
      ++col;
      at = comma + 1;
      if (comma == line.size()) break;
    }
    if (col != columns || at <= line.size()) fail("expected " + std::to_string(columns) + " columns");
    if (v[0] != static_cast<double>(t.points.size())) fail("the index is not the row number");
    if (v[19] < 0 || v[19] != std::floor(v[19])) fail("the path is not a sub-path number");
    TrajectoryPoint p;
    p.position = Vec3(v[1], v[2], v[3]);
    p.normal = Vec3(v[4], v[5], v[6]);
    p.tangent = Vec3(v[7], v[8], v[9]);
    p.build = Vec3(v[10], v[11], v[12]);
    p.revolution = static_cast<int>(v[13]);
    p.generatrix = static_cast<int>(v[14]);
    p.height = v[15];
    p.travelSpeed = v[16];
    p.wireFeed = v[17] * 1000.0 / 60.0;
    p.arcOn = v[18] != 0.0;
    p.path = static_cast<int>(v[19]);
    t.points.push_back(p);
  }
  if (lineNo == 0) fail("the file is empty");
  return t;
}

Trajectory readTrajectoryCsv(const std::filesystem::path& file)
{
  return trajectoryFromCsv(readFile(file), file.string());
}

}  // namespace spira
