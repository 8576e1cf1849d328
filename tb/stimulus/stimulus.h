// Stimulus written once for every core: seeded random streams, job files,
// validation against a variant's widths and the hang budget. A is the core's
// adapter; what it supplies here (see tb/cores/dda_line/dda_line_adapter.h):
//   A::Setup random_setup(Rng&)
//   A::Command random_command(Rng&, const VariantSpec&, const LatticePoint& at,
//                             const A::Command& previous)
//   void apply(const A::Command&, LatticePoint& at)      where the command ends
//   void validate(const A::Command&, const LatticePoint& from, const VariantSpec&,
//                 const std::string& where)             widths; throws UsageError
//                 (`from`: where the command starts, counted from the case
//                 start as pos_o counts it)
//   uint64_t work(const A::Command&)                    engine operations, at most
//   bool job_directive(JobLine<A>&)                     the core's job directives
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "tb/base/args.h"
#include "tb/base/variant_spec.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/rng.h"
#include "tb/stimulus/settings.h"

namespace hwinterp::tb {

template <class A>
RunSettings<A> default_settings(const VariantSpec& spec) {
  RunSettings<A> s;
  s.feed = spec.full_feed();
  s.timing = spec.default_timing;
  return s;
}

template <class A>
RunSettings<A> random_settings(Rng& rng, const VariantSpec& spec) {
  RunSettings<A> s;
  s.feed = random_feed(rng, spec);
  s.setup = A::random_setup(rng);
  s.timing = random_timing(rng, spec);
  return s;
}

// What a random stream adds besides commands, settings changes, gaps and
// drains. Drawn from a second generator, so the plain stream of a seed is
// the same with or without them.
struct RandomExtras {
  bool aborts = false;  // abort_i pulses while commands run, then more commands
  bool holds = false;   // feed 0 for a while (feed hold), then the feed again
};

// A seeded random stream of `commands` commands in one case, starting at the
// origin: every direction the core's random_command draws, back-to-back
// commands and idle gaps, random timing settings, feed words and setups
// changed while the core runs. The same seed gives the same case everywhere.
template <class A>
Case<A> random_case(const VariantSpec& spec, uint64_t commands, uint64_t seed,
                    RandomExtras extras = {}) {
  using Kind = typename Item<A>::Kind;
  Rng rng(seed), extra(seed ^ 0x5eedab0f7ULL);
  Case<A> c;
  c.name = "random";
  c.start.assign(static_cast<size_t>(spec.axes), 0);
  c.settings = random_settings<A>(rng, spec);
  RunSettings<A> now = c.settings;
  models::LatticePoint at = c.start;
  typename A::Command previous{};
  auto push = [&](Kind kind, uint64_t cycles = 0) {
    Item<A> it;
    it.kind = kind;
    it.cycles = cycles;
    it.settings = now;
    c.items.push_back(it);
  };
  for (uint64_t n = 0; n < commands; ++n) {
    if (rng.chance(1, 8)) {
      now = random_settings<A>(rng, spec);
      push(Kind::kSettings);
    }
    if (rng.chance(1, 10)) push(Kind::kGap, static_cast<uint64_t>(rng.range(1, 20)));
    if (rng.chance(1, 30)) push(Kind::kDrain);
    if (extras.aborts && n > 0 && extra.chance(1, 12)) {
      // Abort while the previous commands run, at a random depth into them;
      // wait for idle, so the time busy_o takes to fall is measured.
      push(Kind::kGap, static_cast<uint64_t>(extra.range(1, 60)));
      push(Kind::kAbort);
      push(Kind::kDrain);
    }
    if (extras.holds && n > 0 && extra.chance(1, 12)) {
      const RunSettings<A> resume = now;
      push(Kind::kGap, static_cast<uint64_t>(extra.range(1, 30)));
      now.feed = 0;
      push(Kind::kSettings);
      push(Kind::kGap, static_cast<uint64_t>(extra.range(1, 80)));
      now = resume;
      push(Kind::kSettings);
    }
    const typename A::Command cmd = A::random_command(rng, spec, at, previous);
    A::apply(cmd, at);
    previous = cmd;
    c.items.push_back(command_item<A>(cmd));
  }
  return c;
}

// Random feed profile limits (Case::profile): one level of 1/250 to 1/16
// operation a clock (log-uniform), a moving sum of 1 to 24 ticks (1: a
// trapezoid).
inline CaseProfile random_profile(Rng& rng) {
  CaseProfile p;
  p.level =
      std::exp(std::log(1.0 / 250) +
               std::log(250.0 / 16) * static_cast<double>(rng.below(1 << 20)) / double(1 << 20));
  p.len = static_cast<unsigned>(rng.range(1, 24));
  return p;
}

// A core whose commands carry their own feed word (A::follow_feed_input:
// motion_top's cmd_feed_i, 0 = feed_i) follows the feed input instead.
template <class A, class = void>
struct HasFeedInput : std::false_type {};
template <class A>
struct HasFeedInput<
    A, std::void_t<decltype(A::follow_feed_input(std::declval<typename A::Command&>()))>>
    : std::true_type {};

// Puts the case behind a feed profile with limits `p` (Case::profile): its
// commands follow feed_i.
template <class A>
void put_behind_profile(Case<A>& c, const CaseProfile& p) {
  c.profile = p;
  if constexpr (HasFeedInput<A>::value)
    for (auto& it : c.items)
      if (it.kind == Item<A>::Kind::kCommand) A::follow_feed_input(it.cmd);
}

// The profile case of every core's regression ("random_profile"): the
// first `commands` (at most 40) of the seed's stream, no aborts or feed
// holds, the case's step/dir timing throughout (a profile's move is planned
// for the timing it runs with), behind a feed profile with random limits.
template <class A>
Case<A> random_profile_case(const VariantSpec& spec, uint64_t commands, uint64_t seed) {
  using Kind = typename Item<A>::Kind;
  Case<A> c = random_case<A>(spec, std::min<uint64_t>(commands, 40), seed);
  c.name = "random_profile";
  for (auto& it : c.items)
    if (it.kind == Kind::kSettings) it.settings.timing = c.settings.timing;
  Rng rng(seed ^ 0x9e3779b97f4a7c15ULL);
  put_behind_profile(c, random_profile(rng));
  return c;
}

// The random part of every core's regression: a seeded stream of `commands`
// ("random"), the same seed with aborts and feed holds
// ("random_abort_hold") and behind a feed profile ("random_profile");
// nothing when `commands` is 0.
template <class A>
void append_random_streams(std::vector<Case<A>>& cases, const VariantSpec& spec, uint64_t commands,
                           uint64_t seed) {
  if (!commands) return;
  cases.push_back(random_case<A>(spec, commands, seed));
  cases.push_back(random_case<A>(spec, commands, seed, {true, true}));
  cases.back().name = "random_abort_hold";
  cases.push_back(random_profile_case<A>(spec, commands, seed));
}

// Checks a case against the variant's widths: every command fits the core's
// datapath (the adapter's validate), every position reached fits POS_W
// (signed, counted from the case start as the core counts), settings fit
// TIM_W / FEED_W, and no command or drain waits under feed hold (feed 0), which
// would never end. Throws cli::UsageError naming the case, the job line and
// the value: nothing is simulated that would overflow.
template <class A>
void validate_case(const Case<A>& c, const VariantSpec& spec) {
  using Kind = typename Item<A>::Kind;
  const std::string name = "case '" + c.name + "'";
  if (static_cast<int>(c.start.size()) != spec.axes)
    throw cli::UsageError(name + ": start has " + std::to_string(c.start.size()) + " axes");
  for (const int64_t v : c.start) check_coordinate(v, name + ": start");
  validate_feed_and_timing(c.settings.feed, c.settings.timing, spec, name);
  uint64_t feed = c.settings.feed;
  models::LatticePoint at = c.start;
  for (const auto& it : c.items) {
    const std::string where =
        name + (it.source_line ? " (job line " + std::to_string(it.source_line) + ")" : "");
    if (it.kind == Kind::kSettings) {
      validate_feed_and_timing(it.settings.feed, it.settings.timing, spec, where);
      feed = it.settings.feed;
    }
    if ((it.kind == Kind::kCommand || it.kind == Kind::kDrain) && feed == 0)
      throw cli::UsageError(where + ": a " +
                            (it.kind == Kind::kDrain ? std::string("drain") : "command") +
                            " under feed 0 (hold) would wait forever; set a feed first");
    if (it.kind != Kind::kCommand) continue;
    models::LatticePoint from = at;  // as the core's position counters see it
    for (size_t a = 0; a < from.size(); ++a) from[a] -= c.start[a];
    A::validate(it.cmd, from, spec, where);
    models::LatticePoint next = at;
    A::apply(it.cmd, next);
    for (int i = 0; i < spec.axes; ++i) {
      // The core counts from 0 after reset: the counter holds at - start.
      const size_t a = static_cast<size_t>(i);
      const int64_t rel = next[a] - c.start[a];
      if (rel > spec.pos_max() || rel < spec.pos_min())
        throw cli::UsageError(where + ": axis " + std::to_string(i) + " would reach position " +
                              std::to_string(next[a]) + ", past the " + std::to_string(spec.pos_w) +
                              "-bit position counter");
    }
    at = next;
  }
  if (feed == 0)
    throw cli::UsageError(name + ": ends in feed hold (feed 0); resume the feed first");
}

// One complete step/dir timing round (len + space + setup + hold), the worst
// stall of one engine operation.
inline uint64_t timing_round(const StepdirTiming& t) {
  auto m = [](uint32_t v) { return uint64_t{v ? v : 1u}; };
  return m(t.step_len) + m(t.step_space) + m(t.dir_setup) + m(t.dir_hold) + 2;
}

// The clocks a command streamed by a Case's ItemSource may take on a correct
// core, with the same margin as cycle_budget(): added to the budget as the
// bench pulls it.
template <class A>
uint64_t streamed_command_budget(const typename A::Command& cmd, const VariantSpec& spec,
                                 const RunSettings<A>& s) {
  const uint64_t feed = s.feed ? s.feed : spec.full_feed();
  const uint64_t feed_period = (spec.full_feed() + feed - 1) / feed;
  return 2 * (16 + A::work(cmd, spec) * (feed_period + timing_round(s.timing)));
}

// Upper bound on the clock edges the case needs on a correct core, with
// margin; running past it means the core hung. (Streamed items add theirs as
// they come: streamed_command_budget().)
template <class A>
uint64_t cycle_budget(const Case<A>& c, const VariantSpec& spec) {
  using Kind = typename Item<A>::Kind;
  // Worst case per engine operation: a full feed period plus one complete
  // step/dir timing round (len + space + setup + hold) of stall.
  uint64_t min_feed = c.settings.feed ? c.settings.feed : spec.full_feed();
  uint64_t max_round = timing_round(c.settings.timing);
  uint64_t budget = 64, operations = 0;
  for (const auto& it : c.items) {
    if (it.kind == Kind::kSettings) {
      if (it.settings.feed) min_feed = std::min(min_feed, it.settings.feed);
      max_round = std::max(max_round, timing_round(it.settings.timing));
    } else if (it.kind == Kind::kGap) {
      budget += it.cycles;
    } else if (it.kind == Kind::kCommand) {
      operations += A::work(it.cmd, spec);
      budget += 16;
    } else {
      budget += 16;
    }
  }
  const uint64_t feed_period = (spec.full_feed() + min_feed - 1) / min_feed;
  return 2 * (budget + operations * (feed_period + max_round)) + 1000;
}

// One directive of a job file as a core's adapter sees it (A::job_directive):
// its words, where it is, the position the commands so far lead to, and
// what it may add.
template <class A>
class JobLine {
 public:
  JobLine(const std::vector<std::string>& words, std::string where, const VariantSpec& spec,
          Case<A>& c, models::LatticePoint& at, int line_no)
      : words(words), where(std::move(where)), spec(spec), case_(c), at_(at), line_(line_no) {}

