// The deposit calibration table (CSV of height and travel speed).
#include <sstream>

#include "../fuzz_support.h"
#include "spira/path/calibration_table.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::refusalsAllowed([&] {
    std::istringstream in{std::string(spira::fuzz::bytes(data, size))};
    const spira::CalibrationTable table = spira::parseCalibrationCsv(in, "fuzz.csv");
    for (size_t i = 1; i < table.size(); ++i)
      if (!(table.heights()[i] > table.heights()[i - 1]))
        spira::fuzz::violated("a calibration table was accepted with heights that do not increase");
  });
}
