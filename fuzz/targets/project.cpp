// The .spira project file. Its payload is checked by a CRC-32, which random changes almost never
// pass; an input that does not start with the magic is therefore taken as the payload (CBOR) and
// wrapped in a valid header and checksum, so that the decoder behind the check is reached too.
#include <cstring>

#include "../fuzz_support.h"
#include "spira/document/project_file.h"

namespace {

void putLe(std::string& out, uint64_t v, size_t bytes)
{
  for (size_t i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

std::string wrapped(std::string_view payload)
{
  std::string out(spira::kProjectMagic);
  putLe(out, spira::kProjectFormatVersion, 4);
  putLe(out, payload.size(), 8);
  out.append(payload);
  putLe(out, spira::crc32(payload), 4);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string_view input = spira::fuzz::bytes(data, size);
  const bool whole = input.substr(0, spira::kProjectMagic.size()) == spira::kProjectMagic;
  return spira::fuzz::refusalsAllowed([&] { spira::decodeProject(whole ? input : wrapped(input)); });
}
