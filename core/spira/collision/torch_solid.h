#pragma once

#include "spira/collision/convex_shape.h"
#include "spira/collision/torch_params.h"

namespace spira {

// The torch solid placed at a TCP pose. T_part_tcp comes from toolFrame() (spira/path/tool_frame.h):
// its z axis points from the torch towards the deposit, so the solid lies along -z, starting
// `standoff` mm from the TCP (the wire stick-out and arc between TCP and nozzle are not solid).
// The nozzle cone widening into the cylindrical body has a concave radius profile, so the union is
// convex: it is the convex hull of three coaxial circles (tip, shoulder, top), which gives an exact
// support mapping for GJK.
class TorchSolid final : public ConvexShape {
 public:
  TorchSolid(const TorchParams& params, const Transform& T_part_tcp);

  Vec3 support(const Vec3& direction) const override;
  Vec3 anyPoint() const override { return 0.5 * (centers_[0] + centers_[2]); }
  BoundingBox bounds() const override;
  // The axis from the tip to the top, inflated by the largest radius.
  bool boundingCapsule(Vec3& a, Vec3& b, double& radius) const override;

  // Unit axis from the nozzle tip into the body (-z of the TCP frame, the planned build direction b).
  const Vec3& axis() const { return axis_; }
  const Vec3& tcp() const { return tcp_; }
  const Vec3& tipCenter() const { return centers_[0]; }

  // Signed distance of the torch above the plane through `point` with unit normal `normal` (the
  // solid half-space is on the -normal side): negative when the torch dips below the plane.
  double heightAbove(const Vec3& point, const Vec3& normal) const;

 private:
  Vec3 tcp_, axis_;
  Vec3 centers_[3];  // tip, shoulder (cone meets body), top
  double radii_[3];
};

}  // namespace spira
