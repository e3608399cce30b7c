// Marching triangles over many levels at once, and the chaining of the segments into contours.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include <tbb/parallel_for.h>

#include "spira/base/error.h"
#include "spira/contour/iso_contour.h"

namespace spira {

namespace {

using EdgeKey = std::uint64_t;

EdgeKey edgeKey(int a, int b)
{
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<EdgeKey>(lo) << 32) | hi;
}

// One face's piece of an iso-line, oriented with the higher field on its left.
struct Segment {
  EdgeKey key[2];
  ContourPoint point[2];
  int face;
};

// The crossing on the edge from `below` (field < level) to `above` (field >= level). Both faces of
// the edge compute it from the same ordered pair, so it is bit-identical on either side.
ContourPoint crossing(const TriangleMesh& mesh, const std::vector<double>& field, int below, int above,
                      double level)
{
  const double t = (level - field[below]) / (field[above] - field[below]);
  if (t >= 1.0) return ContourPoint{mesh.vertices[above], above, above, 0.0};
  return ContourPoint{(1.0 - t) * mesh.vertices[below] + t * mesh.vertices[above], below, above, t};
}

bool segmentOfFace(const TriangleMesh& mesh, const std::vector<double>& field, int f, double level,
                   Segment& seg)
{
  const Face& fc = mesh.faces[f];
  bool up[3];
  for (int k = 0; k < 3; ++k) up[k] = field[fc[k]] >= level;
  if (up[0] == up[1] && up[1] == up[2]) return false;
  // The corner on its own side of the level.
  const int i = (up[0] == up[1]) ? 2 : (up[0] == up[2] ? 1 : 0);
  const int vi = fc[i], vn = fc[(i + 1) % 3], vp = fc[(i + 2) % 3];
  // Faces run counter-clockwise seen from outside; with corner i above the level, the segment
  // from edge (i, i+1) to edge (i+2, i) keeps corner i on its left.
  const ContourPoint onNext =
      up[i] ? crossing(mesh, field, vn, vi, level) : crossing(mesh, field, vi, vn, level);
  const ContourPoint onPrev =
      up[i] ? crossing(mesh, field, vp, vi, level) : crossing(mesh, field, vi, vp, level);
  const EdgeKey kNext = edgeKey(vi, vn), kPrev = edgeKey(vi, vp);
  if (up[i]) {
    seg = Segment{{kNext, kPrev}, {onNext, onPrev}, f};
  } else {
    seg = Segment{{kPrev, kNext}, {onPrev, onNext}, f};
  }
  return true;
}

bool samePoint(const ContourPoint& a, const ContourPoint& b)
{
  return a.onVertex() && b.onVertex() && a.v0 == b.v0;
}

// Drops the repeats left where a contour passes through a vertex at the level: of a run of points
// on one vertex the first is kept, and the segment leaving the run keeps its face (which holds
// the vertex too). Returns false when fewer than two distinct points (three for a loop) remain.
bool mergeRepeats(IsoContour& c)
{
  const size_t m = c.points.size();
  if (c.closed) {
    size_t r = 0;
    while (r < m && samePoint(c.points[r], c.points[(r + m - 1) % m])) ++r;
    if (r == m) return false;
    std::rotate(c.points.begin(), c.points.begin() + r, c.points.end());
    std::rotate(c.segmentFaces.begin(), c.segmentFaces.begin() + r, c.segmentFaces.end());
  }
  std::vector<ContourPoint> pts{c.points[0]};
  std::vector<int> faces;
  for (size_t i = 1; i < m; ++i) {
    if (samePoint(c.points[i], pts.back())) continue;
    faces.push_back(c.segmentFaces[i - 1]);
    pts.push_back(c.points[i]);
  }
  if (c.closed) faces.push_back(c.segmentFaces[m - 1]);
  c.points.swap(pts);
  c.segmentFaces.swap(faces);
  return c.points.size() >= (c.closed ? 3u : 2u);
}

IsoLevel chainSegments(const std::vector<Segment>& segs, double level)
{
  const size_t n = segs.size();
  // Endpoint 2*s+e of segment s; endpoints on the same edge are joined.
  std::vector<std::pair<EdgeKey, int>> ends;
  ends.reserve(2 * n);
  for (size_t s = 0; s < n; ++s)
    for (int e = 0; e < 2; ++e) ends.emplace_back(segs[s].key[e], static_cast<int>(2 * s + e));
  std::sort(ends.begin(), ends.end());
  std::vector<int> partner(2 * n, -1);
  for (size_t i = 0; i < ends.size();) {
    size_t j = i + 1;
    while (j < ends.size() && ends[j].first == ends[i].first) ++j;
    if (j - i > 2) {
      const int v0 = static_cast<int>(ends[i].first >> 32),
                v1 = static_cast<int>(ends[i].first & 0xffffffffu);
      throw InputError("the iso-line at field value " + std::to_string(level) + " crosses edge (" +
                           std::to_string(v0) + ", " + std::to_string(v1) + ") in " + std::to_string(j - i) +
                           " faces: the edge is non-manifold",
                       "repair the mesh so that every edge has at most two faces");
    }
    if (j - i == 2) {
      partner[ends[i].second] = ends[i + 1].second;
      partner[ends[i + 1].second] = ends[i].second;
    }
    i = j;
  }

  IsoLevel out;
  out.value = level;
  std::vector<char> used(n, 0);
  auto walk = [&](int startEnd) {
    IsoContour c;
    c.level = level;
    c.closed = false;
    size_t forward = 0;
    const int firstSeg = startEnd / 2;
    int s = firstSeg, e = startEnd % 2;
    c.points.push_back(segs[s].point[e]);
    while (true) {
      used[s] = 1;
      forward += (e == 0);
      c.segmentFaces.push_back(segs[s].face);
      const int far = 2 * s + (1 - e);
      const int next = partner[far];
      if (next >= 0 && next / 2 == firstSeg) {
        c.closed = true;
        break;
      }
      c.points.push_back(segs[s].point[1 - e]);
      if (next < 0 || used[next / 2]) break;
      s = next / 2;
      e = next % 2;
    }
    // Faces of an oriented mesh all agree; where they do not, the majority decides.
    if (2 * forward < c.segmentFaces.size()) c.reverse();
    if (mergeRepeats(c)) out.contours.push_back(std::move(c));
  };
  // Polylines first (from an end with no partner), then the loops left.
  for (size_t s = 0; s < n; ++s)
    for (int e = 0; e < 2; ++e)
      if (!used[s] && partner[2 * s + e] < 0) walk(static_cast<int>(2 * s + e));
  for (size_t s = 0; s < n; ++s)
    if (!used[s]) walk(static_cast<int>(2 * s));
  std::stable_sort(out.contours.begin(), out.contours.end(),
                   [](const IsoContour& a, const IsoContour& b) { return a.length() > b.length(); });
  return out;
}

void checkField(const TriangleMesh& mesh, const std::vector<double>& field)
{
  if (field.size() != mesh.vertexCount())
    throw InputError("the scalar field has " + std::to_string(field.size()) + " values for " +
                         std::to_string(mesh.vertexCount()) + " mesh vertices",
                     "recompute the field on this mesh");
  for (size_t v = 0; v < field.size(); ++v)
    if (!std::isfinite(field[v]))
      throw InputError("the scalar field is not finite at vertex " + std::to_string(v),
                       "recompute the field; check the mesh for isolated or degenerate parts");
}

}  // namespace

