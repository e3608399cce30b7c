#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// What an STL holds: a triangle soup. Vertices 3i, 3i+1 and 3i+2 are the corners of face i, so
// faces[i] == {3i, 3i+1, 3i+2}; welding is left to the caller. Stored normals are ignored (the
// corner order defines the orientation, as every CAD exporter writes it).
struct StlData {
  TriangleMesh soup;
  bool binary = false;
  std::string name;          // the ASCII solid name or the binary header text, trimmed
  size_t polygonFacets = 0;  // ASCII facets with more than three vertices, fan-triangulated
};

// Parses STL bytes. Binary and ASCII are told apart by the size a binary file must have
// (84 + 50 * count), so binary files whose header starts with "solid" read correctly.
// `source` names the file in messages. Throws InputError (empty, truncated, malformed; the
// message gives sizes or the line number) and Cancelled.
StlData parseStl(std::string_view bytes, const std::string& source, Progress& progress);

// Maps (or reads) the whole file once and parses it. Throws IoError when it cannot be read.
StlData readStl(const std::filesystem::path& file, Progress& progress);

}  // namespace spira
