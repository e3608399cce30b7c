#pragma once

#include "spira/path/spiral_settings.h"
#include "spira/path/trajectory.h"

namespace spira {

// Generatrices ready for the spiral builder: checked, with unit normals, resampled when asked.
// Refers to the input when nothing had to change (no copy), so the input must outlive it.
class PreparedGeneratrices {
 public:
  const Generatrices& generatrices() const { return source_ ? *source_ : owned_; }
  bool normalsEstimated() const { return normalsEstimated_; }

 private:
  friend PreparedGeneratrices prepareGeneratrices(const Generatrices&, const SpiralSettings&);
  const Generatrices* source_ = nullptr;
  Generatrices owned_;
  bool normalsEstimated_ = false;
};

// Throws InputError, saying what is wrong and how to fix it, for settings the builder cannot use
// (the height window is checked by StartupProfile).
void validateSpiralSettings(const SpiralSettings& s);

// Throws InputError for fewer than 3 generatrices, a generatrix with fewer than 2 points, zero
// length or non-finite coordinates, normals whose shape differs from the lines', zero or
// non-finite normals, and (closed parts) a generatrix ending farther than h_min / 2 from the
// closure point. Normalises the normals, estimates them when none are given.
PreparedGeneratrices prepareGeneratrices(const Generatrices& g, const SpiralSettings& s);

}  // namespace spira
