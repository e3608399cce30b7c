#include "stl_importer.h"

#include "spira/io/stl_reader.h"
#include "unit_parameter.h"

namespace spira::import_mesh {

std::string StlImporter::description() const
{
  return "Binary or ASCII STL triangle mesh. STL stores no unit: set the file unit if it is not millimetres.";
}

const ParamSchema& StlImporter::schema() const
{
  return unitlessMeshSchema();
}

ImportedMesh StlImporter::read(const std::filesystem::path& file, const ParamSet&, Progress& progress) const
{
  StlData stl = readStl(file, progress);
  ImportedMesh out;
  out.mesh = std::move(stl.soup);
  if (stl.polygonFacets > 0)
    out.warnings.push_back(std::to_string(stl.polygonFacets) +
                           " ASCII STL facets had more than three vertices and were split into triangles");
  return out;
}

}  // namespace spira::import_mesh
