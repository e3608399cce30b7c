#include "spira/io/ply_reader.h"

#include <algorithm>
#include <limits>

#include "spira/base/error.h"
#include "spira/io/mapped_file.h"
#include "spira/io/ply_body_cursor.h"
#include "spira/io/polygon_fan.h"

namespace spira {
namespace {

using ply_detail::AsciiCursor;
using ply_detail::BinaryCursor;
using ply_detail::PlyBodyProblem;

constexpr size_t kCancelStride = 1 << 16;
const char* const kTruncatedHint = "the file is truncated or its header is wrong; export the part again";
const char* const kCorruptHint = "the file is corrupt; export the part again";

// "vertices" and "faces" read better than "'vertex' items"; other elements keep their name.
std::string itemsOf(const PlyElement& e)
{
  if (e.name == "vertex") return "vertices";
  if (e.name == "face") return "faces";
  return "'" + plyExcerpt(e.name) + "' items";
}

std::string counted(const PlyElement& e)
{
  if (e.count != 1) return std::to_string(e.count) + " " + itemsOf(e);
  return "1 " + (e.name == "vertex" || e.name == "face" ? e.name : "'" + plyExcerpt(e.name) + "' item");
}

std::string itemOf(const PlyElement& e, std::uint64_t index)
{
  const std::string n = std::to_string(index);
  if (e.name == "vertex") return "vertex " + n;
  if (e.name == "face") return "face " + n;
  return "item " + n + " of element '" + plyExcerpt(e.name) + "'";
}

std::uint64_t saturatingMul(std::uint64_t a, std::uint64_t b)
{
  std::uint64_t r = 0;
  return __builtin_mul_overflow(a, b, &r) ? std::numeric_limits<std::uint64_t>::max() : r;
}

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b)
{
  std::uint64_t r = 0;
  return __builtin_add_overflow(a, b, &r) ? std::numeric_limits<std::uint64_t>::max() : r;
}

// The fewest bytes a body holding the declared elements can take: exact for binary scalars (lists
// count as empty), and for ASCII one character per value plus one separator between values.
std::uint64_t minimumBodyBytes(const PlyHeader& h)
{
  std::uint64_t total = 0;
  for (const PlyElement& e : h.elements) {
    if (h.encoding == PlyEncoding::Ascii)
      total = saturatingAdd(total, saturatingMul(e.count, 2 * e.properties.size()));
    else
      total = saturatingAdd(total, saturatingMul(e.count, e.minBinaryBytes()));
  }
  return h.encoding == PlyEncoding::Ascii && total > 0 ? total - 1 : total;
}

std::string declaredCounts(const PlyHeader& h)
{
  std::string s;
  for (const PlyElement& e : h.elements) {
    if (!s.empty()) s += ", ";
    s += counted(e);
  }
  return s;
}

class PlyParser {
 public:
  // `points`: a point cloud, whose faces (if any) are read past.
  PlyParser(std::string_view bytes, const std::string& source, Progress& progress, bool points)
      : bytes_(bytes),
        source_(source),
        progress_(progress),
        header_(parsePlyHeader(bytes, source)),
        points_(points)
  {
  }

  PlyData parse()
  {
    out_.encoding = header_.encoding;
    findRoles();
    checkSizes();
    switch (header_.encoding) {
      case PlyEncoding::Ascii:
        readBody(AsciiCursor(bytes_, header_.bodyOffset, header_.lines + 1));
        break;
      case PlyEncoding::BinaryLittleEndian:
        readBody(BinaryCursor<false>(bytes_, header_.bodyOffset));
        break;
      case PlyEncoding::BinaryBigEndian:
        readBody(BinaryCursor<true>(bytes_, header_.bodyOffset));
        break;
    }
    addCountWarnings();
    return std::move(out_);
  }

