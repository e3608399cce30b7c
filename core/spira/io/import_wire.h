#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "spira/base/progress.h"
#include "spira/plugin/importer.h"

// The stream an isolated importer (the spira-import helper) sends to the process that started
// it: a header, then progress, warnings and finally either the mesh or an error. Every frame is
// a tag byte, a 64-bit little-endian payload length and the payload; the reader checks the
// header, every length and every count against the bytes that carry it.
namespace spira::wire {

enum class ErrorKind : char { Input = 'I', Io = 'O', Algorithm = 'A', Internal = 'N', Memory = 'M' };

struct RemoteError {
  ErrorKind kind = ErrorKind::Internal;
  std::string what;
  std::string hint;
};

class Writer {
 public:
  explicit Writer(int fd) : fd_(fd) {}
  void header();
  void progress(double fraction, std::string_view stage);
  void warning(const std::string& text);
  void mesh(const ImportedMesh& mesh);
  void error(ErrorKind kind, const std::string& what, const std::string& hint);

 private:
  void frame(char tag, const std::string& payload);
  int fd_;
};

// Parses the frames as they arrive. Throws InternalError on a stream no Writer produced.
class Reader {
 public:
  // Appends `n` bytes and handles every frame they complete; progress goes to `progress`.
  void feed(const char* data, size_t n, Progress& progress);
  // True when the stream ended on a frame boundary after a result or an error.
  bool complete() const { return pending_.empty() && (mesh_ || error_); }
  std::optional<ImportedMesh>& mesh() { return mesh_; }
  const std::optional<RemoteError>& error() const { return error_; }

 private:
  void handle(char tag, std::string_view payload, Progress& progress);
  std::string pending_;
  bool header_ = false;
  std::vector<std::string> warnings_;
  std::optional<ImportedMesh> mesh_;
  std::optional<RemoteError> error_;
};

}  // namespace spira::wire
