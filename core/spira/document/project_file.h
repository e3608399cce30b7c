#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "spira/document/document_state.h"

namespace spira {

// The .spira project file: one self-contained binary file.
//
//   offset  size  content
//   0       8     magic "SPIRAPRJ"
//   8       4     format version, uint32 little-endian (kProjectFormatVersion)
//   12      8     payload size n, uint64 little-endian
//   20      n     payload: CBOR (RFC 8949) of the project JSON
//   20+n    4     CRC-32 (IEEE 802.3, as zlib) of the payload, uint32 little-endian
//
// The payload holds the writing Spira version and, per section (part, substrate, cell, plan,
// results), a schema number for future migrations. Meshes and numeric arrays are binary blobs
// of little-endian doubles / int32, so a round trip is bit-for-bit.
constexpr std::uint32_t kProjectFormatVersion = 1;
constexpr std::string_view kProjectMagic = "SPIRAPRJ";
constexpr const char* kProjectExtension = ".spira";

// The complete file contents for `state`, for a project file in `projectDir`: the cell's files are
// also stored relative to it (empty: not stored).
std::string encodeProject(const DocumentState& state, const std::filesystem::path& projectDir = {});
// Parses file contents; throws InputError (not a Spira project, newer format, truncated or
// damaged, malformed content). The cell's files are looked for relative to `projectDir` first,
// at their absolute paths when not there (or when `projectDir` is empty).
DocumentState decodeProject(std::string_view bytes, const std::filesystem::path& projectDir = {});

// Writes atomically (the previous file survives any failure); throws IoError.
void saveProject(const DocumentState& state, const std::filesystem::path& path);
// Throws IoError (unreadable) or InputError (see decodeProject); returns a new state only.
DocumentState loadProject(const std::filesystem::path& path);

std::uint32_t crc32(std::string_view bytes);

}  // namespace spira
