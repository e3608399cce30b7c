#include "base_ring.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spira/base/error.h"
#include "spira/base/units.h"

namespace spira::geodesic {

namespace {

double cross2(double ax, double ay, double bx, double by)
{
  return ax * by - ay * bx;
}

}  // namespace

BaseRing::BaseRing(const GeodesicMesh& mesh, const BoundaryLoop& lower) : mesh_(mesh), loop_(lower)
{
  const auto& v = lower.vertices;
  if (v.size() < 3) throw InputError("the lower edge has fewer than 3 vertices", "repair the mesh");
  const auto& X = mesh.mesh().vertices;
  double total = 0.0, area = 0.0;
  Vec3 sum = Vec3::Zero();
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = X[size_t(v[i])];
    const Vec3& b = X[size_t(v[(i + 1) % v.size()])];
    const double len = (b - a).norm();
    sum += 0.5 * len * (a + b);
    total += len;
    area += 0.5 * cross2(a.x(), a.y(), b.x(), b.y());
  }
  if (!(total > 0.0) || !(std::abs(area) > 1e-9 * total * total))
    throw InputError("the lower edge encloses no area seen from above",
                     "stand the part on its base: the build direction is +Z");
  centroid_ = sum / total;
  ccw_ = area > 0.0;
}

bool BaseRing::crossing(size_t edge, double angle, double& s, double& t) const
{
  const auto& v = loop_.vertices;
  const auto& X = mesh_.mesh().vertices;
  const Vec3& a = X[size_t(v[edge])];
  const Vec3& b = X[size_t(v[(edge + 1) % v.size()])];
  const double ux = std::cos(angle), uy = std::sin(angle);
  const double px = a.x() - centroid_.x(), py = a.y() - centroid_.y();
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double den = cross2(ux, uy, dx, dy);
  if (std::abs(den) < 1e-300) return false;
  // centroid + s u = a + t (b - a)
  s = cross2(px, py, dx, dy) / den;
  t = cross2(px, py, ux, uy) / den;
  if (s <= 0.0 || t < -1e-12 || t > 1.0 + 1e-12) return false;
  t = std::clamp(t, 0.0, 1.0);
  return true;
}

BasePoint BaseRing::pointOnEdge(size_t edge, double t, double angle) const
{
  const auto& v = loop_.vertices;
  const int a = v[edge], b = v[(edge + 1) % v.size()];
  const int f = mesh_.faceWithEdge(a, b);
  if (f < 0)
    throw InternalError("the lower edge (" + std::to_string(a) + ", " + std::to_string(b) + ") has no face");
  const Face& fc = mesh_.mesh().faces[size_t(f)];
  Vec3 bary = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    if (fc[size_t(k)] == a) bary[k] = 1.0 - t;
    if (fc[size_t(k)] == b) bary[k] = t;
  }
  BasePoint out;
  out.point = mesh_.pointOn(f, bary);
  out.angle = angle;
  return out;
}

void BaseRing::Crossings::add(size_t edge, double s, double t)
{
  // A crossing at a shared vertex shows up on both of its edges: count it once.
  bool seen = false;
  for (double x : distances) seen = seen || std::abs(x - s) <= 1e-9 * (1.0 + s);
  if (!seen) distances.push_back(s);
  if (s > best) {
    best = s;
    bestEdge = edge;
    bestT = t;
  }
}

std::optional<BasePoint> BaseRing::at(double angle, bool* several) const
{
  Crossings c;
  for (size_t e = 0; e < loop_.vertices.size(); ++e) {
    double s = 0.0, t = 0.0;
    if (crossing(e, angle, s, t)) c.add(e, s, t);
  }
  if (several) *several = c.distances.size() > 1;
  if (c.best < 0.0) return std::nullopt;
  return pointOnEdge(c.bestEdge, c.bestT, angle);
}

std::vector<BasePoint> BaseRing::discretise(size_t n, size_t* ambiguous) const
{
  // Each loop edge is tested against the few angles its own angular span covers (seen from the
  // centroid), not against all n: O(edges + n).
  const auto& v = loop_.vertices;
  const auto& X = mesh_.mesh().vertices;
  const double step = 2.0 * kPi / double(n);
  auto angleOf = [&](int vertex) {
    return std::atan2(X[size_t(vertex)].y() - centroid_.y(), X[size_t(vertex)].x() - centroid_.x());
  };
  std::vector<Crossings> hits(n);
  for (size_t e = 0; e < v.size(); ++e) {
    const double a0 = angleOf(v[e]);
    const double sweep = std::remainder(angleOf(v[(e + 1) % v.size()]) - a0, 2.0 * kPi);
    const double lo = std::min(a0, a0 + sweep), hi = std::max(a0, a0 + sweep);
    const auto kFirst = static_cast<long long>(std::ceil(lo / step - 1e-9));
    const auto kLast = static_cast<long long>(std::floor(hi / step + 1e-9));
    for (long long k = kFirst; k <= kLast; ++k) {
      // Angle k step is generatrix i = k (counter-clockwise loop) or -k (clockwise), modulo n.
      const long long signedIndex = ccw_ ? k : -k;
      const auto i = size_t(((signedIndex % (long long)n) + (long long)n) % (long long)n);
      const double angle = (ccw_ ? step : -step) * double(i);
      double s = 0.0, t = 0.0;
      if (crossing(e, angle, s, t)) hits[i].add(e, s, t);
    }
  }
  std::vector<BasePoint> out;
  out.reserve(n);
  size_t many = 0;
  for (size_t i = 0; i < n; ++i) {
    const double angle = (ccw_ ? step : -step) * double(i);
    if (hits[i].best < 0.0)
      throw InputError("the vertical half-plane at " + std::to_string(angle * 180.0 / kPi) +
                           " deg about the base centroid misses the lower edge",
                       "the base must go around its centroid (seen from above); split the part or "
                       "use --strategy isovalue");
    many += hits[i].distances.size() > 1 ? 1 : 0;
    out.push_back(pointOnEdge(hits[i].bestEdge, hits[i].bestT, angle));
  }
  if (ambiguous) *ambiguous = many;
  return out;
}

double BaseRing::midAngle(double a, double b) const
{
  double d = ccw_ ? b - a : a - b;
  d = std::fmod(d, 2.0 * kPi);
  if (d <= 0.0) d += 2.0 * kPi;
  return ccw_ ? a + 0.5 * d : a - 0.5 * d;
}

}  // namespace spira::geodesic
