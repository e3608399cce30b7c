#pragma once

#include <optional>
#include <vector>

#include "geodesic_mesh.h"
#include "spira/mesh/boundary_loops.h"

namespace spira::geodesic {

// A point of the lower edge where a generatrix starts.
struct BasePoint {
  SurfacePoint point;
  double angle = 0.0;  // rad, about the vertical axis through the base centroid, from +X
};

// The lower free edge seen from the vertical axis through its centroid (the length-weighted mean
// of its edges), for the thesis's constant-angle discretisation of the base (000_dbb97c2716e10cc3.txt
// §3.3.2.2, Fig. 3.18a).
class BaseRing {
 public:
  // Throws InputError for a loop of fewer than 3 vertices or one that encloses no area seen from above.
  BaseRing(const GeodesicMesh& mesh, const BoundaryLoop& lower);

  const Vec3& centroid() const { return centroid_; }
  // Whether the loop runs counter-clockwise seen from above (+Z).
  bool counterClockwise() const { return ccw_; }

  // Where the vertical half-plane at `angle` crosses the loop: the crossing farthest from the
  // axis when there are several (a base that is not star-shaped about its centroid), which
  // `several` then reports. Empty when the half-plane misses the loop.
  std::optional<BasePoint> at(double angle, bool* several = nullptr) const;

  // `n` points at constant angle 2 pi / n, the first at angle 0 (+X), following the loop's
  // direction. `ambiguous` counts the angles where the loop was crossed several times.
  // Throws InputError when a half-plane misses the loop (the centroid lies outside it).
  std::vector<BasePoint> discretise(size_t n, size_t* ambiguous) const;

  // The angle halfway from `a` to `b` in the loop's direction.
  double midAngle(double a, double b) const;

 private:
  // The crossings of one half-plane with the loop: the outermost, and how many distinct ones.
  struct Crossings {
    double best = -1.0, bestT = 0.0;
    size_t bestEdge = 0;
    std::vector<double> distances;
    void add(size_t edge, double s, double t);
  };
  // Whether the half-plane at `angle` crosses loop edge `edge`, at distance s from the axis and
  // parameter t along the edge.
  bool crossing(size_t edge, double angle, double& s, double& t) const;
  BasePoint pointOnEdge(size_t edge, double t, double angle) const;

  const GeodesicMesh& mesh_;
  const BoundaryLoop& loop_;
  Vec3 centroid_ = Vec3::Zero();
  bool ccw_ = true;
};

}  // namespace spira::geodesic
