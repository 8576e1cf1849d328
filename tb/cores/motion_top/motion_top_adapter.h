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
#include <string>
#include <vector>

#include "hls/motion_top.h"
#include "models/motion_top_model.h"
#include "tb/cli/cli_args.h"
#include "tb/lockstep/pins.h"
#include "tb/lockstep/rtl_pins.h"
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

  // --- pins -----------------------------------------------------------------
  static std::vector<PortSpec> own_ports(const CoreLimits& l);
  static size_t own_values(const Command& c, const Setup&, const CoreLimits& l, uint64_t* out);
  // Direct mode: the Verilated --cc model's and the HLS core's own inputs.
  template <class Cfg, class Rtl, class Own>
  static void drive(const Command& c, const Setup&, Rtl& rtl, Own& own) {
    rtl.cmd_arc_i = c.kind == models::MotionKind::kArc;
    own.arc = c.kind == models::MotionKind::kArc;
    for (int i = 0; i < Cfg::AXES; ++i) {
      const uint64_t d = static_cast<uint64_t>(c.delta[static_cast<size_t>(i)]);
      put_bits(rtl.cmd_delta_i, i * Cfg::ACC_W, Cfg::ACC_W, d);
      own.delta[i] = d;
    }
    rtl.cmd_plane_i = static_cast<uint32_t>(c.plane);
    own.plane = static_cast<unsigned>(c.plane);
    for (int i = 0; i < 2; ++i) {
      const uint64_t cen = static_cast<uint64_t>(c.center[static_cast<size_t>(i)]);
      const uint64_t end = static_cast<uint64_t>(c.end[static_cast<size_t>(i)]);
      put_bits(rtl.cmd_center_i, i * Cfg::COORD_W, Cfg::COORD_W, cen);
      put_bits(rtl.cmd_end_i, i * Cfg::COORD_W, Cfg::COORD_W, end);
      own.center[i] = cen;
      own.end[i] = end;
    }
    rtl.cmd_ccw_i = c.ccw;
    own.ccw = c.ccw;
    rtl.cmd_ops_i = c.ops;
    own.ops = c.ops;
    rtl.cmd_feed_i = c.feed;
    own.feed = c.feed;
  }
  // SystemC mode: the own input signals, bound to both DUTs.
  template <class Cfg>
  struct ScPins {
    static constexpr int DW = Cfg::AXES * Cfg::ACC_W, CW = 2 * Cfg::COORD_W;
    sc_core::sc_signal<bool> arc{"cmd_arc"}, ccw{"cmd_ccw"};
    sc_core::sc_signal<hls::pin_t<DW>> delta{"cmd_delta"};
    sc_core::sc_signal<hls::pin_t<2>> plane{"cmd_plane"};
    sc_core::sc_signal<hls::pin_t<CW>> center{"cmd_center"}, end{"cmd_end"};
    sc_core::sc_signal<hls::pin_t<Cfg::OPS_W>> ops{"cmd_ops"};
    sc_core::sc_signal<hls::pin_t<Cfg::FEED_W + 1>> feed{"cmd_feed"};
    hls::pin_t<DW> delta_value = 0;  // kept: wide pin values allocate
    hls::pin_t<CW> center_value = 0, end_value = 0;
    template <class Dut>
    void bind(Dut& d) {
      d.cmd_arc_i(arc);
      d.cmd_delta_i(delta);
      d.cmd_plane_i(plane);
      d.cmd_center_i(center);
      d.cmd_end_i(end);
      d.cmd_ccw_i(ccw);
      d.cmd_ops_i(ops);
      d.cmd_feed_i(feed);
    }
    void write(const Command& c, const Setup&) {
      arc.write(c.kind == models::MotionKind::kArc);
      for (int i = 0; i < Cfg::AXES; ++i)
        hls::set_pin_field<DW>(delta_value, i * Cfg::ACC_W, Cfg::ACC_W,
                               static_cast<uint64_t>(c.delta[static_cast<size_t>(i)]));
      delta.write(delta_value);
      plane.write(static_cast<unsigned>(c.plane));
      for (int i = 0; i < 2; ++i) {
        hls::set_pin_field<CW>(center_value, i * Cfg::COORD_W, Cfg::COORD_W,
                               static_cast<uint64_t>(c.center[static_cast<size_t>(i)]));
        hls::set_pin_field<CW>(end_value, i * Cfg::COORD_W, Cfg::COORD_W,
                               static_cast<uint64_t>(c.end[static_cast<size_t>(i)]));
      }
      center.write(center_value);
      end.write(end_value);
      ccw.write(c.ccw);
      ops.write(c.ops);
      feed.write(c.feed);
    }
  };

  // --- reference model (models/motion_top_model.h) ------------------------------
  class Reference {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const CoreLimits& l);
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
  static uint64_t work(const Command& c, const CoreLimits& l);

  // --- stimulus ---------------------------------------------------------------
  // Fits the widths: deltas ACC_W, arc coordinates COORD_W, ops OPS_W (and
  // equal to models::motion_arc_ops), slaved |delta| <= ops, plane axes' deltas
  // 0, a feed word in [1, 2^FEED_W]; the arc's circle inside POS_W.
  static void validate(const Command& c, const models::LatticePoint& from, const CoreLimits& l,
                       const std::string& where);
  static Setup random_setup(Rng&) { return {}; }
  // Lines (short and long, every octant, zero-length), arcs in the three
  // planes (radii 2 to 3000 steps, any sweep, full circles, ends off the
  // circle) with and without slaved axes, back and forth; a feed word per
  // move, mostly full.
  static Command random_command(Rng& rng, const CoreLimits& l, const models::LatticePoint& at,
                                const Command& previous);
  // `line X Y Z [A]`, `move DX DY DZ [DA]`, `arc xy|zx|yz CX CY X1 Y1 cw|ccw
  // [END...]` (centre and end absolute in the plane's axes, then the
  // absolute ends of the other axes, which move slaved), `movefeed
  // full|WORD|F` (the feed word of the commands that follow).
  static bool job_directive(JobLine<Adapter>& line);
  // The main regression: a rounded rectangle (lines and quarter arcs in XY),
  // a helix, arcs in ZX and YZ, a seeded random stream, and (`commands` > 0)
  // one with aborts and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const CoreLimits& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core motion_top) ------------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"demo"}; }
  static void setup_from_options(const cli::Args&, Setup&) {}
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const CoreLimits& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::motion_top
