// ppc_arc's adapter to the shared lockstep harness: the command payload and
// its pins, the reference model (models::PpcArcStream, rule M), the stimulus,
// the error bound and the command-line options. Everything else (runners,
// scoreboard, monitors, reports, traces) is the harness's.
//
// Command: centre and end relative to the start (G-code I, J and the end
// offset; the start is wherever the axes are) and the direction. No setup.
// Bound: every visited point lies within 1 + |re - rs| steps of the ideal
// spiral from start to end (models::PpcArcIdeal; the radial error 1 when the
// end is on the circle through the start).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hls/ppc_arc.h"
#include "models/ppc.h"
#include "tb/base/args.h"
#include "tb/base/variant_spec.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb {
template <class A>
class JobLine;
}

namespace hwinterp::tb::cores::ppc_arc {

struct Adapter {
  static constexpr const char* kName = "ppc_arc";
  static constexpr const char* kSummary =
      "2-axis point-by-point comparison arc interpolator, CW/CCW, exact end (rule M)";
  template <class Cfg>
  using Hls = hls::PpcArc<Cfg>;

  struct Command {
    std::array<int64_t, 2> center{};  // centre - start (I, J)
    std::array<int64_t, 2> end{};     // end - start
    bool ccw = true;
  };
  struct Setup {};

  // --- payload (hls/ppc_arc.h Own; tb/lockstep/payload_pins.h) ---------------
  template <class Own>
  static void to_own(const Command& c, const Setup&, Own& own) {
    for (size_t i = 0; i < 2; ++i) {
      own.center[i] = static_cast<uint64_t>(c.center[i]);
      own.end[i] = static_cast<uint64_t>(c.end[i]);
    }
    own.ccw = c.ccw;
  }

  // --- reference model (models/ppc.h) -----------------------------------------
  // Works relative to the command's start, so absolute positions anywhere in
  // the position counters' range are fine.
  class Reference {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const VariantSpec& l);
    bool next(Move& m);
    double error(const models::LatticePoint& p) const;
    models::ErrorBound bound() const { return ideal_.bound(); }
    // The ideal spiral (an arc when both ends are on one circle), for plots.
    std::vector<std::vector<double>> ideal() const { return ideal_.polyline(64); }

   private:
    models::LatticePoint start_;
    models::PpcArcStream stream_;
    models::PpcArcIdeal ideal_;
    // Scratch, kept so that a move allocates nothing: the stream's move, and
    // a point relative to the start.
    models::StepMove move_;
    mutable models::LatticePoint rel_ = models::LatticePoint(2, 0);
  };
  static void apply(const Command& c, models::LatticePoint& at) {
    at[0] += c.end[0];
    at[1] += c.end[1];
  }
  // Engine operations, at most (models::PpcArcStream::operation_bound()).
  static uint64_t work(const Command& c, const VariantSpec&);
  // The feed ticks (engine operations) the command takes, exactly: a feed
  // profile's move for it ends on its last (tb/lockstep/case_profile.h).
  static uint64_t operations(const Command& c, const VariantSpec&);  // the model's
  // The direction turns within a command: axis speed only.
  static constexpr bool kAxisFollowsPath = false;

  // --- stimulus ---------------------------------------------------------------
  // Every coordinate fits COORD_W (signed) and the whole circle, centre +-
  // (max(rs, re) + 2), fits the position counters (POS_W, signed, from the
  // case start).
  static void validate(const Command& c, const models::LatticePoint& from, const VariantSpec& l,
                       const std::string& where);
  static Setup random_setup(Rng&) { return {}; }
  // Both directions; small, medium and large radii within the widths (large
  // ones with short sweeps); quadrant crossings, full circles (end == start),
  // ends on the circle, rounded from a real point on it, or a few steps off;
  // now and then a degenerate command (start within one step of the centre).
  static Command random_command(Rng& rng, const VariantSpec& l, const models::LatticePoint& at,
                                const Command& previous);
  // `arc CX CY X1 Y1 cw|ccw`: absolute centre and end; the start is the
  // planned position.
  static bool job_directive(JobLine<Adapter>& line);
  static Case<Adapter> arc_case(const VariantSpec& l, const std::string& name,
                                const models::LatticePoint& center,
                                const models::LatticePoint& start, const models::LatticePoint& end,
                                bool ccw, const RunSettings<Adapter>& settings);
  // 003_b291717b57510359.txt's arc (4,0)->(0,4) CCW around (0,0) (003_arc).
  static std::vector<Case<Adapter>> paper_arcs(const VariantSpec& l,
                                               const RunSettings<Adapter>& settings);
  // The main regression: the paper arc, a full circle and an off-circle end,
  // a seeded random stream, and (`commands` > 0) a random stream with aborts
  // and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core ppc_arc) --------------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"arc", "paper-arcs"}; }
  static void setup_from_options(const cli::Args&, Setup&) {}
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::ppc_arc
