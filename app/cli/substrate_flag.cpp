#include "substrate_flag.h"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/scan/scan_processing.h"
#include "spira/scan/scan_reader.h"
#include "spira/scan/scan_surface.h"

namespace spira::cli {
namespace {

constexpr const char* kExample =
    "--substrate cylinder:32,y (radius 32 mm about the y axis), or --substrate pipe.stl";

Substrate cylinder(const std::string& spec)
{
  std::vector<std::string> parts;
  std::istringstream in(spec);
  for (std::string p; std::getline(in, p, ',');) parts.push_back(p);
  if (parts.empty() || parts.size() > 3)
    throw UsageError("--substrate cylinder:" + spec + ": expected a radius, an axis and a length at most",
                     kExample);
  const double radius = finiteNumberFlag("--substrate cylinder radius", parts[0], kExample);
  if (!(radius > 0.0 && radius <= 1e5))
    throw UsageError("--substrate cylinder radius '" + parts[0] + "' must be above 0 and at most 100000 mm",
                     kExample);
  const std::string axis = parts.size() > 1 ? parts[1] : "y";
  if (axis != "x" && axis != "y" && axis != "z")
    throw UsageError("--substrate cylinder axis '" + axis + "' must be x, y or z", kExample);
  const double length =
      parts.size() > 2 ? finiteNumberFlag("--substrate cylinder length", parts[2], kExample) : 8.0 * radius;
  if (!(length > 0.0 && length <= 1e5))
    throw UsageError("--substrate cylinder length '" + parts[2] + "' must be above 0 and at most 100000 mm",
                     kExample);
  auto mesh = std::make_shared<const TriangleMesh>(makePipeAbout(radius, axis[0], length));
  std::ostringstream name;
  name << "cylinder R " << radius << " mm about " << axis;
  return Substrate::fromMesh(std::move(mesh), name.str());
}

}  // namespace

Substrate substrateFromFlag(const std::string& value, ImporterFlags& importer, Progress& progress)
{
  const std::string prefix = "cylinder:";
  if (value.rfind(prefix, 0) == 0) return cylinder(value.substr(prefix.size()));
  if (value.rfind(kScanPrefix, 0) == 0) {
    const std::string file = value.substr(std::string(kScanPrefix).size());
    const PointCloud scan = filterScan(readScan(builtinRegistry(), file, progress), ScanFilterSettings{});
    auto mesh = std::make_shared<const TriangleMesh>(heightFieldFromScan(scan, heightFieldCell(scan)));
    return Substrate::fromMesh(std::move(mesh), "scan " + std::filesystem::path(file).stem().string(), file);
  }
  ImportedPart imported = importer.import(value, progress);
  auto mesh = std::make_shared<const TriangleMesh>(std::move(imported.mesh));
  return Substrate::fromMesh(std::move(mesh), std::filesystem::path(value).stem().string(), value);
}

}  // namespace spira::cli
