#include "spira/io/obj_reader.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/io/mapped_file.h"
#include "spira/io/polygon_fan.h"

namespace spira {
namespace {

constexpr size_t kCancelStride = 1 << 16;
constexpr size_t kExcerptChars = 40;
const char* const kCorruptHint = "the file is damaged or not a Wavefront OBJ; export the part again";
const char* const kNumberHint =
    "coordinates are finite decimal numbers such as 12.5 or -3e2; export the part again";
const char* const kCornerHint =
    "a face corner names a vertex defined above it, counting from 1 (or back from -1); the file is "
    "damaged or cut, export the part again";
const char* const kNoSurfaceHint = "Spira needs a surface; export the part as a mesh with faces";

bool isSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// OBJ is text: control bytes other than white space mean binary data.
bool isBinary(char c)
{
  const auto u = static_cast<unsigned char>(c);
  return (u < 0x20 && !isSpace(c) && c != '\n') || u == 0x7F;
}

// File text quoted in a message: at most 40 characters, control and non-ASCII bytes shown as '?',
// so that a megabyte token or binary data is never echoed.
std::string excerpt(std::string_view text)
{
  std::string shown(text.substr(0, kExcerptChars));
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
  return text.size() > kExcerptChars ? shown + "..." : shown;
}

std::string_view withoutBom(std::string_view s)
{
  if (s.size() >= 3 && s.substr(0, 3) == "\xEF\xBB\xBF") s.remove_prefix(3);
  return s;
}

// Lines that start a vertex statement, at most one per 8 bytes (the shortest is "v 0 0 0\n").
// Reserving them up front spares a large file the growth by doubling, which holds the old and the
// new copy at once; whatever the file holds, the reserve stays within 3 bytes per file byte.
size_t vertexLines(std::string_view text)
{
  size_t n = 0;
  for (size_t p = 0; p < text.size();) {
    if (text[p] == 'v' && p + 1 < text.size() && (text[p + 1] == ' ' || text[p + 1] == '\t')) ++n;
    const void* nl = std::memchr(text.data() + p, '\n', text.size() - p);
    if (!nl) break;
    p = static_cast<size_t>(static_cast<const char*>(nl) - text.data()) + 1;
  }
  return std::min(n, text.size() / 8 + 1);
}

enum class Statement { Vertex, Face, Ignored, Unknown };

Statement statementOf(std::string_view keyword)
{
  if (keyword == "v") return Statement::Vertex;
  if (keyword == "f") return Statement::Face;
  // Texture coordinates, normals, parameter-space vertices, names, groups, smoothing, materials,
  // lines and points: nothing a deposition path is planned on.
  for (const char* k : {"vt", "vn", "vp", "o", "g", "s", "usemtl", "mtllib", "l", "p"})
    if (keyword == k) return Statement::Ignored;
  return Statement::Unknown;
}

class ObjParser {
 public:
  ObjParser(std::string_view bytes, const std::string& source, Progress& progress)
      : text_(withoutBom(bytes)), source_(source), progress_(progress)
  {
  }

  ObjData parse()
  {
    out_.mesh.vertices.reserve(vertexLines(text_));
    for (size_t statements = 0; nextStatement(); ++statements) {
      if (statements % kCancelStride == 0) {
        progress_.checkCancel();
        progress_.report(static_cast<double>(pos_) / static_cast<double>(text_.size()), "Reading OBJ");
      }
      const std::string_view keyword = token();
      checkText(keyword);
      switch (statementOf(keyword)) {
        case Statement::Vertex:
          vertex();
          break;
        case Statement::Face:
          face();
          break;
        case Statement::Ignored:
          break;
        case Statement::Unknown:
          if (out_.unknownStatements++ == 0) {
            firstUnknown_ = excerpt(keyword);
            firstUnknownLine_ = line_;
          }
          break;
      }
      skipStatement();
    }
    finish();
    return std::move(out_);
  }

