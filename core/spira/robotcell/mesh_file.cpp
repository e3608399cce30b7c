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
#include "spira/io/stl_reader.h"
#include "spira/mesh/mesh_weld.h"

namespace spira {
namespace {

constexpr double kMetre = 1000.0;  // ROS mesh files are in metres (COLLADA after its <unit>)

void appendMesh(const aiMesh& m, const aiMatrix4x4& T, TriangleMesh& out)
{
  const int base = static_cast<int>(out.vertices.size());
  for (unsigned i = 0; i < m.mNumVertices; ++i) {
    const aiVector3D p = T * m.mVertices[i];
    out.vertices.emplace_back(p.x, p.y, p.z);
  }
  // A mirroring node transform would turn the faces inside out: swapping two corners undoes it.
  const bool mirrored = T.Determinant() < 0;
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines carry no surface
    Face tri{base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
             base + static_cast<int>(face.mIndices[2])};
    if (mirrored) std::swap(tri[1], tri[2]);
    out.faces.push_back(tri);
  }
}

void visit(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, TriangleMesh& out)
{
  const aiMatrix4x4 T = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i)
    if (node.mMeshes[i] < scene.mNumMeshes && scene.mMeshes[node.mMeshes[i]])
      appendMesh(*scene.mMeshes[node.mMeshes[i]], T, out);
  for (unsigned i = 0; i < node.mNumChildren; ++i)
    if (node.mChildren[i]) visit(scene, *node.mChildren[i], T, out);
}

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
  TriangleMesh mesh;
  if (scene->mRootNode) {
    visit(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  } else {
    for (unsigned i = 0; i < scene->mNumMeshes; ++i)
      if (scene->mMeshes[i]) appendMesh(*scene->mMeshes[i], aiMatrix4x4(), mesh);
  }
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
