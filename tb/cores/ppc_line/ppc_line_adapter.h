// ppc_line's adapter to the shared lockstep harness: the command payload and
// its pins, the reference model (models::PpcLineStream, the guarded rule),
// the stimulus, the error bound and the command-line options. Everything
// else (runners, scoreboard, monitors, reports, traces) is the harness's.
//
// Command: one signed delta per axis (cmd_delta_i, dx then dy). No setup.
// Bound: the normal distance of every visited point from the line is at most
// max(|dx|, |dy|) / L < 1 step (models::ppc_line_error_bound; reached).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hls/ppc_line.h"
#include "models/ppc.h"
#include "tb/base/args.h"
#include "tb/base/variant_spec.h"
#include "tb/cores/delta_payload.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb::cores::ppc_line {

struct Adapter : DeltaPayload<Adapter> {
  static constexpr const char* kName = "ppc_line";
  static constexpr const char* kSummary =
      "2-axis point-by-point comparison line interpolator (003/004 papers' PPC)";
  template <class Cfg>
  using Hls = hls::PpcLine<Cfg>;

  // Command (cmd_delta_i), pins, apply, validation, the `line`/`move` job
  // directives: DeltaPayload (tb/cores/delta_payload.h).

  // --- reference model (models/ppc.h) -----------------------------------------
  class Reference : public IdealLine {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const VariantSpec& l);
    bool next(Move& m);
    models::ErrorBound bound() const { return bound_; }

   private:
    models::PpcLineStream stream_;
    models::ErrorBound bound_;
    models::StepMove move_;  // scratch, kept: a move allocates nothing
  };
  // |dx| + |dy| operations; a zero-length command takes one.
  static uint64_t work(const Command& c, const VariantSpec&);
  // The feed ticks (engine operations) the command takes, exactly: a feed
  // profile's move for it ends on its last (tb/lockstep/case_profile.h).
  // |dx| + |dy|, and 1 for a command of no step (it still takes a tick).
  static uint64_t operations(const Command& c, const VariantSpec& l) { return work(c, l); }
  // Each axis steps a fixed fraction of the operations (a line).
  static constexpr bool kAxisFollowsPath = true;

  // --- stimulus ---------------------------------------------------------------
  // Every octant, axis-parallel and vertical lines, zero-length commands,
  // reversals, and long lines up to the widths.
  static Command random_command(Rng& rng, const VariantSpec& l, const models::LatticePoint& at,
                                const Command& previous);
  // The eight test lines of 004_dc68f1177cad466f.txt (004_line1..8) and the
  // line (0,0)->(4,3) of 003_b291717b57510359.txt (003_line).
  static std::vector<Case<Adapter>> paper_lines(const VariantSpec& l,
                                                const RunSettings<Adapter>& settings);
  // The main regression: the paper lines, a seeded random stream, and
  // (`commands` > 0) a random stream with aborts and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core ppc_line) -------------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"line", "paper-lines"}; }
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::ppc_line
