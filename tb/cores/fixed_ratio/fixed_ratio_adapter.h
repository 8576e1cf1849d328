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
#include "tb/base/args.h"
#include "tb/base/variant_spec.h"
#include "tb/cores/delta_payload.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb::cores::fixed_ratio {

struct Adapter : DeltaPayload<Adapter> {
  static constexpr const char* kName = "fixed_ratio";
  static constexpr const char* kSummary =
      "N-axis fixed-ratio (velocity-synthesis) line generator (004 paper's fixed ratio)";
  template <class Cfg>
  using Hls = hls::FixedRatio<Cfg>;

  // Command (cmd_delta_i), pins, apply, validation, the `line`/`move` job
  // directives: DeltaPayload (tb/cores/delta_payload.h).

  // --- reference model (models/fixed_ratio_model.h) ---------------------------
  class Reference : public IdealLine {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const VariantSpec& l);
    bool next(Move& m);
    models::ErrorBound bound() const { return bound_; }

   private:
    models::FixedRatioMoveStream stream_;
    models::FixedRatioMove move_;
    models::ErrorBound bound_;
  };
  // Engine ticks: max(M, 1). (The FRAC_W + 2 divider clocks overlap the
  // previous command; the hang budget's per-command margin covers them
  // where they do not.)
  static uint64_t work(const Command& c, const VariantSpec&);
  // The feed ticks (engine operations) the command takes, exactly: a feed
  // profile's move for it ends on its last (tb/lockstep/case_profile.h).
  static uint64_t operations(const Command& c, const VariantSpec& l) { return work(c, l); }
  // Each axis steps a fixed fraction of the operations (a line).
  static constexpr bool kAxisFollowsPath = true;

  // --- stimulus ---------------------------------------------------------------
  // Every octant, axis-parallel and zero-length commands, reversals,
  // near-diagonal long lines (on the narrow variants up to the delta width,
  // on the wide ones 10^5 to 10^6 steps) and the extremes of the delta width
  // where the position counters allow them.
  static Command random_command(Rng& rng, const VariantSpec& l, const models::LatticePoint& at,
                                const Command& previous);
  // The main regression: the eight lines of 004, a seeded random stream, and
  // (`commands` > 0) a random stream with aborts and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core fixed_ratio) ----------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"line", "paper-lines"}; }
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::fixed_ratio
