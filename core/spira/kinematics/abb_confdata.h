#pragma once

#include <array>
#include <string>

#include "spira/kinematics/arm_ik.h"
#include "spira/kinematics/opw_model.h"

namespace spira {

// ABB RAPID confdata [cf1, cf4, cf6, cfx] of a serial 6-axis arm pose (IRB 140, 1600, 2600, 4600...),
// as ABB's "Technical reference manual - RAPID Instructions, Functions and Data types" (RobotWare 6,
// 3HAC050917-001, data type confdata) defines it:
//   cf1, cf4, cf6  the quadrant of axes 1, 4 and 6: the axis angle in quarter revolutions rounded
//                  down, 0 for [0, 90) deg, -1 for [-90, 0), 1 for [90, 180) ...
//   cfx            0..7 from three yes/no questions, in this bit order:
//                  bit 2  the wrist centre is behind axis 1 (front = in front of axis 1),
//                  bit 1  the wrist centre is behind the lower arm (the line through axes 2 and 3),
//                  bit 0  axis 5 is negative.
//                  cfx 0 = in front, in front, axis 5 positive; cfx 7 = behind, behind, negative.
// With the IRB 1600's URDF (no offset between axes 3 and 4) "in front of the lower arm" is the
// elbow bent as at the all-zero pose (arm_configuration.h "up"), so cfx = 4 back + 2 down + flip.
// The same table and the same geometric reading (wrist centre in the frames turned by axes 1 and
// 2) are implemented by the ARTE toolbox (arvc.umh.es/arte, compute_configuration_standard_6R for
// the IRB 140/120/6650). ARTE puts an axis at exactly -90, -180... deg in the quadrant below; here
// floor() puts it in the quadrant above, as for positive angles.
// Axis values are the controller's (= URDF angles in degrees, controller_convention.h). Derived
// from the URDF model; check a confdata on a controller before relying on it to pick a branch.
struct AbbConfData {
  std::array<int, 4> values{};  // cf1, cf4, cf6, cfx

  bool operator==(const AbbConfData& o) const { return values == o.values; }
  bool operator!=(const AbbConfData& o) const { return !(*this == o); }
  // "[0,-1,0,1]": the text a robtarget holds.
  std::string format() const;
};

// floor(deg / 90) with angles within 1e-6 deg below a quadrant boundary taken as on it, so that
// 0 / 90 deg values carrying solver noise land in the quadrant that starts there.
int abbQuadrant(double deg);
AbbConfData abbConfData(const OpwModel& model, const JointVector& q);

}  // namespace spira
