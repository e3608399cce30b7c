#include "examples/plugin_sdk/ruled_decomposer.h"

#include <cmath>
#include <optional>

#include "spira/base/progress.h"
#include "spira/base/units.h"

namespace spira::example {
namespace {

Vec3 centroid(const TriangleMesh& mesh, const BoundaryLoop& loop)
{
  Vec3 c = Vec3::Zero();
  for (int v : loop.vertices) c += mesh.vertices[static_cast<size_t>(v)];
  return c / static_cast<double>(loop.vertices.size());
}

// Where the half-line from `c` at `angle` (about z) crosses the closed loop, seen from above.
std::optional<Vec3> crossing(const TriangleMesh& mesh, const BoundaryLoop& loop, const Vec3& c, double angle)
{
  const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
  const size_t n = loop.vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = mesh.vertices[static_cast<size_t>(loop.vertices[i])];
    const Vec3& b = mesh.vertices[static_cast<size_t>(loop.vertices[(i + 1) % n])];
    const Eigen::Vector2d e = (b - a).head<2>(), w = (a - c).head<2>();
    const double den = d.x() * e.y() - d.y() * e.x();
    if (std::abs(den) < 1e-12) continue;
    const double t = (w.x() * e.y() - w.y() * e.x()) / den;  // along the half-line
    const double s = (w.x() * d.y() - w.y() * d.x()) / den;  // along the edge
    if (t > 0.0 && s >= 0.0 && s <= 1.0) return a + s * (b - a);
  }
  return std::nullopt;
}

}  // namespace

std::string RuledDecomposer::description() const
{
  return "Straight generatrices from the lower to the upper edge, evenly spread in angle (open ruled walls).";
}

const ParamSchema& RuledDecomposer::schema() const
{
  static const ParamSchema s({ParamDef{"lines",
                                       ParamType::Int,
                                       std::int64_t{120},
                                       8.0,
                                       2000.0,
                                       "",
                                       "Generatrices",
                                       "How many straight generatrices around the part.",
                                       "Discretisation",
                                       {}},
                              ParamDef{"samples",
                                       ParamType::Int,
                                       std::int64_t{40},
                                       2.0,
                                       1000.0,
                                       "",
                                       "Points per generatrix",
                                       "Points along each generatrix.",
                                       "Discretisation",
                                       {}}});
  return s;
}

bool RuledDecomposer::accepts(const DecomposeInput& input, std::string* why) const
{
  if (input.partClass == PartClass::Open && input.upper) return true;
  if (why) *why = "the ruled example needs an open wall with a lower and an upper edge";
  return false;
}

DecomposeResult RuledDecomposer::decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                                  Progress& progress) const
{
  // DecomposerPlugin::decompose() called accepts() and validated `values` against schema() first.
  const auto lines = static_cast<int>(values.getInt("lines"));
  const auto samples = static_cast<int>(values.getInt("samples"));
  const Vec3 lowCentre = centroid(input.mesh, input.lower);
  const Vec3 highCentre = centroid(input.mesh, *input.upper);
  DecomposeResult out;
  for (int k = 0; k < lines; ++k) {
    progress.checkCancel();
    const double angle = 2.0 * kPi * k / lines;
    const std::optional<Vec3> low = crossing(input.mesh, input.lower, lowCentre, angle);
    const std::optional<Vec3> high = crossing(input.mesh, *input.upper, highCentre, angle);
    if (!low || !high) {
      out.warnings.push_back("no edge crossing at " + std::to_string(angle * 180.0 / kPi) + " deg: skipped");
      continue;
    }
    Polyline line;
    for (int i = 0; i < samples; ++i) line.push_back(*low + (*high - *low) * i / (samples - 1.0));
    out.generatrices.lines.push_back(std::move(line));
    progress.report((k + 1.0) / lines, "ruled generatrices");
  }
  return out;
}

}  // namespace spira::example