 private:
  void findRoles()
  {
    for (size_t i = 0; i < header_.elements.size(); ++i) {
      const PlyElement& e = header_.elements[i];
      if (e.name == "vertex") vertex_ = static_cast<int>(i);
      if (e.name == "face" && !points_) face_ = static_cast<int>(i);
    }
    if (vertex_ < 0)
      throw InputError("'" + source_ + "' has no 'vertex' element in its PLY header",
                       points_ ? "export the scan again as a PLY point cloud with x, y, z vertices"
                               : "export the part again as a PLY mesh with vertices and faces");
    if (points_) {
      findVertexProperties();
      if (header_.elements[static_cast<size_t>(vertex_)].count == 0)
        throw InputError("'" + source_ + "' holds no point: its PLY header declares 0 vertices",
                         "choose the scan's file, or export the scan again");
      return;
    }
    if (face_ < 0)
      throw InputError("'" + source_ + "' has no 'face' element in its PLY header: it holds points only",
                       "Spira needs a surface; export the part as a mesh with faces");
    findVertexProperties();
    const PlyElement& v = header_.elements[static_cast<size_t>(vertex_)];
    const PlyElement& f = header_.elements[static_cast<size_t>(face_)];
    corners_ = f.find("vertex_indices");
    if (corners_ < 0) corners_ = f.find("vertex_index");
    if (corners_ < 0 || !f.properties[static_cast<size_t>(corners_)].isList)
      headerFail(f, "element 'face' has no list property 'vertex_indices' (or 'vertex_index')");
    if (!plyTypeIsInteger(f.properties[static_cast<size_t>(corners_)].type))
      headerFail(f, "the corner indices of element 'face' do not have an integer type");
    if (v.count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      headerFail(v, "the header declares " + std::to_string(v.count) +
                        " vertices, more than Spira's limit of " +
                        std::to_string(std::numeric_limits<int>::max()));
  }

  // x, y, z (required) and nx, ny, nz (all three or none) of the vertex element.
  void findVertexProperties()
  {
    const PlyElement& v = header_.elements[static_cast<size_t>(vertex_)];
    axisOf_.assign(v.properties.size(), -1);
    normalOf_.assign(v.properties.size(), -1);
    int normals = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const char name[2] = {static_cast<char>('x' + axis), '\0'};
      const int p = v.find(name);
      if (p < 0 || v.properties[static_cast<size_t>(p)].isList)
        headerFail(v, "element 'vertex' has no scalar property '" + std::string(name) + "'");
      axisOf_[static_cast<size_t>(p)] = axis;
      const int n = v.find("n" + std::string(name));
      if (n >= 0 && !v.properties[static_cast<size_t>(n)].isList)
        normalOf_[static_cast<size_t>(n)] = axis, ++normals;
    }
    hasNormals_ = normals == 3;
  }

  // Refuses a header whose counts the body cannot hold before anything is allocated for them.
  void checkSizes()
  {
    const std::uint64_t available = bytes_.size() - header_.bodyOffset;
    const std::uint64_t needed = minimumBodyBytes(header_);
    if (needed > available)
      throw InputError("'" + source_ + "': the PLY header declares " + declaredCounts(header_) +
                           ", which take at least " + std::to_string(needed) + " bytes, but only " +
                           std::to_string(available) + " bytes follow the header",
                       kTruncatedHint);
    out_.mesh.vertices.resize(static_cast<size_t>(header_.elements[static_cast<size_t>(vertex_)].count));
    if (hasNormals_) out_.normals.resize(out_.mesh.vertices.size());
    if (face_ < 0) return;
    const PlyElement& f = header_.elements[static_cast<size_t>(face_)];
    const PlyProperty& list = f.properties[static_cast<size_t>(corners_)];
    // A triangle takes at least 8 ASCII bytes ("3 0 1 2\n"); reserving more than the body can hold
    // would let a lying header allocate memory.
    const std::uint64_t triangleBytes =
        header_.encoding == PlyEncoding::Ascii ? 8 : plyTypeSize(list.countType) + 3 * plyTypeSize(list.type);
    out_.mesh.faces.reserve(static_cast<size_t>(std::min(f.count, available / triangleBytes)));
  }