 private:
  // The length of a backslash line continuation at `p` ("\\\n" or "\\\r\n", or a backslash ending
  // the file), else 0.
  size_t continuationAt(size_t p) const
  {
    if (text_[p] != '\\') return 0;
    if (p + 1 == text_.size() || text_[p + 1] == '\n') return p + 1 == text_.size() ? 1 : 2;
    if (text_[p + 1] == '\r' && p + 2 < text_.size() && text_[p + 2] == '\n') return 3;
    return 0;
  }

  // Spaces and continuations within a statement.
  void skipSpaces()
  {
    while (pos_ < text_.size()) {
      if (isSpace(text_[pos_])) {
        ++pos_;
      } else if (const size_t n = continuationAt(pos_)) {
        pos_ += n;
        ++line_;
      } else {
        break;
      }
    }
  }

  void skipComment()
  {
    const void* nl = std::memchr(text_.data() + pos_, '\n', text_.size() - pos_);
    pos_ = nl ? static_cast<size_t>(static_cast<const char*>(nl) - text_.data()) : text_.size();
  }

  // Moves to the first character of the next statement past blank and comment lines; false at the end.
  bool nextStatement()
  {
    for (;;) {
      skipSpaces();
      if (pos_ == text_.size()) return false;
      if (text_[pos_] == '\n') {
        ++pos_;
        ++line_;
      } else if (text_[pos_] == '#') {
        skipComment();
      } else {
        return true;
      }
    }
  }

  // The statement's next word, or empty at its end (a line end or a comment).
  std::string_view token()
  {
    skipSpaces();
    if (pos_ == text_.size() || text_[pos_] == '\n') return {};
    if (text_[pos_] == '#') {
      skipComment();
      return {};
    }
    const size_t begin = pos_;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (isSpace(c) || c == '\n' || (c == '\\' && continuationAt(pos_) > 0)) break;
      ++pos_;
    }
    return text_.substr(begin, pos_ - begin);
  }

  void skipStatement()
  {
    while (!token().empty()) {
    }
  }

  void checkText(std::string_view keyword) const
  {
    for (char c : keyword)
      if (isBinary(c)) {
        static const char digits[] = "0123456789ABCDEF";
        const auto u = static_cast<unsigned char>(c);
        fail(std::string("the file holds binary data (a byte 0x") + digits[u >> 4] + digits[u & 15] +
                 "), not OBJ text",
             "choose the right file: an OBJ is a text file");
      }
  }

