#include "spira/planning/planar_baseline.h"
#include "spira/base/segment_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "spira/base/error.h"
#include "spira/contour/iso_contour.h"
#include "spira/contour/point_grid.h"

namespace spira {

namespace {

// The contours of one layer, with a grid over their points for nearest-point queries.
class Layer {
 public:
  Layer(double z, std::vector<std::vector<Vec3>> lines, std::vector<bool> closed)
      : z_(z), lines_(std::move(lines)), closed_(std::move(closed))
  {
    std::vector<Vec3> all;
    double length = 0.0;
    for (size_t l = 0; l < lines_.size(); ++l)
      for (size_t i = 0; i < lines_[l].size(); ++i) {
        all.push_back(lines_[l][i]);
        owner_.push_back({static_cast<int>(l), static_cast<int>(i)});
        if (i > 0) length += (lines_[l][i] - lines_[l][i - 1]).norm();
      }
    if (!all.empty())
      grid_.emplace(std::move(all), std::max(length / static_cast<double>(owner_.size()), 1e-6));
  }
  double z() const { return z_; }
  bool empty() const { return !grid_; }

  // Distance from p to the layer's polylines: to the two segments at the nearest point (exact
  // unless another segment passes closer than that point without its ends doing so).
  double distance(const Vec3& p) const
  {
    if (!grid_) return std::numeric_limits<double>::infinity();
    const auto [l, i] = owner_[grid_->nearest(p)];
    const std::vector<Vec3>& line = lines_[static_cast<size_t>(l)];
    const auto n = static_cast<int>(line.size());
    double best = (p - line[static_cast<size_t>(i)]).norm();
    for (int j : {i - 1, i + 1}) {
      int k = j;
      if (closed_[static_cast<size_t>(l)]) k = (j + n) % n;
      if (k < 0 || k >= n || k == i) continue;
      best =
          std::min(best, pointSegmentDistance(p, line[static_cast<size_t>(i)], line[static_cast<size_t>(k)]));
    }
    return best;
  }

 private:
  double z_;
  std::vector<std::vector<Vec3>> lines_;
  std::vector<bool> closed_;
  std::vector<std::pair<int, int>> owner_;
  std::optional<PointGrid> grid_;
};

Layer loopLayer(const TriangleMesh& mesh, const BoundaryLoop& loop, double z)
{
  std::vector<Vec3> line;
  for (int v : loop.vertices) line.push_back(mesh.vertices[static_cast<size_t>(v)]);
  return Layer(z, {line}, {loop.closed});
}

}  // namespace

PlanarBaseline planarBaseline(const TriangleMesh& mesh, const MeshReport& report, int lowerLoop,
                              const PlanarBaselineSettings& settings, Progress& progress)
{
  if (!(settings.h > 0))
    throw InputError("the layer height must be positive", "set --h to the deposit height, e.g. --h 2");
  if (lowerLoop < 0 || static_cast<size_t>(lowerLoop) >= report.boundaryLoops.size())
    throw InputError("the part has no lower free edge to slice from", "check the part's free edges");
  const BoundaryLoop& lower = report.boundaryLoops[static_cast<size_t>(lowerLoop)];
  const double z0 = lower.zMax;
  const double zTop = report.bounds.max.z();
  if (!(zTop - z0 >= settings.h))
    throw InputError(
        "the part rises " + std::to_string(zTop - z0) + " mm above its lower edge, less than one layer",
        "choose a smaller layer height");

  std::vector<double> z(mesh.vertexCount());
  for (size_t v = 0; v < z.size(); ++v) z[v] = mesh.vertices[v].z();
  std::vector<double> levels;
  for (int k = 1; z0 + k * settings.h < zTop; ++k) levels.push_back(z0 + k * settings.h);
  const std::vector<IsoLevel> slices = extractIsoContours(mesh, z, levels, &progress);

  PlanarBaseline out;
  std::vector<Layer> layers;
  layers.push_back(loopLayer(mesh, lower, z0));
  auto add = [&](const Vec3& p, double height, int layer) {
    out.points.push_back(PlanarPoint{p, height, layer});
  };
  for (size_t k = 0; k < slices.size(); ++k) {
    progress.checkCancel();
    std::vector<std::vector<Vec3>> lines;
    std::vector<bool> closed;
    for (const IsoContour& c : slices[k].contours) {
      lines.push_back(c.positions());
      closed.push_back(c.closed);
    }
    Layer layer(levels[k], std::move(lines), std::move(closed));
    const Layer& below = layers.back();
    for (const IsoContour& c : slices[k].contours)
      for (const ContourPoint& p : c.points)
        add(p.position, below.distance(p.position), static_cast<int>(k + 1));
    layers.push_back(std::move(layer));
  }

  // The last layer: the upper free edges, or the top of a closed part, over the highest planes
  // below each of its points.
  std::vector<Vec3> top;
  for (size_t l = 0; l < report.boundaryLoops.size(); ++l)
    if (static_cast<int>(l) != lowerLoop)
      for (int v : report.boundaryLoops[l].vertices) top.push_back(mesh.vertices[static_cast<size_t>(v)]);
  if (top.empty()) {
    size_t highest = 0;
    for (size_t v = 1; v < mesh.vertexCount(); ++v)
      if (mesh.vertices[v].z() > mesh.vertices[highest].z()) highest = v;
    top.push_back(mesh.vertices[highest]);
  }
  const int lastLayer = static_cast<int>(slices.size()) + 1;
  for (const Vec3& p : top) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t j = layers.size(); j-- > 0;) {
      if (layers[j].z() > p.z() - 1e-9) continue;
      if (p.z() - layers[j].z() >= best) break;
      best = std::min(best, layers[j].distance(p));
    }
    if (std::isfinite(best)) add(p, best, lastLayer);
  }
  out.layers = lastLayer;

  double sum = 0.0;
  out.heightMin = std::numeric_limits<double>::infinity();
  out.heightMax = -std::numeric_limits<double>::infinity();
  for (const PlanarPoint& p : out.points) {
    out.heightMin = std::min(out.heightMin, p.height);
    out.heightMax = std::max(out.heightMax, p.height);
    sum += p.height;
    out.outside +=
        p.height < settings.hMin - settings.tolerance || p.height > settings.hMax + settings.tolerance;
  }
  if (out.points.empty()) out.heightMin = out.heightMax = 0.0;
  out.heightMean = out.points.empty() ? 0.0 : sum / static_cast<double>(out.points.size());
  return out;
}

}  // namespace spira