  template <class Cursor>
  void readBody(Cursor cursor)
  {
    for (size_t i = 0; i < header_.elements.size(); ++i) {
      const PlyElement& e = header_.elements[i];
      if (e.properties.empty() || e.count == 0) continue;
      if (static_cast<int>(i) != vertex_ && static_cast<int>(i) != face_)
        out_.warnings.push_back("'" + source_ + "': element '" + plyExcerpt(e.name) + "' (" + counted(e) +
                                ") was ignored; Spira reads vertices and faces");
      for (std::uint64_t k = 0; k < e.count; ++k) {
        if (k % kCancelStride == 0) {
          progress_.checkCancel();
          progress_.report(static_cast<double>(cursor.position()) / static_cast<double>(bytes_.size()),
                           "Reading PLY");
        }
        try {
          cursor.beginItem();
          if (static_cast<int>(i) == vertex_)
            readVertex(cursor, e, static_cast<size_t>(k));
          else if (static_cast<int>(i) == face_)
            readFace(cursor, e, k);
          else
            skipItem(cursor, e, k);
          cursor.endItem();
        } catch (const PlyBodyProblem& problem) {
          bodyFail(cursor, e, k, problem);
        }
      }
    }
    checkTrailing(cursor);
  }

  template <class Cursor>
  std::uint64_t listCount(Cursor& cursor, const PlyElement& e, std::uint64_t k, const PlyProperty& p)
  {
    const std::int64_t n = cursor.whole(p.countType);
    if (n < 0)
      throw InputError("'" + source_ + "' " + cursor.where() + ": " + itemOf(e, k) + " has a list '" +
                           plyExcerpt(p.name) + "' of " + std::to_string(n) + " values",
                       kCorruptHint);
    return static_cast<std::uint64_t>(n);
  }

  template <class Cursor>
  void skipItem(Cursor& cursor, const PlyElement& e, std::uint64_t k)
  {
    for (const PlyProperty& p : e.properties) {
      if (p.isList)
        cursor.skipList(listCount(cursor, e, k, p), p.type);
      else
        cursor.skip(p.type);
    }
  }

  template <class Cursor>
  void readVertex(Cursor& cursor, const PlyElement& e, size_t k)
  {
    double xyz[3] = {0.0, 0.0, 0.0}, nxyz[3] = {0.0, 0.0, 0.0};
    for (size_t p = 0; p < e.properties.size(); ++p) {
      const PlyProperty& prop = e.properties[p];
      if (axisOf_[p] >= 0)
        xyz[axisOf_[p]] = cursor.real(prop.type);
      else if (hasNormals_ && normalOf_[p] >= 0)
        nxyz[normalOf_[p]] = cursor.real(prop.type);
      else if (prop.isList)
        cursor.skipList(listCount(cursor, e, k, prop), prop.type);
      else
        cursor.skip(prop.type);
    }
    out_.mesh.vertices[k] = Vec3(xyz[0], xyz[1], xyz[2]);
    if (hasNormals_) out_.normals[k] = Vec3(nxyz[0], nxyz[1], nxyz[2]);
  }

  template <class Cursor>
  void readFace(Cursor& cursor, const PlyElement& e, std::uint64_t k)
  {
    const auto vertexCount = static_cast<std::int64_t>(out_.mesh.vertices.size());
    loop_.clear();
    for (size_t p = 0; p < e.properties.size(); ++p) {
      const PlyProperty& prop = e.properties[p];
      if (!prop.isList) {
        cursor.skip(prop.type);
        continue;
      }
      const std::uint64_t n = listCount(cursor, e, k, prop);
      if (static_cast<int>(p) != corners_) {
        cursor.skipList(n, prop.type);
        continue;
      }
      for (std::uint64_t c = 0; c < n; ++c) {
        const std::int64_t v = cursor.whole(prop.type);
        if (v < 0 || v >= vertexCount)
          throw InputError("'" + source_ + "' " + cursor.where() + ": face " + std::to_string(k) +
                               " refers to vertex " + std::to_string(v) + ", but the file has " +
                               std::to_string(vertexCount) + " vertices (indices 0 to " +
                               std::to_string(vertexCount - 1) + ")",
                           kCorruptHint);
        loop_.push_back(static_cast<int>(v));
      }
    }
    fan_.add(loop_, out_.mesh.faces);
  }

