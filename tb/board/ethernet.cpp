#include "tb/board/ethernet.h"

namespace hwinterp::board {

namespace {

constexpr uint16_t kEtherIpv4 = 0x0800;
constexpr uint16_t kEtherArp = 0x0806;
constexpr size_t kMinFrame = 60;  // without the FCS

void put16(Bytes& b, uint16_t v) {
  b.push_back(static_cast<uint8_t>(v >> 8));
  b.push_back(static_cast<uint8_t>(v));
}
void put32(Bytes& b, uint32_t v) {
  put16(b, static_cast<uint16_t>(v >> 16));
  put16(b, static_cast<uint16_t>(v));
}
void put_mac(Bytes& b, const Mac& m) { b.insert(b.end(), m.begin(), m.end()); }
uint16_t get16(const Bytes& b, size_t at) { return static_cast<uint16_t>(b[at] << 8 | b[at + 1]); }
uint32_t get32(const Bytes& b, size_t at) {
  return static_cast<uint32_t>(get16(b, at)) << 16 | get16(b, at + 2);
}

// The Internet checksum (RFC 1071) of b[from, to), plus `sum`.
uint16_t inet_checksum(const Bytes& b, size_t from, size_t to, uint32_t sum = 0) {
  for (size_t i = from; i + 1 < to; i += 2) sum += get16(b, i);
  if ((to - from) % 2) sum += static_cast<uint32_t>(b[to - 1]) << 8;
  while (sum >> 16) sum = (sum & 0xFFFF) + (sum >> 16);
  return static_cast<uint16_t>(~sum);
}

}  // namespace

uint32_t crc32(const uint8_t* data, size_t n, uint32_t crc) {
  crc = ~crc;
  for (size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string ip_text(Ip4 ip) {
  return std::to_string(ip >> 24) + "." + std::to_string((ip >> 16) & 0xFF) + "." +
         std::to_string((ip >> 8) & 0xFF) + "." + std::to_string(ip & 0xFF);
}

Bytes wire_frame(const Bytes& frame) {
  Bytes body = frame;
  if (body.size() < kMinFrame) body.resize(kMinFrame, 0);
  Bytes w(7, 0x55);
  w.push_back(0xD5);
  w.insert(w.end(), body.begin(), body.end());
  const uint32_t fcs = crc32(body);
  for (int i = 0; i < 4; ++i) w.push_back(static_cast<uint8_t>(fcs >> (8 * i)));
  return w;
}

Bytes udp_frame(const Station& src, uint16_t src_port, const Station& dst, uint16_t dst_port,
                const Bytes& payload, uint16_t ip_id) {
  Bytes f;
  put_mac(f, dst.mac);
  put_mac(f, src.mac);
  put16(f, kEtherIpv4);
  const size_t ip = f.size();
  const auto udp_len = static_cast<uint16_t>(8 + payload.size());
  f.push_back(0x45);  // IPv4, 5 words of header
  f.push_back(0);
  put16(f, static_cast<uint16_t>(20 + udp_len));
  put16(f, ip_id);
  put16(f, 0x4000);  // don't fragment
  f.push_back(64);   // TTL
  f.push_back(17);   // UDP
  put16(f, 0);       // checksum, below
  put32(f, src.ip);
  put32(f, dst.ip);
  const uint16_t ip_sum = inet_checksum(f, ip, ip + 20);
  f[ip + 10] = static_cast<uint8_t>(ip_sum >> 8);
  f[ip + 11] = static_cast<uint8_t>(ip_sum);
  const size_t udp = f.size();
  put16(f, src_port);
  put16(f, dst_port);
  put16(f, udp_len);
  put16(f, 0);  // checksum, below
  f.insert(f.end(), payload.begin(), payload.end());
  // The pseudo-header: addresses, protocol, UDP length.
  const uint32_t pseudo =
      (src.ip >> 16) + (src.ip & 0xFFFF) + (dst.ip >> 16) + (dst.ip & 0xFFFF) + 17u + udp_len;
  uint16_t udp_sum = inet_checksum(f, udp, f.size(), pseudo);
  if (udp_sum == 0) udp_sum = 0xFFFF;
  f[udp + 6] = static_cast<uint8_t>(udp_sum >> 8);
  f[udp + 7] = static_cast<uint8_t>(udp_sum);
  return f;
}

Bytes arp_reply(const Station& from, const Station& to) {
  Bytes f;
  put_mac(f, to.mac);
  put_mac(f, from.mac);
  put16(f, kEtherArp);
  put16(f, 1);       // Ethernet
  put16(f, 0x0800);  // IPv4
  f.push_back(6);
  f.push_back(4);
  put16(f, 2);  // reply
  put_mac(f, from.mac);
  put32(f, from.ip);
  put_mac(f, to.mac);
  put32(f, to.ip);
  return f;
}

RxFrame parse_wire_frame(const Bytes& wire) {
  RxFrame r;
  size_t sfd = 0;
  while (sfd < wire.size() && wire[sfd] == 0x55) ++sfd;
  if (sfd == 0 || sfd >= wire.size() || wire[sfd] != 0xD5) {
    r.problem = "no preamble/SFD";
    return r;
  }
  const Bytes f(wire.begin() + static_cast<long>(sfd) + 1, wire.end());
  if (f.size() < kMinFrame + 4) {
    r.problem = "runt frame (" + std::to_string(f.size()) + " bytes)";
    return r;
  }
  const size_t body = f.size() - 4;
  uint32_t fcs = 0;
  for (int i = 0; i < 4; ++i)
    fcs |= static_cast<uint32_t>(f[body + static_cast<size_t>(i)]) << (8 * i);
  if (crc32(f.data(), body) != fcs) {
    r.problem = "bad FCS";
    return r;
  }
  for (int i = 0; i < 6; ++i) r.src_mac[static_cast<size_t>(i)] = f[6 + static_cast<size_t>(i)];
  const uint16_t type = get16(f, 12);
  if (type == kEtherArp) {
    if (get16(f, 20) != 1) {
      r.kind = RxFrame::Kind::kOther;
      return r;
    }
    r.kind = RxFrame::Kind::kArpRequest;
    r.src_ip = get32(f, 28);
    r.dst_ip = get32(f, 38);
    return r;
  }
  if (type != kEtherIpv4 || f[14] != 0x45 || f[23] != 17) {
    r.kind = RxFrame::Kind::kOther;
    return r;
  }
  if (inet_checksum(f, 14, 34) != 0) {
    r.problem = "bad IPv4 header checksum";
    return r;
  }
  const uint16_t total = get16(f, 16);
  const uint16_t udp_len = get16(f, 38);
  if (total < 28 || 14u + total > body || udp_len < 8 || udp_len > total - 20) {
    r.problem = "bad IPv4/UDP length";
    return r;
  }
  r.kind = RxFrame::Kind::kUdp;
  r.src_ip = get32(f, 26);
  r.dst_ip = get32(f, 30);
  r.src_port = get16(f, 34);
  r.dst_port = get16(f, 36);
  r.payload.assign(f.begin() + 42, f.begin() + 34 + udp_len);
  return r;
}

}  // namespace hwinterp::board
