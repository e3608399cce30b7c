// What running an importer in the spira-import helper costs: the same CAD file read in this
// process and through the helper (best of 5 each, alternated), the helper's fixed cost on a file
// it refuses at once (the first import of a session, which starts the warm server, and the next
// ones, which it forks), the result stream alone for a 100,000-triangle mesh, and the KUKA
// package's seven COLLADA link meshes read by Assimp here and through the helper.
// Usage: bench_import_isolation [CAD_FILE [LINEAR_DEFLECTION_MM ANGULAR_DEFLECTION_DEG]]
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

#include "builtin_plugins.h"
#include "link_mesh_importer.h"
#include "spira/base/error.h"
#include "spira/io/import_process.h"
#include "spira/io/import_wire.h"
#include "spira/io/isolated_import.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/plugin/plugin_registry.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double timed(const std::function<void()>& run)
{
  const auto t0 = Clock::now();
  run();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// 400 segments x 125 rings x 2 = 100,000 triangles.
spira::ImportedMesh hundredThousandTriangles()
{
  std::vector<Eigen::Vector2d> profile;
  for (int i = 0; i <= 125; ++i) profile.emplace_back(80.0 + 5.0 * std::sin(i / 10.0), 1.6 * i);
  spira::ImportedMesh m;
  m.mesh = spira::makeRevolved(profile, 400);
  return m;
}

}  // namespace

int main(int argc, char** argv)
{
  const fs::path file =
      argc > 1 ? fs::path(argv[1]) : fs::path(SPIRA_SOURCE_DIR) / "tests/data/real/hepa_filter_assembly.step";
  const spira::PluginRegistry& registry = spira::builtinRegistry();
  const spira::ImporterPlugin& importer = registry.importerForFile(file.filename().string());
  spira::ParamSet params;
  if (argc > 3) {
    params.set("linear_deflection", std::stod(argv[2]));
    params.set("angular_deflection", std::stod(argv[3]));
  }
  params = params.withDefaults(importer.schema());
  spira::NullProgress progress;
  // A first read in a process pays the page faults of its fresh memory, as every helper does; a
  // read in a forked child of this process (before this process has read anything, so no thread
  // pool is forked) has that cost and nothing of the isolation.
  double forked = 1e300;
  for (int i = 0; i < 5; ++i)
    forked = std::min(forked, timed([&] {
                        const pid_t pid = ::fork();
                        if (pid == 0) {
                          importer.read(file, params, progress);
                          ::_exit(0);
                        }
                        ::waitpid(pid, nullptr, 0);
                      }));
  double inProcess = 1e300, isolated = 1e300;
  size_t faces = 0;
  for (int i = 0; i < 5; ++i) {
    inProcess =
        std::min(inProcess, timed([&] { faces = importer.read(file, params, progress).mesh.faces.size(); }));
    isolated = std::min(isolated, timed([&] { spira::readIsolated(importer, file, params, progress); }));
  }
  std::printf(
      "%s: %zu triangles; read in this process %.3f s, in a forked child %.3f s, through spira-import %.3f s "
      "(best of 5): %+.0f ms over the forked child\n",
      file.filename().string().c_str(), faces, inProcess, forked, isolated, 1e3 * (isolated - forked));

  const fs::path bad =
      fs::temp_directory_path() / ("spira-bench-isolation-" + std::to_string(::getpid()) + ".step");
  std::FILE* f = std::fopen(bad.c_str(), "w");
  std::fputs("not a STEP file\n", f);
  std::fclose(f);
  const auto refusal = [&] {
    try {
      spira::readIsolated(registry.importer("import.step"), bad, params, progress);
    } catch (const spira::InputError&) {
    }
  };
  double first = 1e300, next = 1e300;
  for (int i = 0; i < 10; ++i) {
    spira::import_process::stopServer();
    first = std::min(first, timed(refusal));
    next = std::min(next, timed(refusal));
  }
  fs::remove(bad);
  std::printf("refused at once, first import of a session (starts the server; best of 10): %.1f ms\n",
              1e3 * first);
  std::printf("refused at once, later imports (forked by the warm server; best of 10): %.1f ms\n",
              1e3 * next);

  const spira::ImportedMesh mesh = hundredThousandTriangles();
  double stream = 1e300;
  for (int i = 0; i < 5; ++i)
    stream = std::min(stream, timed([&] {
                        int fds[2];
                        if (::pipe(fds) != 0) return;
                        std::thread writer([&] {
                          spira::wire::Writer w(fds[1]);
                          w.header();
                          w.mesh(mesh);
                          ::close(fds[1]);
                        });
                        spira::wire::Reader r;
                        std::vector<char> buf(1 << 16);
                        ssize_t n;
                        while ((n = ::read(fds[0], buf.data(), buf.size())) > 0)
                          r.feed(buf.data(), static_cast<size_t>(n), progress);
                        ::close(fds[0]);
                        writer.join();
                      }));
  std::printf("result stream of %zu triangles, %zu vertices (best of 5): %.1f ms\n", mesh.mesh.faces.size(),
              mesh.mesh.vertices.size(), 1e3 * stream);

  const fs::path visual = fs::path(SPIRA_SOURCE_DIR) / "resources/robots/kuka_kr16_2/meshes/visual";
  std::vector<fs::path> links;
  for (const auto& entry : fs::directory_iterator(visual))
    if (entry.path().extension() == ".dae") links.push_back(entry.path());
  const spira::LinkMeshImporter linkMeshes;
  double here = 1e300, helper = 1e300;
  size_t linkFaces = 0;
  for (int i = 0; i < 5; ++i) {
    here = std::min(here, timed([&] {
                      linkFaces = 0;
                      for (const fs::path& l : links)
                        linkFaces += linkMeshes.read(l, spira::ParamSet{}, progress).mesh.faces.size();
                    }));
    helper = std::min(helper, timed([&] {
                        for (const fs::path& l : links)
                          spira::readIsolated("import.link_mesh", l, spira::ParamSet{}, progress, "");
                      }));
  }
  std::printf(
      "%zu COLLADA link meshes, %zu triangles: Assimp in this process %.1f ms, in the helper %.1f ms "
      "(best of 5)\n",
      links.size(), linkFaces, 1e3 * here, 1e3 * helper);
  return 0;
}
