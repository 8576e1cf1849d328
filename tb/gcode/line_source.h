// Reads a text stream one line at a time for the program readers, with the
// file name and line number every error message starts with.
//
// Contract: next() returns one line without its '\n' (and without a '\r'
// before it), or false at the end of the stream. A line longer than the
// limit ends the read with cli::UsageError, so a line never costs more than
// the limit in memory, whatever the input holds. fail() throws
// cli::UsageError("FILE:LINE: what") for the line last read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>

namespace hwinterp::gcode {

class LineSource {
 public:
  LineSource(std::istream& in, std::string name, size_t max_chars);

  bool next(std::string& line);
  // Consumes one line of any length without keeping it; false at the end.
  bool skip();
  uint64_t line_number() const { return line_; }  // of the line last read (0 before any)
  const std::string& name() const { return name_; }

  // "FILE:LINE: what" as cli::UsageError.
  [[noreturn]] void fail(const std::string& what) const;
  std::string where() const;  // "FILE:LINE"

 private:
  std::istream& in_;
  std::string name_;
  size_t max_chars_;
  uint64_t line_ = 0;
};

// `text` shortened to at most `max` characters for an error message
// ("abc..." when cut).
std::string excerpt(const std::string& text, size_t max = 60);

}  // namespace hwinterp::gcode