  void checkTrailing(AsciiCursor& cursor)
  {
    if (!cursor.restIsBlank())
      out_.warnings.push_back("'" + source_ + "' " + cursor.where() +
                              ": the text after the last element was ignored");
  }

  template <bool BigEndian>
  void checkTrailing(BinaryCursor<BigEndian>& cursor)
  {
    const size_t extra = bytes_.size() - cursor.position();
    if (extra > 0)
      out_.warnings.push_back("'" + source_ + "' " + cursor.where() + ": the " + std::to_string(extra) +
                              " bytes after the last element were ignored");
  }

  void addCountWarnings()
  {
    out_.polygonFaces = fan_.polygonFaces;
    out_.degenerateFaces = fan_.degenerateFaces;
    fan_.appendWarnings(source_, out_.warnings);
  }

  template <class Cursor>
  [[noreturn]] void bodyFail(const Cursor& cursor, const PlyElement& e, std::uint64_t k,
                             const PlyBodyProblem& problem) const
  {
    const std::string at = "'" + source_ + "' " + cursor.where() + ": ";
    switch (problem.kind) {
      case PlyBodyProblem::End:
        throw InputError("'" + source_ + "' ends after " + std::to_string(k) + " of the " + counted(e) +
                             " its PLY header declares (" + cursor.where() + ")",
                         "the file is truncated; export the part again");
      case PlyBodyProblem::ShortItem:
        throw InputError(at + itemOf(e, k) + " has fewer values than the header declares for element '" +
                             plyExcerpt(e.name) + "'",
                         kCorruptHint);
      case PlyBodyProblem::LongItem:
        throw InputError(at + itemOf(e, k) + " has more values than the header declares for element '" +
                             plyExcerpt(e.name) + "' (from '" + problem.found + "' on)",
                         kCorruptHint);
      case PlyBodyProblem::NotNumber:
        throw InputError(at + "expected a number in " + itemOf(e, k) + ", found '" + problem.found + "'",
                         kCorruptHint);
      case PlyBodyProblem::NotWhole:
        throw InputError(
            at + "expected a whole number in " + itemOf(e, k) + ", found '" + problem.found + "'",
            kCorruptHint);
    }
    throw InputError(at + "unreadable " + itemOf(e, k), kCorruptHint);
  }

  [[noreturn]] void headerFail(const PlyElement& e, const std::string& what) const
  {
    throw InputError("'" + source_ + "' line " + std::to_string(e.line) + ": " + what,
                     "export the part again as a PLY mesh with x, y, z vertices and vertex_indices faces");
  }

  std::string_view bytes_;
  const std::string& source_;
  Progress& progress_;
  PlyHeader header_;
  PlyData out_;
  int vertex_ = -1;
  int face_ = -1;
  int corners_ = -1;
  bool points_ = false;
  bool hasNormals_ = false;
  std::vector<int> axisOf_;    // per vertex property: 0, 1, 2 for x, y, z, else -1
  std::vector<int> normalOf_;  // per vertex property: 0, 1, 2 for nx, ny, nz, else -1
  std::vector<int> loop_;
  PolygonFan fan_;
};

}  // namespace

PlyData parsePly(std::string_view bytes, const std::string& source, Progress& progress)
{
  if (bytes.empty())
    throw InputError("'" + source + "' is empty (0 bytes)", "choose the right file or re-export it");
  return PlyParser(bytes, source, progress, false).parse();
}

PlyData readPly(const std::filesystem::path& file, Progress& progress)
{
  const MappedFile mapped(file);
  return parsePly(mapped.bytes(), file.filename().string(), progress);
}

PlyData parsePlyPoints(std::string_view bytes, const std::string& source, Progress& progress)
{
  if (bytes.empty())
    throw InputError("'" + source + "' is empty (0 bytes)", "choose the scan's file or export it again");
  return PlyParser(bytes, source, progress, true).parse();
}

PlyData readPlyPoints(const std::filesystem::path& file, Progress& progress)
{
  const MappedFile mapped(file);
  return parsePlyPoints(mapped.bytes(), file.filename().string(), progress);
}

}  // namespace spira
