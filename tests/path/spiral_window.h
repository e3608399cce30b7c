#pragma once

#include "spira/path/spiral_settings.h"

namespace spira::test {

// The thesis's window for its open parts (Table 3.3): h = 2 mm, 1.8 .. 2.2 mm, and its layer count
// (Eq. 3.14).
inline SpiralSettings thesisWindow()
{
  SpiralSettings s;
  s.h = 2.0;
  s.hMin = 1.8;
  s.hMax = 2.2;
  s.layerMode = LayerMode::Floor;
  return s;
}

}  // namespace spira::test
