#include "spira/planning/trajectory_csv_reader.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/path/dwell.h"
#include "spira/path/tool_tilt.h"

namespace spira {
namespace {

constexpr const char* kHeader = "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc,path";
// Plans written before multi-branch parts had no path column: one path.
constexpr const char* kSinglePathHeader = "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc";
constexpr int kAllColumns = 24;
constexpr const char* kColumnNames[kAllColumns] = {
    "index", "x",   "y",   "z",      "nx", "ny",  "nz",  "tx",   "ty",      "tz", "bx", "by",
    "bz",    "rev", "gen", "height", "ts", "wfs", "arc", "path", "dwell_s", "ux", "uy", "uz"};
enum Column {
  kIndex = 0,
  kRev = 13,
  kGen = 14,
  kHeight = 15,
  kTs = 16,
  kWfs = 17,
  kArc = 18,
  kPath = 19,
  kDwell = 20,
  kUp = 21
};

// The columns a header names, in file order (semantic Column values), or empty when it is not one
// trajectoryCsv writes: the fixed columns, then a dwell (path/dwell.h) and the up direction of a
// tilted torch (path/tool_tilt.h) when the plan has them.
std::vector<int> layoutOf(std::string_view header)
{
  std::vector<int> layout;
  if (header == kSinglePathHeader) {
    for (int c = 0; c < kPath; ++c) layout.push_back(c);
    return layout;
  }
  const std::string_view fixed(kHeader);
  if (header.substr(0, fixed.size()) != fixed) return layout;
  for (int c = 0; c <= kPath; ++c) layout.push_back(c);
  std::string_view rest = header.substr(fixed.size());
  if (rest.substr(0, 8) == ",dwell_s") {
    layout.push_back(kDwell);
    rest.remove_prefix(8);
  }
  if (rest.substr(0, 9) == ",ux,uy,uz") {
    for (int c = kUp; c < kUp + 3; ++c) layout.push_back(c);
    rest.remove_prefix(9);
  }
  if (!rest.empty()) layout.clear();
  return layout;
}

bool whole(double x)
{
  return x >= 0 && x == std::floor(x) && x < 1e9;
}

}  // namespace

Trajectory trajectoryFromCsv(const std::string& text, const std::string& what)
{
  Trajectory t;
  size_t pos = 0, lineNo = 0;
  std::vector<int> layout;
  bool hasUp = false;
  const auto fail = [&](const std::string& problem) -> void {
    throw InputError(what + " line " + std::to_string(lineNo) + ": " + problem,
                     "use the trajectory.csv that 'spira-cli plan' wrote, unedited");
  };
  const auto failAt = [&](int col, const std::string& problem) -> void {
    fail("column " + std::to_string(col + 1) + " (" + kColumnNames[col] + ") " + problem);
  };
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (lineNo == 1) {
      layout = layoutOf(line);
      if (layout.empty()) fail("the header is not '" + std::string(kHeader) + "'");
      hasUp = layout.back() == kUp + 2;
      continue;
    }
    if (line.empty()) continue;
    const int columns = static_cast<int>(layout.size());
    double v[kAllColumns] = {};
    int col = 0;
    size_t at = 0;
    while (col < columns) {
      const size_t comma = std::min(line.find(',', at), line.size());
      const char* first = line.data() + at;
      const char* last = line.data() + comma;
      const int c = layout[static_cast<size_t>(col)];
      const auto res = std::from_chars(first, last, v[c]);
      if (res.ec != std::errc() || res.ptr != last || !std::isfinite(v[c]))
        failAt(c,
               "is not a finite number, found '" + clippedText(std::string_view(first, last - first)) + "'");
      ++col;
      at = comma + 1;
      if (comma == line.size()) break;
    }
    if (col != columns || at <= line.size()) fail("expected " + std::to_string(columns) + " columns");
    if (v[kIndex] != static_cast<double>(t.points.size())) failAt(kIndex, "is not the row number");
    if (!whole(v[kPath]))
      failAt(kPath,
             "must be a sub-path number (a whole number from 0), found " + significantText(v[kPath], 6));
    for (int c : {kRev, kGen})
      if (!whole(v[c])) failAt(c, "must be a whole number from 0, found " + significantText(v[c], 6));
    // Sub-paths are numbered from 0 in the order they are built: a number that goes back or skips
    // would make the program start the arc where no sub-path starts.
    if (t.points.empty() && v[kPath] != 0)
      failAt(kPath, "must be 0 on the first row (sub-paths are numbered in order from 0), found " +
                        significantText(v[kPath], 6));
    if (const int previous = t.points.empty() ? 0 : t.points.back().path;
        v[kPath] < previous || v[kPath] > previous + 1)
      failAt(kPath, "must stay " + std::to_string(previous) + " or go on to " + std::to_string(previous + 1) +
                        " (sub-paths are numbered in order from 0), found " + significantText(v[kPath], 6));
    if (v[kTs] <= 0)
      failAt(kTs, "must be a positive travel speed in mm/s, found " + significantText(v[kTs], 6));
    if (v[kArc] != 0 && v[kArc] != 1) failAt(kArc, "must be 0 or 1, found " + significantText(v[kArc], 6));
    if (v[kArc] == 1 ? v[kWfs] <= 0 : v[kWfs] < 0)
      failAt(kWfs, std::string(v[kArc] == 1 ? "must be a positive wire-feed speed with the arc on"
                                            : "must not be negative") +
                       ", found " + significantText(v[kWfs], 6));
    if (v[kHeight] < 0) failAt(kHeight, "must not be negative, found " + significantText(v[kHeight], 6));
    if (v[kDwell] < 0) failAt(kDwell, "must be a wait in s from 0, found " + significantText(v[kDwell], 6));
    // The torch arrives at a dwell depositing; it stops the arc there, so there must be one to stop.
    if (v[kDwell] > 0 && v[kArc] != 1)
      failAt(kDwell, "must be 0 where the arc is off (a dwell stops the arc), found " +
                         significantText(v[kDwell], 6));
    if (hasUp && Vec3(v[kUp], v[kUp + 1], v[kUp + 2]).norm() < 1e-9)
      failAt(kUp, "must hold, with uy and uz, the build direction (a unit vector), found zero");
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
    t.extra[kDwellChannel].push_back(v[kDwell]);
    if (hasUp)
      for (int k = 0; k < 3; ++k) t.extra[kUpChannels[k]].push_back(v[kUp + k]);
  }
  if (lineNo == 0) fail("the file is empty");
  // As trajectoryCsv writes the column: a column of zeros plans no dwell, so it reads as none.
  if (!hasDwell(t)) t.extra.erase(kDwellChannel);
  return t;
}

Trajectory readTrajectoryCsv(const std::filesystem::path& file)
{
  return trajectoryFromCsv(readFile(file), file.string());
}

}  // namespace spira
