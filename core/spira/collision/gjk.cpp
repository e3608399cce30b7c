#include "spira/collision/gjk.h"

#include <algorithm>
#include <cmath>

namespace spira {

namespace {

// Below this squared length (mm^2) a vector counts as zero: the shapes touch.
constexpr double kZeroSq = 1e-20;
constexpr int kMaxIterations = 128;

struct Vertex {
  Vec3 w;     // a - b
  Vec3 a, b;  // the support points it came from, for the witnesses
};

struct Simplex {
  Vertex v[4];
  double lambda[4] = {1.0, 0.0, 0.0, 0.0};
  int size = 0;
};

// Keeps only the listed vertices (with their barycentric weights) and returns the point they give.
Vec3 keep(Simplex& s, std::initializer_list<std::pair<int, double>> items)
{
  Vertex kept[4];
  double weights[4];
  int n = 0;
  Vec3 point = Vec3::Zero();
  for (const auto& [index, weight] : items) {
    kept[n] = s.v[index];
    weights[n] = weight;
    point += weight * kept[n].w;
    ++n;
  }
  for (int k = 0; k < n; ++k) {
    s.v[k] = kept[k];
    s.lambda[k] = weights[k];
  }
  s.size = n;
  return point;
}

Vec3 closestOnSegment(Simplex& s, int i, int j)
{
  const Vec3& A = s.v[i].w;
  const Vec3 ab = s.v[j].w - A;
  const double len2 = ab.squaredNorm();
  const double t = len2 > kZeroSq ? -A.dot(ab) / len2 : 0.0;
  if (t <= 0.0) return keep(s, {{i, 1.0}});
  if (t >= 1.0) return keep(s, {{j, 1.0}});
  return keep(s, {{i, 1.0 - t}, {j, t}});
}

// Ericson, Real-Time Collision Detection 5.1.5, with the query point at the origin.
Vec3 closestOnTriangle(Simplex& s, int i, int j, int k)
{
  const Vec3 &A = s.v[i].w, &B = s.v[j].w, &C = s.v[k].w;
  const Vec3 ab = B - A, ac = C - A;
  const double d1 = -ab.dot(A), d2 = -ac.dot(A);
  if (d1 <= 0.0 && d2 <= 0.0) return keep(s, {{i, 1.0}});
  const double d3 = -ab.dot(B), d4 = -ac.dot(B);
  if (d3 >= 0.0 && d4 <= d3) return keep(s, {{j, 1.0}});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return keep(s, {{i, 1.0 - t}, {j, t}});
  }
  const double d5 = -ab.dot(C), d6 = -ac.dot(C);
  if (d6 >= 0.0 && d5 <= d6) return keep(s, {{k, 1.0}});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return keep(s, {{i, 1.0 - t}, {k, t}});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return keep(s, {{j, 1.0 - t}, {k, t}});
  }
  const double sum = va + vb + vc;  // = |ab x ac|^2: zero for a flat (collinear) triangle
  if (!(sum > 1e-14 * ab.squaredNorm() * ac.squaredNorm()) || sum <= 0.0) {
    // Collinear vertices: the nearest of the three edges is the answer.
    Simplex best = s;
    Vec3 bestPoint = closestOnSegment(best, i, j);
    for (const auto& [p, q] : {std::pair<int, int>{i, k}, std::pair<int, int>{j, k}}) {
      Simplex trial = s;
      const Vec3 point = closestOnSegment(trial, p, q);
      if (point.squaredNorm() < bestPoint.squaredNorm()) {
        best = trial;
        bestPoint = point;
      }
    }
    s = best;
    return bestPoint;
  }
  const double v = vb / sum, w = vc / sum;
  return keep(s, {{i, 1.0 - v - w}, {j, v}, {k, w}});
}

