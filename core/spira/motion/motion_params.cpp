#include "spira/motion/motion_params.h"

#include <cmath>
#include <string>

#include "spira/base/error.h"

namespace spira {

namespace {

void require(bool ok, const std::string& what, const std::string& hint)
{
  if (!ok) throw InputError("motion parameters: " + what, hint);
}

}  // namespace

void MotionParams::validate() const
{
  require(degree >= 0 && degree <= 6, "degree " + std::to_string(degree) + " is outside 0..6",
          "use a spin polynomial of degree 1 to 3");
  require(std::isfinite(dexterityFloor) && dexterityFloor >= 0.0 && dexterityFloor < 1.0,
          "dexterity floor must be in [0, 1)", "use 0.05 (about 6 deg from a wrist singularity) or 0");
  require(std::isfinite(cableTwistLimitDeg) && cableTwistLimitDeg >= 0.0,
          "cable twist limit must be >= 0 deg", "use the cell's cable_twist_limit_deg, or 0 for no limit");
  require(std::isfinite(limitMarginDeg) && limitMarginDeg >= 0.0 && limitMarginDeg < 90.0,
          "joint limit margin must be in [0, 90) deg", "use a few degrees, e.g. 2");
  require(
      std::isfinite(buildTiltToleranceDeg) && buildTiltToleranceDeg >= 0.0 && buildTiltToleranceDeg < 45.0,
      "build tilt tolerance must be in [0, 45) deg", "use about 2 deg");
  require(std::isfinite(centringWeight) && centringWeight >= 0.0, "centring weight must be >= 0",
          "use 0.01, or 0 for the pure joint motion objective");
  require(maxIterations >= 1 && maxIterations <= 10000, "max iterations must be in 1..10000", "use about 40");
  require(searchSamples >= 4 && searchSamples <= 100000, "search samples must be in 4..100000",
          "use about 36 points per layer");
  if (variable == SpinVariable::PolarAngle)
    require(axisPoint.allFinite() && axisDirection.allFinite() && axisDirection.norm() > 1e-12,
            "the axis of revolution needs a finite point and a non-zero direction",
            "give the part's axis in the part frame, or use the point index as the spin variable");
}

}  // namespace spira
