// What the testbench knows of one core variant without being a template over
// it: its core and name, the widths of the shared port contract, its timing
// defaults, every RTL parameter (from the generated <variant>_cfg.h, i.e.
// cmake/cores.cmake) and its own input ports (the core's payload field list,
// hls/fields.h). Stimulus is validated against it; reports and traces name
// ports from it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tb/base/stepdir_timing.h"

namespace hwinterp::tb {

// The testbench's per-axis arrays hold this many axes.
inline constexpr int kMaxAxes = 8;

// One input port as traces, frame dumps and reports see it: `count` elements
// of `width` bits, element i in bits [i*width +: width] (the RTL's flat
// per-axis vectors), two's complement when `is_signed`. Element values are at
// most 64 bits.
struct PortSpec {
  std::string name;
  int count = 1;
  int width = 1;
  bool is_signed = false;

  // Element value `raw` (the low `width` bits) as the number it stands for.
  int64_t value(uint64_t raw) const {
    if (!is_signed || width >= 64) return static_cast<int64_t>(raw);
    const uint64_t sign = uint64_t{1} << (width - 1);
    return static_cast<int64_t>((raw ^ sign) - sign);
  }
  // The range of element values, as text ("-2048..2047", "0..255").
  std::string range_text() const;
  // Whether `v` fits one element.
  bool fits(int64_t v) const;
};

struct VariantSpec {
  std::string core, variant;
  int axes = 0, pos_w = 0, tim_w = 0, feed_w = 0;  // the shared contract's widths
  StepdirTiming default_timing;
  std::vector<std::pair<std::string, int>> params;  // every RTL parameter, cores.cmake order
  std::vector<PortSpec> own_ports;  // the core's own inputs (its payload), RTL order

  // An RTL parameter by name; a core's adapter asks for its own widths.
  int param(const std::string& name) const {
    for (const auto& [k, v] : params)
      if (k == name) return v;
    throw std::logic_error(variant + " has no parameter " + name);
  }
  // An own input port by name.
  const PortSpec& own_port(const std::string& name) const {
    for (const auto& p : own_ports)
      if (p.name == name) return p;
    throw std::logic_error(variant + " has no input " + name);
  }
  // `value`, the `what` of a command at `where`, fits one element of own
  // input `port`; else cli::UsageError "<where>: <what> <value><detail> is
  // wider than the <W>-bit <port> of <variant> (limit <range>)".
  void check_fits(const std::string& port, int64_t value, const std::string& what,
                  const std::string& where, const std::string& detail = "") const;
  uint64_t full_feed() const { return uint64_t{1} << feed_w; }
  uint64_t tim_max() const { return (uint64_t{1} << tim_w) - 1; }
  int64_t pos_max() const { return pos_w >= 64 ? INT64_MAX : (int64_t{1} << (pos_w - 1)) - 1; }
  int64_t pos_min() const { return -pos_max() - 1; }
};

// How a command picks one variant of a core: by name, else by its axes
// (exactly, or the first with at least that many), else the first.
struct VariantChoice {
  std::string name;       // empty: not by name
  int axes = 0;           // 0: not by axes
  bool at_least = false;  // axes: the first with at least this many
};

// An index into `variants` (one core's, cores.cmake order); throws
// cli::UsageError naming the choice and listing the variants.
std::size_t choose_variant(const std::string& core, const std::vector<VariantSpec>& variants,
                           const VariantChoice& choice);

// The shared part of a variant's spec from its generated configuration (the
// whole spec, own ports included: spec_of<A, Cfg>() in tb/lockstep/payload_pins.h).
template <class Cfg>
VariantSpec spec_of_config() {
  static_assert(Cfg::AXES >= 1 && Cfg::AXES <= kMaxAxes,
                "raise kMaxAxes in tb/base/variant_spec.h");
  VariantSpec s;
  s.core = Cfg::kCore;
  s.variant = Cfg::kVariant;
  s.axes = Cfg::AXES;
  s.pos_w = Cfg::POS_W;
  s.tim_w = Cfg::TIM_W;
  s.feed_w = Cfg::FEED_W;
  s.default_timing = {Cfg::DEFAULT_STEP_LEN, Cfg::DEFAULT_STEP_SPACE, Cfg::DEFAULT_DIR_SETUP,
                      Cfg::DEFAULT_DIR_HOLD};
  for (int i = 0; i < Cfg::kParamCount; ++i)
    s.params.emplace_back(Cfg::kParamNames[i], Cfg::kParamValues[i]);
  return s;
}

}  // namespace hwinterp::tb
