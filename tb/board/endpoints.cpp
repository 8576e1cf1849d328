#include "tb/board/endpoints.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace hwinterp::board {

namespace {
[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error(what + ": " + std::strerror(errno));
}
}  // namespace

UdpEndpoint::UdpEndpoint(uint16_t port) {
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) fail("socket");
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(port);
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0)
    fail("bind 127.0.0.1:" + std::to_string(port));
  socklen_t n = sizeof a;
  if (::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &n) != 0) fail("getsockname");
  port_ = ntohs(a.sin_port);
}

UdpEndpoint::~UdpEndpoint() {
  if (fd_ >= 0) ::close(fd_);
}

bool UdpEndpoint::receive(std::vector<uint8_t>& datagram, uint16_t& peer_port) {
  uint8_t buf[65536];
  sockaddr_in from{};
  socklen_t n = sizeof from;
  const ssize_t got = ::recvfrom(fd_, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &n);
  if (got < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return false;
    fail("recvfrom");
  }
  datagram.assign(buf, buf + got);
  have_peer_ = true;
  peer_ip_ = from.sin_addr.s_addr;
  peer_port_ = from.sin_port;
  peer_port = ntohs(from.sin_port);
  return true;
}

void UdpEndpoint::send(const std::vector<uint8_t>& datagram) {
  if (!have_peer_) return;
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = peer_ip_;
  to.sin_port = peer_port_;
  // A host that went away (ECONNREFUSED) or a full buffer loses the reply,
  // as a network would.
  (void)::sendto(fd_, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&to),
                 sizeof to);
}

PtyEndpoint::PtyEndpoint() {
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (master_ < 0) fail("posix_openpt");
  if (::grantpt(master_) != 0 || ::unlockpt(master_) != 0) fail("grantpt/unlockpt");
  const char* name = ::ptsname(master_);
  if (!name) fail("ptsname");
  path_ = name;
  slave_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (slave_ < 0) fail("open " + path_);
  termios t{};
  if (::tcgetattr(slave_, &t) != 0) fail("tcgetattr " + path_);
  ::cfmakeraw(&t);
  if (::tcsetattr(slave_, TCSANOW, &t) != 0) fail("tcsetattr " + path_);
}

PtyEndpoint::~PtyEndpoint() {
  if (slave_ >= 0) ::close(slave_);
  if (master_ >= 0) ::close(master_);
}

bool PtyEndpoint::receive(std::vector<uint8_t>& bytes) {
  uint8_t buf[4096];
  const ssize_t got = ::read(master_, buf, sizeof buf);
  if (got <= 0) {
    if (got < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR && errno != EIO)
      fail("read " + path_);
    return false;
  }
  bytes.insert(bytes.end(), buf, buf + got);
  return true;
}

void PtyEndpoint::send(const std::vector<uint8_t>& bytes) {
  size_t at = 0;
  while (at < bytes.size()) {
    const ssize_t put = ::write(master_, bytes.data() + at, bytes.size() - at);
    if (put <= 0) {
      // Nobody reads (the buffer is full): the bytes are lost, as on a
      // serial line with nobody listening.
      if (put < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return;
      if (put < 0) fail("write " + path_);
      return;
    }
    at += static_cast<size_t>(put);
  }
}

}  // namespace hwinterp::board
