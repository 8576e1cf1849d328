#include "tb/gcode/line_source.h"

#include <utility>

#include "tb/base/args.h"

namespace hwinterp::gcode {

LineSource::LineSource(std::istream& in, std::string name, size_t max_chars)
    : in_(in), name_(std::move(name)), max_chars_(max_chars) {}

bool LineSource::next(std::string& line) {
  line.clear();
  std::streambuf* buf = in_.rdbuf();
  if (buf == nullptr) return false;
  bool any = false;
  for (;;) {
    const auto c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      if (!any) return false;
      break;
    }
    if (!any) ++line_;
    any = true;
    if (c == '\n') break;
    // One character of slack for the '\r' of a CRLF line, removed below.
    if (line.size() >= max_chars_ + 1)
      fail("line longer than " + std::to_string(max_chars_) + " characters");
    line.push_back(static_cast<char>(c));
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.size() > max_chars_)
    fail("line longer than " + std::to_string(max_chars_) + " characters");
  return true;
}

bool LineSource::skip() {
  std::streambuf* buf = in_.rdbuf();
  if (buf == nullptr) return false;
  bool any = false;
  for (;;) {
    const auto c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) return any;
    if (!any) ++line_;
    any = true;
    if (c == '\n') return true;
  }
}

std::string LineSource::where() const { return name_ + ":" + std::to_string(line_); }

void LineSource::fail(const std::string& what) const {
  throw cli::UsageError(where() + ": " + what);
}

std::string excerpt(const std::string& text, size_t max) {
  if (text.size() <= max) return text;
  return text.substr(0, max) + "...";
}

}  // namespace hwinterp::gcode
