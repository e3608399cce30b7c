#include "spira/contour/loop_following.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/error.h"

namespace spira {

namespace {

// The closed contour as a polyline with an arc-length parameter; arcs are "lifted": s and s + L
// name the same point, so a parameter can run around the loop more than once without a jump.
class ArcLoop {
 public:
  explicit ArcLoop(const IsoContour& loop) : loop_(loop), m_(loop.points.size()), cum_(m_ + 1, 0.0)
  {
    for (size_t i = 0; i < m_; ++i) {
      const double len = (point(i + 1) - point(i)).norm();
      cum_[i + 1] = cum_[i] + len;
      maxSegment_ = std::max(maxSegment_, len);
    }
  }
  double length() const { return cum_[m_]; }
  double maxSegment() const { return maxSegment_; }
  const Vec3& point(size_t i) const { return loop_.points[i % m_].position; }

  // Segment holding arc s (lifted) and the number of whole turns below it.
  size_t segmentAt(double s, long* turns) const
  {
    const double L = length();
    const double turn = std::floor(s / L);
    *turns = static_cast<long>(turn);
    const double local = s - turn * L;
    const size_t i = static_cast<size_t>(std::upper_bound(cum_.begin(), cum_.end(), local) - cum_.begin());
    return std::min(i == 0 ? size_t(0) : i - 1, m_ - 1);
  }

  // Foot of q on segment i: lifted arc (in turn `turns`) and squared distance.
  std::pair<double, double> foot(size_t i, long turns, const Vec3& q) const
  {
    const Vec3& a = point(i);
    const Vec3 ab = point(i + 1) - a;
    const double len2 = ab.squaredNorm();
    const double u = len2 > 0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const double arc = static_cast<double>(turns) * length() + cum_[i] + u * (cum_[i + 1] - cum_[i]);
    return {arc, (a + u * ab - q).squaredNorm()};
  }

  // Foot of q over the whole loop (lifted arc in [0, L]) and its squared distance.
  std::pair<double, double> nearest(const Vec3& q) const
  {
    std::pair<double, double> best{0.0, std::numeric_limits<double>::infinity()};
    for (size_t i = 0; i < m_; ++i) {
      const auto f = foot(i, 0, q);
      if (f.second < best.second) best = f;
    }
    return best;
  }

  // Foot of q over the segments within arc distance `radius` of the lifted arc `centre`.
  std::pair<double, double> nearestNear(const Vec3& q, double centre, double radius) const
  {
    long turns = 0;
    const size_t start = segmentAt(centre, &turns);
    std::pair<double, double> best = foot(start, turns, q);
    auto visit = [&](size_t i, long t) {
      const auto f = foot(i, t, q);
      if (f.second < best.second) best = f;
    };
    // Forward, then backward, at most once around.
    long t = turns;
    size_t i = start;
    for (size_t step = 0; step < m_; ++step) {
      if (++i == m_) {
        i = 0;
        ++t;
      }
      if (static_cast<double>(t) * length() + cum_[i] > centre + radius) break;
      visit(i, t);
    }
    t = turns;
    i = start;
    for (size_t step = 0; step < m_; ++step) {
      if (i == 0) {
        i = m_;
        --t;
      }
      --i;
      if (static_cast<double>(t) * length() + cum_[i + 1] < centre - radius) break;
      visit(i, t);
    }
    return best;
  }

  SurfacePoint at(const TriangleMesh& mesh, double s) const
  {
    long turns = 0;
    const size_t i = segmentAt(s, &turns);
    const double local = s - static_cast<double>(turns) * length();
    const double segLen = cum_[i + 1] - cum_[i];
    const double u = segLen > 0 ? std::clamp((local - cum_[i]) / segLen, 0.0, 1.0) : 0.0;
    const size_t j = (i + 1) % m_;
    const int face = loop_.segmentFaces[i];
    SurfacePoint p;
    p.position = (1.0 - u) * point(i) + u * point(j);
    p.face = face;
    p.bary = (1.0 - u) * loop_.barycentricIn(mesh, i, face) + u * loop_.barycentricIn(mesh, j, face);
    return p;
  }

