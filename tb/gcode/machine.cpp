#include "tb/gcode/machine.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/base/args.h"
#include "tb/gcode/line_source.h"

namespace hwinterp::gcode {

namespace {

using nlohmann::json;

constexpr size_t kMaxFileBytes = 1 << 20;
constexpr int kMaxDepth = 8;

class Reader {
 public:
  explicit Reader(const std::string& name) : name_(name) {}

  [[noreturn]] void fail(const std::string& key, const json& value, const std::string& why) const {
    throw cli::UsageError(name_ + ": " + key + " = " + excerpt(value.dump(), 40) + ": " + why);
  }

  int64_t integer(const std::string& key, const json& v, int64_t lo, int64_t hi) const {
    const std::string range = "outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!v.is_number()) fail(key, v, "not a number");
    if (v.is_number_float()) {
      const double d = v.get<double>();
      if (std::floor(d) != d) fail(key, v, "not an integer");
      if (d < static_cast<double>(lo) || d > static_cast<double>(hi)) fail(key, v, range);
      return static_cast<int64_t>(d);
    }
    if (v.is_number_unsigned()) {
      const uint64_t u = v.get<uint64_t>();
      if (u > static_cast<uint64_t>(hi) || static_cast<int64_t>(u) < lo) fail(key, v, range);
      return static_cast<int64_t>(u);
    }
    const int64_t n = v.get<int64_t>();
    if (n < lo || n > hi) fail(key, v, range);
    return n;
  }

  double positive(const std::string& key, const json& v, double hi) const {
    if (!v.is_number()) fail(key, v, "not a number");
    const double d = v.get<double>();
    if (!(d > 0 && d <= hi)) fail(key, v, "outside (0, " + json(hi).dump() + "]");
    return d;
  }

  int axis(const std::string& key, const std::string& letter, const json& shown) const {
    const std::string names = kAxisNames;
    if (letter.size() != 1 || names.find(letter[0]) == std::string::npos)
      fail(key, shown, "not an axis (one of X Y Z A B C)");
    return static_cast<int>(names.find(letter[0]));
  }

  // An object {"X": value, ...} over axes the machine has: read(key.X, value, axis).
  template <class Read>
  void per_axis(const std::string& key, const json& value, const Machine& m, const char* what,
                Read read) const {
    if (!value.is_object())
      fail(key, value, std::string("not an object {\"X\": ") + what + ", ...}");
    for (const auto& [letter, v] : value.items()) {
      const std::string k = key + "." + letter;
      const int i = axis(k, letter, v);
      if (!m.has_axis[i])
        fail(k, v, "the machine has no " + letter + " axis (axes " + m.axes() + ")");
      read(k, v, i);
    }
  }

 private:
  std::string name_;
};

// Parses, refusing repeated keys and deep nesting (the callback sees every
// key before its value).
json parse(const std::string& text, const std::string& name) {
  std::vector<std::set<std::string>> keys;
  std::vector<std::string> path;  // the key being read at each level
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    if (depth > kMaxDepth)
      throw cli::UsageError(name + ": nested deeper than " + std::to_string(kMaxDepth) + " levels");
    if (event == json::parse_event_t::object_start) {
      keys.emplace_back();
      path.emplace_back();
    }
    if (event == json::parse_event_t::object_end && !keys.empty()) {
      keys.pop_back();
      path.pop_back();
    }
    if (event == json::parse_event_t::key && !keys.empty()) {
      const std::string k = parsed.get<std::string>();
      if (!keys.back().insert(k).second)
        throw cli::UsageError(name + ": key '" + excerpt(k, 40) + "' given twice");
      path.back() = k;
    }
    return true;
  };
  try {
    return json::parse(text, check);
  } catch (const json::parse_error& e) {
    // nlohmann's message has the line and column.
    throw cli::UsageError(name + ": not a JSON machine description: " + e.what());
  } catch (const json::exception& e) {
    // A value the parser cannot hold (a number beyond a double: 1e999): the
    // key being read, and the value's line and column.
    std::string key;
    for (const std::string& k : path)
      if (!k.empty()) key += (key.empty() ? "" : ".") + k;
    std::string where;
    const std::string what = e.what();
    const size_t q = what.find('\'');
    const size_t q2 = q == std::string::npos ? q : what.find('\'', q + 1);
    if (q2 != std::string::npos) {
      const size_t at = text.find(what.substr(q + 1, q2 - q - 1));
      if (at != std::string::npos) {
        const size_t line_start = text.rfind('\n', at);
        where = " (line " + std::to_string(1 + std::count(text.begin(), text.begin() + at, '\n')) +
                ", column " +
                std::to_string(at - (line_start == std::string::npos ? 0 : line_start + 1) + 1) +
                ")";
      }
    }
    throw cli::UsageError(name + ": " + (key.empty() ? "a value" : key) + where + ": " + what);
  }
}

}  // namespace

