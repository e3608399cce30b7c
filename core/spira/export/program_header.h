#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace spira {

// The comment block every exported program opens with: the Spira version, then "key: value"
// lines for the part, the cell and the date (in that order when given), the other entries of
// `header` in key order, then `settings` (the exporter's own key parameters) in the order given.
// Values are made plain with plainText(); writers add their comment marker and wrap as needed.
std::vector<std::string> programHeaderLines(const std::map<std::string, std::string>& header,
                                            const std::vector<std::pair<std::string, std::string>>& settings);

// `text` reduced to what every controller's comment accepts: printable ASCII. Control
// characters become spaces, each non-ASCII (UTF-8) sequence becomes one '?', and the characters in
// `forbidden` become ' '.
std::string plainText(std::string_view text, std::string_view forbidden = {});

// `text` split at spaces into lines of at most `width` characters; a word longer than `width` is
// cut. Returns at least one line.
std::vector<std::string> wrapText(std::string_view text, size_t width);

}  // namespace spira
