#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace spira {

// The longest token (a quoted string or a run of other characters between delimiters) a STEP file
// may hold before OpenCASCADE reads it. Names and descriptions in real files are far shorter;
// OpenCASCADE's parser needs seconds and gigabytes for a token of a few megabytes.
constexpr size_t kMaxStepTokenChars = 1'000'000;

// Scans ISO 10303-21 text (quoted strings with '' escapes, /* comments */) and throws InputError
// naming `source`, the line and the token's length when a token is longer than `limit`, or when a
// string or a comment never ends. Linear in the size, no allocation.
void checkStepTokens(std::string_view text, const std::string& source, size_t limit = kMaxStepTokenChars);

}  // namespace spira
