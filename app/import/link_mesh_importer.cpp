#include "link_mesh_importer.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "assimp_scene.h"
#include "spira/base/error.h"

namespace spira {
namespace {

const char* const kReexport = "re-export it as STL or COLLADA from the robot's support package";

}  // namespace

std::string LinkMeshImporter::description() const
{
  return "Robot link meshes (COLLADA and others) read with Assimp, in the import helper.";
}

const ParamSchema& LinkMeshImporter::schema() const
{
  static const ParamSchema none;
  return none;
}

ImportedMesh LinkMeshImporter::read(const std::filesystem::path& file, const ParamSet&,
                                    Progress& progress) const
{
  progress.report(0.0, "reading link mesh");
  Assimp::Importer importer;
  // rviz keeps the COLLADA unit (Assimp folds it into the root transform) but not the up axis.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene =
      importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_ValidateDataStructure);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    throw IoError("the link mesh " + file.string() + " could not be read: " + importer.GetErrorString(),
                  kReexport);
  ImportedMesh out;
  out.mesh = collectSceneTriangles(*scene).mesh;
  if (out.mesh.faces.empty())
    throw IoError("the link mesh " + file.string() + " holds no triangles", kReexport);
  progress.report(1.0, "reading link mesh");
  return out;
}

}  // namespace spira
