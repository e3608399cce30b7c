#include "part_placement.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "spira/mesh/mesh_report.h"

namespace spira::cli {
namespace {

int parseLoop(const std::string& text)
{
  const bool digits =
      !text.empty() && text.size() <= 6 && text.find_first_not_of("0123456789") == std::string::npos;
  const int n = digits ? std::stoi(text) : 0;
  if (n < 1)
    throw UsageError(
        "--lower-loop takes a loop number from 1, as 'spira-cli info' lists the loops; got '" + text + "'",
        "e.g. --lower-loop 1, or leave it out to stand the part on its lowest loop");
  return n - 1;
}

double parseZ(const std::string& text)
{
  size_t used = 0;
  double z = 0.0;
  try {
    z = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(z) || std::abs(z) > 1e6)
    throw UsageError("--substrate-z takes a height in mm; got '" + text + "'", "e.g. --substrate-z 0");
  return z;
}

}  // namespace

PartPlacement PartPlacement::take(Args& args)
{
  PartPlacement p;
  const std::string loop = args.takeOption("--lower-loop");
  const std::string z = args.takeOption("--substrate-z");
  p.drop = args.takeSwitch("--drop");
  if (!loop.empty()) p.lowerLoop = parseLoop(loop);
  if (!z.empty()) p.substrateZ = parseZ(z);
  return p;
}

double PartPlacement::apply(ImportedPart& part) const
{
  if (!drop || part.report.bounds.empty()) return 0.0;
  const double shift = substrateZ - part.report.bounds.min.z();
  if (shift == 0.0) return 0.0;
  for (Vec3& v : part.mesh.vertices) v.z() += shift;
  part.report = validateMesh(part.mesh);
  return shift;
}

}  // namespace spira::cli
