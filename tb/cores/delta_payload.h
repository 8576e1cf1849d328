// The command payload of the cores whose command is one signed delta per axis
// on cmd_delta_i (ACC_W bits an axis, axis i at [i*ACC_W +: ACC_W]): dda_line,
// ppc_line, fixed_ratio. Written once: its conversion to the HLS payload (the
// pins of both lockstep modes follow from the payload's field list,
// hls/fields.h), how a command moves the position, its validation and its
// job directives.
//
// DeltaPayload<A> is the whole payload of a core with no other command input
// (ppc_line, fixed_ratio): the adapter A derives from it and adds its
// reference model and stimulus. A core with more own inputs (dda_line's
// half_preload_i) builds its own payload from the pieces below.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "models/lattice_path.h"
#include "tb/base/args.h"
#include "tb/stimulus/delta_commands.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb::cores {

struct DeltaCommand {
  std::array<int64_t, kMaxAxes> delta{};  // signed steps per axis
};

// The first `axes` deltas, as the models take them.
inline std::vector<int64_t> delta_vector(const DeltaCommand& c, size_t axes) {
  return {c.delta.begin(), c.delta.begin() + static_cast<std::ptrdiff_t>(axes)};
}

// One random delta magnitude of the line cores' random streams: mostly short
// (0-3, 0-40, 0-300 steps), now and then up to 3000.
inline int64_t random_delta_magnitude(Rng& rng) {
  switch (rng.below(8)) {
    case 0:
    case 1:
      return rng.range(0, 3);
    case 2:
    case 3:
    case 4:
      return rng.range(0, 40);
    case 5:
    case 6:
      return rng.range(0, 300);
    default:
      return rng.chance(1, 4) ? rng.range(300, 3000) : rng.range(0, 100);
  }
}

// The position after a delta command from `at`.
inline void apply_deltas(const DeltaCommand& c, models::LatticePoint& at) {
  for (size_t i = 0; i < at.size(); ++i) at[i] += c.delta[i];
}

// The deltas into the HLS payload's delta field (cmd_delta_i: Own::delta,
// one element per axis).
template <class Own>
void deltas_to_own(const DeltaCommand& c, Own& own) {
  for (size_t i = 0; i < std::size(own.delta); ++i)
    own.delta[i] = static_cast<uint64_t>(c.delta[i]);
}

// The ideal path of a delta command, the line from its start to start +
// delta: the deviation metric and the plot polyline of every line core's
// reference model (its Reference derives from it and adds the move stream
// and the bound).
class IdealLine {
 public:
  IdealLine(const models::LatticePoint& start, const DeltaCommand& c)
      : start_(start), end_(end_of(start, c)), distance_(start_, end_) {}
  // Normal distance of a visited point from the line, in steps
  // (models::point_line_distance).
  double error(const models::LatticePoint& p) const { return distance_(p); }
  // The ideal path as a polyline (for plots): the line itself.
  std::vector<std::vector<double>> ideal() const {
    return {{start_.begin(), start_.end()}, {end_.begin(), end_.end()}};
  }

 protected:
  models::LatticePoint start_, end_;

 private:
  static models::LatticePoint end_of(models::LatticePoint p, const DeltaCommand& c) {
    apply_deltas(c, p);
    return p;
  }
  models::LineDistance distance_;  // from start_ to end_
};

// The payload of a core whose only own input is cmd_delta_i; A is the
// adapter deriving from it.
template <class A>
struct DeltaPayload {
  using Command = DeltaCommand;
  struct Setup {};

  // The payload (tb/lockstep/payload_pins.h): cmd_delta_i.
  template <class Own>
  static void to_own(const Command& c, const Setup&, Own& own) {
    deltas_to_own(c, own);
  }

  static void apply(const Command& c, models::LatticePoint& at) { apply_deltas(c, at); }
  // Deltas fit ACC_W (validate_case() checks the end point against POS_W; a
  // line stays in its box).
  static void validate(const Command& c, const models::LatticePoint&, const VariantSpec& l,
                       const std::string& where) {
    validate_deltas<A>(c, l, where);
  }
  static Setup random_setup(Rng&) { return {}; }
  // `line X Y ...` (to an absolute point), `move DX DY ...` (by a delta).
  static bool job_directive(JobLine<A>& line) { return delta_job_directive(line); }
  static void setup_from_options(const cli::Args&, Setup&) {}
};

}  // namespace hwinterp::tb::cores
