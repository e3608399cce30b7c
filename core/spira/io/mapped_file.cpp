#include "spira/io/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "spira/base/atomic_file.h"

namespace spira {
namespace {

// Below this size a plain read is as fast and needs no mapping.
constexpr off_t kMapThreshold = 1 << 20;

}  // namespace

MappedFile::MappedFile(const std::filesystem::path& file)
{
  requireRegularFile(file);
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size >= kMapThreshold) {
    void* p = ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (p != MAP_FAILED) {
      map_ = p;
      mapSize_ = static_cast<size_t>(st.st_size);
      view_ = std::string_view(static_cast<const char*>(p), mapSize_);
    }
  }
  if (fd >= 0) ::close(fd);
  if (!map_) {
    copy_ = readFile(file);  // also produces the IoError for missing or unreadable files
    view_ = copy_;
  }
}

MappedFile::~MappedFile()
{
  if (map_) ::munmap(map_, mapSize_);
}

}  // namespace spira
