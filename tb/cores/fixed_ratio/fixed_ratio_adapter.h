// fixed_ratio's adapter to the shared lockstep harness: the command payload
// and its pins, the reference model (models::FixedRatioMoveStream, the
// hardware's integer arithmetic), the stimulus, the error bound and the
// command-line options. Everything else (runners, scoreboard, monitors,
// reports, traces) is the harness's.
//
// Command: one signed delta per axis (cmd_delta_i), as dda_line's. No setup.
// Bound: models::fixed_ratio_hw_bound() of each command at the variant's
// FRAC_W (the lag box of its minor axes with their own rate-word rounding),
// at most sqrt(N - 1) (1/2 + 2^(ACC_W-1-FRAC_W)) < 1 step for the shipped
// variants; checked on every move.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hls/fixed_ratio.h"
#include "models/fixed_ratio_model.h"
#include "tb/cli/cli_args.h"
#include "tb/lockstep/pins.h"
#include "tb/lockstep/rtl_pins.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/delta_commands.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb::cores::fixed_ratio {

struct Adapter {
  static constexpr const char* kName = "fixed_ratio";
  static constexpr const char* kSummary =
      "N-axis fixed-ratio (velocity-synthesis) line generator (004 paper's fixed ratio)";
  template <class Cfg>
  using Hls = hls::FixedRatio<Cfg>;

  struct Command {
    std::array<int64_t, kMaxAxes> delta{};  // signed steps per axis
  };
  struct Setup {};

  // --- pins -----------------------------------------------------------------
  static std::vector<PortSpec> own_ports(const CoreLimits& l) {
    return {{"cmd_delta_i", l.axes, l.param("ACC_W")}};
  }
  static size_t own_values(const Command& c, const Setup&, const CoreLimits& l, uint64_t* out) {
    for (int i = 0; i < l.axes; ++i)
      out[i] = static_cast<uint64_t>(c.delta[static_cast<size_t>(i)]);
    return static_cast<size_t>(l.axes);
  }
  // Direct mode: the Verilated --cc model's and the HLS core's own inputs.
  template <class Cfg, class Rtl, class Own>
  static void drive(const Command& c, const Setup&, Rtl& rtl, Own& own) {
    for (int i = 0; i < Cfg::AXES; ++i) {
      const uint64_t d = static_cast<uint64_t>(c.delta[static_cast<size_t>(i)]);
      put_bits(rtl.cmd_delta_i, i * Cfg::ACC_W, Cfg::ACC_W, d);
      own.delta[i] = d;
    }
  }
  // SystemC mode: the own input signal, bound to both DUTs.
  template <class Cfg>
  struct ScPins {
    sc_core::sc_signal<hls::pin_t<Cfg::AXES * Cfg::ACC_W>> delta{"cmd_delta"};
    hls::pin_t<Cfg::AXES* Cfg::ACC_W> value = 0;  // kept: building a wide pin value allocates
    template <class Dut>
    void bind(Dut& d) {
      d.cmd_delta_i(delta);
    }
    void write(const Command& c, const Setup&) {
      for (int i = 0; i < Cfg::AXES; ++i)
        hls::set_pin_field<Cfg::AXES * Cfg::ACC_W>(
            value, i * Cfg::ACC_W, Cfg::ACC_W,
            static_cast<uint64_t>(c.delta[static_cast<size_t>(i)]));
      delta.write(value);
    }
  };

  // --- reference model (models/fixed_ratio_model.h) ---------------------------
  class Reference {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const CoreLimits& l);
    bool next(Move& m);
    double error(const models::LatticePoint& p) const;
    models::ErrorBound bound() const { return bound_; }
    // The ideal path as a polyline (for plots): the line itself.
    std::vector<std::vector<double>> ideal() const {
      return {{start_.begin(), start_.end()}, {end_.begin(), end_.end()}};
    }

   private:
    models::FixedRatioMoveStream stream_;
    models::FixedRatioMove move_;
    models::LatticePoint start_, end_;
    models::ErrorBound bound_;
  };
  static void apply(const Command& c, models::LatticePoint& at) {
    for (size_t i = 0; i < at.size(); ++i) at[i] += c.delta[i];
  }
  // Engine ticks: max(M, 1). (The FRAC_W + 1 divider clocks overlap the
  // previous command; the hang budget's per-command margin covers them
  // where they do not.)
  static uint64_t work(const Command& c);

  // --- stimulus ---------------------------------------------------------------
  // Deltas fit ACC_W (validate_case() checks the end point against POS_W;
  // a line stays in its box).
  static void validate(const Command& c, const models::LatticePoint&, const CoreLimits& l,
                       const std::string& where) {
    validate_deltas<Adapter>(c, l, where);
  }
  static Setup random_setup(Rng&) { return {}; }
  // Every octant, axis-parallel and zero-length commands, reversals,
  // near-diagonal long lines (on the narrow variants up to the delta width,
  // on the wide ones 10^5 to 10^6 steps) and the extremes of the delta width
  // where the position counters allow them.
  static Command random_command(Rng& rng, const CoreLimits& l, const models::LatticePoint& at,
                                const Command& previous);
  // `line X Y ...` (to an absolute point), `move DX DY ...`
  // (tb/stimulus/delta_commands.h).
  static bool job_directive(JobLine<Adapter>& line) { return delta_job_directive(line); }
  // The main regression: the eight lines of 004, a seeded random stream, and
  // (`commands` > 0) a random stream with aborts and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const CoreLimits& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core fixed_ratio) ----------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"line", "paper-lines"}; }
  static void setup_from_options(const cli::Args&, Setup&) {}
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const CoreLimits& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::fixed_ratio
