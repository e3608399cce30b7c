#pragma once

namespace spira {

// The welding torch as a collision solid: a truncated cone (the nozzle) widening from the tip into
// a cylinder (the body), on the torch axis. Lengths in mm. The defaults describe a common
// water-cooled MIG/CMT torch; measure the real one for production plans.
struct TorchParams {
  double nozzleRadius = 8.0;  // outer radius of the nozzle at its tip
  double coneLength = 30.0;   // axial length over which the radius grows to bodyRadius
  double bodyRadius = 20.0;
  double bodyLength = 150.0;  // cylindrical part above the cone (the rest of the torch and the
                              // robot wrist are the kinematics' link meshes)
  double standoff = 15.0;     // from the TCP (the arc point on the deposit) to the nozzle tip
  double clearance = 2.0;     // safety margin: nearer than this to anything counts as a collision
};

// Throws InputError naming the first bad field (negative or non-finite lengths, a nozzle wider than
// the body, a zero-length torch).
void validateTorchParams(const TorchParams& params);

}  // namespace spira
