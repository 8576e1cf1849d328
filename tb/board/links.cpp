#include "tb/board/links.h"

namespace hwinterp::board {

namespace {
// Preamble + SFD (8) and the Ethernet, IPv4 and UDP headers (42): where a
// wire frame's UDP payload starts.
constexpr size_t kWirePayload = 8 + 42;
// A reordered frame waits for the next one at most this many clocks.
constexpr uint64_t kReorderHold = 200000;
}  // namespace

EthLink::EthLink(uint16_t port, const FaultSpec& to_board, const FaultSpec& to_host, uint64_t seed,
                 EthAddresses a)
    : endpoint_(port), a_(a), board_faults_(to_board, seed), host_faults_(to_host, seed + 1) {}

void EthLink::to_board(Bytes frame, bool is_udp) {
  Bytes w = wire_frame(frame);
  if (!is_udp || !board_faults_.spec().any()) {
    wire_.send(std::move(w));
    return;
  }
  const FaultAction f = board_faults_.next(to_board_faults_);
  if (f.drop) return;
  if (f.corrupt) {
    // One bit of the UDP payload, after the FCS was computed: the MAC sees a
    // bad FCS; the frame dropper must keep its writes from running.
    const size_t payload = w.size() - kWirePayload - 4;
    const size_t at = kWirePayload + board_faults_.below(payload);
    w[at] ^= static_cast<uint8_t>(1u << board_faults_.below(8));
  }
  const int copies = f.dup ? 2 : 1;
  for (int i = 0; i < copies; ++i) {
    if (f.reorder)
      held_to_board_.emplace_back(w, 0);
    else
      wire_.send(w);
  }
}

void EthLink::to_host(const Bytes& payload) {
  if (!host_faults_.spec().any()) {
    endpoint_.send(payload);
    return;
  }
  const FaultAction f = host_faults_.next(to_host_faults_);
  // A corrupted frame fails the host card's FCS check: it is lost.
  if (f.drop || f.corrupt) return;
  const int copies = f.dup ? 2 : 1;
  for (int i = 0; i < copies; ++i) {
    if (f.reorder)
      held_to_host_.push_back(payload);
    else
      endpoint_.send(payload);
  }
  if (!f.reorder)
    while (!held_to_host_.empty()) {
      endpoint_.send(held_to_host_.front());
      held_to_host_.pop_front();
    }
}

void EthLink::poll(uint64_t clock) {
  for (Bytes& w : delivered_) {
    const RxFrame r = parse_wire_frame(w);
    switch (r.kind) {
      case RxFrame::Kind::kBad:
        if (board_bad_frames_++ == 0) first_bad_frame_ = r.problem;
        break;
      case RxFrame::Kind::kArpRequest:
        if (r.dst_ip == a_.host.ip) {
          ++arp_replies_;
          Station board{r.src_mac, r.src_ip};
          to_board(arp_reply(a_.host, board), false);
        }
        break;
      case RxFrame::Kind::kUdp:
        if (r.dst_ip == a_.host.ip) {
          ++datagrams_out_;
          to_host(r.payload);
        } else {
          ++other_frames_;
        }
        break;
      case RxFrame::Kind::kOther:
        ++other_frames_;
        break;
    }
  }
  delivered_.clear();
  Bytes d;
  uint16_t peer_port = 0;
  while (endpoint_.receive(d, peer_port)) {
    ++datagrams_in_;
    const size_t held = held_to_board_.size();
    to_board(udp_frame(a_.host, peer_port, a_.board, a_.board_port, d, ip_id_++), true);
    // A frame held back goes after the next one that is not.
    if (held_to_board_.size() == held)
      while (!held_to_board_.empty()) {
        wire_.send(held_to_board_.front().first);
        held_to_board_.pop_front();
      }
  }
  // ... or when nothing follows it for a while.
  for (auto& h : held_to_board_)
    if (h.second == 0) h.second = clock;
  while (!held_to_board_.empty() && clock - held_to_board_.front().second > kReorderHold) {
    wire_.send(held_to_board_.front().first);
    held_to_board_.pop_front();
  }
}

Json EthLink::stats() const {
  return Json{{"uri", uri()},
              {"datagrams_from_host", datagrams_in_},
              {"datagrams_to_host", datagrams_out_},
              {"arp_replies", arp_replies_},
              {"other_frames_from_board", other_frames_},
              {"bad_frames_from_board", board_bad_frames_},
              {"first_bad_frame", board_bad_frames_ ? Json(first_bad_frame_) : Json(nullptr)},
              {"faults_to_board", to_board_faults_.to_json()},
              {"faults_to_host", to_host_faults_.to_json()}};
}

UartLink::UartLink(uint64_t clk_hz, uint64_t baud, const FaultSpec& to_board,
                   const FaultSpec& to_host, uint64_t seed)
    : wire_(clk_hz, baud),
      baud_(baud),
      board_faults_(to_board, seed),
      host_faults_(to_host, seed + 1) {}

std::string UartLink::uri() const {
  return "serial:" + endpoint_.path() + "@" + std::to_string(baud_);
}

void UartLink::poll() {
  std::vector<uint8_t> in;
  endpoint_.receive(in);
  for (uint8_t b : in) {
    ++bytes_in_;
    if (!board_faults_.spec().any()) {
      wire_.send(b);
      continue;
    }
    const FaultAction f = board_faults_.next(to_board_faults_);
    if (f.drop) continue;
    if (f.corrupt) b ^= static_cast<uint8_t>(1u << board_faults_.below(8));
    wire_.send(b);
    if (f.dup) wire_.send(b);
  }
  if (delivered_.empty()) return;
  std::vector<uint8_t> out;
  for (uint8_t b : delivered_) {
    ++bytes_out_;
    if (!host_faults_.spec().any()) {
      out.push_back(b);
      continue;
    }
    const FaultAction f = host_faults_.next(to_host_faults_);
    if (f.drop) continue;
    if (f.corrupt) b ^= static_cast<uint8_t>(1u << host_faults_.below(8));
    out.push_back(b);
    if (f.dup) out.push_back(b);
  }
  delivered_.clear();
  endpoint_.send(out);
}

Json UartLink::stats() const {
  return Json{{"uri", uri()},
              {"bytes_from_host", bytes_in_},
              {"bytes_to_host", bytes_out_},
              {"framing_errors_from_board", wire_.framing_errors()},
              {"faults_to_board", to_board_faults_.to_json()},
              {"faults_to_host", to_host_faults_.to_json()}};
}

}  // namespace hwinterp::board