std::vector<IsoLevel> extractIsoContours(const TriangleMesh& mesh, const std::vector<double>& field,
                                         const std::vector<double>& levels, Progress* progress)
{
  checkField(mesh, field);
  if (!std::is_sorted(levels.begin(), levels.end()))
    throw InputError("iso-levels must be sorted ascending", "sort the levels before extracting contours");
  const size_t L = levels.size();
  if (L == 0) return {};

  // Face f is crossed by level c when min < c <= max of its field values: levels [first, last).
  const size_t F = mesh.faceCount();
  std::vector<std::uint32_t> first(F), last(F);
  std::vector<std::ptrdiff_t> count(L + 1, 0);
  for (size_t f = 0; f < F; ++f) {
    const Face& fc = mesh.faces[f];
    const double lo = std::min({field[fc[0]], field[fc[1]], field[fc[2]]});
    const double hi = std::max({field[fc[0]], field[fc[1]], field[fc[2]]});
    first[f] =
        static_cast<std::uint32_t>(std::upper_bound(levels.begin(), levels.end(), lo) - levels.begin());
    last[f] = static_cast<std::uint32_t>(std::upper_bound(levels.begin() + first[f], levels.end(), hi) -
                                         levels.begin());
    ++count[first[f]];
    --count[last[f]];
  }
  // Counting sort of (level, face) pairs into per-level face lists.
  std::vector<size_t> offset(L + 1, 0);
  std::ptrdiff_t running = 0;
  for (size_t k = 0; k < L; ++k) {
    running += count[k];
    offset[k + 1] = offset[k] + static_cast<size_t>(running);
  }
  std::vector<int> faces(offset[L]);
  std::vector<size_t> fill(offset.begin(), offset.end() - 1);
  for (size_t f = 0; f < F; ++f)
    for (std::uint32_t k = first[f]; k < last[f]; ++k) faces[fill[k]++] = static_cast<int>(f);
  if (progress) progress->checkCancel();

  std::vector<IsoLevel> out(L);
  tbb::parallel_for(size_t(0), L, [&](size_t k) {
    if (progress) progress->checkCancel();
    std::vector<Segment> segs;
    segs.reserve(offset[k + 1] - offset[k]);
    Segment seg;
    for (size_t i = offset[k]; i < offset[k + 1]; ++i)
      if (segmentOfFace(mesh, field, faces[i], levels[k], seg)) segs.push_back(seg);
    out[k] = chainSegments(segs, levels[k]);
  });
  return out;
}

IsoLevel extractIsoContour(const TriangleMesh& mesh, const std::vector<double>& field, double level)
{
  return extractIsoContours(mesh, field, {level}).front();
}

}  // namespace spira
