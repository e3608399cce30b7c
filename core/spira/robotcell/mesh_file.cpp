#include "spira/robotcell/mesh_file.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cctype>
#include <string>
#include <utility>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/io/assimp_scene.h"
#include "spira/io/stl_reader.h"
#include "spira/mesh/mesh_weld.h"

namespace spira {
namespace {

constexpr double kMetre = 1000.0;  // ROS mesh files are in metres (COLLADA after its <unit>)

TriangleMesh readWithAssimp(const std::filesystem::path& file)
{
  Assimp::Importer importer;
  // rviz keeps the COLLADA unit (Assimp folds it into the root transform) but not the up axis.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene =
      importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_ValidateDataStructure);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    throw IoError("the link mesh " + file.string() + " could not be read: " + importer.GetErrorString(),
                  "re-export it as STL or COLLADA from the robot's support package");
  TriangleMesh mesh = collectSceneTriangles(*scene).mesh;
  if (mesh.faces.empty())
    throw IoError("the link mesh " + file.string() + " holds no triangles",
                  "re-export it as STL or COLLADA from the robot's support package");
  return mesh;
}

}  // namespace

TriangleMesh readLinkMesh(const std::filesystem::path& file, const Vec3& scale)
{
  if (!std::filesystem::exists(file))
    throw IoError("the link mesh " + file.string() + " is missing",
                  "check the mesh paths in the URDF (relative to its folder)");
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  TriangleMesh mesh;
  if (ext == ".stl") {
    NullProgress progress;
    mesh = weldTriangleSoup(readStl(file, progress).soup.vertices);
  } else {
    mesh = readWithAssimp(file);
  }
  const Vec3 s = scale * kMetre;
  for (Vec3& v : mesh.vertices) v = v.cwiseProduct(s);
  // A negative scale mirrors the mesh: reverse the faces so the normals stay outward.
  if (s.x() * s.y() * s.z() < 0)
    for (Face& f : mesh.faces) std::swap(f[1], f[2]);
  return mesh;
}

}  // namespace spira
