#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

enum class MeshFileFormat { StlBinary, StlAscii, Obj, PlyAscii, PlyBinary };

// The format a file name's extension asks for: .stl -> binary STL, .obj -> OBJ, .ply -> binary
// PLY (case-insensitive); nullopt for anything else.
std::optional<MeshFileFormat> meshFileFormatForPath(const std::filesystem::path& file);

// The file's bytes. Coordinates are written in millimetres as they are in the mesh. Binary STL
// and binary PLY store 32-bit floats (what the formats and every reader expect); ASCII formats
// write the shortest text that reads back to the same double.
std::string encodeMesh(const TriangleMesh& mesh, MeshFileFormat format, std::string_view name = "spira");

// Writes the mesh through writeFileAtomically (the target is replaced whole or not at all).
// Throws IoError when the file cannot be written and InputError when the mesh cannot be stored
// in the format (binary STL holds at most 2^32 - 1 triangles).
void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& file, MeshFileFormat format);
// Same, with the format taken from the extension; throws InputError for an unknown extension.
void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& file);

}  // namespace spira
