// motion_top's adapter to the shared lockstep harness: the command payload
// (models::MotionCommand: a line or an arc with slaved axes, and the move's
// feed word) and its pins, the reference model (models::MotionMoveStream,
// models::MotionIdeal and its bound), the stimulus and the command-line
// options. Everything else (runners, scoreboard, monitors, reports, traces)
// is the harness's. `hwinterp gcode` feeds the same core from part programs
// (tb/gcode/motion_compiler.h).
//
// Setup: `move_feed`, the feed word the job-file commands get (job directive
// `movefeed full|WORD|F`; 0: full feed); the hardware takes the feed word
// from each command (cmd_feed_i).
#pragma once

#include <array>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "hls/motion_top.h"
#include "models/motion_top_model.h"
#include "tb/base/args.h"
#include "tb/base/variant_spec.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb {
template <class A>
class JobLine;
}

namespace hwinterp::tb::cores::motion_top {

struct Adapter {
  static constexpr const char* kName = "motion_top";
  static constexpr const char* kSummary =
      "lines (DDA, all axes) and arcs (PPC rule M in XY/ZX/YZ, other axes slaved) in one core";
  template <class Cfg>
  using Hls = hls::MotionTop<Cfg>;

  using Command = models::MotionCommand;
  struct Setup {
    uint64_t move_feed = 0;  // the feed word job-file commands get; 0: full feed
  };

  // --- payload (hls/motion_top.h Own; tb/lockstep/payload_pins.h) ------------
  template <class Own>
  static void to_own(const Command& c, const Setup&, Own& own) {
    own.arc = c.kind == models::MotionKind::kArc;
    for (size_t i = 0; i < std::size(own.delta); ++i)
      own.delta[i] = static_cast<uint64_t>(c.delta[i]);
    own.plane = static_cast<unsigned>(c.plane);
    for (size_t i = 0; i < 2; ++i) {
      own.center[i] = static_cast<uint64_t>(c.center[i]);
      own.end[i] = static_cast<uint64_t>(c.end[i]);
    }
    own.ccw = c.ccw;
    own.ops = c.ops;
    own.feed = c.feed;
  }

  // --- reference model (models/motion_top_model.h) ------------------------------
  class Reference {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const VariantSpec& l);
    bool next(Move& m);
    // Deviation of the point the last move reached (its operation's progress).
    double error(const models::LatticePoint& p) const { return ideal_.error(p, op_); }
    models::ErrorBound bound() const { return ideal_.bound(); }
    std::vector<std::vector<double>> ideal() const;

   private:
    models::LatticePoint start_;
    Command cmd_;
    models::MotionMoveStream stream_;
    models::MotionIdeal ideal_;
    models::MotionMove move_;
    uint64_t op_ = 0;
  };
  static void apply(const Command& c, models::LatticePoint& at);
  // Engine operations times the clocks each takes at the command's feed word.
  static uint64_t work(const Command& c, const VariantSpec& l);
  // The feed ticks (engine operations) the command takes, exactly: a feed
  // profile's move for it ends on its last (tb/lockstep/case_profile.h).
  static uint64_t operations(const Command& c, const VariantSpec&) {
    return models::motion_operations(c);
  }
  // Behind a feed profile, a command follows feed_i (cmd_feed_i 0).
  static void follow_feed_input(Command& c) { c.feed = 0; }
  // Arcs turn within a command: axis speed only.
  static constexpr bool kAxisFollowsPath = false;

  // --- stimulus ---------------------------------------------------------------
  // Fits the widths: deltas ACC_W, arc coordinates COORD_W, ops OPS_W (and
  // equal to models::motion_arc_ops), slaved |delta| <= ops, plane axes' deltas
  // 0, a feed word in [1, 2^FEED_W]; the arc's circle inside POS_W.
  static void validate(const Command& c, const models::LatticePoint& from, const VariantSpec& l,
                       const std::string& where);
  static Setup random_setup(Rng&) { return {}; }
  // Lines (short and long, every octant, zero-length), arcs in the three
  // planes (radii 2 to 3000 steps, any sweep, full circles, ends off the
  // circle) with and without slaved axes, back and forth; a feed word per
  // move, mostly full.
  static Command random_command(Rng& rng, const VariantSpec& l, const models::LatticePoint& at,
                                const Command& previous);
  // `line X Y Z [A]`, `move DX DY DZ [DA]`, `arc xy|zx|yz CX CY X1 Y1 cw|ccw
  // [END...]` (centre and end absolute in the plane's axes, then the
  // absolute ends of the other axes, which move slaved), `movefeed
  // full|WORD|F` (the feed word of the commands that follow).
  static bool job_directive(JobLine<Adapter>& line);
  // The main regression: a rounded rectangle (lines and quarter arcs in XY),
  // a helix, arcs in ZX and YZ, a seeded random stream, and (`commands` > 0)
  // one with aborts and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core motion_top) ------------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"demo"}; }
  static void setup_from_options(const cli::Args&, Setup&) {}
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::motion_top