// Returns false when the origin lies inside the tetrahedron (the shapes overlap).
bool closestOnTetrahedron(Simplex& s, Vec3& point)
{
  static const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
  bool found = false;
  Simplex best;
  for (const auto& f : faces) {
    const Vec3 &P = s.v[f[0]].w, &Q = s.v[f[1]].w, &R = s.v[f[2]].w, &X = s.v[f[3]].w;
    const Vec3 n = (Q - P).cross(R - P);
    const double sideOrigin = -n.dot(P), sideOpposite = n.dot(X - P);
    // A flat tetrahedron has no inside: every face is a candidate then.
    const bool flat = sideOpposite * sideOpposite <= 1e-20 * n.squaredNorm() * (X - P).squaredNorm();
    if (!flat && sideOrigin * sideOpposite > 0.0) continue;
    Simplex trial = s;
    const Vec3 candidate = closestOnTriangle(trial, f[0], f[1], f[2]);
    if (!found || candidate.squaredNorm() < point.squaredNorm()) {
      found = true;
      point = candidate;
      best = trial;
    }
  }
  if (!found) return false;
  s = best;
  return true;
}

struct Outcome {
  double lower = 0.0, upper = 0.0;
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();
  bool intersecting = false;
};

void witnesses(const Simplex& s, Outcome& out)
{
  out.pointA.setZero();
  out.pointB.setZero();
  for (int k = 0; k < s.size; ++k) {
    out.pointA += s.lambda[k] * s.v[k].a;
    out.pointB += s.lambda[k] * s.v[k].b;
  }
}

// Runs GJK until the gap between the bounds is below `tolerance`, the upper bound drops to
// `stopBelow`, or the lower bound rises above `stopAbove`.
Outcome runGjk(const ConvexShape& A, const ConvexShape& B, double tolerance, double stopBelow,
               double stopAbove)
{
  Simplex s;
  // Start from the supports facing each other: much nearer the answer than the central points.
  const Vec3 towardsB = B.anyPoint() - A.anyPoint();
  s.v[0].a = A.support(towardsB);
  s.v[0].b = B.support(-towardsB);
  s.v[0].w = s.v[0].a - s.v[0].b;
  s.size = 1;  // any point of a - b is a valid first vertex
  Vec3 v = s.v[0].w;
  Outcome out;
  witnesses(s, out);
  out.lower = -std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double vv = v.squaredNorm();
    out.upper = std::sqrt(vv);
    if (vv <= kZeroSq) {
      out.intersecting = true;
      out.upper = out.lower = 0.0;
      return out;
    }
    if (out.upper <= stopBelow) return out;
    Vertex w;
    w.a = A.support(-v);
    w.b = B.support(v);
    w.w = w.a - w.b;
    out.lower = std::max(out.lower, v.dot(w.w) / out.upper);
    if (out.lower > stopAbove) return out;
    if (out.upper - out.lower <= tolerance + 1e-12 * out.upper) return out;
    for (int k = 0; k < s.size; ++k)
      if ((s.v[k].w - w.w).squaredNorm() <= kZeroSq) return out;  // no new direction: converged
    Simplex next = s;
    next.v[next.size++] = w;
    Vec3 nv = Vec3::Zero();
    switch (next.size) {
      case 2:
        nv = closestOnSegment(next, 0, 1);
        break;
      case 3:
        nv = closestOnTriangle(next, 0, 1, 2);
        break;
      default:
        if (!closestOnTetrahedron(next, nv)) {
          out.intersecting = true;
          out.upper = out.lower = 0.0;
          return out;
        }
    }
    // Rounding can stall the descent; the last simplex is then as good as it gets.
    if (nv.squaredNorm() >= vv) return out;
    s = next;
    v = nv;
    witnesses(s, out);
  }
  return out;
}

}  // namespace

GjkResult gjkDistance(const ConvexShape& a, const ConvexShape& b, double tolerance, double stopAbove)
{
  const Outcome o = runGjk(a, b, tolerance, -1.0, stopAbove);
  GjkResult r;
  r.intersecting = o.intersecting;
  r.exceeded = !o.intersecting && o.lower > stopAbove;
  r.distance = o.intersecting ? 0.0 : r.exceeded ? o.lower : o.upper;
  r.pointA = o.pointA;
  r.pointB = o.pointB;
  return r;
}

bool gjkWithin(const ConvexShape& a, const ConvexShape& b, double margin)
{
  const Outcome o = runGjk(a, b, 1e-9, margin, margin);
  if (o.intersecting) return true;
  if (o.upper <= margin) return true;
  if (o.lower > margin) return false;
  return 0.5 * (o.upper + o.lower) <= margin;  // converged right at the margin
}

}  // namespace spira
