// The wires of a simulated board's links, clock by clock.
//
// EthWire: the byte-wide wire at the MAC's side of the PHY (the gateware's
// PHY model: one byte a clock while valid, a frame ends on the first clock
// without valid). Frames for the board are queued whole (wire_frame: preamble
// to FCS) and put on the wire with a 12-clock gap; the board's bytes are
// gathered into frames.
//
// UartWire: 8N1 at `baud` on a `clk_hz` clock, bit boundaries placed exactly
// (a phase accumulator: each bit lasts clk_hz / baud clocks on average, the
// fraction spread); the board's TX pin is sampled in the middle of each bit,
// a byte whose stop bit is low is counted as a framing error and dropped.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "tb/board/ethernet.h"

namespace hwinterp::board {

class EthWire {
 public:
  static constexpr int kGap = 12;  // idle clocks between frames (the IFG)

  void send(Bytes wire) { queue_.push_back(std::move(wire)); }
  bool idle() const { return queue_.empty() && at_ == 0; }

  // The byte for the coming clock edge: valid and data.
  void drive(bool& valid, uint8_t& data) {
    if (gap_ > 0) {
      --gap_;
      valid = false;
      return;
    }
    if (queue_.empty()) {
      valid = false;
      return;
    }
    const Bytes& f = queue_.front();
    valid = true;
    data = f[at_++];
    if (at_ == f.size()) {
      queue_.pop_front();
      at_ = 0;
      gap_ = kGap;
    }
  }
  // The board's pins after the edge; a frame that ended is appended to `out`.
  void observe(bool valid, uint8_t data, std::vector<Bytes>& out) {
    if (valid) {
      rx_.push_back(data);
    } else if (!rx_.empty()) {
      out.push_back(std::move(rx_));
      rx_.clear();
    }
  }

 private:
  std::deque<Bytes> queue_;
  size_t at_ = 0;
  int gap_ = 0;
  Bytes rx_;
};

class UartWire {
 public:
  UartWire(uint64_t clk_hz, uint64_t baud) : clk_hz_(clk_hz), baud_(baud) {}

  void send(uint8_t b) { queue_.push_back(b); }
  bool idle() const { return queue_.empty() && tx_bit_ < 0; }

  // The level of the board's RX pin for the coming clock edge.
  bool drive() {
    if (tx_bit_ < 0) {
      if (queue_.empty()) return true;
      tx_byte_ = queue_.front();
      queue_.pop_front();
      tx_bit_ = 0;
      tx_acc_ = 0;
    }
    const bool level = tx_bit_ == 0   ? false
                       : tx_bit_ <= 8 ? ((tx_byte_ >> (tx_bit_ - 1)) & 1)
                                      : true;
    tx_acc_ += baud_;
    if (tx_acc_ >= clk_hz_) {
      tx_acc_ -= clk_hz_;
      if (++tx_bit_ == 10) tx_bit_ = -1;
    }
    return level;
  }
  // The board's TX pin after the edge; a byte received is appended to `out`.
  void observe(bool tx, std::vector<uint8_t>& out) {
    if (rx_bit_ < 0) {
      if (!tx && last_tx_) {  // a start bit's falling edge
        rx_bit_ = 0;
        rx_acc_ = clk_hz_ / 2;  // the first sample half a bit in
        rx_byte_ = 0;
      }
      last_tx_ = tx;
      return;
    }
    last_tx_ = tx;
    rx_acc_ += baud_;
    if (rx_acc_ < clk_hz_) return;
    rx_acc_ -= clk_hz_;
    // The middle of bit rx_bit_.
    if (rx_bit_ == 0) {
      if (tx)
        rx_bit_ = -1;  // a glitch, not a start bit
      else
        rx_bit_ = 1;
      return;
    }
    if (rx_bit_ <= 8) {
      rx_byte_ = static_cast<uint8_t>(rx_byte_ | (tx ? 1 : 0) << (rx_bit_ - 1));
      ++rx_bit_;
      return;
    }
    if (tx)
      out.push_back(rx_byte_);
    else
      ++framing_errors_;
    rx_bit_ = -1;
  }
  uint64_t framing_errors() const { return framing_errors_; }

 private:
  uint64_t clk_hz_, baud_;
  std::deque<uint8_t> queue_;
  int tx_bit_ = -1;  // -1 idle, 0 start, 1..8 data, 9 stop
  uint8_t tx_byte_ = 0;
  uint64_t tx_acc_ = 0;
  int rx_bit_ = -1;
  uint8_t rx_byte_ = 0;
  uint64_t rx_acc_ = 0;
  bool last_tx_ = true;
  uint64_t framing_errors_ = 0;
};

}  // namespace hwinterp::board
