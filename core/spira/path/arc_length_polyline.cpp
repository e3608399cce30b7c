#include "spira/path/arc_length_polyline.h"

#include <algorithm>

namespace spira {

ArcLengthPolyline::ArcLengthPolyline(const Polyline& points, const std::vector<Vec3>& normals)
    : points_(&points), normals_(&normals), cumulative_(points.size(), 0.0)
{
  for (size_t k = 1; k < points.size(); ++k)
    cumulative_[k] = cumulative_[k - 1] + (points[k] - points[k - 1]).norm();
}

ArcLengthPolyline::Sample ArcLengthPolyline::at(double s) const
{
  if (s <= 0.0) return {points_->front(), normals_->front()};
  if (s >= length()) return {points_->back(), normals_->back()};
  // First point beyond s; the segment [k-1, k] holds s and has a positive length.
  const size_t k =
      static_cast<size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), s) - cumulative_.begin());
  return interpolate(k, s);
}

ArcLengthPolyline::Sample ArcLengthPolyline::at(double s, size_t& cursor) const
{
  if (s <= 0.0) return {points_->front(), normals_->front()};
  if (s >= length()) return {points_->back(), normals_->back()};
  if (cursor == 0 || cumulative_[cursor - 1] > s) cursor = 1;
  while (cumulative_[cursor] <= s) ++cursor;
  return interpolate(cursor, s);
}

ArcLengthPolyline::Sample ArcLengthPolyline::interpolate(size_t k, double s) const
{
  const Polyline& p = *points_;
  const std::vector<Vec3>& n = *normals_;
  const double t = (s - cumulative_[k - 1]) / (cumulative_[k] - cumulative_[k - 1]);
  Sample out;
  out.position = p[k - 1] + t * (p[k] - p[k - 1]);
  const Vec3 blend = (1.0 - t) * n[k - 1] + t * n[k];
  const double len = blend.norm();
  // Opposite normals at the ends of one segment would blend to nothing: keep the nearer one.
  out.normal = len > 1e-9 ? Vec3(blend / len) : (t < 0.5 ? n[k - 1] : n[k]);
  return out;
}

}  // namespace spira
