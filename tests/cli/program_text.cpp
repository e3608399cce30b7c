#include "program_text.h"

#include <cctype>

namespace spira::test {

namespace {

bool isDigit(char c)
{
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

bool isSpace(char c)
{
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// End of the run of digits starting at `at` (== at when there is none).
size_t digitsEnd(const std::string& text, size_t at)
{
  while (at < text.size() && isDigit(text[at])) ++at;
  return at;
}

size_t spacesEnd(const std::string& text, size_t at)
{
  while (at < text.size() && isSpace(text[at])) ++at;
  return at;
}

}  // namespace

std::set<std::string> e6posStatusValues(const std::string& dat)
{
  const std::string head = "DECL E6POS XP";
  std::set<std::string> status;
  for (size_t at = dat.find(head); at != std::string::npos; at = dat.find(head, at + 1)) {
    const size_t number = at + head.size();
    const size_t open = digitsEnd(dat, number);
    if (open == number || dat.compare(open, 2, "={") != 0) continue;
    const size_t close = dat.find('}', open);
    const std::string body =
        dat.substr(open + 2, close == std::string::npos ? std::string::npos : close - open - 2);
    // The last "S <digits>,T" inside the braces.
    for (size_t s = body.rfind("S "); s != std::string::npos;
         s = s == 0 ? std::string::npos : body.rfind("S ", s - 1)) {
      const size_t end = digitsEnd(body, s + 2);
      if (end > s + 2 && body.compare(end, 2, ",T") == 0) {
        status.insert(body.substr(s + 2, end - s - 2));
        break;
      }
    }
  }
  return status;
}

bool tpLineCount(const std::string& ls, size_t& count)
{
  const std::string key = "LINE_COUNT";
  for (size_t at = ls.find(key); at != std::string::npos; at = ls.find(key, at + 1)) {
    size_t p = spacesEnd(ls, at + key.size());
    if (p >= ls.size() || ls[p] != '=') continue;
    p = spacesEnd(ls, p + 1);
    const size_t end = digitsEnd(ls, p);
    if (end == p || end >= ls.size() || ls[end] != ';') continue;
    count = std::stoul(ls.substr(p, end - p));
    return true;
  }
  return false;
}

bool isNumberedTpLine(const std::string& line)
{
  const size_t p = spacesEnd(line, 0);
  const size_t end = digitsEnd(line, p);
  return end > p && end < line.size() && line[end] == ':';
}

}  // namespace spira::test