  void vertex()
  {
    double xyz[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < 3; ++k) {
      const std::string_view t = token();
      if (t.empty())
        fail("the vertex has " + std::to_string(k) + (k == 1 ? " coordinate" : " coordinates") +
                 "; 'v' needs x, y and z",
             kCorruptHint);
      std::string problem;
      const auto x = parseFiniteNumber(t, problem);
      if (!x) fail("the coordinate '" + excerpt(t) + "' " + problem, kNumberHint);
      xyz[k] = *x;
    }
    if (out_.mesh.vertices.size() == static_cast<size_t>(std::numeric_limits<int>::max()))
      fail("the file has more vertices than Spira's limit of " +
               std::to_string(std::numeric_limits<int>::max()),
           "split the part or simplify its mesh");
    out_.mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  void face()
  {
    loop_.clear();
    for (std::string_view t = token(); !t.empty(); t = token()) loop_.push_back(corner(t));
    fan_.add(loop_, out_.mesh.faces);
  }

  // The vertex a corner `v`, `v/vt`, `v//vn` or `v/vt/vn` names, as a 0-based index.
  int corner(std::string_view t)
  {
    const size_t slash = t.find('/');
    checkTextureAndNormal(t, slash);
    std::string problem;
    const auto index = parseWholeNumber(t.substr(0, slash), problem);
    if (!index) fail("the vertex index of the face corner '" + excerpt(t) + "' " + problem, kCornerHint);
    const auto count = static_cast<long long>(out_.mesh.vertices.size());
    if (*index == 0)
      fail("the face corner '" + excerpt(t) + "' names vertex 0, but OBJ numbers vertices from 1",
           kCornerHint);
    if (*index > count || *index < -count)
      fail("the face corner '" + excerpt(t) + "' names vertex " + std::to_string(*index) + ", but " +
               definedAbove(count),
           kCornerHint);
    return static_cast<int>(*index > 0 ? *index - 1 : count + *index);
  }

  // Spira does not use texture and normal indices but refuses a corner that is not one of the forms.
  void checkTextureAndNormal(std::string_view t, size_t slash)
  {
    if (slash == std::string_view::npos) return;
    const std::string_view rest = t.substr(slash + 1);
    const size_t second = rest.find('/');
    for (const std::string_view part :
         {rest.substr(0, second),
          second == std::string_view::npos ? std::string_view() : rest.substr(second + 1)}) {
      std::string problem;
      if (part.find('/') != std::string_view::npos || (!part.empty() && !parseWholeNumber(part, problem)))
        fail("the face corner '" + excerpt(t) + "' is not v, v/vt, v//vn or v/vt/vn with whole numbers",
             kCorruptHint);
    }
  }

  static std::string definedAbove(long long count)
  {
    if (count == 0) return "no vertex is defined above it";
    if (count == 1) return "only 1 vertex is defined above it (1, or -1)";
    const std::string n = std::to_string(count);
    return "only " + n + " vertices are defined above it (1 to " + n + ", or -1 to -" + n + ")";
  }

  void finish()
  {
    out_.polygonFaces = fan_.polygonFaces;
    out_.degenerateFaces = fan_.degenerateFaces;
    if (out_.mesh.faces.empty()) {
      if (out_.degenerateFaces > 0)
        throw InputError("'" + source_ + "' has no face with three or more corners (only " +
                             std::to_string(out_.degenerateFaces) + " with fewer)",
                         kNoSurfaceHint);
      const size_t n = out_.mesh.vertices.size();
      throw InputError(
          "'" + source_ + "' has no faces ('f' lines)" +
              (n == 0 ? std::string(" and no vertices")
                      : ": it holds " + std::to_string(n) + (n == 1 ? " vertex" : " vertices") + " only"),
          kNoSurfaceHint);
    }
    fan_.appendWarnings(source_, out_.warnings);
    if (out_.unknownStatements > 0)
      out_.warnings.push_back(
          "'" + source_ + "': " +
          (out_.unknownStatements == 1 ? std::string("1 statement")
                                       : std::to_string(out_.unknownStatements) + " statements") +
          " of a kind Spira does not read ignored, the first '" + firstUnknown_ + "' on line " +
          std::to_string(firstUnknownLine_) + "; Spira reads vertices ('v') and faces ('f')");
  }

  [[noreturn]] void fail(const std::string& what, const char* hint) const
  {
    throw InputError("'" + source_ + "' line " + std::to_string(line_) + ": " + what, hint);
  }

  std::string_view text_;
  const std::string& source_;
  Progress& progress_;
  ObjData out_;
  size_t pos_ = 0;
  size_t line_ = 1;
  std::vector<int> loop_;
  PolygonFan fan_;
  std::string firstUnknown_;
  size_t firstUnknownLine_ = 0;
};

}  // namespace

ObjData parseObj(std::string_view bytes, const std::string& source, Progress& progress)
{
  if (bytes.empty())
    throw InputError("'" + source + "' is empty (0 bytes)", "choose the right file or re-export it");
  return ObjParser(bytes, source, progress).parse();
}

ObjData readObj(const std::filesystem::path& file, Progress& progress)
{
  const MappedFile mapped(file);
  return parseObj(mapped.bytes(), file.filename().string(), progress);
}

}  // namespace spira
