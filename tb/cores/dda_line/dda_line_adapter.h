// dda_line's adapter to the shared lockstep harness: the command payload and
// its pins, the reference model, the stimulus, the error bound and the
// command-line options. Everything else (runners, scoreboard, monitors,
// reports, traces) is the harness's, for every core.
//
// Command: one signed delta per axis (cmd_delta_i). Setup: half_preload_i,
// sampled with each command (job directive `preload half|zero`, random
// streams change it while the core runs, `--half-preload` on the command line).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hls/dda_line.h"
#include "models/dda_line_model.h"
#include "tb/base/args.h"
#include "tb/base/variant_spec.h"
#include "tb/cores/delta_payload.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/delta_commands.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb::cores::dda_line {

struct Adapter {
  static constexpr const char* kName = "dda_line";
  static constexpr const char* kSummary = "N-axis DDA line interpolator (004 paper's DDA)";
  template <class Cfg>
  using Hls = hls::DdaLine<Cfg>;

  using Command = DeltaCommand;  // cmd_delta_i (tb/cores/delta_payload.h)
  struct Setup {
    bool half_preload = false;
  };

  // --- payload (hls/dda_line.h Own; tb/lockstep/payload_pins.h) --------------
  template <class Own>
  static void to_own(const Command& c, const Setup& s, Own& own) {
    deltas_to_own(c, own);
    own.half_preload = s.half_preload;
  }

  // --- reference model (models/dda_line_model.h) ------------------------------
  class Reference : public IdealLine {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const VariantSpec& l);
    bool next(Move& m);
    models::ErrorBound bound() const { return bound_; }

   private:
    models::DdaMoveStream stream_;
    models::DdaMove move_;
    models::ErrorBound bound_;
  };
  static void apply(const Command& c, models::LatticePoint& at) { apply_deltas(c, at); }
  static uint64_t work(const Command& c, const VariantSpec&);  // 2^n iterations
  // The feed ticks (engine operations) the command takes, exactly: a feed
  // profile's move for it ends on its last (tb/lockstep/case_profile.h).
  static uint64_t operations(const Command& c, const VariantSpec& l) { return work(c, l); }
  // Each axis steps a fixed fraction of the operations (a line).
  static constexpr bool kAxisFollowsPath = true;

  // --- stimulus ---------------------------------------------------------------
  // Deltas fit ACC_W (validate_case() checks the end point against POS_W;
  // a line stays in its box).
  static void validate(const Command& c, const models::LatticePoint&, const VariantSpec& l,
                       const std::string& where) {
    validate_deltas<Adapter>(c, l, where);
  }
  static Setup random_setup(Rng& rng) { return {rng.chance(1, 2)}; }
  static Command random_command(Rng& rng, const VariantSpec& l, const models::LatticePoint& at,
                                const Command& previous);
  // `line X Y ...` (to an absolute point), `move DX DY ...`
  // (tb/stimulus/delta_commands.h), `preload half|zero`.
  static bool job_directive(JobLine<Adapter>& line);
  // The main regression: the paper lines with plain and half preload, a
  // seeded random stream, and (`commands` > 0) a random stream with aborts
  // and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core dda_line) -------------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"line", "paper-lines"}; }
  static void setup_from_options(const cli::Args& args, Setup& s) {
    s.half_preload = args.given("half-preload");
  }
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::dda_line
