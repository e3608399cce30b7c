#include "spira/io/mesh_writers.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "binary mesh writers assume a little-endian host");

namespace spira {
namespace {

void checkIndices(const TriangleMesh& mesh)
{
  const auto n = static_cast<int>(mesh.vertices.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f])
      if (v < 0 || v >= n)
        throw InternalError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " +
                            std::to_string(n) + " while writing a mesh");
}

void appendVec(std::string& out, const Vec3& p)
{
  appendNumber(out, p.x());
  out += ' ';
  appendNumber(out, p.y());
  out += ' ';
  appendNumber(out, p.z());
}

template <class T>
void appendRaw(std::string& out, T value)
{
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  out.append(b, sizeof(T));
}

void appendFloats(std::string& out, const Vec3& p)
{
  appendRaw(out, static_cast<float>(p.x()));
  appendRaw(out, static_cast<float>(p.y()));
  appendRaw(out, static_cast<float>(p.z()));
}

// Names go into headers and "solid" lines: keep them to one printable word.
std::string sanitizedName(std::string_view name)
{
  std::string s;
  for (char c : name) s += std::isgraph(static_cast<unsigned char>(c)) ? c : '_';
  return s.empty() ? std::string("spira") : s;
}

std::string stlBinary(const TriangleMesh& mesh, std::string_view name)
{
  if (mesh.faces.size() > std::numeric_limits<std::uint32_t>::max())
    throw InputError(
        "the mesh has " + std::to_string(mesh.faces.size()) + " triangles, more than binary STL can hold",
        "write OBJ or PLY instead");
  std::string out;
  out.reserve(84 + 50 * mesh.faces.size());
  // The header must not start with "solid": some readers would take the file for ASCII.
  std::string header = "Spira binary STL " + sanitizedName(name);
  header.resize(80, ' ');
  out += header;
  appendRaw(out, static_cast<std::uint32_t>(mesh.faces.size()));
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    appendFloats(out, mesh.faceNormal(f));
    for (int v : mesh.faces[f]) appendFloats(out, mesh.vertices[static_cast<size_t>(v)]);
    appendRaw(out, std::uint16_t{0});
  }
  return out;
}

std::string stlAscii(const TriangleMesh& mesh, std::string_view name)
{
  const std::string solid = sanitizedName(name);
  std::string out = "solid " + solid + "\n";
  out.reserve(out.size() + 200 * mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    out += "facet normal ";
    appendVec(out, mesh.faceNormal(f));
    out += "\n outer loop\n";
    for (int v : mesh.faces[f]) {
      out += "  vertex ";
      appendVec(out, mesh.vertices[static_cast<size_t>(v)]);
      out += '\n';
    }
    out += " endloop\nendfacet\n";
  }
  out += "endsolid " + solid + "\n";
  return out;
}

std::string obj(const TriangleMesh& mesh, std::string_view name)
{
  std::string out = "# Spira mesh, millimetres\no " + sanitizedName(name) + "\n";
  out.reserve(out.size() + 40 * mesh.vertices.size() + 25 * mesh.faces.size());
  for (const Vec3& p : mesh.vertices) {
    out += "v ";
    appendVec(out, p);
    out += '\n';
  }
  for (const Face& f : mesh.faces) {
    out += 'f';
    for (int v : f) {
      out += ' ';
      appendNumber(out, static_cast<long long>(v) + 1);
    }
    out += '\n';
  }
  return out;
}

std::string plyHeader(const TriangleMesh& mesh, bool binary)
{
  std::string h = "ply\nformat ";
  h += binary ? "binary_little_endian" : "ascii";
  h += " 1.0\ncomment Spira mesh, millimetres\nelement vertex " + std::to_string(mesh.vertices.size()) + "\n";
  const char* type = binary ? "float" : "double";
  for (const char* axis : {"x", "y", "z"}) h += std::string("property ") + type + " " + axis + "\n";
  h += "element face " + std::to_string(mesh.faces.size()) +
       "\nproperty list uchar int vertex_indices\nend_header\n";
  return h;
}

std::string ply(const TriangleMesh& mesh, bool binary)
{
  std::string out = plyHeader(mesh, binary);
  if (binary) {
    out.reserve(out.size() + 12 * mesh.vertices.size() + 13 * mesh.faces.size());
    for (const Vec3& p : mesh.vertices) appendFloats(out, p);
    for (const Face& f : mesh.faces) {
      appendRaw(out, std::uint8_t{3});
      for (int v : f) appendRaw(out, static_cast<std::int32_t>(v));
    }
    return out;
  }
  out.reserve(out.size() + 40 * mesh.vertices.size() + 25 * mesh.faces.size());
  for (const Vec3& p : mesh.vertices) {
    appendVec(out, p);
    out += '\n';
  }
  for (const Face& f : mesh.faces) {
    out += '3';
    for (int v : f) {
      out += ' ';
      appendNumber(out, static_cast<long long>(v));
    }
    out += '\n';
  }
  return out;
}

}  // namespace

std::optional<MeshFileFormat> meshFileFormatForPath(const std::filesystem::path& file)
{
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".stl") return MeshFileFormat::StlBinary;
  if (ext == ".obj") return MeshFileFormat::Obj;
  if (ext == ".ply") return MeshFileFormat::PlyBinary;
  return std::nullopt;
}

std::string encodeMesh(const TriangleMesh& mesh, MeshFileFormat format, std::string_view name)
{
  checkIndices(mesh);
  switch (format) {
    case MeshFileFormat::StlBinary:
      return stlBinary(mesh, name);
    case MeshFileFormat::StlAscii:
      return stlAscii(mesh, name);
    case MeshFileFormat::Obj:
      return obj(mesh, name);
    case MeshFileFormat::PlyAscii:
      return ply(mesh, false);
    case MeshFileFormat::PlyBinary:
      return ply(mesh, true);
  }
  throw InternalError("unknown mesh file format");
}

void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& file, MeshFileFormat format)
{
  writeFileAtomically(file, encodeMesh(mesh, format, file.stem().string()));
}

void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& file)
{
  const auto format = meshFileFormatForPath(file);
  if (!format)
    throw InputError("cannot tell the mesh format of '" + file.string() + "' from its extension",
                     "name the file .stl, .obj or .ply");
  writeMesh(mesh, file, *format);
}

}  // namespace spira
