#include "spira/io/import_service.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <new>
#include <sstream>

#include "spira/base/error.h"
#include "spira/io/isolated_import.h"
#include "spira/io/unit_guess.h"

namespace fs = std::filesystem;

namespace spira {
namespace {

class Stopwatch {
 public:
  double lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void checkReadableFile(const fs::path& file)
{
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (!fs::exists(status))
    throw IoError("file '" + file.string() + "' does not exist", "check the path and the file name");
  if (fs::is_directory(status))
    throw IoError("'" + file.string() + "' is a folder, not a file", "choose a part file inside it");
  if (!fs::is_regular_file(status))
    throw IoError("'" + file.string() + "' is not a regular file", "choose a part file");
  std::ifstream probe(file, std::ios::binary);
  if (!probe)
    throw IoError("cannot open '" + file.string() + "' for reading", "check the file's permissions");
}

LengthUnit resolveUnit(const ImportedMesh& raw, const ImporterPlugin& importer, const ParamSet& params)
{
  if (raw.unit) return *raw.unit;
  if (!importer.schema().find("unit")) return LengthUnit::Millimetre;
  const std::string& symbol = params.getString("unit");
  const auto unit = parseLengthUnit(symbol);
  if (!unit)
    throw InternalError("importer '" + importer.id() + "' declares an unknown unit '" + symbol + "'");
  return *unit;
}

std::string formatPoint(const Vec3& p)
{
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// Everything that would make welding or validation meaningless is refused here, with the count
// and the first place so the user can find it in the CAD program.
void checkGeometry(const TriangleMesh& mesh, const std::string& source)
{
  if (mesh.faces.empty())
    throw InputError("'" + source + "' contains no triangles",
                     "check that the file holds a surface or solid, not only points or lines");
  const auto n = static_cast<int>(mesh.vertices.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f])
      if (v < 0 || v >= n)
        throw InputError("'" + source + "': triangle " + std::to_string(f) + " refers to vertex " +
                             std::to_string(v) + " but the file has " + std::to_string(n) + " vertices",
                         "the file is corrupt; re-export it");
  std::vector<char> bad(mesh.vertices.size(), 0);
  size_t badCount = 0;
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite()) {
      bad[v] = 1;
      ++badCount;
    }
  if (badCount == 0) return;
  const std::string what = "'" + source + "': " + std::to_string(badCount) +
                           " vertices have non-finite coordinates (NaN or infinity)";
  const char* hint = "repair the mesh or re-export it from the CAD program";
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (size_t k = 0; k < 3; ++k) {
      const auto v = static_cast<size_t>(mesh.faces[f][k]);
      if (bad[v])
        throw InputError(what + "; the first is corner " + std::to_string(k) + " of triangle " +
                             std::to_string(f) + " at " + formatPoint(mesh.vertices[v]),
                         hint);
    }
  // Even unused, a non-finite vertex would poison the bounding box that sets the weld tolerance.
  const auto first = static_cast<size_t>(std::find(bad.begin(), bad.end(), 1) - bad.begin());
  throw InputError(what + "; the first is vertex " + std::to_string(first), hint);
}

bool isSoup(const TriangleMesh& mesh)
{
  if (mesh.vertices.size() != 3 * mesh.faces.size()) return false;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const int b = static_cast<int>(3 * f);
    if (mesh.faces[f] != Face{b, b + 1, b + 2}) return false;
  }
  return true;
}

// OpenCASCADE's readers crash, hang or exhaust memory on damaged files: they run in a helper
// process so that only the helper dies.
bool runsIsolated(const ImporterPlugin& importer)
{
  const std::string& id = importer.id();
  return id == "import.step" || id == "import.iges" || id == "import.brep";
}

ImportedMesh readWith(const ImporterPlugin& importer, const fs::path& file, const ParamSet& params,
                      Progress& progress)
{
  try {
    if (runsIsolated(importer)) return readIsolated(importer, file, params, progress);
    return importer.read(file, params, progress);
  } catch (const Error&) {
    throw;
  } catch (const Cancelled&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw InputError("not enough memory to read '" + file.filename().string() + "'",
                     "close other programs or simplify the part");
  } catch (const std::exception& e) {
    throw InternalError(
        "importer '" + importer.id() + "' failed on '" + file.filename().string() + "': " + e.what(),
        "please report this with the file");
  }
}

}  // namespace

ImportedPart finishImport(ImportedMesh raw, LengthUnit unit, const std::string& source, Progress& progress)
{
  ImportedPart part;
  Stopwatch clock;
  part.warnings = std::move(raw.warnings);
  part.sourceUnit = raw.fileUnit.value_or(unit);
  const double scale = millimetresPer(unit);
  if (scale != 1.0)
    for (Vec3& p : raw.mesh.vertices) p *= scale;
  checkGeometry(raw.mesh, source);
  part.seconds.read = clock.lap();
  progress.checkCancel();

  progress.report(0.6, "Welding");
  part.mesh = isSoup(raw.mesh) ? weldTriangleSoup(raw.mesh.vertices, kDefaultWeldTolerance, &part.weld)
                               : weldVertices(raw.mesh, kDefaultWeldTolerance, &part.weld);
  raw = ImportedMesh();
  part.seconds.weld = clock.lap();
  progress.checkCancel();

  progress.report(0.8, "Validating");
  part.report = validateMesh(part.mesh);
  if (auto unitNote = unitWarning(part.report.bounds, unit)) part.warnings.push_back(*unitNote);
  part.seconds.validate = clock.lap();
  progress.report(1.0, "Imported");
  return part;
}

ImportedPart importPart(const PluginRegistry& registry, const fs::path& file, const ParamSet* importerParams,
                        Progress& progress)
{
  checkReadableFile(file);
  const ImporterPlugin& importer = registry.importerForFile(file.filename().string());
  const ParamSet params = (importerParams ? *importerParams : ParamSet()).withDefaults(importer.schema());
  importer.schema().validate(params);
  const std::string source = file.filename().string();
  std::error_code ec;
  if (fs::file_size(file, ec) == 0 && !ec)
    throw InputError("'" + source + "' is empty (0 bytes)", "choose the right file or export the part again");

  Stopwatch clock;
  SubProgress readProgress(progress, 0.0, 0.6, "Reading");
  ImportedMesh raw = readWith(importer, file, params, readProgress);
  const double readSeconds = clock.lap();
  const LengthUnit unit = resolveUnit(raw, importer, params);
  ImportedPart part = finishImport(std::move(raw), unit, source, progress);
  part.importerId = importer.id();
  part.seconds.read += readSeconds;
  return part;
}

}  // namespace spira
