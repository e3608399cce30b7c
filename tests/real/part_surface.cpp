#include "real/part_surface.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "builtin_plugins.h"
#include "spira/base/progress.h"
#include "spira/io/import_service.h"

namespace spira::test::real {
namespace {

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::vector<Triangle> readStl(const std::filesystem::path& file, double scale)
{
  std::ifstream in(file, std::ios::binary);
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Triangle> out;
  if (data.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    if (84 + 50 * static_cast<size_t>(n) == data.size()) {
      for (size_t f = 0; f < n; ++f) {
        const char* rec = data.data() + 84 + 50 * f + 12;  // skip the stored normal
        Triangle t;
        for (int k = 0; k < 3; ++k) {
          float c[3];
          std::memcpy(c, rec + 12 * k, 12);
          t[static_cast<size_t>(k)] = V3(c[0], c[1], c[2]) * scale;
        }
        out.push_back(t);
      }
      return out;
    }
  }
  std::istringstream s(data);
  std::string word;
  Triangle t;
  int k = 0;
  while (s >> word) {
    if (word != "vertex") continue;
    double x = 0, y = 0, z = 0;
    s >> x >> y >> z;
    t[static_cast<size_t>(k)] = V3(x, y, z) * scale;
    if (++k == 3) {
      out.push_back(t);
      k = 0;
    }
  }
  if (out.empty()) throw std::runtime_error(file.string() + ": no triangles read");
  return out;
}

}  // namespace

double millimetresPer(const std::string& unit)
{
  if (unit == "mm") return 1.0;
  if (unit == "cm") return 10.0;
  if (unit == "m") return 1000.0;
  if (unit == "in") return 25.4;
  throw std::invalid_argument("unknown length unit '" + unit + "'");
}

std::vector<Triangle> readPartSurface(const std::filesystem::path& file, const std::string& unit)
{
  if (lower(file.extension().string()) == ".stl") return readStl(file, millimetresPer(unit));
  ParamSet params;
  if (unit != "mm") params.set("unit", unit);  // CAD formats state their own unit
  NullProgress progress;
  const ImportedPart part = importPart(builtinRegistry(), file, &params, progress);
  std::vector<Triangle> out;
  for (const auto& f : part.mesh.faces) {
    Triangle t;
    for (size_t k = 0; k < 3; ++k) {
      const auto& v = part.mesh.vertices[static_cast<size_t>(f[k])];
      t[k] = V3(v.x(), v.y(), v.z());
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace spira::test::real
