#include "dda_line_frames.h"

#include <stdexcept>

namespace hwinterp::tb {

DdaLineFrameWriter::DdaLineFrameWriter(const std::string& path, const DdaLineLimits& limits)
    : path_(path), limits_(limits), out_(path) {
  if (!out_) throw std::runtime_error("cannot write frames '" + path + "'");
}

int DdaLineFrameWriter::frame_bits(const DdaLineLimits& l) {
  return 2 + l.axes * l.acc_w + (l.feed_w + 1) + 1 + 4 * l.tim_w;
}

void DdaLineFrameWriter::field(uint64_t value, int width) {
  for (int b = width - 1; b >= 0; --b) bits_ += ((value >> b) & 1) ? '1' : '0';
}

void DdaLineFrameWriter::write(const DdaLineFrame& f) {
  bits_.clear();
  field(f.rst_n, 1);
  field(f.cmd_valid, 1);
  for (int i = limits_.axes - 1; i >= 0; --i)
    field(static_cast<uint64_t>(f.cmd_delta[static_cast<size_t>(i)]), limits_.acc_w);
  field(f.feed, limits_.feed_w + 1);
  field(f.half_preload, 1);
  field(f.timing.step_len, limits_.tim_w);
  field(f.timing.step_space, limits_.tim_w);
  field(f.timing.dir_setup, limits_.tim_w);
  field(f.timing.dir_hold, limits_.tim_w);
  // Left-pad to whole hex digits, then four bits a digit.
  bits_.insert(0, (4 - bits_.size() % 4) % 4, '0');
  std::string hex;
  for (size_t i = 0; i < bits_.size(); i += 4) {
    const int nibble = (bits_[i] - '0') * 8 + (bits_[i + 1] - '0') * 4 + (bits_[i + 2] - '0') * 2 +
                       (bits_[i + 3] - '0');
    hex += "0123456789abcdef"[nibble];
  }
  out_ << hex << '\n';
}

void DdaLineFrameWriter::close() {
  if (!out_.is_open()) return;
  out_.close();
  if (!out_) throw std::runtime_error("error writing frames '" + path_ + "'");
}

}  // namespace hwinterp::tb
