#include <iostream>
#include <sstream>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/field/field_writers.h"
#include "spira/field/harmonic_field.h"
#include "spira/field/heat_distance.h"
#include "spira/planning/part_topology.h"

namespace spira::cli {
namespace {

std::vector<int> parseVertexIds(const std::string& text, size_t vertexCount)
{
  std::vector<int> ids;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    long v = -1;
    try {
      v = std::stol(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || v < 0 || static_cast<size_t>(v) >= vertexCount)
      throw InputError("source '" + item + "' is not a vertex id of this part (0 .. " +
                           std::to_string(vertexCount - 1) + ")",
                       "use --sources lower, upper, or comma-separated vertex ids");
    ids.push_back(static_cast<int>(v));
  }
  if (ids.empty()) throw InputError("no source vertex given", "use --sources lower, upper, or vertex ids");
  return ids;
}

}  // namespace

int cmdField(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags importFlags(registry);
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout
        << "usage: spira-cli field PART --kind geodesic|harmonic [--sources lower|upper|IDS] -o FILE\n\n"
           "Writes a per-vertex scalar field as CSV (vertex,x,y,z,value) or VTK XML PolyData (.vtp).\n"
           "geodesic: heat-method distance from the source vertices taken as one set (default: the\n"
           "lower boundary); harmonic: Laplace field, 0 on the lower boundary and 1 on the upper one\n"
           "(open parts).\n"
        << paramFlagsHelp(importFlags.targets());
    return kExitOk;
  }
  const std::string out = args.takeOption("-o");
  std::string kind = args.takeOption("--kind");
  std::string sources = args.takeOption("--sources");
  args.rest = takeParamFlags(args.rest, importFlags.targets());
  const auto positional = args.finish("field", 1, 1);
  if (out.empty()) throw UsageError("'field' needs an output file", "write -o FILE.csv or -o FILE.vtp");
  if (kind.empty()) kind = "geodesic";
  if (kind != "geodesic" && kind != "harmonic")
    throw UsageError("--kind must be geodesic or harmonic", "e.g. --kind geodesic");
  const std::filesystem::path outPath(out);
  const std::string ext = outPath.extension().string();
  if (ext != ".csv" && ext != ".vtp")
    throw InputError("output '" + out + "' must end in .csv or .vtp",
                     "choose the format by the file extension");
  ensureWritableDirectory(outPath.has_parent_path() ? outPath.parent_path() : std::filesystem::path("."));

  NullProgress progress;
  const ImportedPart part = importFlags.import(positional[0], progress);
  const PartTopology topology = findPartTopology(part.report, part.mesh, 0.0);
  std::vector<double> values;
  if (kind == "harmonic") {
    if (topology.partClass != PartClass::Open)
      throw InputError("the harmonic field needs an open part (two boundary loops); this part is closed",
                       "use --kind geodesic");
    values = harmonicField(part.mesh, topology.lower.vertices, topology.upper->vertices, progress);
  } else {
    std::vector<int> ids;
    if (sources.empty() || sources == "lower") {
      ids = topology.lower.vertices;
    } else if (sources == "upper") {
      if (!topology.upper)
        throw InputError("the part has no upper boundary", "use --sources lower or vertex ids");
      ids = topology.upper->vertices;
    } else {
      ids = parseVertexIds(sources, part.mesh.vertexCount());
    }
    values = heatGeodesicDistance(part.mesh, ids, HeatDistanceOptions{}, progress);
  }
  if (ext == ".csv")
    writeFieldCsv(outPath, part.mesh, values);
  else
    writeFieldVtp(outPath, part.mesh, values, kind == "harmonic" ? "harmonic" : "geodesic_distance");
  std::cout << "wrote " << out << " (" << values.size() << " vertices, " << kind << " field)\n";
  return kExitOk;
}

}  // namespace spira::cli
