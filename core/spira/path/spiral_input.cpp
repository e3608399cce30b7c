#include "spira/path/spiral_input.h"

#include <cmath>
#include <string>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/path/surface_normals.h"

namespace spira {

namespace {

bool finite(const Vec3& v)
{
  return v.allFinite();
}

void checkLines(const Generatrices& g, const SpiralSettings& s)
{
  const size_t n = g.lines.size();
  if (n < 3)
    throw InputError("the part has " + std::to_string(n) + " generatrices; a spiral needs at least 3",
                     "decompose the part into more generatrices (one per degree around the part is typical)");
  for (size_t i = 0; i < n; ++i) {
    const Polyline& line = g.lines[i];
    const std::string which = "generatrix " + std::to_string(i);
    if (line.size() < 2)
      throw InputError(which + " has " + std::to_string(line.size()) +
                           " point(s); each needs at least 2 (its base and its end)",
                       "check the decomposition");
    double length = 0.0;
    for (size_t k = 0; k < line.size(); ++k) {
      if (!finite(line[k]))
        throw InputError(which + ", point " + std::to_string(k) + " is not a finite position",
                         "check the part mesh and the decomposition");
      if (k > 0) length += (line[k] - line[k - 1]).norm();
    }
    if (length <= 0.0)
      throw InputError(which + " has zero length",
                       "check the decomposition: every generatrix must climb the part");
    if (g.hasClosurePoint) {
      const double gap = (line.back() - g.closurePoint).norm();
      if (!(gap <= 0.5 * s.hMin))
        throw InputError(which + " ends " + significantText(gap, 6) +
                             " mm from the closure point; on a closed part every "
                             "generatrix must end there (within h_min / 2 = " +
                             significantText(0.5 * s.hMin, 6) + " mm)",
                         "re-run the closure search and the decomposition, or mark the part as open");
    }
  }
}

void checkNormals(const Generatrices& g)
{
  if (g.normals.size() != g.lines.size())
    throw InputError("normals are given for " + std::to_string(g.normals.size()) +
                         " generatrices but there are " + std::to_string(g.lines.size()),
                     "give one unit normal per generatrix point, or none to let Spira estimate them");
  for (size_t i = 0; i < g.lines.size(); ++i) {
    if (g.normals[i].size() != g.lines[i].size())
      throw InputError("generatrix " + std::to_string(i) + " has " + std::to_string(g.lines[i].size()) +
                           " points but " + std::to_string(g.normals[i].size()) + " normals",
                       "give one unit normal per generatrix point, or none to let Spira estimate them");
    for (size_t k = 0; k < g.normals[i].size(); ++k) {
      const Vec3& nk = g.normals[i][k];
      if (!finite(nk) || nk.norm() < 1e-9)
        throw InputError(
            "normal " + std::to_string(k) + " of generatrix " + std::to_string(i) + " is zero or not finite",
            "give unit surface normals, or none to let Spira estimate them");
    }
  }
}

}  // namespace

void validateSpiralSettings(const SpiralSettings& s)
{
  if (!std::isfinite(s.heightTolerance) || s.heightTolerance < 0.0)
    throw InputError(
        "the height tolerance must be zero or positive, not " + significantText(s.heightTolerance, 6),
        "use a small fraction of h such as 0.01");
  if (!std::isfinite(s.minRevolutionLength) || s.minRevolutionLength < 0.0)
    throw InputError("the minimum revolution length must be zero or positive, not " +
                         significantText(s.minRevolutionLength, 6),
                     "use 0 (one layer height) or a length in mm");
}

PreparedGeneratrices prepareGeneratrices(const Generatrices& g, const SpiralSettings& s)
{
  checkLines(g, s);
  PreparedGeneratrices out;
  if (!g.normals.empty()) {
    checkNormals(g);
    bool unit = true;
    for (const auto& line : g.normals)
      for (const Vec3& nk : line) unit = unit && std::abs(nk.squaredNorm() - 1.0) < 1e-12;
    if (unit) {
      out.source_ = &g;
      return out;
    }
  }
  out.owned_ = g;
  Generatrices& pg = out.owned_;
  if (pg.normals.empty()) {
    pg.normals = estimateNormals(pg);
    out.normalsEstimated_ = true;
  } else {
    for (auto& line : pg.normals)
      for (Vec3& nk : line) nk.normalize();
  }
  return out;
}

}  // namespace spira
