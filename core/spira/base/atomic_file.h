#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace spira {

// Writes a whole file or nothing: data goes to a temporary file beside the target, which is
// flushed, synced and renamed over the target. A reader never sees a half-written file and a
// failure leaves the previous file untouched. Throws IoError with the reason.
void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

// Writes `bytes` to `path` (created or truncated), flushed and synced to disk. Returns the
// system's reason when it fails, empty on success; the caller decides what a failure means.
std::string writeSynced(const std::filesystem::path& path, std::string_view bytes);

// Writes all of `bytes` to the open descriptor `fd` (a file, a pipe), again after a signal cuts a
// write short. Returns the system's reason when it fails, empty on success.
std::string writeAll(int fd, std::string_view bytes);

// The system's reason for the last failed call (strerror(errno)), for messages.
std::string errnoText();

// Random hex digits for the name of a temporary file or folder beside the one it will replace.
std::string randomSuffix();

// Throws IoError unless `dir` exists (or can be created) and a file can be created in it.
// Call it before starting work whose output would otherwise be lost at the end.
void ensureWritableDirectory(const std::filesystem::path& dir);

// Throws IoError naming `path` unless it is a regular file once symbolic links are followed: a
// folder, a named pipe, a device or a socket is refused before anything opens it (a pipe would block
// the reader forever). Every file a user names goes through this check.
void requireRegularFile(const std::filesystem::path& path);

// Reads a whole file; throws IoError if it is missing, not a regular file or unreadable.
std::string readFile(const std::filesystem::path& path);

}  // namespace spira
