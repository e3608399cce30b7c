#include "spira/robotcell/mesh_file.h"

#include <cctype>
#include <string>
#include <utility>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/io/isolated_import.h"
#include "spira/io/stl_reader.h"
#include "spira/mesh/mesh_weld.h"

namespace spira {
namespace {

constexpr double kMetre = 1000.0;  // ROS mesh files are in metres (COLLADA after its <unit>)

// Assimp reads the other formats, in the import helper: a damaged file must not take Spira down.
TriangleMesh readInHelper(const std::filesystem::path& file)
{
  NullProgress progress;
  return readIsolated("import.link_mesh", file, ParamSet{}, progress,
                      "re-export it as STL or COLLADA from the robot's support package")
      .mesh;
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
    mesh = readInHelper(file);
  }
  const Vec3 s = scale * kMetre;
  for (Vec3& v : mesh.vertices) v = v.cwiseProduct(s);
  // A negative scale mirrors the mesh: reverse the faces so the normals stay outward.
  if (s.x() * s.y() * s.z() < 0)
    for (Face& f : mesh.faces) std::swap(f[1], f[2]);
  return mesh;
}

}  // namespace spira
