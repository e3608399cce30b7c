// The cell file reader (.cell JSON). The robots' URDF files are not opened here (the URDF target
// covers them): a cell names them, and RobotCell loads them later.
#include "../fuzz_support.h"
#include "spira/robotcell/cell_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::refusalsAllowed([&] {
    spira::cellFromText(std::string(spira::fuzz::bytes(data, size)), "/nonexistent/spira-fuzz", "fuzz.cell");
  });
}