std::string Machine::axes() const {
  std::string s;
  for (int a = 0; a < kAxes; ++a)
    if (has_axis[a]) s += kAxisNames[a];
  return s;
}

Machine read_machine(std::istream& in, const std::string& name) {
  std::string text;
  char buf[4096];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxFileBytes)
      throw cli::UsageError(name + ": larger than " + std::to_string(kMaxFileBytes) + " bytes");
  }
  const json doc = parse(text, name);
  const Reader r(name);
  if (!doc.is_object()) r.fail("the file", doc, "not a JSON object");

  Machine m;
  // The axes first: steps_per_unit may only name axes the machine has.
  if (const auto it = doc.find("axes"); it != doc.end()) {
    if (!it->is_array() || it->empty()) r.fail("axes", *it, "not a non-empty list of axis names");
    m.has_axis.fill(false);
    for (const json& a : *it) {
      if (!a.is_string()) r.fail("axes", a, "not an axis name (\"X\" ... \"C\")");
      const int i = r.axis("axes", a.get<std::string>(), a);
      if (m.has_axis[i]) r.fail("axes", a, "listed twice");
      m.has_axis[i] = true;
    }
  }
  for (const auto& [key, value] : doc.items()) {
    if (key == "comment") {
      if (!value.is_string()) r.fail(key, value, "not a string");
    } else if (key == "axes") {
      // read above
    } else if (key == "steps_per_unit") {
      r.per_axis(key, value, m, "steps", [&](const std::string& k, const json& v, int i) {
        m.steps_per_unit[i] = r.integer(k, v, 1, 10'000'000);
      });
    } else if (key == "clock_hz") {
      m.clock_hz = r.integer(key, value, 1, 10'000'000'000);
    } else if (key == "rapid_mm_per_min") {
      m.rapid_mm_per_min = r.positive(key, value, 1e7);
    } else if (key == "timing_clocks") {
      if (!value.is_object()) r.fail(key, value, "not an object {\"step_len\": clocks, ...}");
      for (const auto& [field, clocks] : value.items()) {
        const std::string k = "timing_clocks." + field;
        int64_t* slot = field == "step_len"     ? &m.timing.step_len
                        : field == "step_space" ? &m.timing.step_space
                        : field == "dir_setup"  ? &m.timing.dir_setup
                        : field == "dir_hold"   ? &m.timing.dir_hold
                                                : nullptr;
        if (slot == nullptr)
          r.fail(k, clocks, "unknown key (step_len, step_space, dir_setup, dir_hold)");
        *slot = r.integer(k, clocks, 1, 65535);
      }
    } else if (key == "travel") {
      r.per_axis(key, value, m, "[min, max]", [&](const std::string& k, const json& v, int i) {
        if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
          r.fail(k, v, "not [min, max] (two numbers)");
        const double lo = v[0].get<double>(), hi = v[1].get<double>();
        if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) r.fail(k, v, "not min < max");
        m.travel[i] = {lo, hi};
      });
    } else if (key == "max_velocity" || key == "max_accel" || key == "max_jerk") {
      // (a pointer to the member: a lambda may not name a structured binding in C++17)
      double AxisLimits::*slot = key == "max_velocity" ? &AxisLimits::velocity
                                 : key == "max_accel"  ? &AxisLimits::accel
                                                       : &AxisLimits::jerk;
      r.per_axis(key, value, m, "a limit", [&](const std::string& k, const json& v, int i) {
        m.limits[i].*slot = r.positive(k, v, 1e12);
      });
    } else if (key == "profile") {
      if (!value.is_string()) r.fail(key, value, "not \"scurve\", \"trapezoid\" or \"off\"");
      m.profile = parse_profile(value.get<std::string>(), name + ": profile");
    } else {
      r.fail(key, value,
             "unknown key (comment, axes, steps_per_unit, clock_hz, rapid_mm_per_min, "
             "timing_clocks, travel, max_velocity, max_accel, max_jerk, profile)");
    }
  }
  return m;
}

const char* profile_name(ProfileKind k) {
  return k == ProfileKind::kScurve ? "scurve" : k == ProfileKind::kTrapezoid ? "trapezoid" : "off";
}

ProfileKind parse_profile(const std::string& text, const std::string& what) {
  for (ProfileKind k : {ProfileKind::kOff, ProfileKind::kScurve, ProfileKind::kTrapezoid})
    if (text == profile_name(k)) return k;
  throw cli::UsageError(what + ": '" + text + "' is not scurve, trapezoid or off");
}

Machine load_machine(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw cli::UsageError("--machine: cannot open '" + path + "'");
  return read_machine(in, path);
}

}  // namespace hwinterp::gcode
