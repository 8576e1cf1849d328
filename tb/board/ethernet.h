// The Ethernet wire of a simulated board, seen from the host's network card:
// UDP datagrams from the host become Ethernet II frames (IPv4, UDP) with
// preamble, SFD and FCS, as a PHY puts them on the MAC's side; the board's
// frames are checked (preamble, FCS) and parsed back into ARP requests and
// UDP datagrams. Plain functions on byte vectors: no simulator here.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hwinterp::board {

using Bytes = std::vector<uint8_t>;
using Mac = std::array<uint8_t, 6>;

// CRC-32 of IEEE 802.3 (reflected, initial 0xFFFFFFFF, final XOR
// 0xFFFFFFFF): the Ethernet FCS and the UART link's frame check.
uint32_t crc32(const uint8_t* data, size_t n, uint32_t crc = 0);
inline uint32_t crc32(const Bytes& b) { return crc32(b.data(), b.size()); }

// An IPv4 address in host order (192.168.1.50 = 0xC0A80132).
using Ip4 = uint32_t;
std::string ip_text(Ip4 ip);

// One end of the simulated network: a MAC and an IPv4 address.
struct Station {
  Mac mac;
  Ip4 ip;
};

// Preamble (7 x 0x55), SFD (0xD5), the frame padded to 60 bytes, FCS
// (least significant byte first): what the MAC's receive path takes.
Bytes wire_frame(const Bytes& frame);

// An Ethernet II frame carrying `payload` in UDP from `src`:`src_port` to
// `dst`:`dst_port` (IPv4 header checksum and UDP checksum computed).
Bytes udp_frame(const Station& src, uint16_t src_port, const Station& dst, uint16_t dst_port,
                const Bytes& payload, uint16_t ip_id);

// An ARP reply from `from` to `to`.
Bytes arp_reply(const Station& from, const Station& to);

// A frame the board sent, as the host's card sees it.
struct RxFrame {
  enum class Kind { kBad, kArpRequest, kUdp, kOther } kind = Kind::kBad;
  std::string problem;  // kBad: what was wrong (preamble, FCS, length)
  Mac src_mac{};
  Ip4 src_ip = 0, dst_ip = 0;  // kArpRequest: sender and target; kUdp: source and destination
  uint16_t src_port = 0, dst_port = 0;
  Bytes payload;  // kUdp
};

// Checks preamble, SFD and FCS of `wire` (as wire_frame makes them) and
// parses the frame.
RxFrame parse_wire_frame(const Bytes& wire);

}  // namespace hwinterp::board
