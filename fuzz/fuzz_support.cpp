#include "fuzz_support.h"

#include <cstdio>
#include <cstdlib>

namespace spira::fuzz {

void violated(const char* property)
{
  std::fprintf(stderr, "fuzz target property violated: %s\n", property);
  std::abort();
}

}  // namespace spira::fuzz
