#include "spira/contour/branch_levels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "spira/base/error.h"
#include "spira/contour/isovalue_decomposition.h"

namespace spira {

namespace {

// The midpoint of the closest pair of points of the two longest contours: where they part.
Vec3 partingPoint(const IsoLevel& level)
{
  if (level.contours.size() < 2) return Vec3::Zero();
  const auto& a = level.contours[0].points;
  const auto& b = level.contours[1].points;
  double best = std::numeric_limits<double>::infinity();
  Vec3 mid = Vec3::Zero();
  for (const auto& p : a)
    for (const auto& q : b) {
      const double d = (p.position - q.position).squaredNorm();
      if (d < best) {
        best = d;
        mid = 0.5 * (p.position + q.position);
      }
    }
  return mid;
}

}  // namespace

size_t significantContourCount(const IsoLevel& level, double minPerimeter, bool* touchesEdge)
{
  size_t n = 0;
  bool open = false;
  for (const auto& c : level.contours) {
    if (!c.closed) {
      open = true;
      continue;
    }
    if (c.length() >= minPerimeter) ++n;
  }
  if (touchesEdge) *touchesEdge = open;
  return n;
}

double highestValueOn(const std::vector<int>& vertices, const std::vector<double>& field)
{
  double top = -std::numeric_limits<double>::infinity();
  for (int v : vertices) top = std::max(top, field[static_cast<size_t>(v)]);
  return top;
}

std::vector<int> saddleVertices(const TriangleMesh& mesh, const std::vector<double>& field, double lo,
                                double hi)
{
  // Ties are broken by vertex id (simulation of simplicity), so that a saddle spread over an edge
  // whose ends have the same value (a symmetric mesh) still has one vertex that is a saddle.
  const auto over = [&](int w, int v) {
    const double fw = field[static_cast<size_t>(w)], fv = field[static_cast<size_t>(v)];
    return fw > fv || (fw == fv && w > v);
  };
  std::vector<int> changes(mesh.vertexCount(), 0);
  for (const Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      const int v = f[k];
      const double c = field[static_cast<size_t>(v)];
      if (!(c >= lo && c <= hi)) continue;
      changes[static_cast<size_t>(v)] += over(f[(k + 1) % 3], v) != over(f[(k + 2) % 3], v);
    }
  std::vector<int> out;
  for (size_t v = 0; v < changes.size(); ++v)
    if (changes[v] >= 4) out.push_back(static_cast<int>(v));
  std::sort(out.begin(), out.end(),
            [&](int a, int b) { return field[static_cast<size_t>(a)] < field[static_cast<size_t>(b)]; });
  return out;
}

int saddleVertexIn(const TriangleMesh& mesh, const std::vector<double>& field, double lo, double hi)
{
  const double mid = 0.5 * (lo + hi);
  int best = -1;
  for (int v : saddleVertices(mesh, field, lo, hi))
    if (best < 0 ||
        std::abs(field[static_cast<size_t>(v)] - mid) < std::abs(field[static_cast<size_t>(best)] - mid))
      best = v;
  return best;
}

BranchSplit findFirstBranchSplit(const TriangleMesh& mesh, const std::vector<double>& field, double from,
                                 const BranchScanOptions& options, Progress& progress)
{
  if (field.size() != mesh.vertexCount())
    throw InputError("the field has " + std::to_string(field.size()) + " values for " +
                         std::to_string(mesh.vertexCount()) + " vertices",
                     "compute the field on this mesh");
  double top = -std::numeric_limits<double>::infinity();
  for (double v : field) {
    if (!std::isfinite(v))
      throw InputError("the field has non-finite values", "grow the field from the base over the whole part");
    top = std::max(top, v);
  }
  BranchSplit out;
  out.stopLevel = top;
  if (!(top > from)) {
    out.vanished = true;
    return out;
  }
  const double meanEdge = mesh.meanEdgeLength();
  const double minPerimeter = options.minPerimeter > 0 ? options.minPerimeter : 3.0 * meanEdge;
  double step = options.levelStep > 0 ? options.levelStep : meanEdge * meanFieldGradient(mesh, field);
  if (!(step > 0)) step = (top - from) / 64.0;
  step = std::max(step, (top - from) / static_cast<double>(std::max<size_t>(options.maxLevels, 2)));
  std::vector<double> levels;
  for (double c = from + step; c < top; c += step) levels.push_back(c);
  const std::vector<IsoLevel> scanned = extractIsoContours(mesh, field, levels, &progress);

  size_t k = 0;
  bool split = false;
  for (; k < scanned.size(); ++k) {
    bool touches = false;
    const size_t count = significantContourCount(scanned[k], minPerimeter, &touches);
    if (count >= 2) {
      split = true;
      break;
    }
    if (count == 0 || touches) break;
  }
  double a = k == 0 ? from : levels[k - 1];
  double b = k < levels.size() ? levels[k] : top;
  IsoLevel atB = k < scanned.size() ? scanned[k] : IsoLevel();

  // A branch can part and end within one scan step. The count only changes at saddle vertices, so
  // each saddle below the scan's first event is also checked just above its value, where no
  // other vertex is; the first that splits brackets the saddle at once.
  std::vector<double> sorted = field;
  std::sort(sorted.begin(), sorted.end());
  const std::vector<int> saddles = saddleVertices(mesh, field, from, b);
  for (size_t i = 0; i < saddles.size() && i < options.maxSaddleChecks; ++i) {
    progress.checkCancel();
    const double c = field[static_cast<size_t>(saddles[i])];
    const auto next = std::upper_bound(sorted.begin(), sorted.end(), c);
    if (next == sorted.end() || c >= b) break;
    const double above = 0.5 * (c + std::min(*next, b));
    IsoLevel l = extractIsoContour(mesh, field, above);
    if (significantContourCount(l, minPerimeter) >= 2) {
      split = true;
      a = c - 1e-12 * (top - from);
      b = above;
      atB = std::move(l);
      break;
    }
  }
  if (!split) {
    out.vanished = true;
    out.stopLevel = b;
    return out;
  }

  // Bisect the bracket [one contour, several contours]. The count of a piecewise linear field
  // changes only at a vertex value, so the bracket closes onto the saddle vertex's value.
  const double tolerance = options.tolerance > 0 ? options.tolerance : 1e-9 * (top - from);
  while (b - a > tolerance && out.bisections < 200) {
    progress.checkCancel();
    const double mid = 0.5 * (a + b);
    if (!(mid > a && mid < b)) break;
    IsoLevel l = extractIsoContour(mesh, field, mid);
    if (significantContourCount(l, minPerimeter) >= 2) {
      b = mid;
      atB = std::move(l);
    } else {
      a = mid;
    }
    ++out.bisections;
  }
  out.found = true;
  out.below = a;
  out.above = b;
  out.saddle = 0.5 * (a + b);
  out.stopLevel = b;
  out.branches = significantContourCount(atB, minPerimeter);
  // Contours come longest first; the two that part at the saddle are among the significant ones.
  IsoLevel longest = atB;
  longest.contours.erase(
      std::remove_if(longest.contours.begin(), longest.contours.end(),
                     [&](const IsoContour& c) { return !c.closed || c.length() < minPerimeter; }),
      longest.contours.end());
  const double widen = std::max(b - a, 1e-12 * (top - from));
  out.saddleVertex = saddleVertexIn(mesh, field, a - widen, b + widen);
  out.position =
      out.saddleVertex >= 0 ? mesh.vertices[static_cast<size_t>(out.saddleVertex)] : partingPoint(longest);
  return out;
}

}  // namespace spira
