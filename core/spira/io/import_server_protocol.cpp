#include "spira/io/import_server_protocol.h"

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace spira::import_server {
namespace {

constexpr size_t kMaxMessage = 64 * 1024;
constexpr size_t kMaxFds = 4;

}  // namespace

int highDescriptor(int fd)
{
  if (fd < 0) return -1;
  const int high = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
  ::close(fd);
  return high;
}

bool send(int socket, const nlohmann::json& body, const std::vector<int>& fds)
{
  const std::string text = body.dump();
  if (text.size() > kMaxMessage || fds.size() > kMaxFds) return false;
  iovec io{const_cast<char*>(text.data()), text.size()};
  msghdr msg{};
  msg.msg_iov = &io;
  msg.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(kMaxFds * sizeof(int))] = {};
  if (!fds.empty()) {
    msg.msg_control = control;
    msg.msg_controllen = CMSG_SPACE(fds.size() * sizeof(int));
    cmsghdr* c = CMSG_FIRSTHDR(&msg);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SCM_RIGHTS;
    c->cmsg_len = CMSG_LEN(fds.size() * sizeof(int));
    std::memcpy(CMSG_DATA(c), fds.data(), fds.size() * sizeof(int));
  }
  ssize_t n;
  while ((n = ::sendmsg(socket, &msg, MSG_NOSIGNAL)) < 0 && errno == EINTR) {
  }
  return n == static_cast<ssize_t>(text.size());
}

std::optional<Message> receive(int socket)
{
  std::string text(kMaxMessage, '\0');
  iovec io{text.data(), text.size()};
  msghdr msg{};
  msg.msg_iov = &io;
  msg.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(kMaxFds * sizeof(int))] = {};
  msg.msg_control = control;
  msg.msg_controllen = sizeof(control);
  ssize_t n;
  while ((n = ::recvmsg(socket, &msg, MSG_CMSG_CLOEXEC)) < 0 && errno == EINTR) {
  }
  Message out;
  for (cmsghdr* c = CMSG_FIRSTHDR(&msg); n >= 0 && c; c = CMSG_NXTHDR(&msg, c)) {
    if (c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_RIGHTS) continue;
    const size_t count = (c->cmsg_len - CMSG_LEN(0)) / sizeof(int);
    for (size_t i = 0; i < count; ++i) {
      int fd = -1;
      std::memcpy(&fd, CMSG_DATA(c) + i * sizeof(int), sizeof(int));
      out.fds.push_back(highDescriptor(fd));
    }
  }
  const auto refuse = [&out]() -> std::optional<Message> {
    for (int fd : out.fds)
      if (fd >= 0) ::close(fd);
    return std::nullopt;
  };
  if (n <= 0 || (msg.msg_flags & (MSG_TRUNC | MSG_CTRUNC))) return refuse();
  for (int fd : out.fds)
    if (fd < 0) return refuse();
  text.resize(static_cast<size_t>(n));
  out.body = nlohmann::json::parse(text, nullptr, false);
  if (!out.body.is_object()) return refuse();
  return out;
}

}  // namespace spira::import_server
