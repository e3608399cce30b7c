// A plan folder's trajectory.csv, which export turns into a robot program. What it accepts must
// write back to a file that reads as the same trajectory; the wire-feed speed, written in m/min and
// kept in mm/s, may differ in its last bits.
#include <cmath>
#include <limits>

#include "../fuzz_support.h"
#include "spira/planning/plan_files.h"
#include "spira/planning/trajectory_csv_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::refusalsAllowed([&] {
    const spira::Trajectory read = spira::trajectoryFromCsv(std::string(spira::fuzz::bytes(data, size)));
    spira::Trajectory again = spira::trajectoryFromCsv(spira::trajectoryCsv(read));
    if (again.size() != read.size())
      spira::fuzz::violated("a written trajectory reads back with another length");
    for (size_t i = 0; i < read.size(); ++i) {
      double& wireFeed = again.points[i].wireFeed;
      const double original = read.points[i].wireFeed;
      if (std::abs(wireFeed - original) <= 4 * std::numeric_limits<double>::epsilon() * std::abs(original))
        wireFeed = original;
    }
    if (!(again == read))
      spira::fuzz::violated("an accepted trajectory.csv does not survive a write and read");
  });
}
