// A simulated board's host link, between its endpoint on this machine and
// its wire (tb/board/wires.h), with the faults a test asks for
// (tb/board/faults.h):
//
//   EthLink   the UDP socket on 127.0.0.1 <-> Ethernet frames. It plays the
//             host's network card: each datagram from the host becomes a
//             frame from 192.168.1.100 (MAC 02:00:00:00:00:01) to the board's
//             address and port; it answers the board's ARP requests for that
//             address; the board's UDP frames go back to the host as
//             datagrams; a frame from the board with a bad FCS or headers is
//             counted (a gateware fault: the run fails).
//   UartLink  the pseudo terminal <-> the UART's bytes.
//
// Both: poll() moves what the endpoint has into the wire and what the wire
// delivered out to the endpoint (between clocks, every few hundred); the
// per-clock work is the wire's.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "tb/base/json.h"
#include "tb/board/endpoints.h"
#include "tb/board/ethernet.h"
#include "tb/board/faults.h"
#include "tb/board/wires.h"

namespace hwinterp::board {

// The board's side of the network (the gateware's defaults:
// boards/hwinterp_litex/link.py add_etherbone_link).
struct EthAddresses {
  Station board{{0x10, 0xE2, 0xD5, 0x00, 0x00, 0x00}, 0xC0A80132};  // 192.168.1.50
  uint16_t board_port = 1234;
  Station host{{0x02, 0x00, 0x00, 0x00, 0x00, 0x01}, 0xC0A80164};  // 192.168.1.100
};

class EthLink {
 public:
  EthLink(uint16_t port, const FaultSpec& to_board, const FaultSpec& to_host, uint64_t seed,
          EthAddresses a = {});

  std::string uri() const { return endpoint_.uri(); }
  EthWire& wire() { return wire_; }
  // Frames the wire delivered since the last poll, then the endpoint.
  void poll(uint64_t clock);
  bool busy() const { return !wire_.idle() || !held_to_board_.empty(); }
  Json stats() const;
  uint64_t board_bad_frames() const { return board_bad_frames_; }
  std::vector<Bytes>& delivered() { return delivered_; }

 private:
  void to_board(Bytes frame, bool is_udp);
  void to_host(const Bytes& payload);

  UdpEndpoint endpoint_;
  EthAddresses a_;
  EthWire wire_;
  FaultInjector board_faults_, host_faults_;  // to the board, to the host
  FaultCounts to_board_faults_, to_host_faults_;
  std::vector<Bytes> delivered_;                          // the wire's finished frames
  std::deque<std::pair<Bytes, uint64_t>> held_to_board_;  // reordered: frame, clock held
  std::deque<Bytes> held_to_host_;
  uint16_t ip_id_ = 1;
  uint64_t datagrams_in_ = 0, datagrams_out_ = 0, arp_replies_ = 0, other_frames_ = 0;
  uint64_t board_bad_frames_ = 0;
  std::string first_bad_frame_;
};

class UartLink {
 public:
  UartLink(uint64_t clk_hz, uint64_t baud, const FaultSpec& to_board, const FaultSpec& to_host,
           uint64_t seed);

  std::string uri() const;
  UartWire& wire() { return wire_; }
  void poll();
  bool busy() const { return !wire_.idle(); }
  Json stats() const;
  std::vector<uint8_t>& delivered() { return delivered_; }

 private:
  PtyEndpoint endpoint_;
  UartWire wire_;
  uint64_t baud_;
  FaultInjector board_faults_, host_faults_;
  FaultCounts to_board_faults_, to_host_faults_;
  std::vector<uint8_t> delivered_;  // the wire's bytes from the board
  uint64_t bytes_in_ = 0, bytes_out_ = 0;
};

}  // namespace hwinterp::board
