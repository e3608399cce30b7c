#include "spira/base/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "spira/base/error.h"

namespace fs = std::filesystem;

namespace spira {
namespace {

fs::path temporarySibling(const fs::path& target)
{
  return target.parent_path() / ("." + target.filename().string() + ".tmp" + randomSuffix());
}

}  // namespace

std::string errnoText()
{
  return std::strerror(errno);
}

std::string randomSuffix()
{
  std::random_device rd;
  std::ostringstream s;
  s << std::hex << rd() << rd();
  return s.str();
}

std::string writeAll(int fd, std::string_view bytes)
{
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errnoText();
    if (n == 0) return "nothing could be written";
    done += static_cast<size_t>(n);
  }
  return {};
}

std::string writeSynced(const fs::path& path, std::string_view bytes)
{
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return errnoText();
  if (const std::string why = writeAll(fd, bytes); !why.empty()) {
    ::close(fd);
    return why;
  }
  if (::fsync(fd) != 0) {
    const std::string why = errnoText();
    ::close(fd);
    return why;
  }
  if (::close(fd) != 0) return errnoText();
  return {};
}

void writeFileAtomically(const fs::path& target, std::string_view bytes)
{
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw IoError("cannot write '" + target.string() + "': folder '" + dir.string() + "' does not exist",
                  "create the folder or choose another output path");
  const fs::path tmp = temporarySibling(dir / target.filename());
  if (const std::string why = writeSynced(tmp, bytes); !why.empty()) {
    fs::remove(tmp, ec);
    throw IoError("cannot write '" + target.string() + "': " + why,
                  "check that the folder is writable and the disk is not full");
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw IoError("cannot replace '" + target.string() + "': " + ec.message(),
                  "check that the file is not read-only");
  }
}

void ensureWritableDirectory(const fs::path& dir)
{
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    fs::create_directories(dir, ec);
    if (ec)
      throw IoError("cannot create output folder '" + dir.string() + "': " + ec.message(),
                    "choose a folder you can write to");
  }
  if (!fs::is_directory(dir, ec))
    throw IoError("output path '" + dir.string() + "' is not a folder", "choose a folder");
  const fs::path probe = temporarySibling(dir / ".spira-write-probe");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0)
    throw IoError("cannot write into output folder '" + dir.string() + "': " + errnoText(),
                  "choose a folder you can write to");
  ::close(fd);
  fs::remove(probe, ec);
}

void requireRegularFile(const fs::path& path)
{
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw IoError("file '" + path.string() + "' does not exist", "check the path");
  if (fs::is_directory(status))
    throw IoError("'" + path.string() + "' is a folder, not a file", "give a file");
  if (!fs::is_regular_file(status))
    throw IoError("'" + path.string() + "' is not a regular file (it is a named pipe, a device or a socket)",
                  "give a file saved on disk");
}

std::string readFile(const fs::path& path)
{
  requireRegularFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open '" + path.string() + "' for reading", "check the file's permissions");
  std::string data;
  in.seekg(0, std::ios::end);
  const auto size = in.tellg();
  if (size > 0) {
    data.resize(static_cast<size_t>(size));
    in.seekg(0);
    in.read(data.data(), size);
  }
  if (!in) throw IoError("cannot read '" + path.string() + "'", "check the file");
  return data;
}

}  // namespace spira