 private:
  const IsoContour& loop_;
  size_t m_;
  std::vector<double> cum_;
  double maxSegment_ = 0.0;
};

// Solves (1 + 2 lambda) x_k - lambda (x_k-1 + x_k+1) = r_k with indices modulo n (a cyclic
// tridiagonal system, diagonally dominant): Thomas algorithm plus a Sherman-Morrison correction
// for the two corner entries.
std::vector<double> solveCyclic(double lambda, const std::vector<double>& r)
{
  const size_t n = r.size();
  const double diag = 1.0 + 2.0 * lambda, off = -lambda;
  const double gamma = -diag;
  std::vector<double> b(n, diag);
  b[0] = diag - gamma;
  b[n - 1] = diag - off * off / gamma;
  auto thomas = [&](std::vector<double> d) {
    std::vector<double> c(n);
    c[0] = off / b[0];
    d[0] /= b[0];
    for (size_t k = 1; k < n; ++k) {
      const double denom = b[k] - off * c[k - 1];
      c[k] = off / denom;
      d[k] = (d[k] - off * d[k - 1]) / denom;
    }
    for (size_t k = n - 1; k-- > 0;) d[k] -= c[k] * d[k + 1];
    return d;
  };
  std::vector<double> x = thomas(r);
  std::vector<double> u(n, 0.0);
  u[0] = gamma;
  u[n - 1] = off;
  const std::vector<double> z = thomas(u);
  const double fact = (x[0] + off * x[n - 1] / gamma) / (1.0 + z[0] + off * z[n - 1] / gamma);
  for (size_t k = 0; k < n; ++k) x[k] -= fact * z[k];
  return x;
}

// Makes the lifted parameters s (s_n = s_0 + L) climb by at least `gap` from each to the next,
// moving them as little as possible in the least-squares sense (pool-adjacent-violators on
// s_k - k gap, the sequence cut open after its widest step). Returns false when no such ordering
// exists around the loop.
bool enforceMinimumSpacing(std::vector<double>& s, double L, double gap)
{
  const size_t n = s.size();
  size_t widest = 0;
  double widestGap = -std::numeric_limits<double>::infinity();
  bool ok = true;
  for (size_t k = 0; k < n; ++k) {
    const double step = (k + 1 < n ? s[k + 1] : s[0] + L) - s[k];
    ok = ok && step >= gap;
    if (step > widestGap) {
      widestGap = step;
      widest = k;
    }
  }
  if (ok) return true;
  // v_j: the parameters from just after the widest step on, lifted to increase.
  std::vector<double> value(n), weight(n, 1.0);
  std::vector<size_t> size(n, 1);
  for (size_t j = 0; j < n; ++j) {
    const size_t k = widest + 1 + j;
    value[j] = (k < n ? s[k] : s[k - n] + L) - static_cast<double>(j) * gap;
  }
  // Pool adjacent violators: blocks of equal value, merged while they decrease.
  size_t blocks = 0;
  for (size_t j = 0; j < n; ++j) {
    value[blocks] = value[j];
    weight[blocks] = 1.0;
    size[blocks] = 1;
    ++blocks;
    while (blocks > 1 && value[blocks - 2] > value[blocks - 1]) {
      const double w = weight[blocks - 2] + weight[blocks - 1];
      value[blocks - 2] =
          (weight[blocks - 2] * value[blocks - 2] + weight[blocks - 1] * value[blocks - 1]) / w;
      weight[blocks - 2] = w;
      size[blocks - 2] += size[blocks - 1];
      --blocks;
    }
  }
  std::vector<double> v(n);
  for (size_t b = 0, j = 0; b < blocks; ++b)
    for (size_t q = 0; q < size[b]; ++q, ++j) v[j] = value[b] + static_cast<double>(j) * gap;
  if (v[0] + L - v[n - 1] < gap * (1.0 - 1e-9)) return false;
  for (size_t j = 0; j < n; ++j) {
    const size_t k = widest + 1 + j;
    if (k < n) {
      s[k] = v[j];
    } else {
      s[k - n] = v[j] - L;
    }
  }
  return true;
}

}  // namespace

ResampledLoop resampleLoopFollowing(const TriangleMesh& mesh, const IsoContour& loop,
                                    const std::vector<Vec3>& previous, const LoopFollowingOptions& options)
{
  const size_t n = previous.size();
  if (!loop.closed || loop.points.size() < 3 || n < 3) return resampleLoop(mesh, loop, n);
  const ArcLoop arc(loop);
  const double L = arc.length();
  const double even = L / static_cast<double>(n);

  // Feet of the previous contour's points, each searched near the one before it so that the
  // parameter runs on continuously around the loop.
  std::vector<double> t(n);
  double gapSum = 0.0;
  auto [t0, d0] = arc.nearest(previous[0]);
  t[0] = t0;
  gapSum += std::sqrt(d0);
  double lastGap = std::sqrt(d0);
  for (size_t k = 1; k < n; ++k) {
    const double stride = (previous[k] - previous[k - 1]).norm();
    const double radius = 2.0 * stride + lastGap + 2.0 * arc.maxSegment();
    const auto [tk, dk] = arc.nearestNear(previous[k], t[k - 1], radius);
    t[k] = tk;
    lastGap = std::sqrt(dk);
    gapSum += lastGap;
  }
  // One turn around the loop, no more and no less.
  const double turn = t[n - 1] + even - t[0];
  if (!(turn > 0.5 * L && turn < 1.5 * L)) return resampleLoop(mesh, loop, n, t[0]);

  // s = t + e, e minimising the shear and spacing terms of LoopFollowingOptions:
  // (1 + 2 lambda) e_k - lambda (e_k-1 + e_k+1) = lambda (delta_k - delta_k-1), where delta_k is
  // the feet's step from k to k + 1 minus the even spacing.
  const double g = std::max(gapSum / static_cast<double>(n), 1e-3 * even);
  const double lambda = options.spacingWeight * (g * g) / (even * even);
  std::vector<double> delta(n), rhs(n);
  for (size_t k = 0; k < n; ++k) delta[k] = (k + 1 < n ? t[k + 1] : t[0] + L) - t[k] - even;
  for (size_t k = 0; k < n; ++k) rhs[k] = lambda * (delta[k] - delta[(k + n - 1) % n]);
  std::vector<double> s = t;
  if (lambda > 0) {
    const std::vector<double> e = solveCyclic(lambda, rhs);
    for (size_t k = 0; k < n; ++k) s[k] += e[k];
  }
  if (!enforceMinimumSpacing(s, L, options.minSpacing * even)) return resampleLoop(mesh, loop, n, t[0]);

  ResampledLoop out;
  out.level = loop.level;
  out.length = L;
  out.points.resize(n);
  for (size_t k = 0; k < n; ++k) out.points[k] = arc.at(mesh, s[k]);
  return out;
}

}  // namespace spira
