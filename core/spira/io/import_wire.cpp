#include "spira/io/import_wire.h"

#include <unistd.h>

#include <cstring>
#include <limits>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"

namespace spira::wire {
namespace {

constexpr std::string_view kMagic = "SPIRA-IMPORT/1";
constexpr char kHeader = 'H', kProgress = 'P', kWarning = 'W', kMesh = 'M', kError = 'E';
constexpr uint8_t kNoUnit = 0xFF;
constexpr size_t kFrameHead = 9;

template <class T>
void put(std::string& out, T v)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  out.append(bytes, sizeof(T));
}

void putString(std::string& out, std::string_view s)
{
  put<uint64_t>(out, s.size());
  out.append(s);
}

uint8_t unitCode(const std::optional<LengthUnit>& u)
{
  return u ? static_cast<uint8_t>(*u) : kNoUnit;
}

[[noreturn]] void malformed(const std::string& why)
{
  throw InternalError("the import helper sent a malformed result: " + why,
                      "please report this with the file");
}

// Reads fields from one frame's payload, never past its end.
class Cursor {
 public:
  explicit Cursor(std::string_view p) : p_(p) {}
  template <class T>
  T get()
  {
    need(sizeof(T));
    T v;
    std::memcpy(&v, p_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::string getString()
  {
    const auto n = get<uint64_t>();
    need(n);
    std::string s(p_.substr(at_, n));
    at_ += n;
    return s;
  }
  size_t left() const { return p_.size() - at_; }
  const char* here() const { return p_.data() + at_; }
  void skip(size_t n)
  {
    need(n);
    at_ += n;
  }
  void end() const
  {
    if (left() != 0) malformed(std::to_string(left()) + " stray bytes in a frame");
  }

 private:
  void need(uint64_t n) const
  {
    if (n > left()) malformed("a frame is shorter than its fields");
  }
  std::string_view p_;
  size_t at_ = 0;
};

std::optional<LengthUnit> unitFrom(uint8_t code)
{
  if (code == kNoUnit) return std::nullopt;
  if (code > static_cast<uint8_t>(LengthUnit::Micrometre)) malformed("unknown unit " + std::to_string(code));
  return static_cast<LengthUnit>(code);
}

}  // namespace

void Writer::frame(char tag, const std::string& payload)
{
  std::string bytes;
  bytes.reserve(kFrameHead + payload.size());
  bytes.push_back(tag);
  put<uint64_t>(bytes, payload.size());
  bytes.append(payload);
  if (!writeAll(fd_, bytes).empty())
    throw IoError("the import helper cannot write its result", "the program that started it stopped");
}

void Writer::header()
{
  frame(kHeader, std::string(kMagic));
}

void Writer::progress(double fraction, std::string_view stage)
{
  std::string p;
  put<double>(p, fraction);
  putString(p, stage);
  frame(kProgress, p);
}

void Writer::warning(const std::string& text)
{
  std::string p;
  putString(p, text);
  frame(kWarning, p);
}

void Writer::mesh(const ImportedMesh& m)
{
  std::string p;
  p.reserve(18 + m.mesh.vertices.size() * 24 + m.mesh.faces.size() * 12);
  p.push_back(static_cast<char>(unitCode(m.unit)));
  p.push_back(static_cast<char>(unitCode(m.fileUnit)));
  put<uint64_t>(p, m.mesh.vertices.size());
  put<uint64_t>(p, m.mesh.faces.size());
  for (const Vec3& v : m.mesh.vertices)
    for (int k = 0; k < 3; ++k) put<double>(p, v[k]);
  for (const Face& f : m.mesh.faces)
    for (int k = 0; k < 3; ++k) put<int32_t>(p, f[k]);
  for (const std::string& w : m.warnings) warning(w);
  frame(kMesh, p);
}

void Writer::error(ErrorKind kind, const std::string& what, const std::string& hint)
{
  std::string p;
  p.push_back(static_cast<char>(kind));
  putString(p, what);
  putString(p, hint);
  frame(kError, p);
}

void Reader::feed(const char* data, size_t n, Progress& progress)
{
  pending_.append(data, n);
  size_t at = 0;
  while (pending_.size() - at >= kFrameHead) {
    const char tag = pending_[at];
    uint64_t length = 0;
    std::memcpy(&length, pending_.data() + at + 1, sizeof length);
    if (!header_ && (tag != kHeader || length != kMagic.size())) malformed("no 'SPIRA-IMPORT/1' header");
    if (length > std::numeric_limits<size_t>::max() - kFrameHead - at) malformed("a frame length overflows");
    if (pending_.size() - at - kFrameHead < length) break;
    handle(tag, std::string_view(pending_).substr(at + kFrameHead, length), progress);
    at += kFrameHead + length;
  }
  pending_.erase(0, at);
}

void Reader::handle(char tag, std::string_view payload, Progress& progress)
{
  if (!header_) {
    if (tag != kHeader || payload != kMagic) malformed("no 'SPIRA-IMPORT/1' header");
    header_ = true;
    return;
  }
  if (mesh_ || error_) malformed("a frame after the result");
  Cursor c(payload);
  switch (tag) {
    case kProgress: {
      const double fraction = c.get<double>();
      const std::string stage = c.getString();
      c.end();
      if (!(fraction >= 0.0 && fraction <= 1.0)) malformed("progress outside [0, 1]");
      progress.report(fraction, stage);
      return;
    }
    case kWarning:
      warnings_.push_back(c.getString());
      c.end();
      return;
    case kError: {
      RemoteError e;
      e.kind = static_cast<ErrorKind>(c.get<char>());
      if (std::string_view("IOANM").find(static_cast<char>(e.kind)) == std::string_view::npos)
        malformed("unknown error kind");
      e.what = c.getString();
      e.hint = c.getString();
      c.end();
      error_ = std::move(e);
      return;
    }
    case kMesh: {
      ImportedMesh m;
      m.unit = unitFrom(c.get<uint8_t>());
      m.fileUnit = unitFrom(c.get<uint8_t>());
      const auto nv = c.get<uint64_t>();
      const auto nf = c.get<uint64_t>();
      if (nv > c.left() / 24 || nf > (c.left() - nv * 24) / 12 || c.left() != nv * 24 + nf * 12)
        malformed(std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces do not fill " +
                  std::to_string(c.left()) + " bytes");
      m.mesh.vertices.resize(nv);
      for (Vec3& v : m.mesh.vertices)
        for (int k = 0; k < 3; ++k) v[k] = c.get<double>();
      m.mesh.faces.resize(nf);
      for (Face& f : m.mesh.faces)
        for (int k = 0; k < 3; ++k) f[k] = c.get<int32_t>();
      c.end();
      m.warnings = std::move(warnings_);
      mesh_ = std::move(m);
      return;
    }
    default:
      malformed(std::string("unknown frame '") + tag + "'");
  }
}

}  // namespace spira::wire
