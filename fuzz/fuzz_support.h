#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "spira/base/error.h"

// What every fuzz target shares. A target hands the input to one reader of user files; the
// reader may refuse it with the errors its contract names, and anything else escaping (another
// exception, a crash, a hang, a leak) is a finding.
namespace spira::fuzz {

inline std::string_view bytes(const uint8_t* data, size_t size)
{
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `read`; the refusals a reader of user files may give (InputError, IoError) end the run
// normally, everything else propagates so that the fuzzer reports it.
template <class Read>
int refusalsAllowed(Read&& read)
{
  try {
    read();
  } catch (const InputError&) {
  } catch (const IoError&) {
  }
  return 0;
}

// Stops the run as a finding when a property the target checks does not hold.
[[noreturn]] void violated(const char* property);

}  // namespace spira::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
