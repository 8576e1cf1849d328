#include "tb/report/vcd_writer.h"

#include <map>
#include <sstream>
#include <stdexcept>

namespace hwinterp::tb {

VcdWriter::VcdWriter(const std::string& path) : path_(path), out_(path) {
  if (!out_) throw std::runtime_error("cannot write trace '" + path + "'");
}

int VcdWriter::add(const std::string& scope, const std::string& name, int width) {
  if (begun_) throw std::logic_error("VcdWriter::add after begin");
  if (width < 1 || width > 64) throw std::logic_error("VcdWriter: width must be 1..64");
  // Identifier codes: base-94 over the printable characters '!'..'~'.
  std::string code;
  size_t n = signals_.size();
  do {
    code += static_cast<char>('!' + n % 94);
    n /= 94;
  } while (n);
  signals_.push_back({scope, name, code, width, 0, false});
  return static_cast<int>(signals_.size() - 1);
}

void VcdWriter::begin(const std::string& timescale) {
  out_ << "$version hwinterp cosim $end\n$timescale " << timescale << " $end\n";
  // Group by scope; nested scopes from dotted names.
  std::map<std::string, std::vector<const Signal*>> by_scope;
  for (const auto& s : signals_) by_scope[s.scope].push_back(&s);
  for (const auto& [scope, sigs] : by_scope) {
    std::vector<std::string> parts;
    std::stringstream ss(scope);
    for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
    for (const auto& p : parts) out_ << "$scope module " << p << " $end\n";
    for (const Signal* s : sigs)
      out_ << "$var wire " << s->width << ' ' << s->code << ' ' << s->name
           << (s->width > 1 ? " [" + std::to_string(s->width - 1) + ":0]" : "") << " $end\n";
    for (size_t i = 0; i < parts.size(); ++i) out_ << "$upscope $end\n";
  }
  out_ << "$enddefinitions $end\n";
  begun_ = true;
}

void VcdWriter::at(uint64_t time) {
  if (time != time_ || !time_written_) {
    time_ = time;
    time_written_ = false;
  }
}

void VcdWriter::set(int id, uint64_t value) {
  Signal& s = signals_[static_cast<size_t>(id)];
  if (s.width < 64) value &= (uint64_t{1} << s.width) - 1;
  if (s.written && s.value == value) return;
  if (!time_written_) {
    out_ << '#' << time_ << '\n';
    time_written_ = true;
  }
  s.value = value;
  s.written = true;
  if (s.width == 1) {
    out_ << (value ? '1' : '0') << s.code << '\n';
    return;
  }
  std::string bits;
  for (int b = s.width - 1; b >= 0; --b) bits += ((value >> b) & 1) ? '1' : '0';
  const size_t first_one = bits.find('1');
  out_ << 'b' << (first_one == std::string::npos ? "0" : bits.substr(first_one)) << ' ' << s.code
       << '\n';
}

void VcdWriter::close() {
  if (out_.is_open()) {
    out_.close();
    if (!out_) throw std::runtime_error("error writing trace '" + path_ + "'");
  }
}

}  // namespace hwinterp::tb
