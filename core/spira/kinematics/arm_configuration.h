#pragma once

#include <array>
#include <string>

namespace spira {

// Which of the (up to) eight closed-form solutions of a 6R arm with a spherical wrist a joint
// vector belongs to. Defined on the arm's OPW form (see opw_model.h), independent of any controller:
//   front   the wrist centre lies in front of axis 1: its x in the frame that turns with joint 1 is >= 0
//           (KUKA: basic area, S bit 0 clear; FANUC: T). Back = overhead (KUKA S bit 0; FANUC B).
//   up      the elbow angle, measured from the stretched arm (wrist centre on the line through axes
//           2 and 3), is >= 0 in the OPW sense: bent like the all-zero pose of both bundled arms
//           (KUKA: A3 >= the stretched angle, S bit 1 set; FANUC: U).
//   noFlip  OPW joint 5 angle >= 0 (KUKA: A5 >= 0, S bit 2 clear; FANUC: N, J5 < 0).
// Controllers derive their own flags from joint values (kuka_status_turn.h, fanuc_config.h).
struct ArmConfiguration {
  bool front = true;
  bool up = true;
  bool noFlip = true;

  bool operator==(const ArmConfiguration& o) const
  {
    return front == o.front && up == o.up && noFlip == o.noFlip;
  }
  bool operator!=(const ArmConfiguration& o) const { return !(*this == o); }

  // 0..7, bit 0 = back, bit 1 = down, bit 2 = flip (the order solutions are returned in).
  int index() const { return (front ? 0 : 1) | (up ? 0 : 2) | (noFlip ? 0 : 4); }
  static ArmConfiguration fromIndex(int index);
  static std::array<ArmConfiguration, 8> all();

  // "front/up/noflip" and its inverse; parse throws InputError on anything else.
  std::string label() const;
  static ArmConfiguration parse(const std::string& label);
};

}  // namespace spira
