#include "spira/path/calibration_table.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {

namespace {

const char* const kHint =
    "give at least two beads as height_mm,travel_speed_mm_s rows, the speed falling as the height grows";

std::string trim(const std::string& s)
{
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::vector<std::string> splitCsv(const std::string& line)
{
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

CalibrationTable::CalibrationTable(std::vector<double> heights, std::vector<double> travelSpeeds)
{
  if (heights.size() != travelSpeeds.size())
    throw InputError("the calibration table has " + std::to_string(heights.size()) + " heights but " +
                         std::to_string(travelSpeeds.size()) + " travel speeds",
                     kHint);
  if (heights.size() < 2)
    throw InputError("the calibration table needs at least 2 rows, it has " + std::to_string(heights.size()),
                     kHint);
  for (size_t r = 0; r < heights.size(); ++r)
    if (!std::isfinite(heights[r]) || !std::isfinite(travelSpeeds[r]) || heights[r] <= 0.0 ||
        travelSpeeds[r] <= 0.0) {
      std::ostringstream m;
      m << "calibration row " << r + 1 << " (height " << heights[r] << " mm, travel speed " << travelSpeeds[r]
        << " mm/s) is not a pair of positive numbers";
      throw InputError(m.str(), kHint);
    }
  std::vector<size_t> order(heights.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return heights[a] < heights[b]; });
  for (size_t r : order) {
    heights_.push_back(heights[r]);
    travelSpeeds_.push_back(travelSpeeds[r]);
  }
  for (size_t k = 1; k < heights_.size(); ++k) {
    std::ostringstream m;
    if (heights_[k] == heights_[k - 1]) {
      m << "the calibration table gives height " << heights_[k] << " mm twice (rows " << order[k - 1] + 1
        << " and " << order[k] + 1 << ")";
      throw InputError(m.str(), "keep one travel speed per height (average repeated measurements)");
    }
    if (travelSpeeds_[k] >= travelSpeeds_[k - 1]) {
      m << "calibration travel speeds must fall as the height grows, but height " << heights_[k - 1] << " -> "
        << heights_[k] << " mm goes with travel speed " << travelSpeeds_[k - 1] << " -> " << travelSpeeds_[k]
        << " mm/s (rows " << order[k - 1] + 1 << " and " << order[k] + 1 << ")";
      throw InputError(m.str(), "re-measure or drop the outlier: a thicker bead needs a slower travel speed");
    }
  }
}

double CalibrationTable::travelSpeed(double height) const
{
  if (height <= heights_.front()) return travelSpeeds_.front();
  if (height >= heights_.back()) return travelSpeeds_.back();
  const size_t k =
      static_cast<size_t>(std::upper_bound(heights_.begin(), heights_.end(), height) - heights_.begin());
  const double t = (height - heights_[k - 1]) / (heights_[k] - heights_[k - 1]);
  return travelSpeeds_[k - 1] + t * (travelSpeeds_[k] - travelSpeeds_[k - 1]);
}

double CalibrationTable::height(double travelSpeed) const
{
  // Speeds decrease as heights grow: the segment whose speeds bracket travelSpeed.
  if (travelSpeed >= travelSpeeds_.front()) return heights_.front();
  if (travelSpeed <= travelSpeeds_.back()) return heights_.back();
  const size_t k = static_cast<size_t>(
      std::upper_bound(travelSpeeds_.begin(), travelSpeeds_.end(), travelSpeed, std::greater<double>()) -
      travelSpeeds_.begin());
  const double t = (travelSpeed - travelSpeeds_[k - 1]) / (travelSpeeds_[k] - travelSpeeds_[k - 1]);
  return heights_[k - 1] + t * (heights_[k] - heights_[k - 1]);
}

CalibrationTable parseCalibrationCsv(std::istream& in, const std::string& source)
{
  std::string line;
  int lineNo = 0;
  int hCol = -1, tsCol = -1;
  std::vector<double> heights, speeds;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> cells = splitCsv(t);
    if (hCol < 0) {
      for (size_t c = 0; c < cells.size(); ++c) {
        if (lower(cells[c]) == "height_mm") hCol = static_cast<int>(c);
        if (lower(cells[c]) == "travel_speed_mm_s") tsCol = static_cast<int>(c);
      }
      if (hCol < 0 || tsCol < 0)
        throw InputError(source + ", line " + std::to_string(lineNo) +
                             ": the header must name the columns height_mm and travel_speed_mm_s",
                         "start the file with the line: height_mm,travel_speed_mm_s");
      continue;
    }
    double values[2] = {0.0, 0.0};
    const int cols[2] = {hCol, tsCol};
    for (int v = 0; v < 2; ++v) {
      const std::string cell = static_cast<size_t>(cols[v]) < cells.size() ? cells[cols[v]] : std::string();
      std::string problem;
      const auto x = parseFiniteNumber(cell, problem);
      if (!x)
        throw InputError(
            source + ", line " + std::to_string(lineNo) + ": '" + clippedText(cell) + "' " + problem,
            "write plain decimal numbers with a '.' decimal point");
      values[v] = *x;
    }
    heights.push_back(values[0]);
    speeds.push_back(values[1]);
  }
  if (hCol < 0)
    throw InputError(source + " holds no calibration table",
                     "start the file with the line: height_mm,travel_speed_mm_s");
  try {
    return CalibrationTable(std::move(heights), std::move(speeds));
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what(), e.hint());
  }
}

CalibrationTable readCalibrationCsv(const std::string& path)
{
  std::istringstream in(readFile(path));
  return parseCalibrationCsv(in, path);
}

}  // namespace spira
