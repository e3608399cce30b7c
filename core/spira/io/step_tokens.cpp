#include "spira/io/step_tokens.h"

#include "spira/base/error.h"

namespace spira {
namespace {

bool isDelimiter(char c)
{
  switch (c) {
    case ' ':
    case '\t':
    case '\r':
    case '\n':
    case '(':
    case ')':
    case ',':
    case ';':
    case '=':
    case '\'':
      return true;
    default:
      return false;
  }
}

[[noreturn]] void refuse(const std::string& source, size_t line, const std::string& what)
{
  throw InputError("'" + source + "' line " + std::to_string(line) + ": " + what,
                   "the file is damaged or not a STEP file; export it again from the CAD program");
}

}  // namespace

void checkStepTokens(std::string_view text, const std::string& source, size_t limit)
{
  size_t line = 1, i = 0;
  const size_t n = text.size();
  const auto tooLong = [&](size_t startLine, size_t length) {
    refuse(source, startLine,
           "a token of " + std::to_string(length) + " characters (at most " + std::to_string(limit) +
               " are read)");
  };
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      const size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) refuse(source, line, "a comment (/*) that never ends");
      for (size_t k = i; k < end; ++k) line += text[k] == '\n';
      i = end + 2;
    } else if (c == '\'') {
      const size_t startLine = line;
      size_t k = i + 1, length = 0;
      for (;; ++k) {
        if (k >= n) refuse(source, startLine, "a quoted string that never ends");
        if (text[k] == '\'') {
          if (k + 1 < n && text[k + 1] == '\'') {
            ++k;  // '' stands for one quote inside the string
          } else {
            break;
          }
        }
        line += text[k] == '\n';
        ++length;
      }
      if (length > limit) tooLong(startLine, length);
      i = k + 1;
    } else if (isDelimiter(c)) {
      ++i;
    } else {
      const size_t start = i;
      while (i < n && !isDelimiter(text[i]) && !(text[i] == '/' && i + 1 < n && text[i + 1] == '*')) ++i;
      if (i - start > limit) tooLong(line, i - start);
    }
  }
}

}  // namespace spira
