#include "spira/contour/isovalue_decomposition.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/units.h"
#include "spira/contour/branch_detection.h"
#include "spira/contour/generatrix_chain.h"
#include "spira/contour/loop_following.h"
#include "spira/mesh/corner_normals.h"

namespace spira {

namespace {

struct Range {
  double lo = 0.0, hi = 0.0;
};

Range fieldOn(const std::vector<int>& vertices, const std::vector<double>& field)
{
  Range r{field[vertices[0]], field[vertices[0]]};
  for (int v : vertices) {
    r.lo = std::min(r.lo, field[v]);
    r.hi = std::max(r.hi, field[v]);
  }
  return r;
}

// Drops the contours shorter than `minLength` that are not the longest of their level (loops
// around a lone vertex of a noisy field); returns how many.
size_t dropSpecks(IsoLevel& level, double minLength)
{
  if (level.contours.size() < 2) return 0;
  const size_t before = level.contours.size();
  level.contours.erase(std::remove_if(level.contours.begin() + 1, level.contours.end(),
                                      [&](const IsoContour& c) { return c.length() < minLength; }),
                       level.contours.end());
  return before - level.contours.size();
}

[[noreturn]] void refuseBranches(const IsoLevel& level, size_t before)
{
  const size_t after = level.contours.size();
  const std::string where = "at field value " + significantText(level.value, 4) +
                            " (about z = " + significantText(meanZ(level), 4) + " mm)";
  std::string what;
  if (after == 0)
    what = "the field has no iso-contour " + where +
           ": it does not grow steadily from the lower edge to the top";
  else if (after > before)
    what = "the part splits into " + std::to_string(after) + " branches " + where;
  else
    what = std::to_string(before) + " branches of the part merge into " + std::to_string(after) + " " + where;
  if (after > before)
    throw InputError(what +
                         ", narrower than a branch Spira plans on its own (a contour at least one bead ring, "
                         "pi x bead width, and 5 % of the base edge around)",
                     "remove the narrow branch in the CAD tool or cut the part below it; a narrower bead "
                     "width (--bead-width) lets narrower branches count");
  throw InputError(what +
                       ": the wall closes around a hole or a handle, which one spiral per branch cannot "
                       "follow",
                   "cut the part below the merge and plan the pieces on their own");
}

SurfacePoint surfacePointAtVertex(const TriangleMesh& mesh, int v)
{
  for (size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.faces[f][k] == v) {
        SurfacePoint p;
        p.position = mesh.vertices[v];
        p.face = static_cast<int>(f);
        p.bary[k] = 1.0;
        return p;
      }
  throw InternalError("vertex " + std::to_string(v) + " belongs to no face");
}

}  // namespace

double meanFieldGradient(const TriangleMesh& mesh, const std::vector<double>& field)
{
  double sum = 0.0, area = 0.0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const Face& fc = mesh.faces[f];
    const Vec3 &x0 = mesh.vertices[fc[0]], &x1 = mesh.vertices[fc[1]], &x2 = mesh.vertices[fc[2]];
    const Vec3 N = (x1 - x0).cross(x2 - x0);
    const double a2 = N.norm();
    if (!(a2 > 0)) continue;
    const Vec3 n = N / a2;
    const Vec3 g = (field[fc[0]] * n.cross(x2 - x1) + field[fc[1]] * n.cross(x0 - x2) +
                    field[fc[2]] * n.cross(x1 - x0)) /
                   a2;
    sum += 0.5 * a2 * g.norm();
    area += 0.5 * a2;
  }
  return area > 0 ? sum / area : 0.0;
}

