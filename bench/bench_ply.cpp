// PLY read speed: a 100,000-triangle binary PLY read by Spira's reader and by Assimp (with the
// post-processing the old Assimp route asked for), best of 3; and how long a 167-byte PLY that
// declares 99,999,999 vertices takes to be refused by the import.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <unistd.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/io/import_service.h"
#include "spira/io/mesh_writers.h"
#include "spira/io/ply_reader.h"
#include "spira/mesh/mesh_primitives.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double bestOf3(const std::function<void()>& run)
{
  double best = 1e300;
  for (int i = 0; i < 3; ++i) {
    const auto t0 = Clock::now();
    run();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main()
{
  const fs::path dir = fs::temp_directory_path() / ("spira-bench-ply-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "cylinder_100k.ply";
  // 250 segments x 200 rings x 2 = 100,000 triangles.
  const spira::TriangleMesh mesh = spira::makeOpenCylinder(50.0, 100.0, 250, 200);
  spira::writeMesh(mesh, file, spira::MeshFileFormat::PlyBinary);
  std::printf("mesh: %zu triangles, %zu vertices; binary PLY %.2f MB\n", mesh.faceCount(), mesh.vertexCount(),
              static_cast<double>(fs::file_size(file)) / 1e6);

  spira::NullProgress progress;
  size_t spiraFaces = 0, assimpFaces = 0;
  const double spiraSeconds = bestOf3([&] { spiraFaces = spira::readPly(file, progress).mesh.faceCount(); });
  const double assimpSeconds = bestOf3([&] {
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    assimpFaces = scene && scene->mNumMeshes > 0 ? scene->mMeshes[0]->mNumFaces : 0;
  });
  std::printf("read: Spira %.2f ms (%zu triangles), Assimp %.2f ms (%zu triangles)\n", 1e3 * spiraSeconds,
              spiraFaces, 1e3 * assimpSeconds, assimpFaces);

  const fs::path huge = fs::path(SPIRA_SOURCE_DIR) / "tests/data/hostile/ply/huge_vertex_count.ply";
  const auto t0 = Clock::now();
  std::string message;
  try {
    spira::importPart(spira::builtinRegistry(), huge, nullptr, progress);
  } catch (const spira::InputError& e) {
    message = e.what();
  }
  std::printf("refusal of %s (%ju bytes): %.3f ms: %s\n", huge.filename().c_str(),
              static_cast<std::uintmax_t>(fs::file_size(huge)),
              1e3 * std::chrono::duration<double>(Clock::now() - t0).count(), message.c_str());
  fs::remove_all(dir);
  return 0;
}
