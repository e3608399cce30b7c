#include "spira/io/stl_reader.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/io/mapped_file.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the binary STL reader assumes a little-endian host");

namespace spira {
namespace {

constexpr size_t kHeaderBytes = 80;
constexpr size_t kBinaryPrefix = 84;
constexpr size_t kFacetBytes = 50;
constexpr size_t kCancelStride = 1 << 16;
const char* const kNotStlHint = "the file is truncated or not an STL";

char lower(char c)
{
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

bool equalsNoCase(std::string_view a, std::string_view b)
{
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return lower(x) == lower(y); });
}

bool isSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view trimmed(std::string_view s)
{
  while (!s.empty() && (isSpace(s.front()) || s.front() == '\0')) s.remove_prefix(1);
  while (!s.empty() && (isSpace(s.back()) || s.back() == '\0')) s.remove_suffix(1);
  return s;
}

std::string_view withoutBom(std::string_view s)
{
  if (s.size() >= 3 && s.substr(0, 3) == "\xEF\xBB\xBF") s.remove_prefix(3);
  return s;
}

bool startsWithSolid(std::string_view bytes)
{
  std::string_view s = withoutBom(bytes);
  while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
  return s.size() >= 5 && equalsNoCase(s.substr(0, 5), "solid");
}

// ASCII STL never holds control characters; binary data (the triangle count, float zeros) does.
bool looksLikeText(std::string_view bytes)
{
  const std::string_view head = bytes.substr(0, 4096);
  return std::none_of(head.begin(), head.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c == 0x7F || (c < 0x20 && !isSpace(ch));
  });
}

StlData parseBinary(std::string_view bytes, size_t count, Progress& progress)
{
  StlData out;
  out.binary = true;
  out.name = std::string(trimmed(bytes.substr(0, kHeaderBytes)));
  auto& vertices = out.soup.vertices;
  auto& faces = out.soup.faces;
  vertices.resize(3 * count);
  faces.resize(count);
  const char* facet = bytes.data() + kBinaryPrefix;
  for (size_t i = 0; i < count; ++i, facet += kFacetBytes) {
    if (i % kCancelStride == 0) {
      progress.checkCancel();
      progress.report(static_cast<double>(i) / static_cast<double>(count), "Reading STL");
    }
    float c[9];
    std::memcpy(c, facet + 12, sizeof c);  // skip the stored normal
    const size_t v = 3 * i;
    vertices[v] = Vec3(c[0], c[1], c[2]);
    vertices[v + 1] = Vec3(c[3], c[4], c[5]);
    vertices[v + 2] = Vec3(c[6], c[7], c[8]);
    const int b = static_cast<int>(v);
    faces[i] = {b, b + 1, b + 2};
  }
  return out;
}

// A hand-written tokenizer: ASCII STL files reach hundreds of megabytes and stream-based
// parsing is several times slower than scanning the buffer once.
class AsciiStlParser {
 public:
  AsciiStlParser(std::string_view text, const std::string& source, Progress& progress)
      : text_(withoutBom(text)), source_(source), progress_(progress)
  {
  }

  StlData parse()
  {
    StlData out;
    out.binary = false;
    expectKeyword("solid");
    out.name = std::string(trimmed(restOfLine()));
    // Roughly 250 bytes per facet in typical exporters.
    out.soup.vertices.reserve(3 * (text_.size() / 250 + 1));
    out.soup.faces.reserve(text_.size() / 250 + 1);
    for (;;) {
      const std::string_view t = token();
      if (t.empty()) break;  // a missing "endsolid" loses nothing
      if (equalsNoCase(t, "facet")) {
        facet(out);
      } else if (equalsNoCase(t, "endsolid")) {
        restOfLine();
        const std::string_view next = token();
        if (next.empty()) break;
        if (!equalsNoCase(next, "solid")) fail("expected 'solid' or the end of the file", next);
        restOfLine();
      } else {
        fail("expected 'facet' or 'endsolid'", t);
      }
    }
    return out;
  }

