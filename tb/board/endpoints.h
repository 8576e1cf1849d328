// Where a simulated board meets its host, on this machine only: a UDP socket
// on 127.0.0.1 (Etherbone, as the board's Ethernet port) or a pseudo
// terminal (the UART, as the board's USB serial port). Both non-blocking:
// the simulation polls them between clocks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hwinterp::board {

class UdpEndpoint {
 public:
  // Binds 127.0.0.1:port (0: a free port). Throws std::runtime_error.
  explicit UdpEndpoint(uint16_t port);
  ~UdpEndpoint();
  UdpEndpoint(const UdpEndpoint&) = delete;
  UdpEndpoint& operator=(const UdpEndpoint&) = delete;

  uint16_t port() const { return port_; }
  std::string uri() const { return "udp:127.0.0.1:" + std::to_string(port_); }
  // One datagram if one waits; its sender becomes the peer replies go to.
  bool receive(std::vector<uint8_t>& datagram, uint16_t& peer_port);
  // To the last sender (dropped if none yet).
  void send(const std::vector<uint8_t>& datagram);

 private:
  int fd_ = -1;
  uint16_t port_ = 0;
  bool have_peer_ = false;
  uint32_t peer_ip_ = 0;
  uint16_t peer_port_ = 0;
};

class PtyEndpoint {
 public:
  // Opens a pseudo terminal in raw mode. Throws std::runtime_error.
  PtyEndpoint();
  ~PtyEndpoint();
  PtyEndpoint(const PtyEndpoint&) = delete;
  PtyEndpoint& operator=(const PtyEndpoint&) = delete;

  const std::string& path() const { return path_; }  // what the host opens
  // Bytes the host wrote (appended); false when none wait.
  bool receive(std::vector<uint8_t>& bytes);
  void send(const std::vector<uint8_t>& bytes);

 private:
  int master_ = -1;
  int slave_ = -1;  // kept open, so that the master never reads EIO between hosts
  std::string path_;
};

}  // namespace hwinterp::board
