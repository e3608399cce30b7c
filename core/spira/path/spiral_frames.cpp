#include "spira/path/spiral_frames.h"

namespace spira {

namespace {

constexpr double kTiny = 1e-12;

}  // namespace

void computeFrames(Trajectory& path)
{
  auto& pts = path.points;
  const size_t count = pts.size();
  if (count == 0) return;
  std::vector<Vec3> chord(count, Vec3::Zero());
  std::vector<bool> valid(count, false);
  for (size_t q = 0; q + 1 < count; ++q) {
    chord[q] = pts[q + 1].position - pts[q].position;
    valid[q] = chord[q].norm() > kTiny;
  }
  size_t firstValid = count;
  for (size_t q = 0; q < count && firstValid == count; ++q)
    if (valid[q]) firstValid = q;
  // A path of one repeated point has no travel direction: keep any tangent normal to n.
  const Vec3 fallback = firstValid < count ? chord[firstValid] : pts[0].normal.unitOrthogonal();
  Vec3 last = fallback;
  for (size_t q = 0; q < count; ++q) {
    const bool seam = q > 0 && q + 1 < count && pts[q + 1].revolution != pts[q].revolution &&
                      pts[q - 1].revolution == pts[q].revolution && valid[q - 1];
    if (seam) {
      last = chord[q - 1];
    } else if (valid[q]) {
      last = chord[q];
    }
    const Vec3& n = pts[q].normal;
    Vec3 t = last - last.dot(n) * n;
    // A chord along the normal has no tangent-plane part: keep the chord itself.
    t = t.norm() > kTiny * last.norm() ? t.normalized() : last.normalized();
    pts[q].tangent = t;
    pts[q].build = n.cross(t);
  }
}

bool orientBuildDirection(Trajectory& path, const std::vector<Vec3>& steps)
{
  double sum = 0.0;
  for (size_t q = 0; q < path.points.size(); ++q) sum += path.points[q].build.dot(steps[q]);
  if (sum >= 0.0) return false;
  for (auto& p : path.points) {
    p.normal = -p.normal;
    p.build = -p.build;
  }
  return true;
}

void computeDepositHeights(Trajectory& path, const std::vector<Vec3>& steps, size_t firstRing)
{
  // Build directions flatter than this do not look down onto a plane (as in the deposit check).
  constexpr double kPlaneMinBz = 0.1;
  for (size_t q = 0; q < path.points.size(); ++q) {
    const Vec3& b = path.points[q].build;
    path.points[q].height = q < firstRing && b.z() >= kPlaneMinBz ? steps[q].z() / b.z() : steps[q].dot(b);
  }
}

}  // namespace spira
