#include "cell_variant.h"

#include <fstream>
#include <sstream>

#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {

fs::path bundledCellVariant(const std::string& name, const fs::path& dir,
                            const std::function<void(nlohmann::json&)>& edit)
{
  const fs::path cells = sourceDir() / "resources" / "cells";
  std::ifstream in(cells / name);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json cell = nlohmann::json::parse(text.str());
  for (const char* unit : {"robot", "positioner"})
    if (cell[unit].is_object())
      cell[unit]["urdf"] = (cells / cell[unit]["urdf"].get<std::string>()).lexically_normal().string();
  edit(cell);
  const fs::path out = dir / name;
  writeBytes(out, cell.dump(2));
  return out;
}

fs::path cylinderPart(const fs::path& dir, double r, double height)
{
  const fs::path file = dir / "cylinder.stl";
  writeMesh(makeOpenCylinder(r, height, segmentsForEdge(r, 2.0), ringsForEdge(height, 2.0)), file);
  return file;
}

}  // namespace spira::test
