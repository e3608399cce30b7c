#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace spira::test {

// A part the determinism tests plan. Every strategy that accepts it is planned twice in one
// process; the flags, cell and program format given here are also run by two spira-cli processes
// with different thread counts (the slower half of the tests, so one run per part).
struct DeterminismPart {
  std::string file;                // relative to the source tree
  std::vector<std::string> flags;  // 'plan' flags of the two-process run (strategy, parameters)
  std::string cell;                // its cell, relative to the source tree ("": no cell)
  std::string program;             // its robot program format: krl, fanuc_tp
};

// One line per part. Third-party meshes (tests/data/real/) go here too.
inline const std::vector<DeterminismPart>& determinismParts()
{
  static const std::vector<DeterminismPart> parts = {
      {"resources/samples/dome.stl",
       {"--strategy", "isovalue"},
       "resources/cells/fanuc_m20ia_positioner.cell",
       "fanuc_tp"},
      {"resources/samples/cone.stl", {"--strategy", "envelope_projection", "--axis", "skeleton"}, "", "krl"},
      {"resources/samples/open_cylinder.stl", {"--strategy", "geodesic"}, "", "krl"},
  };
  return parts;
}

// "cone" for "resources/samples/cone.stl": a test name part (letters, digits and '_' only).
std::string partName(const DeterminismPart& part);

// How a test failure names the part.
void PrintTo(const DeterminismPart& part, std::ostream* out);

}  // namespace spira::test
