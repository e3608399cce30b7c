#include "assimp_scene.h"

#include <assimp/scene.h>

namespace spira {
namespace {

void appendMesh(const aiMesh& m, const aiMatrix4x4& T, SceneTriangles& out)
{
  auto& verts = out.mesh.vertices;
  const int base = static_cast<int>(verts.size());
  verts.reserve(verts.size() + m.mNumVertices);
  for (unsigned i = 0; i < m.mNumVertices; ++i) {
    const aiVector3D p = T * m.mVertices[i];
    verts.emplace_back(p.x, p.y, p.z);
  }
  // A mirroring node transform would turn every face inside out: undo it by swapping corners.
  const bool mirrored = T.Determinant() < 0;
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    if (face.mNumIndices != 3) {
      ++out.skippedPrimitives;
      continue;
    }
    Face tri{base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
             base + static_cast<int>(face.mIndices[2])};
    if (mirrored) std::swap(tri[1], tri[2]);
    out.mesh.faces.push_back(tri);
  }
}

void visit(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, SceneTriangles& out)
{
  const aiMatrix4x4 T = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i)
    if (node.mMeshes[i] < scene.mNumMeshes && scene.mMeshes[node.mMeshes[i]])
      appendMesh(*scene.mMeshes[node.mMeshes[i]], T, out);
  for (unsigned i = 0; i < node.mNumChildren; ++i)
    if (node.mChildren[i]) visit(scene, *node.mChildren[i], T, out);
}

}  // namespace

SceneTriangles collectSceneTriangles(const aiScene& scene)
{
  SceneTriangles out;
  if (scene.mRootNode) {
    visit(scene, *scene.mRootNode, aiMatrix4x4(), out);
  } else {
    for (unsigned i = 0; i < scene.mNumMeshes; ++i)
      if (scene.mMeshes[i]) appendMesh(*scene.mMeshes[i], aiMatrix4x4(), out);
  }
  return out;
}

}  // namespace spira
