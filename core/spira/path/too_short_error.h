#pragma once

#include <string>

#include "spira/base/error.h"

namespace spira {

// A wall too short for the spiral's start-up, termination and one layer: `length` mm of generatrix
// where `needed` mm are required. Both scale with h (the ramps are a fixed number of revolutions of
// heights proportional to h at a given relative window), which is what advice makes of it.
class TooShortError : public InputError {
 public:
  TooShortError(const std::string& what, const std::string& hint, double length, double needed)
      : InputError(what, hint), length_(length), needed_(needed)
  {
  }
  double length() const { return length_; }
  double needed() const { return needed_; }

 private:
  double length_, needed_;
};

}  // namespace spira
