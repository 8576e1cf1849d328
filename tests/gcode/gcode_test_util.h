// Helpers for the G-code reader tests: run a program held in a string
// through a reader, and check a refusal's message.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tb/base/args.h"
#include "tb/gcode/canon_reader.h"
#include "tb/gcode/ngc_reader.h"

namespace hwinterp::gcode::test {

struct Run {
  std::vector<Move> moves;
  ReaderStats stats;
};

template <class Reader>
Run read_all(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  Reader r(in, name);
  Run out;
  Move m;
  while (r.next(m)) out.moves.push_back(m);
  out.stats = r.stats();
  return out;
}

inline Run ngc(const std::string& text) { return read_all<NgcReader>(text, "t.ngc"); }
inline Run canon(const std::string& text) { return read_all<CanonReader>(text, "t.canon"); }

// The cli::UsageError message `read` throws, or "" when it throws none.
template <class F>
std::string error_of(F&& read) {
  try {
    read();
  } catch (const cli::UsageError& e) {
    return e.what();
  }
  return "";
}

inline std::string ngc_error(const std::string& text) {
  return error_of([&] { ngc(text); });
}
inline std::string canon_error(const std::string& text) {
  return error_of([&] { canon(text); });
}

// Every `parts` is in `message`, which is one line.
inline ::testing::AssertionResult mentions(const std::string& message,
                                           const std::vector<std::string>& parts) {
  if (message.empty()) return ::testing::AssertionFailure() << "no UsageError was thrown";
  if (message.find('\n') != std::string::npos)
    return ::testing::AssertionFailure() << "not one line: " << message;
  for (const auto& p : parts)
    if (message.find(p) == std::string::npos)
      return ::testing::AssertionFailure() << "'" << p << "' not in: " << message;
  return ::testing::AssertionSuccess();
}

// A test-name-safe form of `text` (letters, digits and '_').
inline std::string test_name(size_t index, const std::string& text) {
  std::string out = std::to_string(index) + "_";
  for (const char c : text) {
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) {
      out += c;
    } else if (c == '.' || c == '-') {
      out += c == '.' ? 'p' : 'm';
    } else if (out.back() != '_') {
      out += '_';
    }
  }
  return out;
}

}  // namespace hwinterp::gcode::test
