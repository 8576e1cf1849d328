#include "dda_line_stimulus.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli_args.h"
#include "models/dda_line_model.h"
#include "rng.h"

namespace hwinterp::tb {

using cli::UsageError;

DdaLineSettings default_settings(const DdaLineLimits& limits) {
  DdaLineSettings s;
  s.feed = limits.full_feed();
  s.half_preload = false;
  s.timing = limits.default_timing;
  return s;
}

namespace {

std::string join(const std::vector<int64_t>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s;
}

// Pads leading-axis coordinates with zeros to the variant's axis count.
models::LatticePoint pad(const DdaLineLimits& limits, const std::vector<int64_t>& v,
                         const std::string& what) {
  if (v.empty() || static_cast<int>(v.size()) > limits.axes)
    throw UsageError(what + ": " + std::to_string(v.size()) + " coordinates given, " +
                     limits.variant + " has " + std::to_string(limits.axes) + " axes");
  models::LatticePoint p(static_cast<size_t>(limits.axes), 0);
  std::copy(v.begin(), v.end(), p.begin());
  return p;
}

DdaLineItem command(std::vector<int64_t> delta, int line = 0) {
  DdaLineItem it;
  it.kind = DdaLineItem::Kind::kCommand;
  it.delta = std::move(delta);
  it.source_line = line;
  return it;
}

}  // namespace

DdaLineCase line_case(const DdaLineLimits& limits, const std::string& name,
                      const std::vector<int64_t>& start, const std::vector<int64_t>& end,
                      const DdaLineSettings& settings) {
  if (start.size() != end.size())
    throw UsageError("line '" + name + "': start " + join(start) + " and end " + join(end) +
                     " have different axis counts");
  DdaLineCase c;
  c.name = name;
  c.start = pad(limits, start, "line '" + name + "'");
  const models::LatticePoint e = pad(limits, end, "line '" + name + "'");
  std::vector<int64_t> delta(c.start.size());
  for (size_t i = 0; i < delta.size(); ++i) delta[i] = e[i] - c.start[i];
  c.settings = settings;
  c.items.push_back(command(delta));
  return c;
}

std::vector<DdaLineCase> paper_lines_004(const DdaLineLimits& limits,
                                         const DdaLineSettings& settings) {
  // 004_dc68f1177cad466f.txt, section 4.1: Line 1 .. Line 8.
  static const int64_t kLines[8][4] = {{0, 0, 20, 40},     {10, 10, 40, 20},     {10, -10, 40, -20},
                                       {-10, 10, -40, 20}, {-10, -10, -40, -40}, {-10, -5, 30, 20},
                                       {7, -2, -32, -38},  {-10, 20, 30, 20}};
  std::vector<DdaLineCase> cases;
  for (int i = 0; i < 8; ++i) {
    const auto& l = kLines[i];
    cases.push_back(line_case(limits, "004_line" + std::to_string(i + 1), {l[0], l[1]},
                              {l[2], l[3]}, settings));
  }
  return cases;
}

namespace {

StepdirTiming random_timing(Rng& rng) {
  auto one = [&] {
    // Mostly short (fast runs, many stalls), sometimes long.
    return static_cast<uint32_t>(rng.chance(1, 8) ? rng.range(5, 16) : rng.range(0, 4));
  };
  StepdirTiming t;
  t.step_len = one();
  t.step_space = one();
  t.dir_setup = one();
  t.dir_hold = one();
  return t;
}

uint64_t random_feed(Rng& rng, const DdaLineLimits& limits) {
  const int64_t full = static_cast<int64_t>(limits.full_feed());
  const uint64_t pick = rng.below(10);
  if (pick < 4) return static_cast<uint64_t>(full);  // full feed
  if (pick < 5)
    return static_cast<uint64_t>(full + rng.range(1, full - 1));  // above full: still full
  if (pick < 8) return static_cast<uint64_t>(rng.range(full / 4, full - 1));
  return static_cast<uint64_t>(rng.range(full / 16, full / 4 - 1));  // slow
}

DdaLineSettings random_settings(Rng& rng, const DdaLineLimits& limits) {
  DdaLineSettings s;
  s.feed = random_feed(rng, limits);
  s.half_preload = rng.chance(1, 2);
  s.timing = random_timing(rng);
  return s;
}

int64_t random_magnitude(Rng& rng) {
  switch (rng.below(8)) {
    case 0:
    case 1:
      return rng.range(0, 3);
    case 2:
    case 3:
    case 4:
      return rng.range(0, 40);
    case 5:
    case 6:
      return rng.range(0, 300);
    default:
      return rng.chance(1, 4) ? rng.range(300, 3000) : rng.range(0, 100);
  }
}

}  // namespace

DdaLineCase random_case(const DdaLineLimits& limits, uint64_t commands, uint64_t seed) {
  Rng rng(seed);
  DdaLineCase c;
  c.name = "random";
  c.start.assign(static_cast<size_t>(limits.axes), 0);
  c.settings = random_settings(rng, limits);
  const size_t axes = static_cast<size_t>(limits.axes);
  // Positions stay well inside POS_W (and deltas inside ACC_W) for any variant.
  const int64_t pos_room = limits.pos_w >= 20 ? 100000 : (int64_t{1} << (limits.pos_w - 2));
  const int64_t delta_cap = std::min<int64_t>(limits.max_delta(), pos_room / 2);
  models::LatticePoint at = c.start;
  std::vector<int64_t> previous(axes, 0);

  for (uint64_t n = 0; n < commands; ++n) {
    if (rng.chance(1, 8)) {
      DdaLineItem it;
      it.kind = DdaLineItem::Kind::kSettings;
      it.settings = random_settings(rng, limits);
      c.items.push_back(it);
    }
    if (rng.chance(1, 10)) {
      DdaLineItem it;
      it.kind = DdaLineItem::Kind::kGap;
      it.cycles = static_cast<uint64_t>(rng.range(1, 20));
      c.items.push_back(it);
    }
    if (rng.chance(1, 30)) {
      DdaLineItem it;
      it.kind = DdaLineItem::Kind::kDrain;
      c.items.push_back(it);
    }
    std::vector<int64_t> delta(axes, 0);
    const uint64_t kind = rng.below(20);
    if (kind == 0) {
      // all zero: one iteration, no steps
    } else if (kind <= 3) {  // single-axis move
      delta[rng.below(axes)] = random_magnitude(rng) * (rng.chance(1, 2) ? 1 : -1);
    } else if (kind <= 6) {  // reversal of the previous command
      for (size_t i = 0; i < axes; ++i) delta[i] = -previous[i];
    } else {  // any octant
      for (auto& d : delta) d = random_magnitude(rng) * (rng.chance(1, 2) ? 1 : -1);
    }
    for (size_t i = 0; i < axes; ++i) {
      delta[i] = std::clamp<int64_t>(delta[i], -delta_cap, delta_cap);
      // Turn back rather than leave the position window.
      if (std::llabs(at[i] + delta[i]) > pos_room) delta[i] = -delta[i];
      at[i] += delta[i];
    }
    previous = delta;
    c.items.push_back(command(delta));
  }
  return c;
}

namespace {

// Job-file words after the keyword, as integers.
std::vector<int64_t> integers(const std::vector<std::string>& words, const std::string& where) {
  std::vector<int64_t> out;
  for (size_t i = 1; i < words.size(); ++i) out.push_back(cli::parse_integer(words[i], where));
  return out;
}

uint64_t parse_feed(const std::string& w, const DdaLineLimits& limits, const std::string& where) {
  if (w == "full") return limits.full_feed();
  if (w.find('.') != std::string::npos) {  // a fraction of the clock rate
    const double f = cli::parse_real(w, where);
    if (!(f > 0 && f <= 1)) throw UsageError(where + ": feed fraction " + w + " is outside (0, 1]");
    return static_cast<uint64_t>(std::llround(f * static_cast<double>(limits.full_feed())));
  }
  const int64_t v = cli::parse_integer(w, where);
  if (v < 0) throw UsageError(where + ": feed word " + w + " is negative");
  return static_cast<uint64_t>(v);
}

}  // namespace

// Job-file format, one directive a line, '#' starts a comment:
//   case NAME            start a new case (the first may be implicit)
//   start X Y ...        absolute start position of the case (leading axes)
//   line X Y ...         command to the absolute point X Y ...
//   move DX DY ...       command by a relative delta
//   feed full|WORD|F     feed word, or a fraction 0 < F <= 1 written with a '.'
//   preload half|zero
//   step_len N | step_space N | dir_setup N | dir_hold N   (clock cycles)
//   gap N                N clocks with cmd_valid_i low
//   drain                wait until the core is idle
// Settings written before the first command of a case are in force from reset.
std::vector<DdaLineCase> parse_job(const std::string& path, const DdaLineLimits& limits,
                                   const DdaLineSettings& defaults) {
  std::ifstream in(path);
  if (!in) throw UsageError("--job: cannot read '" + path + "'");
  std::vector<DdaLineCase> cases;
  DdaLineCase* c = nullptr;
  models::LatticePoint at;
  auto new_case = [&](const std::string& name) {
    cases.push_back(
        {name, models::LatticePoint(static_cast<size_t>(limits.axes), 0), defaults, {}});
    c = &cases.back();
    at = c->start;
  };
  std::string text;
  int line_no = 0;
  while (std::getline(in, text)) {
    ++line_no;
    const std::string where = path + ":" + std::to_string(line_no);
    if (const auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream ws(text);
    std::vector<std::string> w;
    for (std::string word; ws >> word;) w.push_back(word);
    if (w.empty()) continue;
    const std::string& key = w[0];
    if (key == "case") {
      if (w.size() != 2) throw UsageError(where + ": 'case' takes one name");
      new_case(w[1]);
      continue;
    }
    if (!c) new_case("job" + std::to_string(cases.size() + 1));
    const bool initial = c->items.empty();  // nothing but settings so far in this case

    auto one_int = [&](int64_t lo, int64_t hi) {
      if (w.size() != 2) throw UsageError(where + ": '" + key + "' takes one value");
      const int64_t v = cli::parse_integer(w[1], where);
      if (v < lo || v > hi)
        throw UsageError(where + ": " + key + " " + w[1] + " is outside [" + std::to_string(lo) +
                         ", " + std::to_string(hi) + "]");
      return v;
    };
    // The settings a setting directive changes: the case's reset settings
    // before its first command, otherwise a settings item at this point
    // (consecutive setting lines share one item).
    auto settings_here = [&]() -> DdaLineSettings& {
      if (initial) return c->settings;
      if (c->items.back().kind != DdaLineItem::Kind::kSettings) {
        DdaLineItem it;
        it.kind = DdaLineItem::Kind::kSettings;
        it.settings = c->settings;
        for (const auto& prev : c->items)
          if (prev.kind == DdaLineItem::Kind::kSettings) it.settings = prev.settings;
        it.source_line = line_no;
        c->items.push_back(it);
      }
      return c->items.back().settings;
    };
    const int64_t tim_max = (int64_t{1} << limits.tim_w) - 1;

    if (key == "start") {
      if (!initial) throw UsageError(where + ": 'start' must come before the case's commands");
      c->start = pad(limits, integers(w, where), where + ": start");
      at = c->start;
    } else if (key == "line" || key == "move") {
      const models::LatticePoint v = pad(limits, integers(w, where), where + ": " + key);
      std::vector<int64_t> delta(v.size());
      for (size_t i = 0; i < v.size(); ++i) delta[i] = key == "line" ? v[i] - at[i] : v[i];
      c->items.push_back(command(delta, line_no));
      for (size_t i = 0; i < v.size(); ++i) at[i] += delta[i];
    } else if (key == "feed") {
      if (w.size() != 2) throw UsageError(where + ": 'feed' takes one value");
      settings_here().feed = parse_feed(w[1], limits, where);
    } else if (key == "preload") {
      if (w.size() != 2 || (w[1] != "half" && w[1] != "zero"))
        throw UsageError(where + ": preload must be 'half' or 'zero', not '" +
                         (w.size() > 1 ? w[1] : std::string()) + "'");
      settings_here().half_preload = w[1] == "half";
    } else if (key == "step_len") {
      settings_here().timing.step_len = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "step_space") {
      settings_here().timing.step_space = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "dir_setup") {
      settings_here().timing.dir_setup = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "dir_hold") {
      settings_here().timing.dir_hold = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "gap") {
      DdaLineItem it;
      it.kind = DdaLineItem::Kind::kGap;
      it.cycles = static_cast<uint64_t>(one_int(1, 100000000));
      it.source_line = line_no;
      c->items.push_back(it);
    } else if (key == "drain") {
      if (w.size() != 1) throw UsageError(where + ": 'drain' takes no value");
      DdaLineItem it;
      it.kind = DdaLineItem::Kind::kDrain;
      it.source_line = line_no;
      c->items.push_back(it);
    } else {
      throw UsageError(where + ": unknown directive '" + key + "'");
    }
  }
  if (cases.empty()) throw UsageError("--job: '" + path + "' has no commands");
  for (const auto& k : cases)
    if (command_count(k) == 0) throw UsageError("--job: case '" + k.name + "' has no commands");
  return cases;
}

uint64_t command_count(const DdaLineCase& c) {
  return static_cast<uint64_t>(std::count_if(c.items.begin(), c.items.end(), [](const auto& it) {
    return it.kind == DdaLineItem::Kind::kCommand;
  }));
}

namespace {

void validate_settings(const DdaLineSettings& s, const DdaLineLimits& limits,
                       const std::string& where) {
  if (s.feed == 0) throw UsageError(where + ": feed 0 never advances, the run would not end");
  // feed_i is FEED_W + 1 bits wide; anything at or above 2^FEED_W is full feed.
  if (s.feed >= 2 * limits.full_feed())
    throw UsageError(where + ": feed word " + std::to_string(s.feed) + " does not fit feed_i (" +
                     std::to_string(limits.feed_w + 1) + " bits)");
  const uint64_t tim_max = (uint64_t{1} << limits.tim_w) - 1;
  const std::pair<const char*, uint32_t> t[] = {{"step_len", s.timing.step_len},
                                                {"step_space", s.timing.step_space},
                                                {"dir_setup", s.timing.dir_setup},
                                                {"dir_hold", s.timing.dir_hold}};
  for (const auto& [name, v] : t)
    if (v > tim_max)
      throw UsageError(where + ": " + name + " " + std::to_string(v) + " does not fit " +
                       std::to_string(limits.tim_w) + " bits");
}

}  // namespace

void validate_case(const DdaLineCase& c, const DdaLineLimits& limits) {
  const std::string name = "case '" + c.name + "'";
  const int64_t pos_max = limits.pos_w >= 64 ? INT64_MAX : (int64_t{1} << (limits.pos_w - 1)) - 1;
  const int64_t pos_min = -pos_max - 1;
  if (static_cast<int>(c.start.size()) != limits.axes)
    throw UsageError(name + ": start has " + std::to_string(c.start.size()) + " axes");
  validate_settings(c.settings, limits, name);
  models::LatticePoint at = c.start;
  for (const auto& it : c.items) {
    const std::string where =
        name + (it.source_line ? " (job line " + std::to_string(it.source_line) + ")" : "");
    if (it.kind == DdaLineItem::Kind::kSettings) validate_settings(it.settings, limits, where);
    if (it.kind != DdaLineItem::Kind::kCommand) continue;
    for (size_t i = 0; i < it.delta.size(); ++i) {
      const int64_t d = it.delta[i];
      if (d > limits.max_delta() || d < limits.min_delta())
        throw UsageError(where + ": delta " + std::to_string(d) + " on axis " + std::to_string(i) +
                         " is wider than the " + std::to_string(limits.acc_w) +
                         "-bit datapath of " + limits.variant + " (limit " +
                         std::to_string(limits.min_delta()) + ".." +
                         std::to_string(limits.max_delta()) + ")");
      // The core counts from 0 after reset: the counter holds at - start.
      const int64_t rel = at[i] - c.start[i] + d;
      if (rel > pos_max || rel < pos_min)
        throw UsageError(where + ": axis " + std::to_string(i) + " would reach position " +
                         std::to_string(at[i] + d) + ", past the " + std::to_string(limits.pos_w) +
                         "-bit position counter");
      at[i] += d;
    }
  }
}

uint64_t cycle_budget(const DdaLineCase& c, const DdaLineLimits& limits) {
  // Worst case per DDA iteration: a full feed period plus one complete
  // step/dir timing round (len + space + setup + hold) of stall.
  uint64_t min_feed = c.settings.feed, max_round = 0;
  auto round = [](const StepdirTiming& t) {
    auto m = [](uint32_t v) { return uint64_t{v ? v : 1u}; };
    return m(t.step_len) + m(t.step_space) + m(t.dir_setup) + m(t.dir_hold) + 2;
  };
  max_round = round(c.settings.timing);
  uint64_t budget = 64;
  uint64_t iterations = 0;
  for (const auto& it : c.items) {
    if (it.kind == DdaLineItem::Kind::kSettings) {
      min_feed = std::min(min_feed, it.settings.feed);
      max_round = std::max(max_round, round(it.settings.timing));
    } else if (it.kind == DdaLineItem::Kind::kGap) {
      budget += it.cycles;
    } else if (it.kind == DdaLineItem::Kind::kCommand) {
      iterations += models::dda_iterations(it.delta);
      budget += 16;
    } else {
      budget += 16;
    }
  }
  const uint64_t feed_period =
      (limits.full_feed() + min_feed - 1) / std::max<uint64_t>(min_feed, 1);
  return 2 * (budget + iterations * (feed_period + max_round)) + 1000;
}

}  // namespace hwinterp::tb
