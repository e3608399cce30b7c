#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "spira/base/progress.h"
#include "spira/io/ply_header.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// What a PLY holds for Spira: the vertices in file order and the faces as triangles (polygons
// fan-triangulated from their first corner, in file order). Other vertex properties and other
// elements are read past and dropped.
struct PlyData {
  TriangleMesh mesh;
  // Per vertex, the vertex element's nx, ny, nz when it has all three (as scanners write them), else empty.
  std::vector<Vec3> normals;
  PlyEncoding encoding = PlyEncoding::Ascii;
  size_t polygonFaces = 0;     // faces with more than three corners, split into triangles
  size_t degenerateFaces = 0;  // faces with fewer than three corners, dropped
  // Sentences for the user naming the file: polygons split, faces dropped, elements ignored,
  // bytes after the last element ignored.
  std::vector<std::string> warnings;
};

// Parses PLY bytes (ascii, binary_little_endian, binary_big_endian). The header's counts are
// checked against the bytes that follow it before anything is allocated. `source` names the file
// in messages. Throws InputError naming the line (header, ASCII body) or byte offset (binary body)
// for a malformed header, a body shorter or longer per item than the header declares, a truncated
// file, a corner index outside the vertex list, and a file without a vertex or face element;
// throws Cancelled.
PlyData parsePly(std::string_view bytes, const std::string& source, Progress& progress);

// Maps (or reads) the whole file once and parses it. Throws IoError when it cannot be read.
PlyData readPly(const std::filesystem::path& file, Progress& progress);

// The same for a point cloud (a scan): the vertices and their normals, any face element read past.
// A file without a vertex element, or with no vertex in it, is refused.
PlyData parsePlyPoints(std::string_view bytes, const std::string& source, Progress& progress);
PlyData readPlyPoints(const std::filesystem::path& file, Progress& progress);

}  // namespace spira
