#include "strip_unfolding.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace spira::geodesic {

namespace {

using Vec2 = Eigen::Vector2d;
using Edge = std::array<int, 2>;

double cross2(const Vec2& a, const Vec2& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

// The plane point at 3D distances dp from p and dq from q, on the side of line pq given by `side`
// (+1 left, -1 right).
Vec2 placeByDistances(const Vec2& p, const Vec2& q, double dp, double dq, double side)
{
  const double l = (q - p).norm();
  const Vec2 u = (q - p) / l;
  const Vec2 n(-u.y(), u.x());
  const double a = (dp * dp - dq * dq + l * l) / (2.0 * l);
  const double h = std::sqrt(std::max(0.0, dp * dp - a * a));
  return p + a * u + side * h * n;
}

double sideOf(const Vec2& p, const Vec2& q, const Vec2& x)
{
  return cross2(q - p, x - p) >= 0.0 ? 1.0 : -1.0;
}

bool has(const Edge& e, int v)
{
  return e[0] == v || e[1] == v;
}

bool sameEdge(const Edge& a, const Edge& b)
{
  return has(a, b[0]) && has(a, b[1]);
}

// The face beside edge e whose vertices include every vertex the point names (a point inside the
// face, on one of its edges or at one of its corners): its third vertex, or -1.
int faceHolding(const PathPoint& p, const Edge& e, const StripMesh& mesh)
{
  for (int x : mesh.opposite(e[0], e[1])) {
    if (x < 0) continue;
    bool inside = true;
    for (int v : p.vertices)
      if (v >= 0 && !has(e, v) && v != x) inside = false;
    if (inside) return x;
  }
  return -1;
}

// The edges crossed, with the edge of the face between two crossings on faces that do not touch
// along an edge. Empty when there is no such face pair.
std::vector<Edge> strip(const std::vector<PathPoint>& run, const StripMesh& mesh)
{
  std::vector<Edge> out;
  for (size_t k = 1; k + 1 < run.size(); ++k) {
    const Edge e{run[k].vertices[0], run[k].vertices[1]};
    if (!out.empty()) {
      const Edge& b = out.back();
      if (sameEdge(b, e)) continue;
      const bool touching = has(e, b[0]) || has(e, b[1]);
      // A face on each edge, sharing an edge: {b, x} with x a vertex of e, and {e, y} with y a vertex of b.
      const std::array<int, 2> ob = mesh.opposite(b[0], b[1]), oe = mesh.opposite(e[0], e[1]);
      const bool sharedFace = touching && (has(e, ob[0]) || has(e, ob[1]));
      if (!sharedFace) {
        bool bridged = false;
        for (int x : ob)
          for (int y : oe)
            if (!bridged && x >= 0 && y >= 0 && has(e, x) && has(b, y)) {
              out.push_back({y, x});
              bridged = true;
            }
        if (!bridged) return {};
      }
    }
    out.push_back(e);
  }
  return out;
}

}  // namespace

std::optional<std::vector<PathPoint>> straightRun(const std::vector<PathPoint>& run, const StripMesh& mesh)
{
  if (run.size() < 3) return std::nullopt;
  for (size_t k = 1; k + 1 < run.size(); ++k) {
    const PathPoint& p = run[k];
    if (p.vertices[0] < 0 || p.vertices[1] < 0 || p.vertices[2] >= 0 || p.vertices[0] == p.vertices[1])
      return std::nullopt;
  }
  const std::vector<Edge> edges = strip(run, mesh);
  if (edges.empty()) return std::nullopt;
  const auto dist = [&](int a, int b) { return (mesh.position(a) - mesh.position(b)).norm(); };
  const auto distTo = [&](const Vec3& x, int v) { return (x - mesh.position(v)).norm(); };
  const PathPoint &startPoint = run.front(), &endPoint = run.back();
  if (faceHolding(startPoint, edges.front(), mesh) < 0 || faceHolding(endPoint, edges.back(), mesh) < 0)
    return std::nullopt;

  // The first edge along the x axis, the start on its right; each next face on the far side of
  // the edge it shares with the last face laid. Each edge keeps the coordinates it had when laid:
  // a fan winding more than once round a vertex lays that vertex again further on.
  std::map<int, Vec2> flat;
  Edge e = edges.front();
  flat[e[0]] = Vec2::Zero();
  flat[e[1]] = Vec2(dist(e[0], e[1]), 0.0);
  if (!(flat[e[1]].x() > 0.0)) return std::nullopt;
  const Vec2 start = placeByDistances(flat[e[0]], flat[e[1]], distTo(startPoint.position, e[0]),
                                      distTo(startPoint.position, e[1]), -1.0);
  Vec2 behind = start;  // a point of the last face laid, off the current edge
  std::vector<std::array<Vec2, 2>> laid{{flat[e[0]], flat[e[1]]}};
  for (size_t k = 1; k < edges.size(); ++k) {
    const Edge& next = edges[k];
    const int kept = has(e, next[0]) ? next[0] : next[1];
    const int fresh = kept == next[0] ? next[1] : next[0];
    const int dropped = kept == e[0] ? e[1] : e[0];
    const Vec2 p = flat[e[0]], q = flat[e[1]];
    if (!(dist(e[0], e[1]) > 0.0)) return std::nullopt;
    flat[fresh] = placeByDistances(p, q, dist(e[0], fresh), dist(e[1], fresh), -sideOf(p, q, behind));
    behind = flat[dropped];
    e = {kept, fresh};
    laid.push_back({flat[next[0]], flat[next[1]]});
  }
  const Vec2 p = flat[e[0]], q = flat[e[1]];
  const Vec2 end = placeByDistances(p, q, distTo(endPoint.position, e[0]), distTo(endPoint.position, e[1]),
                                    -sideOf(p, q, behind));

  // The straight line start -> end against each edge: t along the edge where it crosses.
  std::vector<PathPoint> out{startPoint};
  const Vec2 d = end - start;
  const double slack = 1e-9;
  for (size_t k = 0; k < edges.size(); ++k) {
    const Vec2 &a = laid[k][0], &b = laid[k][1];
    const double denom = cross2(d, b - a);
    if (std::abs(denom) < 1e-300) return std::nullopt;
    const double t = cross2(d, start - a) / denom;
    if (t < -slack || t > 1.0 + slack) return std::nullopt;
    const double s = std::clamp(t, 0.0, 1.0);
    PathPoint c;
    c.vertices = {edges[k][0], edges[k][1], -1};
    c.weights = Vec3(1.0 - s, s, 0.0);
    c.position = (1.0 - s) * mesh.position(edges[k][0]) + s * mesh.position(edges[k][1]);
    out.push_back(c);
  }
  out.push_back(endPoint);
  return out;
}

}  // namespace spira::geodesic
