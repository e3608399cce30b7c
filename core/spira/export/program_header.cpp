#include "spira/export/program_header.h"

#include "spira/base/version.h"

namespace spira {

std::vector<std::string> programHeaderLines(const std::map<std::string, std::string>& header,
                                            const std::vector<std::pair<std::string, std::string>>& settings)
{
  std::vector<std::string> lines;
  lines.push_back(std::string(kApplicationName) + " " + kVersion + " WAAM deposition program");
  const char* first[] = {"part", "cell", "date"};
  for (const char* key : first) {
    const auto it = header.find(key);
    if (it != header.end()) lines.push_back(plainText(it->first + ": " + it->second));
  }
  for (const auto& [key, value] : header) {
    if (key == "part" || key == "cell" || key == "date") continue;
    lines.push_back(plainText(key + ": " + value));
  }
  for (const auto& [key, value] : settings) lines.push_back(plainText(key + ": " + value));
  return lines;
}

std::string plainText(std::string_view text, std::string_view forbidden)
{
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      // One '?' per UTF-8 sequence: skip its continuation bytes (top bits 1 and 0).
      out.push_back('?');
      while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80) ++i;
    } else if (c < 0x20 || c == 0x7F || forbidden.find(static_cast<char>(c)) != std::string_view::npos) {
      out.push_back(' ');
    } else {
      out.push_back(static_cast<char>(c));
    }
  }
  return out;
}

std::vector<std::string> wrapText(std::string_view text, size_t width)
{
  std::vector<std::string> lines;
  if (width == 0) width = 1;
  std::string current;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    size_t end = i;
    while (end < text.size() && text[end] != ' ') ++end;
    std::string_view word = text.substr(i, end - i);
    i = end;
    if (word.empty()) break;
    while (word.size() > width) {  // a word longer than a line is cut
      if (!current.empty()) {
        lines.push_back(std::move(current));
        current.clear();
      }
      lines.emplace_back(word.substr(0, width));
      word.remove_prefix(width);
    }
    if (word.empty()) continue;
    if (!current.empty() && current.size() + 1 + word.size() > width) {
      lines.push_back(std::move(current));
      current.clear();
    }
    if (!current.empty()) current.push_back(' ');
    current.append(word);
  }
  if (!current.empty() || lines.empty()) lines.push_back(std::move(current));
  return lines;
}

}  // namespace spira