  const std::vector<std::string>& words;
  const std::string where;  // "file:line"
  const VariantSpec& spec;

  const models::LatticePoint& at() const { return at_; }
  // Appends a command; the planned position follows it (and must stay on the
  // lattice the testbench works on).
  void command(const typename A::Command& cmd) {
    case_.items.push_back(command_item<A>(cmd, line_));
    A::apply(cmd, at_);
    for (const int64_t v : at_) check_coordinate(v, where + ": the position this reaches");
  }
  // The setup in force from this line on: the case's reset settings before
  // its first command, otherwise a settings item here (consecutive setting
  // lines share one item).
  RunSettings<A>& settings() {
    using Kind = typename Item<A>::Kind;
    if (case_.items.empty()) return case_.settings;
    if (case_.items.back().kind != Kind::kSettings) {
      Item<A> it;
      it.kind = Kind::kSettings;
      it.settings = case_.settings;
      for (const auto& prev : case_.items)
        if (prev.kind == Kind::kSettings) it.settings = prev.settings;
      it.source_line = line_;
      case_.items.push_back(it);
    }
    return case_.items.back().settings;
  }
  // The settings in force at this line, without adding a settings item.
  const RunSettings<A>& current_settings() const {
    using Kind = typename Item<A>::Kind;
    for (auto it = case_.items.rbegin(); it != case_.items.rend(); ++it)
      if (it->kind == Kind::kSettings) return it->settings;
    return case_.settings;
  }
  // Words [first, first + n) as lattice coordinates (n = 0: to the end).
  std::vector<int64_t> integers(size_t first, size_t n = 0) const {
    std::vector<int64_t> out;
    const size_t end = n ? first + n : words.size();
    if (end > words.size())
      throw cli::UsageError(where + ": '" + words[0] + "' needs " + std::to_string(end - 1) +
                            " values");
    for (size_t i = first; i < end; ++i) {
      out.push_back(cli::parse_integer(words[i], where));
      check_coordinate(out.back(), where);
    }
    return out;
  }
  // Leading-axis coordinates from word `first` to the end, padded to the axes.
  models::LatticePoint point(size_t first) const {
    return pad_point(spec, integers(first), where + ": " + words[0]);
  }

