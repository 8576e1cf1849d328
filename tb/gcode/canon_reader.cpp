#include "tb/gcode/canon_reader.h"

#include <cmath>
#include <cstdlib>
#include <utility>

namespace hwinterp::gcode {

namespace {

constexpr double kMaxValue = 1e9;
const char* const kBanner = "executing";  // what rs274 writes to stderr first

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_char(char c) { return (c >= 'A' && c <= 'Z') || c == '_' || is_digit(c); }

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(' ');
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

std::vector<std::string> split_args(const std::string& text) {
  std::vector<std::string> out;
  if (trim(text).empty()) return out;
  size_t from = 0;
  for (;;) {
    const size_t comma = text.find(',', from);
    out.push_back(trim(text.substr(from, comma == std::string::npos ? comma : comma - from)));
    if (comma == std::string::npos) return out;
    from = comma + 1;
  }
}

// A plain decimal as rs274 prints it: [-]digits[.digits].
bool plain_decimal(const std::string& t, bool allow_fraction) {
  size_t i = (!t.empty() && t[0] == '-') ? 1 : 0;
  size_t digits = 0;
  while (i < t.size() && is_digit(t[i])) ++i, ++digits;
  if (digits == 0) return false;
  if (i < t.size() && t[i] == '.' && allow_fraction) {
    ++i;
    size_t frac = 0;
    while (i < t.size() && is_digit(t[i])) ++i, ++frac;
    if (frac == 0) return false;
  }
  return i == t.size();
}

}  // namespace

CanonReader::CanonReader(std::istream& in, std::string name)
    : src_(in, std::move(name), kMaxLineChars) {}

bool CanonReader::next(Move& m) {
  std::string line;
  while (src_.next(line)) {
    ++stats_.lines;
    if (run_line(line, m)) {
      m.stop_before = stop_pending_;
      stop_pending_ = false;
      stats_.count(m);
      return true;
    }
  }
  return false;
}

double CanonReader::number(const std::string& text, const std::string& what) const {
  if (!plain_decimal(text, true))
    src_.fail(what + ": '" + excerpt(text, 30) + "' is not a number in " + shown_);
  const double v = std::strtod(text.c_str(), nullptr);
  if (!(std::fabs(v) <= kMaxValue))
    src_.fail(what + ": '" + excerpt(text, 30) + "' is beyond +-1e9 in " + shown_);
  return v;
}

void CanonReader::position(const std::vector<std::string>& args, size_t first, size_t count,
                           const std::string& cmd, Move& m) const {
  // count: 3 (A B C) or 6 (A B C U V W) values from args[first].
  static const char* kNames[] = {"A", "B", "C", "U", "V", "W"};
  for (size_t n = 0; n < count; ++n) {
    const double v = number(args[first + n], cmd + " " + kNames[n]);
    if (n < 3) {
      m.end[kA + n] = v;
    } else if (v != 0) {
      src_.fail(cmd + ": the " + kNames[n] + " axis is not supported (" + args[first + n] +
                ") in " + shown_);
    }
  }
}

bool CanonReader::run_line(const std::string& line, Move& m) {
  shown_ = "'" + excerpt(line, 80) + "'";
  const std::string t = trim(line);
  if (t.empty()) return false;
  if (t == kBanner) {
    ++stats_.ignored_commands[kBanner];
    return false;
  }
  const auto bad = [&](const std::string& why) {
    src_.fail("not a canonical command (" + why + "): " + shown_);
  };

  // "   12 N..... NAME(args)"
  size_t i = line.find_first_not_of(' ');
  const size_t num_begin = i;
  while (i < line.size() && is_digit(line[i])) ++i;
  if (i == num_begin || i - num_begin > 18) bad("no line number");
  const uint64_t canon_line = std::strtoull(line.c_str() + num_begin, nullptr, 10);
  if (i >= line.size() || line[i] != ' ') bad("no space after the line number");
  while (i < line.size() && line[i] == ' ') ++i;
  if (i >= line.size() || line[i] != 'N') bad("no N field");
  ++i;
  if (line.compare(i, 5, ".....") == 0) {
    i += 5;
  } else {
    while (i < line.size() && is_digit(line[i])) ++i;
  }
  while (i < line.size() && line[i] == ' ') ++i;
  const size_t name_begin = i;
  while (i < line.size() && is_name_char(line[i])) ++i;
  if (i == name_begin || is_digit(line[name_begin])) bad("no command name");
  const std::string cmd = line.substr(name_begin, i - name_begin);
  if (i >= line.size() || line[i] != '(') bad("no '(' after " + cmd);
  const size_t close = line.rfind(')');
  if (close == std::string::npos || close < i) bad("no ')'");
  const std::string tail = trim(line.substr(close + 1));
  if (tail == kBanner) {
    ++stats_.ignored_commands[kBanner];
  } else if (!tail.empty()) {
    bad("text after ')'");
  }
  const std::string arg_text = line.substr(i + 1, close - i - 1);

  const auto args_of = [&](std::initializer_list<size_t> counts) {
    std::vector<std::string> args = split_args(arg_text);
    for (const size_t c : counts)
      if (args.size() == c) return args;
    std::string allowed;
    for (const size_t c : counts) allowed += (allowed.empty() ? "" : " or ") + std::to_string(c);
    src_.fail(cmd + " with " + std::to_string(args.size()) + " arguments (" + allowed +
              " expected) in " + shown_);
  };
  const double k = inch_ ? kMmPerInch : 1.0;

  if (cmd == "STRAIGHT_TRAVERSE" || cmd == "STRAIGHT_FEED") {
    const auto args = args_of({6, 9});
    m = Move{};
    m.kind = cmd == "STRAIGHT_FEED" ? MoveKind::kFeed : MoveKind::kTraverse;
    for (int a = kX; a <= kZ; ++a) m.end[a] = k * number(args[a], cmd + " " + kAxisNames[a]);
    position(args, 3, args.size() - 3, cmd, m);
  } else if (cmd == "ARC_FEED") {
    const auto args = args_of({9, 12});
    m = Move{};
    m.kind = MoveKind::kArc;
    const PlaneAxes pa = plane_axes(plane_);
    m.end[pa.first] = k * number(args[0], "ARC_FEED first_end");
    m.end[pa.second] = k * number(args[1], "ARC_FEED second_end");
    m.center[0] = k * number(args[2], "ARC_FEED first_axis");
    m.center[1] = k * number(args[3], "ARC_FEED second_axis");
    if (!plain_decimal(args[4], false) || args[4].size() > 11)
      src_.fail("ARC_FEED rotation: '" + excerpt(args[4], 30) + "' is not an integer in " + shown_);
    const long long rot = std::strtoll(args[4].c_str(), nullptr, 10);
    if (rot == 0 || rot > 1000000000LL || rot < -1000000000LL)
      src_.fail("ARC_FEED rotation: " + args[4] + " (a non-zero count of turns) in " + shown_);
    m.rotation = static_cast<int>(rot);
    m.end[pa.third] = k * number(args[5], "ARC_FEED axis_end_point");
    position(args, 6, args.size() - 6, cmd, m);
  } else if (cmd == "SET_FEED_RATE") {
    const double f = number(args_of({1})[0], cmd);
    if (f < 0) src_.fail("SET_FEED_RATE: a negative feed in " + shown_);
    feed_mm_ = k * f;
    return false;
  } else if (cmd == "USE_LENGTH_UNITS") {
    const std::string u = args_of({1})[0];
    if (u == "CANON_UNITS_MM") {
      inch_ = false;
    } else if (u == "CANON_UNITS_INCHES") {
      inch_ = true;
    } else {
      src_.fail("USE_LENGTH_UNITS: unknown units '" + excerpt(u, 30) + "' in " + shown_);
    }
    return false;
  } else if (cmd == "SELECT_PLANE") {
    const std::string p = args_of({1})[0];
    if (p == "CANON_PLANE_XY") {
      plane_ = Plane::kXY;
    } else if (p == "CANON_PLANE_YZ") {
      plane_ = Plane::kYZ;
    } else if (p == "CANON_PLANE_XZ") {
      plane_ = Plane::kXZ;
    } else {
      src_.fail("SELECT_PLANE: unsupported plane '" + excerpt(p, 30) + "' in " + shown_);
    }
    return false;
  } else {
    if (cmd == "STRAIGHT_PROBE" || cmd == "RIGID_TAP" || cmd.rfind("NURBS_", 0) == 0 ||
        cmd.rfind("SPLINE_", 0) == 0)
      src_.fail(cmd +
                " moves the tool and is not read here (only STRAIGHT_TRAVERSE, "
                "STRAIGHT_FEED and ARC_FEED are) in " +
                shown_);
    if (cmd == "SET_FEED_MODE") {
      const auto args = split_args(arg_text);
      if (args.empty() || !plain_decimal(args.back(), false))
        src_.fail("SET_FEED_MODE: unreadable arguments in " + shown_);
      if (args.back() != "0")
        src_.fail("SET_FEED_MODE: only units per minute (mode 0) is read here, not " + args.back() +
                  ", in " + shown_);
    }
    if (cmd == "SET_G5X_OFFSET" || cmd == "SET_G92_OFFSET" || cmd == "SET_XY_ROTATION") {
      const auto args = split_args(arg_text);
      // SET_G5X_OFFSET's first argument is the coordinate system's index.
      for (size_t n = cmd == "SET_G5X_OFFSET" ? 1 : 0; n < args.size(); ++n)
        if (number(args[n], cmd) != 0)
          src_.fail(cmd + " with a non-zero value (" + args[n] +
                    ") would shift the path; moves are read in program coordinates, in " + shown_);
    }
    if (cmd == "PROGRAM_STOP" || cmd == "OPTIONAL_PROGRAM_STOP") stop_pending_ = true;
    ++stats_.ignored_commands[cmd];
    return false;
  }
  m.plane = plane_;
  m.feed = feed_mm_;
  m.line = canon_line;
  return true;
}

}  // namespace hwinterp::gcode
