#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

// The messages between a Spira process and its warm import server (`spira-import --serve`, see
// import_process.h): one JSON object per datagram of a SOCK_SEQPACKET socket pair, with file
// descriptors passed alongside.
//
//   client -> server  {"importer","file","params","memory","cpu"} + the result and log pipes
//   server -> client  {"pid"} + a pidfd of the forked importer, or {"error"}
//   server -> client  {"status","maxrss"} once the importer has ended and been reaped
namespace spira::import_server {

struct Message {
  nlohmann::json body;
  std::vector<int> fds;  // received descriptors are close-on-exec and numbered 10 or above
};

// False when the peer is gone.
bool send(int socket, const nlohmann::json& body, const std::vector<int>& fds = {});
// Nothing when the peer is gone or sent something that is not a message.
std::optional<Message> receive(int socket);

// Moves `fd` to a close-on-exec descriptor numbered 10 or above (closing `fd`), so that dup2 onto
// 0 to 3 cannot overwrite one still to be copied. -1 when out of descriptors.
int highDescriptor(int fd);

}  // namespace spira::import_server
