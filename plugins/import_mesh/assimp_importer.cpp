#include "assimp_importer.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>

#include "spira/base/error.h"
#include "spira/io/assimp_scene.h"
#include "unit_parameter.h"

namespace spira::import_mesh {
namespace {

// Forwards Assimp's progress and lets a cancel request abort the load.
class ProgressBridge final : public Assimp::ProgressHandler {
 public:
  explicit ProgressBridge(Progress& progress) : progress_(progress) {}
  bool Update(float percentage) override
  {
    if (percentage >= 0.f) progress_.report(static_cast<double>(percentage), "Reading");
    return !progress_.cancelled();
  }

 private:
  Progress& progress_;
};

// The importer deletes the handler it holds; handing it back the default one first keeps ours
// owned by the stack, on every path out of read().
class HandlerScope {
 public:
  HandlerScope(Assimp::Importer& importer, Assimp::ProgressHandler* handler) : importer_(importer)
  {
    importer_.SetProgressHandler(handler);
  }
  ~HandlerScope() { importer_.SetProgressHandler(nullptr); }
  HandlerScope(const HandlerScope&) = delete;
  HandlerScope& operator=(const HandlerScope&) = delete;

 private:
  Assimp::Importer& importer_;
};

}  // namespace

AssimpImporter::AssimpImporter(std::string id, std::string label, std::string formatName,
                               std::vector<std::string> extensions)
    : id_(std::move(id)),
      label_(std::move(label)),
      formatName_(std::move(formatName)),
      extensions_(std::move(extensions))
{
}

std::string AssimpImporter::description() const
{
  return formatName_ + " mesh read with Assimp; polygons are split into triangles. " + formatName_ +
         " stores no unit: set the file unit if it is not millimetres.";
}

const ParamSchema& AssimpImporter::schema() const
{
  return unitlessMeshSchema();
}

ImportedMesh AssimpImporter::read(const std::filesystem::path& file, const ParamSet&,
                                  Progress& progress) const
{
  Assimp::Importer importer;
  ProgressBridge bridge(progress);
  const aiScene* scene = nullptr;
  {
    HandlerScope scope(importer, &bridge);
    // No JoinIdenticalVertices: the import service welds every format the same way.
    scene = importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_ValidateDataStructure);
  }
  progress.checkCancel();
  if (!scene)
    throw InputError(
        "cannot read '" + file.filename().string() + "' as " + formatName_ + ": " + importer.GetErrorString(),
        "the file is damaged or not a " + formatName_ + " file; export it again");
  SceneTriangles tris = collectSceneTriangles(*scene);
  ImportedMesh out;
  out.mesh = std::move(tris.mesh);
  if (tris.skippedPrimitives > 0)
    out.warnings.push_back(std::to_string(tris.skippedPrimitives) + " point and line elements in '" +
                           file.filename().string() +
                           "' were ignored (only triangles and polygons are read)");
  return out;
}

}  // namespace spira::import_mesh
