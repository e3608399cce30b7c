// Import speed: a 1,000,000-triangle binary STL read, welded and validated through importPart,
// per stage and end to end (best of 3), next to Assimp's STL import of the same file.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <unistd.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>

#include "builtin_plugins.h"
#include "spira/io/import_service.h"
#include "spira/io/mesh_writers.h"
#include "spira/io/stl_reader.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/plugin/plugin_registry.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// Best wall time of three runs; `cpu` receives the process CPU time of that run (all threads),
// which shows what the code costs when other programs share the machine.
double bestOf3(const std::function<void()>& run, double* cpu = nullptr)
{
  double best = 1e300;
  for (int i = 0; i < 3; ++i) {
    const std::clock_t c0 = std::clock();
    const auto t0 = Clock::now();
    run();
    const double wall = seconds(t0);
    if (wall < best) {
      best = wall;
      if (cpu) *cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    }
  }
  return best;
}

// A vase: a wavy profile revolved in 1000 segments over 500 rings = 1,000,000 triangles.
spira::TriangleMesh makeVase()
{
  std::vector<Eigen::Vector2d> profile;
  const int rings = 500;
  for (int i = 0; i <= rings; ++i) {
    const double z = 200.0 * i / rings;
    profile.emplace_back(80.0 + 12.0 * std::sin(z / 25.0) + 0.05 * z, z);
  }
  return spira::makeRevolved(profile, 1000);
}

}  // namespace

int main()
{
  const fs::path dir = fs::temp_directory_path() / ("spira-bench-import-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "vase_1m.stl";

  const spira::TriangleMesh vase = makeVase();
  auto t0 = Clock::now();
  spira::writeMesh(vase, file, spira::MeshFileFormat::StlBinary);
  std::printf("mesh: %zu triangles, %zu vertices; binary STL %.1f MB written in %.3f s\n", vase.faceCount(),
              vase.vertexCount(), static_cast<double>(fs::file_size(file)) / 1e6, seconds(t0));

  const spira::PluginRegistry& registry = spira::builtinRegistry();
  spira::NullProgress progress;
  spira::ImportStageSeconds best{1e300, 1e300, 1e300};
  size_t faces = 0, vertices = 0;
  double endToEndCpu = 0.0;
  const double endToEnd = bestOf3(
      [&] {
        const spira::ImportedPart part = spira::importPart(registry, file, nullptr, progress);
        best.read = std::min(best.read, part.seconds.read);
        best.weld = std::min(best.weld, part.seconds.weld);
        best.validate = std::min(best.validate, part.seconds.validate);
        faces = part.mesh.faceCount();
        vertices = part.mesh.vertexCount();
      },
      &endToEndCpu);
  std::printf("importPart (best of 3): %.3f s end to end (CPU %.3f s) -> %zu faces, %zu vertices\n", endToEnd,
              endToEndCpu, faces, vertices);
  std::printf("  stages (best of 3 each): read %.3f s, weld %.3f s, validate %.3f s\n", best.read, best.weld,
              best.validate);

  double readerCpu = 0.0;
  const double readerOnly = bestOf3([&] { spira::readStl(file, progress); }, &readerCpu);
  std::printf("  spira::readStl alone: %.3f s (CPU %.3f s)\n", readerOnly, readerCpu);

  double assimpReadCpu = 0.0, assimpJoinCpu = 0.0;
  const double assimpRead = bestOf3(
      [&] {
        Assimp::Importer importer;
        if (!importer.ReadFile(file.string(), 0))
          std::printf("Assimp failed: %s\n", importer.GetErrorString());
      },
      &assimpReadCpu);
  const double assimpJoin = bestOf3(
      [&] {
        Assimp::Importer importer;
        if (!importer.ReadFile(file.string(), aiProcess_JoinIdenticalVertices))
          std::printf("Assimp failed: %s\n", importer.GetErrorString());
      },
      &assimpJoinCpu);
  std::printf(
      "Assimp STL (best of 3): read %.3f s (CPU %.3f s); read + JoinIdenticalVertices %.3f s (CPU %.3f s)\n",
      assimpRead, assimpReadCpu, assimpJoin, assimpJoinCpu);

  std::error_code ec;
  fs::remove_all(dir, ec);
  return 0;
}