namespace {

const char* const kFieldHint =
    "use the geodesic distance from the lower edge (closed parts) or the harmonic field "
    "(open parts: 0 on the lower edge, 1 on the upper one)";

void requireUsableInput(const TriangleMesh& mesh, const std::vector<double>& field, const BoundaryLoop& lower,
                        size_t n)
{
  if (field.size() != mesh.vertexCount())
    throw InputError("the scalar field has " + std::to_string(field.size()) + " values for " +
                         std::to_string(mesh.vertexCount()) + " mesh vertices",
                     "recompute the field on this mesh");
  if (lower.vertices.size() < 3)
    throw InputError("the lower edge has fewer than 3 vertices", "repair the mesh");
  for (double v : field)
    if (!std::isfinite(v)) throw InputError("the scalar field has non-finite values", kFieldHint);
  if (n < 3)
    throw InputError("the generatrix count must be at least 3, not " + std::to_string(n), "raise n_points");
}

// The field values of the interior levels, evenly spaced between the lower edge and the top.
struct LevelSpan {
  Range base;         // the field along the lower edge
  int topVertex = 0;  // the vertex of maximal field
  double top = 0.0;   // the upper edge's lowest value (open), the maximum (closed)
  std::vector<double> values;
};

// The field range the interior levels span: above every lower-edge value, below every upper-edge
// value (open) or the maximum (closed).
LevelSpan spanLevels(const TriangleMesh& mesh, const std::vector<double>& field, const BoundaryLoop& lower,
                     const BoundaryLoop* upper, double spacing, size_t maxLevels,
                     std::vector<std::string>& warnings)
{
  LevelSpan span;
  span.base = fieldOn(lower.vertices, field);
  const Range& base = span.base;
  span.topVertex = static_cast<int>(std::max_element(field.begin(), field.end()) - field.begin());
  span.top = field[span.topVertex];
  if (upper) {
    if (upper->vertices.size() < 3)
      throw InputError("the upper edge has fewer than 3 vertices", "repair the mesh");
    const Range up = fieldOn(upper->vertices, field);
    span.top = up.lo;
    if (up.hi - up.lo > 0.05 * (span.top - base.hi))
      warnings.push_back("the field varies by " + significantText(up.hi - up.lo, 4) +
                         " along the upper edge; the last contours may run into it");
  }
  const double top = span.top;
  if (!(top > base.hi))
    throw InputError("the field does not grow from the lower edge (" + significantText(base.hi, 4) +
                         ") to the " + (upper ? "upper edge (" : "top (") + significantText(top, 4) + ")",
                     kFieldHint);
  if (base.hi - base.lo > 0.05 * (top - base.hi))
    warnings.push_back("the field varies by " + significantText(base.hi - base.lo, 4) +
                       " along the lower edge; the first contours may be uneven");

  const double gradient = meanFieldGradient(mesh, field);
  const double stepsWanted = gradient > 0 ? (top - base.hi) / (spacing * gradient) : 2.0;
  size_t K = static_cast<size_t>(std::max(2.0, std::ceil(stepsWanted - 1e-9)));
  if (K > maxLevels) {
    warnings.push_back("level spacing " + significantText(spacing, 4) + " mm asks for " + std::to_string(K) +
                       " contours; using " + std::to_string(maxLevels));
    K = maxLevels;
  }
  span.values.resize(K - 1);
  for (size_t k = 1; k < K; ++k) span.values[k - 1] = base.hi + (top - base.hi) * static_cast<double>(k) / K;
  return span;
}

// The iso-contours at the span's values, one closed loop per level: specks dropped, the several
// small loops at the top of a closed part cut off; refused where the part branches or a contour
// runs into a free edge.
std::vector<IsoLevel> singleLoopLevels(const TriangleMesh& mesh, const std::vector<double>& field,
                                       const LevelSpan& span, const BoundaryLoop& lower, bool open,
                                       double spacing, double meanEdge, std::vector<std::string>& warnings,
                                       Progress& progress)
{
  SubProgress extractProgress(progress, 0.0, 0.6, "iso-contours");
  std::vector<IsoLevel> levels = extractIsoContours(mesh, field, span.values, &extractProgress);
  progress.report(0.6, "iso-contours");

  size_t specks = 0;
  for (auto& l : levels) specks += dropSpecks(l, 3.0 * meanEdge);
  if (specks)
    warnings.push_back(
        std::to_string(specks) +
        " tiny iso-contours (under 3 mean edge lengths) around lone field extrema were ignored");
  // Closed parts: several small loops at the very top are several maxima of the field inside the
  // closure zone, not branches; the contours stop below them and the generatrices end at the
  // closure point.
  size_t firstOff = levels.size();
  for (size_t k = 0; k < levels.size() && firstOff == levels.size(); ++k)
    if (levels[k].contours.size() != 1) firstOff = k;
  if (firstOff < levels.size() && !open && firstOff > 0) {
    // Small: loops of radius under two level steps or two mesh edges, or under 5 % of the base.
    const double small = std::max(4.0 * kPi * std::max(spacing, meanEdge), 0.05 * lower.length);
    bool allSmall = true;
    for (size_t k = firstOff; k < levels.size() && allSmall; ++k)
      for (const auto& c : levels[k].contours) allSmall = allSmall && c.length() < small;
    if (allSmall) {
      warnings.push_back("the field has several maxima near its top (field value " +
                         significantText(levels[firstOff].value, 4) + "); the " +
                         std::to_string(levels.size() - firstOff) +
                         " contours above were dropped and the generatrices end at the closure point");
      levels.resize(firstOff);
    }
  }
  for (size_t k = 0; k < levels.size(); ++k) {
    if (levels[k].contours.size() != 1) refuseBranches(levels[k], k == 0 ? 1 : levels[k - 1].contours.size());
    if (!levels[k].contours[0].closed)
      throw InputError("the iso-contour at field value " + significantText(levels[k].value, 4) +
                           " (about z = " + significantText(meanZ(levels[k]), 4) +
                           " mm) runs into a free edge instead of going around the part",
                       std::string("the field must be constant along each free edge: ") + kFieldHint);
  }
  return levels;
}

// Contours base first, one orientation (higher field on the left), each starting next to the
// previous one's start, n points each.
std::vector<ResampledLoop> resampleContours(const TriangleMesh& mesh, std::vector<IsoLevel> levels,
                                            const LevelSpan& span, const BoundaryLoop& lower,
                                            const BoundaryLoop* upper, size_t n, Progress& progress)
{
  std::vector<IsoContour> loops;
  loops.reserve(levels.size() + 2);
  loops.push_back(contourFromBoundaryLoop(mesh, lower.vertices, span.base.hi, true));
  for (auto& l : levels) loops.push_back(std::move(l.contours[0]));
  if (upper) loops.push_back(contourFromBoundaryLoop(mesh, upper->vertices, span.top, false));
  std::vector<ResampledLoop> contours(loops.size());
  contours[0] = resampleLoop(mesh, loops[0], n, 0.0);
  // Each contour is parameterised by the one below it, so that generatrix m links the points that
  // face each other across the gap (see loop_following.h) instead of the points at the same
  // fraction of each contour's length, which shear across the part where consecutive contours
  // differ in shape.
  for (size_t c = 1; c < loops.size(); ++c) {
    progress.checkCancel();
    contours[c] = resampleLoopFollowing(mesh, loops[c], contours[c - 1].positions());
  }
  return contours;
}

// Generatrix m through point (k_c + m) mod n of every contour, then (closed parts) the closure
// point: the finder's, or the hottest vertex.
void linkGeneratrices(const TriangleMesh& mesh, int topVertex, bool open,
                      const std::optional<Vec3>& closurePoint, size_t n, IsoDecomposition& out)
{
  std::optional<SurfacePoint> closure;
  if (!open)
    closure = closurePoint ? closestSurfacePoint(mesh, *closurePoint) : surfacePointAtVertex(mesh, topVertex);

  std::vector<std::vector<Vec3>> positions(out.contours.size());
  for (size_t c = 0; c < out.contours.size(); ++c) positions[c] = out.contours[c].positions();
  const PrincipalGeneratrix principal =
      shortestLinkedGeneratrix(positions, closure ? std::optional<Vec3>(closure->position) : std::nullopt);
  out.principalIndex = principal.index;

  const std::vector<Vec3> normals = cornerNormals(mesh);
  Generatrices& g = out.generatrices;
  const size_t C = out.contours.size();
  g.lines.assign(n, Polyline(C + (closure ? 1 : 0)));
  g.normals.assign(n, std::vector<Vec3>(C + (closure ? 1 : 0)));
  Vec3 closureNormal = Vec3::UnitZ();
  if (closure) {
    g.hasClosurePoint = true;
    g.closurePoint = closure->position;
    closureNormal = surfaceNormalAt(mesh, normals, *closure);
  }
  tbb::parallel_for(size_t(0), n, [&](size_t m) {
    for (size_t c = 0; c < C; ++c) {
      const SurfacePoint& p = out.contours[c].points[(principal.index[c] + m) % n];
      g.lines[m][c] = p.position;
      g.normals[m][c] = surfaceNormalAt(mesh, normals, p);
    }
    if (closure) {
      g.lines[m][C] = closure->position;
      g.normals[m][C] = closureNormal;
    }
  });
}

}  // namespace

IsoDecomposition decomposeByIsoValues(const TriangleMesh& mesh, const std::vector<double>& field,
                                      const BoundaryLoop& lower, const BoundaryLoop* upper,
                                      const std::optional<Vec3>& closurePoint,
                                      const IsoDecompositionOptions& options, Progress& progress)
{
  const size_t n = options.pointsPerContour;
  requireUsableInput(mesh, field, lower, n);
  IsoDecomposition out;
  const double meanEdge = mesh.meanEdgeLength();
  const double spacing = options.levelSpacing > 0 ? options.levelSpacing : meanEdge;
  out.levelSpacing = spacing;
  const LevelSpan span = spanLevels(mesh, field, lower, upper, spacing, options.maxLevels, out.warnings);
  std::vector<IsoLevel> levels =
      singleLoopLevels(mesh, field, span, lower, upper != nullptr, spacing, meanEdge, out.warnings, progress);
  out.contours = resampleContours(mesh, std::move(levels), span, lower, upper, n, progress);
  progress.report(0.75, "resampling");
  linkGeneratrices(mesh, span.topVertex, upper != nullptr, closurePoint, n, out);
  progress.report(1.0, "generatrices");
  return out;
}

}  // namespace spira
