#include "ply_importer.h"

#include "spira/io/ply_reader.h"
#include "unit_parameter.h"

namespace spira::import_mesh {

std::string PlyImporter::description() const
{
  return "ASCII or binary PLY mesh; polygons are split into triangles. PLY stores no unit: set the file unit "
         "if it is not millimetres.";
}

const ParamSchema& PlyImporter::schema() const
{
  return unitlessMeshSchema();
}

ImportedMesh PlyImporter::read(const std::filesystem::path& file, const ParamSet&, Progress& progress) const
{
  PlyData ply = readPly(file, progress);
  ImportedMesh out;
  out.mesh = std::move(ply.mesh);
  out.warnings = std::move(ply.warnings);
  return out;
}

}  // namespace spira::import_mesh
