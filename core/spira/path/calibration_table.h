#pragma once

#include <istream>
#include <string>
#include <vector>

namespace spira {

// A measured deposit-height -> travel-speed relation at constant wire feed (thesis 000_dbb97c2716e10cc3.txt
// §4.3.1: seven beads at different speeds, piecewise-linear interpolation between them). Heights are strictly
// increasing and travel speeds strictly decreasing with them: a thicker bead needs a slower torch.
class CalibrationTable {
 public:
  CalibrationTable() = default;
  // Rows in any order; sorted by height. Throws InputError for fewer than 2 rows, sizes that
  // differ, non-positive or non-finite values, a repeated height, or speeds that do not strictly
  // decrease as the height grows (naming the offending rows).
  CalibrationTable(std::vector<double> heights, std::vector<double> travelSpeeds);

  bool empty() const { return heights_.empty(); }
  size_t size() const { return heights_.size(); }
  const std::vector<double>& heights() const { return heights_; }            // mm, increasing
  const std::vector<double>& travelSpeeds() const { return travelSpeeds_; }  // mm/s, decreasing
  double heightMin() const { return heights_.front(); }
  double heightMax() const { return heights_.back(); }
  bool covers(double height) const { return height >= heightMin() && height <= heightMax(); }
  // Piecewise-linear travel speed for `height`; heights beyond the table take the end value.
  double travelSpeed(double height) const;
  // Its inverse: the height laid at `travelSpeed`; speeds beyond the table take the end value.
  double height(double travelSpeed) const;

 private:
  std::vector<double> heights_;
  std::vector<double> travelSpeeds_;
};

// Reads a CSV table with a header naming the columns `height_mm` and `travel_speed_mm_s` (any
// order, other columns ignored), one row per bead. Blank lines and lines starting with '#' are
// skipped. `source` names the input in messages. Throws InputError (with the line number) for a
// missing column or a bad number, and the CalibrationTable errors for bad values.
CalibrationTable parseCalibrationCsv(std::istream& in, const std::string& source);
// Same from a file; throws IoError when it cannot be opened.
CalibrationTable readCalibrationCsv(const std::string& path);

}  // namespace spira
