#include "obj_importer.h"

#include "spira/io/obj_reader.h"
#include "unit_parameter.h"

namespace spira::import_mesh {

std::string ObjImporter::description() const
{
  return "Wavefront OBJ mesh (vertices and faces; texture coordinates, normals and materials are ignored); "
         "polygons are split into triangles. OBJ stores no unit: set the file unit if it is not millimetres.";
}

const ParamSchema& ObjImporter::schema() const
{
  return unitlessMeshSchema();
}

ImportedMesh ObjImporter::read(const std::filesystem::path& file, const ParamSet&, Progress& progress) const
{
  ObjData obj = readObj(file, progress);
  ImportedMesh out;
  out.mesh = std::move(obj.mesh);
  out.warnings = std::move(obj.warnings);
  return out;
}

}  // namespace spira::import_mesh
