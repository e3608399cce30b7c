#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// What a Wavefront OBJ holds for Spira: every 'v' vertex in file order and the 'f' faces as
// triangles (polygons fan-triangulated from their first corner, in file order). Texture
// coordinates, normals, groups, materials, lines, points and free-form geometry are read past.
struct ObjData {
  TriangleMesh mesh;
  size_t polygonFaces = 0;       // faces with more than three corners, split into triangles
  size_t degenerateFaces = 0;    // faces with fewer than three corners, dropped
  size_t unknownStatements = 0;  // statements whose keyword Spira does not know, ignored
  // Sentences for the user naming the file: polygons split, faces dropped, statements ignored.
  std::vector<std::string> warnings;
};

// Parses OBJ text: `v x y z [w ...]`, `f` with corners `v`, `v/vt`, `v//vn` or `v/vt/vn` (negative
// indices count back from the last vertex read so far), comments, backslash continuation lines,
// CRLF and tabs. Memory grows with the bytes read, never with a number found in them. `source`
// names the file in messages. Throws InputError naming the line and the offending text for binary
// data, a malformed or non-finite number, a vertex with fewer than three coordinates, a corner
// that is 0 or names a vertex not defined above it, and a file without faces; throws Cancelled.
ObjData parseObj(std::string_view bytes, const std::string& source, Progress& progress);

// Maps (or reads) the whole file once and parses it. Throws IoError when it cannot be read.
ObjData readObj(const std::filesystem::path& file, Progress& progress);

}  // namespace spira
