// log_stepper's adapter to the shared lockstep harness: the command payload
// and its pins, the reference model, the stimulus, the checks and the
// command-line options. Everything else (runners, scoreboard, monitors,
// reports, traces) is the harness's.
//
// Command: one logarithmic curve A = a ln(1 + b X) of paper
// 001_46110e999325a38e.txt (D1, spiral S, cone C, rake r, dl, x_end) and the
// steps per unit of the axes, as the core's fixed-point words
// (models/log_stepper_model.h, computed for the variant's format). The curve
// starts where the axes are. No setup.
// Reference: the bit-exact model's points, each segment a DDA line with half
// preload (models/dda_line_model.h): the moves, and the path error against
// the running segment's line, within the 4-axis DDA bound. Checks of its own
// (tb/scoreboard/scoreboard.h) at every coarse point, where the step/dir
// outputs have taken the axes when its segment ends:
//   point_error_steps  max over axes of |lattice - the double model's point
//                      rounded to steps| (models/log_curve.h), limit 1 step;
//                      `points` counts them (the paper's stop rule); the
//                      core must make exactly the double model's points
//   erpa_rad           |a ln(1 + b X) - A| of the lattice point converted
//                      back to mm and rad (reported).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hls/log_stepper.h"
#include "models/dda_line_model.h"
#include "models/log_curve.h"
#include "models/log_stepper_model.h"
#include "tb/base/args.h"
#include "tb/base/case_result.h"
#include "tb/base/variant_spec.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb {
template <class A>
class JobLine;
}

namespace hwinterp::tb::cores::log_stepper {

// The variant's word format.
models::LogFixedFormat word_format(const VariantSpec& l);

struct Adapter {
  static constexpr const char* kName = "log_stepper";
  static constexpr const char* kSummary =
      "4-axis odd-even log-curve stepper (001 paper): fixed-point coarse engine + DDA fine stage";
  template <class Cfg>
  using Hls = hls::LogStepper<Cfg>;

  struct Command {
    models::LogCurveParams curve;
    models::LogStepScale scale;
    models::LogFixedCommand words;
    std::array<int64_t, 4> end{};  // where the curve ends, relative to its start
    uint64_t points = 0;           // coarse points
    uint64_t work = 0;             // DDA iterations plus coarse clocks, at most
    uint64_t operations = 0;       // DDA iterations of its segments (feed ticks)
  };
  struct Setup {};

  // The command for a curve on variant l; throws cli::UsageError naming the
  // value that keeps it off the core (`where` says whose it is).
  static Command make_command(const models::LogCurveParams& curve,
                              const models::LogStepScale& scale, const VariantSpec& l,
                              const std::string& where);

  // --- payload (hls/log_stepper.h Own; tb/lockstep/payload_pins.h) -----------
  template <class Own>
  static void to_own(const Command& c, const Setup&, Own& own) {
    own.b = c.words.b;
    own.ab = c.words.ab;
    own.dl = c.words.dl;
    own.x_end = c.words.x_end;
    for (size_t i = 0; i < 4; ++i) own.k[i] = c.words.k[i];
  }

  // --- reference model ---------------------------------------------------------
  class Reference {
   public:
    Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
              const VariantSpec& l);
    bool next(Move& m);
    // Normal distance of a visited point from the running segment's line.
    double error(const models::LatticePoint& p) const;
    models::ErrorBound bound() const { return models::dda_error_bound(4, models::Preload::kHalf); }
    // The double model's curve in steps, for plots.
    std::vector<std::vector<double>> ideal() const;
    // The coarse-point checks (header comment).
    void check(const models::LatticePoint& at, CaseResult& r, std::vector<std::string>& failures);
    void finish(const models::LatticePoint& at, CaseResult& r, std::vector<std::string>& failures);

   private:
    void check_point(size_t index, const models::LatticePoint& at, CaseResult& r,
                     std::vector<std::string>& failures);
    models::LatticePoint start_, seg_start_, seg_end_;
    models::LogFixedStream points_;
    models::LogFixedPoint point_;  // the end of the running segment
    std::optional<models::DdaMoveStream> seg_;
    uint64_t base_ = 0, seg_iterations_ = 0;  // DDA iterations before the running segment, in it
    std::vector<size_t> pending_;             // segment ends passed, not yet checked
    std::array<int64_t, 4> last_step_{};      // the move next() returned last
    size_t checked_ = 0;
    std::shared_ptr<const models::LogRun> exact_;  // the double model's points
    models::LogStepScale scale_;
  };
  static void apply(const Command& c, models::LatticePoint& at) {
    for (size_t i = 0; i < 4 && i < at.size(); ++i) at[i] += c.end[i];
  }
  static uint64_t work(const Command& c, const VariantSpec&) { return c.work; }
  // The feed ticks (engine operations) the command takes, exactly: a feed
  // profile's move for it ends on its last (tb/lockstep/case_profile.h).
  static uint64_t operations(const Command& c, const VariantSpec&) { return c.operations; }
  // The curve turns (and its segments' lengths change) within a command:
  // axis speed only.
  static constexpr bool kAxisFollowsPath = false;

  // --- stimulus ---------------------------------------------------------------
  static void validate(const Command& c, const models::LatticePoint& from, const VariantSpec& l,
                       const std::string& where);
  static Setup random_setup(Rng&) { return {}; }
  // Short curves (x_end up to 3 mm) over the accepted ranges: D1 4-20 mm,
  // spiral 15-40 deg, cone 2-15 deg, rake 2-20 deg, dl 0.1-0.5 mm, 20-400
  // steps/mm, 5-50 steps/deg.
  static Command random_command(Rng& rng, const VariantSpec& l, const models::LatticePoint& at,
                                const Command& previous);
  // `curve D1 S C R DL XEND [STEPS_PER_MM [STEPS_PER_DEG]]`.
  static bool job_directive(JobLine<Adapter>& line);
  // The paper's case: D1 10 mm, S 30, C 5, r 8 deg, dl 0.2 mm, X to 30 mm,
  // 1000 steps/mm and 1000 steps/deg (152 points).
  static std::vector<Case<Adapter>> paper_cases(const VariantSpec& l,
                                                const RunSettings<Adapter>& settings);
  // The main regression: the paper case at full feed, a seeded random
  // stream, and (`commands` > 0) a random stream with aborts and feed holds.
  static std::vector<Case<Adapter>> regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed);

  // --- command line (hwinterp cosim --core log_stepper) ----------------------
  static void declare_options(cli::Args& args);
  static std::vector<std::string> sources() { return {"d1", "paper-log"}; }
  static void setup_from_options(const cli::Args&, Setup&) {}
  static std::vector<Case<Adapter>> cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings);
};

}  // namespace hwinterp::tb::cores::log_stepper
