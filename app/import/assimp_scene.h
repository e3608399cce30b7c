#pragma once

#include <cstddef>

#include "spira/mesh/triangle_mesh.h"

struct aiScene;

namespace spira {

struct SceneTriangles {
  TriangleMesh mesh;             // every triangle of every mesh instance, node transforms applied
  size_t skippedPrimitives = 0;  // points and lines, which a part surface cannot use
};

// Flattens an Assimp scene (robot link meshes). Vertices are copied as Assimp
// holds them (per-face unless the file shares them); welding is the caller's job.
SceneTriangles collectSceneTriangles(const aiScene& scene);

}  // namespace spira
