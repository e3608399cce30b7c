#pragma once

#include <string>
#include <string_view>

namespace spira {

// RFC 4648 base64 with padding, for binary arrays inside text formats (VTK XML, JSON).
std::string base64Encode(std::string_view bytes);
// Throws InputError naming the offset of the first character that is not base64.
std::string base64Decode(std::string_view text);

}  // namespace spira
