#include "io_test_util.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "builtin_plugins.h"

namespace spira::test {

const PluginRegistry& ioRegistry()
{
  return builtinRegistry();
}

ImportedPart importFile(const std::filesystem::path& file)
{
  NullProgress progress;
  return importPart(ioRegistry(), file, nullptr, progress);
}

ImportedPart importFile(const std::filesystem::path& file, const std::string& key, const ParamValue& value)
{
  NullProgress progress;
  ParamSet params;
  params.set(key, value);
  return importPart(ioRegistry(), file, &params, progress);
}

double maxCornerDistance(const TriangleMesh& a, const TriangleMesh& b)
{
  if (a.faces.size() != b.faces.size()) return std::numeric_limits<double>::infinity();
  double worst = 0.0;
  for (size_t f = 0; f < a.faces.size(); ++f)
    for (size_t k = 0; k < 3; ++k) {
      const Vec3& p = a.vertices[static_cast<size_t>(a.faces[f][k])];
      const Vec3& q = b.vertices[static_cast<size_t>(b.faces[f][k])];
      worst = std::max(worst, (p - q).norm());
    }
  return worst;
}

bool sameConnectivity(const TriangleMesh& a, const TriangleMesh& b)
{
  if (a.faces.size() != b.faces.size() || a.vertices.size() != b.vertices.size()) return false;
  std::unordered_map<int, int> ab, ba;
  for (size_t f = 0; f < a.faces.size(); ++f)
    for (size_t k = 0; k < 3; ++k) {
      const int va = a.faces[f][k], vb = b.faces[f][k];
      const auto [ia, newA] = ab.emplace(va, vb);
      const auto [ib, newB] = ba.emplace(vb, va);
      if ((!newA && ia->second != vb) || (!newB && ib->second != va)) return false;
    }
  return true;
}

double signedVolume(const TriangleMesh& m)
{
  double v = 0.0;
  for (const Face& f : m.faces)
    v += m.vertices[static_cast<size_t>(f[0])].dot(
        m.vertices[static_cast<size_t>(f[1])].cross(m.vertices[static_cast<size_t>(f[2])]));
  return v / 6.0;
}

namespace {

double distanceToLine(const Vec3& p, double r0, double r1, double height)
{
  const Eigen::Vector2d q(std::hypot(p.x(), p.y()), p.z());
  const Eigen::Vector2d a(r0, 0.0), d = Eigen::Vector2d(r1 - r0, height).normalized();
  const Eigen::Vector2d rel = q - a;
  return std::abs(rel.x() * d.y() - rel.y() * d.x());
}

}  // namespace

double maxDistanceToRevolvedLine(const TriangleMesh& m, double r0, double r1, double height, bool vertexOnly)
{
  double worst = 0.0;
  if (vertexOnly) {
    for (const Vec3& p : m.vertices) worst = std::max(worst, distanceToLine(p, r0, r1, height));
    return worst;
  }
  constexpr int kSteps = 12;  // barycentric grid: the sagitta peaks on edge midpoints, which the grid holds
  for (const Face& f : m.faces) {
    const Vec3& a = m.vertices[static_cast<size_t>(f[0])];
    const Vec3& b = m.vertices[static_cast<size_t>(f[1])];
    const Vec3& c = m.vertices[static_cast<size_t>(f[2])];
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j) {
        const double u = static_cast<double>(i) / kSteps, v = static_cast<double>(j) / kSteps;
        worst = std::max(worst, distanceToLine(a + u * (b - a) + v * (c - a), r0, r1, height));
      }
  }
  return worst;
}

::testing::AssertionResult refusedImport(const std::filesystem::path& file, const std::string& mustContain)
{
  const auto r = throwsOneLine<InputError>([&] { importFile(file); }, mustContain);
  if (!r) return r;
  try {
    importFile(file);
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const char* internal :
         {"aiMesh", "aiScene", "Validation failed", "mIndices", "File corrupted", "OBJ: "})
      if (what.find(internal) != std::string::npos)
        return ::testing::AssertionFailure() << "library text in '" << what << "'";
    if (what.find(file.filename().string()) == std::string::npos)
      return ::testing::AssertionFailure() << "'" << what << "' does not name the file";
  }
  return r;
}

::testing::AssertionResult hasImportWarning(const ImportedPart& part, const std::string& text)
{
  for (const std::string& w : part.warnings)
    if (w.find(text) != std::string::npos) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure() << "no warning with '" << text << "' among:";
  for (const std::string& w : part.warnings) failure << "\n  " << w;
  return failure;
}

}  // namespace spira::test
