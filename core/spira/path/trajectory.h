#pragma once

#include <map>
#include <string>
#include <vector>

#include "spira/base/transform.h"

namespace spira {

// One point of a deposition path, with its channels. Units: mm, mm/s (wire feed included,
// converted to m/min only at the file/UI edge), dimensionless unit vectors.
struct TrajectoryPoint {
  Vec3 position = Vec3::Zero();  // TCP position, part frame
  Vec3 normal = Vec3::UnitX();   // n: unit surface normal
  Vec3 tangent = Vec3::UnitY();  // t: unit travel direction
  Vec3 build = Vec3::UnitZ();    // b = n x t: build direction, along the torch axis
  int path = 0;                  // sub-path index (multi-branch parts), 0 for a single spiral
  int revolution = 0;            // revolution (layer) index, 0-based
  int generatrix = 0;            // generatrix index, 0-based
  double height = 0.0;           // deposit height, mm
  double travelSpeed = 0.0;      // TS, mm/s
  double wireFeed = 0.0;         // WFS, mm/s
  bool arcOn = true;

  bool operator==(const TrajectoryPoint& o) const;
};

// An ordered deposition path. Exporters read channels; they never recompute geometry.
// `extra` holds per-point channels added by later features (dwell, weave...), each of size().
struct Trajectory {
  std::vector<TrajectoryPoint> points;
  std::map<std::string, std::vector<double>> extra;

  size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
  double length() const;
  bool operator==(const Trajectory& o) const { return points == o.points && extra == o.extra; }
};

using Polyline = std::vector<Vec3>;

// The decomposition of a part into generatrices: polylines on the surface from the base to the
// upper edge (open parts) or the closure point (closed parts), in base order.
// `normals`, when filled, has the shape of `lines`: one unit surface normal per point. Left empty,
// the spiral builder estimates normals from neighbouring generatrices (see surface_normals.h).
struct Generatrices {
  std::vector<Polyline> lines;
  std::vector<std::vector<Vec3>> normals;
  bool hasClosurePoint = false;
  Vec3 closurePoint = Vec3::Zero();
  // A tube's guide curve, base end first, that its layers were laid about (constant distance); empty
  // for the other strategies.
  Polyline guide;
  bool operator==(const Generatrices& o) const
  {
    return lines == o.lines && normals == o.normals && hasClosurePoint == o.hasClosurePoint &&
           closurePoint == o.closurePoint && guide == o.guide;
  }
};

}  // namespace spira