 private:
  void facet(StlData& out)
  {
    if (++facets_ % kCancelStride == 0) {
      progress_.checkCancel();
      progress_.report(static_cast<double>(pos_) / static_cast<double>(text_.size()), "Reading STL");
    }
    expectKeyword("normal");
    for (int k = 0; k < 3; ++k) number();
    expectKeyword("outer");
    expectKeyword("loop");
    loop_.clear();
    for (;;) {
      const std::string_view t = token();
      if (equalsNoCase(t, "endloop")) break;
      if (!equalsNoCase(t, "vertex")) fail("expected 'vertex' or 'endloop'", t);
      const double x = number();
      const double y = number();
      const double z = number();
      loop_.emplace_back(x, y, z);
    }
    if (loop_.size() < 3)
      throw InputError("'" + source_ + "' line " + std::to_string(line_) + ": a facet has " +
                           std::to_string(loop_.size()) + " vertices, at least 3 are needed",
                       kNotStlHint);
    if (loop_.size() > 3) ++out.polygonFacets;
    for (size_t k = 1; k + 1 < loop_.size(); ++k) {
      const int b = static_cast<int>(out.soup.vertices.size());
      out.soup.vertices.push_back(loop_[0]);
      out.soup.vertices.push_back(loop_[k]);
      out.soup.vertices.push_back(loop_[k + 1]);
      out.soup.faces.push_back({b, b + 1, b + 2});
    }
    expectKeyword("endfacet");
  }

  std::string_view token()
  {
    while (pos_ < text_.size() && isSpace(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const size_t begin = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_])) ++pos_;
    return text_.substr(begin, pos_ - begin);
  }

  std::string_view restOfLine()
  {
    const size_t begin = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    return text_.substr(begin, pos_ - begin);
  }

  void expectKeyword(std::string_view keyword)
  {
    const std::string_view t = token();
    if (!equalsNoCase(t, keyword)) fail("expected '" + std::string(keyword) + "'", t);
  }

  double number()
  {
    const std::string_view t = token();
    const std::optional<double> value = parseMeshNumber(t);
    if (!value) fail("expected a number", t);
    return *value;
  }

  [[noreturn]] void fail(const std::string& expected, std::string_view found) const
  {
    std::string shown(found.substr(0, 40));
    for (char& c : shown)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
    throw InputError("'" + source_ + "' line " + std::to_string(line_) + ": " + expected + ", found " +
                         (found.empty() ? std::string("the end of the file") : "'" + shown + "'"),
                     "the ASCII STL is malformed; re-export it from the CAD program");
  }

  std::string_view text_;
  const std::string& source_;
  Progress& progress_;
  size_t pos_ = 0;
  size_t line_ = 1;
  size_t facets_ = 0;
  std::vector<Vec3> loop_;
};

}  // namespace

StlData parseStl(std::string_view bytes, const std::string& source, Progress& progress)
{
  if (bytes.empty())
    throw InputError("'" + source + "' is empty (0 bytes)", "choose the right file or re-export it");
  const bool solid = startsWithSolid(bytes);
  if (bytes.size() >= kBinaryPrefix) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + kHeaderBytes, sizeof count);
    const std::uint64_t expected = kBinaryPrefix + std::uint64_t{kFacetBytes} * count;
    if (expected == bytes.size() && !(solid && looksLikeText(bytes)))
      return parseBinary(bytes, count, progress);
    if (!solid || !looksLikeText(bytes))
      throw InputError("'" + source + "' is not a valid binary STL: its header announces " +
                           std::to_string(count) + " triangles, which take " + std::to_string(expected) +
                           " bytes, but the file has " + std::to_string(bytes.size()) + " bytes",
                       kNotStlHint);
  } else if (!solid || !looksLikeText(bytes)) {
    throw InputError("'" + source + "' is too short to be an STL: " + std::to_string(bytes.size()) +
                         " bytes, while a binary STL takes at least 84",
                     kNotStlHint);
  }
  return AsciiStlParser(bytes, source, progress).parse();
}

StlData readStl(const std::filesystem::path& file, Progress& progress)
{
  const MappedFile mapped(file);
  return parseStl(mapped.bytes(), file.filename().string(), progress);
}

}  // namespace spira
