#include "spira/path/seam_placement.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "spira/path/arc_length_polyline.h"

namespace spira {
namespace {

// Unit chord of a generatrix over [s0, s1] of its length.
Vec3 chordDirection(const ArcLengthPolyline& arc, double s0, double s1)
{
  const Vec3 d = arc.at(s1).position - arc.at(s0).position;
  const double len = d.norm();
  return len > 0.0 ? Vec3(d / len) : Vec3::Zero();
}

// Unit tangent of the ring through the generatrices' points at arc length s (clamped to each).
std::vector<Vec3> ringTangents(const std::vector<ArcLengthPolyline>& arcs, bool fromTop, double s)
{
  const size_t n = arcs.size();
  std::vector<Vec3> ring(n), tangent(n);
  for (size_t i = 0; i < n; ++i) {
    const double len = arcs[i].length();
    ring[i] = arcs[i].at(fromTop ? std::max(0.0, len - s) : std::min(len, s)).position;
  }
  for (size_t i = 0; i < n; ++i) {
    const Vec3 d = ring[(i + 1) % n] - ring[(i + n - 1) % n];
    const double len = d.norm();
    tangent[i] = len > 0.0 ? Vec3(d / len) : Vec3::Zero();
  }
  return tangent;
}

}  // namespace

int leastLeaningSeam(const Generatrices& g, double reach, double margin)
{
  const size_t n = g.lines.size();
  if (n < 3 || g.normals.size() != n) return 0;
  std::vector<ArcLengthPolyline> arcs;
  arcs.reserve(n);
  for (size_t i = 0; i < n; ++i) arcs.emplace_back(g.lines[i], g.normals[i]);
  std::vector<double> lean(n, 0.0);
  const bool top = !g.hasClosurePoint;
  for (bool fromTop : {false, true}) {
    if (fromTop && !top) break;
    const std::vector<Vec3> tangent = ringTangents(arcs, fromTop, 0.5 * reach);
    for (size_t i = 0; i < n; ++i) {
      const double len = arcs[i].length(), span = std::min(reach, len / 3.0);
      const Vec3 d = fromTop ? chordDirection(arcs[i], len - span, len) : chordDirection(arcs[i], 0.0, span);
      lean[i] = std::max(lean[i], std::abs(d.dot(tangent[i])));
    }
  }
  const auto best = std::min_element(lean.begin(), lean.end());
  return lean[0] > *best + margin ? static_cast<int>(best - lean.begin()) : 0;
}

Generatrices startingAt(const Generatrices& g, int first)
{
  Generatrices out = g;
  const size_t n = g.lines.size();
  if (n == 0 || first == 0) return out;
  std::rotate(out.lines.begin(), out.lines.begin() + first, out.lines.end());
  if (out.normals.size() == n)
    std::rotate(out.normals.begin(), out.normals.begin() + first, out.normals.end());
  return out;
}

}  // namespace spira