 private:
  Case<A>& case_;
  models::LatticePoint& at_;
  int line_;
};

// Job-file format, one directive a line, '#' starts a comment. Shared:
//   case NAME            start a new case (the first may be implicit)
//   start X Y ...        absolute start position of the case (leading axes)
//   feed full|WORD|F     feed word (0 holds the move), or a fraction 0 < F <= 1 with a '.'
//   step_len N | step_space N | dir_setup N | dir_hold N   (clock cycles)
//   gap N                N clocks with cmd_valid_i low
//   drain                wait until the core is idle
//   abort                abort_i high for one clock
// and the core's own (its adapter's job_directive: commands such as `line`,
// `move`, `arc`, and setups such as `preload`). Settings written before the
// first command of a case are in force from reset. Throws cli::UsageError
// naming file:line and the bad value.
// `path` names the job in messages.
template <class A>
std::vector<Case<A>> parse_job(std::istream& in, const std::string& path, const VariantSpec& spec,
                               const RunSettings<A>& defaults) {
  using Kind = typename Item<A>::Kind;
  std::vector<Case<A>> cases;
  models::LatticePoint at;
  auto new_case = [&](const std::string& name) {
    Case<A> c;
    c.name = name;
    c.start.assign(static_cast<size_t>(spec.axes), 0);
    c.settings = defaults;
    cases.push_back(std::move(c));
    at = cases.back().start;
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
      if (w.size() != 2) throw cli::UsageError(where + ": 'case' takes one name");
      new_case(w[1]);
      continue;
    }
    if (cases.empty()) new_case("job" + std::to_string(cases.size() + 1));
    Case<A>& c = cases.back();
    JobLine<A> line(w, where, spec, c, at, line_no);
    auto one_int = [&](int64_t lo, int64_t hi) {
      if (w.size() != 2) throw cli::UsageError(where + ": '" + key + "' takes one value");
      const int64_t v = cli::parse_integer(w[1], where);
      if (v < lo || v > hi)
        throw cli::UsageError(where + ": " + key + " " + w[1] + " is outside [" +
                              std::to_string(lo) + ", " + std::to_string(hi) + "]");
      return v;
    };
    auto simple = [&](Kind kind, uint64_t cycles = 0) {
      Item<A> it;
      it.kind = kind;
      it.cycles = cycles;
      it.source_line = line_no;
      c.items.push_back(it);
    };
    const auto tim_max = static_cast<int64_t>(spec.tim_max());
    if (key == "start") {
      if (!c.items.empty())
        throw cli::UsageError(where + ": 'start' must come before the case's commands");
      c.start = line.point(1);
      at = c.start;
    } else if (key == "feed") {
      if (w.size() != 2) throw cli::UsageError(where + ": 'feed' takes one value");
      line.settings().feed = parse_feed(w[1], spec, where);
    } else if (key == "step_len") {
      line.settings().timing.step_len = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "step_space") {
      line.settings().timing.step_space = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "dir_setup") {
      line.settings().timing.dir_setup = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "dir_hold") {
      line.settings().timing.dir_hold = static_cast<uint32_t>(one_int(0, tim_max));
    } else if (key == "gap") {
      simple(Kind::kGap, static_cast<uint64_t>(one_int(1, 100000000)));
    } else if (key == "drain" || key == "abort") {
      if (w.size() != 1) throw cli::UsageError(where + ": '" + key + "' takes no value");
      simple(key == "drain" ? Kind::kDrain : Kind::kAbort);
    } else if (!A::job_directive(line)) {
      throw cli::UsageError(where + ": unknown directive '" + key + "'");
    }
  }
  if (cases.empty()) throw cli::UsageError("--job: '" + path + "' has no commands");
  for (const auto& k : cases)
    if (command_count(k) == 0)
      throw cli::UsageError("--job: case '" + k.name + "' has no commands");
  return cases;
}

// A job file.
template <class A>
std::vector<Case<A>> parse_job(const std::string& path, const VariantSpec& spec,
                               const RunSettings<A>& defaults) {
  std::ifstream in(path);
  if (!in) throw cli::UsageError("--job: cannot read '" + path + "'");
  return parse_job<A>(in, path, spec, defaults);
}

}  // namespace hwinterp::tb
