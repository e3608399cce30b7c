// The CGAL AABB tree lives in this translation unit only.
#include "spira/scan/scan_deviation.h"

#include <algorithm>
#include <cmath>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;

Point toCgal(const Vec3& v)
{
  return Point(v.x(), v.y(), v.z());
}

}  // namespace

struct MeshDistance::Tree {
  std::vector<Triangle> triangles;
  CGAL::AABB_tree<Traits> tree;
};

MeshDistance::MeshDistance(const TriangleMesh& mesh) : tree_(std::make_unique<Tree>()), mesh_(mesh)
{
  if (mesh.empty())
    throw InputError("the part has no triangles to measure the scan against", "import the part first");
  tree_->triangles.reserve(mesh.faceCount());
  for (const Face& f : mesh.faces)
    tree_->triangles.emplace_back(toCgal(mesh.vertices[size_t(f[0])]), toCgal(mesh.vertices[size_t(f[1])]),
                                  toCgal(mesh.vertices[size_t(f[2])]));
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
  normals_ = mesh.vertexNormals();
}

MeshDistance::~MeshDistance() = default;

MeshDistance::Hit MeshDistance::closest(const Vec3& p) const
{
  const auto [point, it] = tree_->tree.closest_point_and_primitive(toCgal(p));
  Hit hit;
  hit.point = Vec3(point.x(), point.y(), point.z());
  hit.face = size_t(it - tree_->triangles.cbegin());
  // The vertex normals interpolated at the closest point: one side of an edge or corner is "outside"
  // for every point near it, where the facet normals alone would disagree.
  const Face& f = mesh_.faces[hit.face];
  const Vec3 &a = mesh_.vertices[size_t(f[0])], &b = mesh_.vertices[size_t(f[1])],
             &c = mesh_.vertices[size_t(f[2])];
  const Vec3 n = mesh_.faceNormalScaled(hit.face);
  const double area = n.squaredNorm();
  Vec3 normal = n.normalized();
  if (area > 0.0) {
    const double wa = (c - b).cross(hit.point - b).dot(n) / area;
    const double wb = (a - c).cross(hit.point - c).dot(n) / area;
    const Vec3 smooth =
        wa * normals_[size_t(f[0])] + wb * normals_[size_t(f[1])] + (1.0 - wa - wb) * normals_[size_t(f[2])];
    if (smooth.norm() > 1e-9) normal = smooth.normalized();
  }
  const Vec3 d = p - hit.point;
  hit.signedDistance = d.dot(normal) >= 0.0 ? d.norm() : -d.norm();
  return hit;
}

DeviationStats deviationStats(const std::vector<double>& distances, int bins)
{
  DeviationStats s;
  s.count = distances.size();
  if (distances.empty()) return s;
  double sum = 0.0, squares = 0.0;
  s.min = s.max = distances.front();
  std::vector<double> magnitude;
  magnitude.reserve(distances.size());
  for (double d : distances) {
    sum += d, squares += d * d;
    s.min = std::min(s.min, d), s.max = std::max(s.max, d);
    magnitude.push_back(std::abs(d));
  }
  s.mean = sum / double(s.count);
  s.rms = std::sqrt(squares / double(s.count));
  const size_t k = std::min(magnitude.size() - 1, size_t(std::ceil(0.95 * double(magnitude.size()))) - 1);
  std::nth_element(magnitude.begin(), magnitude.begin() + std::ptrdiff_t(k), magnitude.end());
  s.p95 = magnitude[k];
  bins = std::max(1, bins);
  s.binMin = s.min;
  s.binWidth = s.max > s.min ? (s.max - s.min) / bins : 1.0;
  s.histogram.assign(size_t(bins), 0);
  for (double d : distances) ++s.histogram[std::min(size_t(bins) - 1, size_t((d - s.binMin) / s.binWidth))];
  return s;
}

std::vector<double> scanDeviation(const PointCloud& scan, const TriangleMesh& part, Progress& progress)
{
  const MeshDistance distance(part);
  std::vector<double> out(scan.size(), 0.0);
  const size_t block = 1 << 14;
  for (size_t start = 0; start < scan.size(); start += block) {
    progress.checkCancel();
    const size_t end = std::min(scan.size(), start + block);
    tbb::parallel_for(start, end,
                      [&](size_t i) { out[i] = distance.closest(scan.points[i]).signedDistance; });
    progress.report(double(end) / double(scan.size()), "deviation");
  }
  return out;
}

std::optional<std::string> scanUnitHint(const BoundingBox& scan, const BoundingBox& part)
{
  if (scan.empty() || part.empty() || !(part.diagonal() > 0.0) || !(scan.diagonal() > 0.0))
    return std::nullopt;
  const double ratio = scan.diagonal() / part.diagonal();
  if (ratio > 1.0 / 3.0 && ratio < 3.0) return std::nullopt;
  struct Unit {
    const char* name;
    double mm;
  };
  // The scan read as mm is `ratio` times the part: in a unit of `mm / ratio` millimetres.
  const Unit units[] = {{"micrometres", 0.001}, {"centimetres", 10.0}, {"inches", 25.4}, {"metres", 1000.0}};
  const Unit* best = nullptr;
  double bestError = 0.0;
  for (const Unit& u : units) {
    const double error = std::abs(std::log(ratio * u.mm));
    if (!best || error < bestError) best = &u, bestError = error;
  }
  const double factor = ratio >= 1.0 ? ratio : 1.0 / ratio;
  std::string text = "the scan is " +
                     (factor >= 10.0 ? std::to_string(std::lround(factor)) : significantText(factor, 3)) +
                     " times " + (ratio >= 1.0 ? "larger" : "smaller") + " than the part";
  if (best && bestError < std::log(1.5))
    text += ": it is likely in " + std::string(best->name) + " (scale it by " + significantText(best->mm, 6) +
            " to get mm)";
  return text;
}

}  // namespace spira
