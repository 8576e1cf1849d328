// Stimulus of one core, independent of the core: cases made of commands,
// run-time setting changes, idle gaps, drains and aborts. A is the core's
// adapter (tb/cores/<core>/<core>_adapter.h): it supplies the command payload
// (A::Command) and its own run-time setup (A::Setup).
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/lattice_path.h"
#include "tb/monitor/stepdir_monitor.h"

namespace hwinterp::tb {

// Run-time inputs besides the command stream.
template <class A>
struct RunSettings {
  uint64_t feed = 0;  // feed word: operations per clock = feed / 2^FEED_W; >= 2^FEED_W is full
                      // feed, 0 holds the move (no command may be offered while it is 0)
  StepdirTiming timing;
  typename A::Setup setup{};  // the core's own (e.g. dda_line's half preload)
};

template <class A>
struct Item {
  enum class Kind { kCommand, kSettings, kGap, kDrain, kAbort };
  Kind kind = Kind::kCommand;
  typename A::Command cmd{};  // kCommand
  RunSettings<A> settings;    // kSettings: applied from the next clock edge on
  uint64_t cycles = 0;        // kGap: clocks with cmd_valid_i low
  int source_line = 0;        // job-file line, for messages
};

// Items produced one at a time while the case runs, after Case::items: a
// stream of any length in bounded memory (hwinterp gcode's part programs).
// The producer validates what it yields (validate_case() sees only `items`);
// next() is called once per item, never per clock.
template <class A>
class ItemSource {
 public:
  virtual ~ItemSource() = default;
  virtual bool next(Item<A>& it) = 0;  // false at the end
};

// A feed profile in front of the core for the whole case (issue 25;
// tb/lockstep/case_profile.h): the block's registers, fixed for the case.
// Each command becomes one rest-to-rest move of exactly its engine
// operations (A::operations), cruising at the feed word in force when it is
// offered, capped so the step/dir stage never stalls the engine.
// The limits: the speed steps by at most one level a tick (the acceleration)
// and the level is reached over L ticks (the jerk: a level / L a tick^2).
struct CaseProfile {
  double level = 0;  // operations/clock of one level (q L / 2^SPD_W, rounded down to q)
  unsigned len = 1;  // L, ticks of the moving sum (1: a trapezoid)
};

template <class A>
struct Case {
  std::string name;
  uint64_t ordinal = 0;  // its position in its run's full list (regress --shard keeps a subset)
  models::LatticePoint start;  // absolute position the core's counters start from
  RunSettings<A> settings;     // in force from reset
  std::vector<Item<A>> items;
  std::shared_ptr<ItemSource<A>> more;  // items after `items`; null: none
  std::optional<CaseProfile> profile;   // feed_i from a feed profile; none: the feed word
};

template <class A>
Item<A> command_item(const typename A::Command& cmd, int source_line = 0) {
  Item<A> it;
  it.kind = Item<A>::Kind::kCommand;
  it.cmd = cmd;
  it.source_line = source_line;
  return it;
}

template <class A>
uint64_t command_count(const Case<A>& c) {
  return static_cast<uint64_t>(std::count_if(c.items.begin(), c.items.end(), [](const auto& it) {
    return it.kind == Item<A>::Kind::kCommand;
  }));
}

}  // namespace hwinterp::tb
