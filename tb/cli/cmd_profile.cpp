// hwinterp profile: a stream of moves through the jerk-limited feed profile
// (hls/feed_profile.h), with its registers from the limits, each move's end,
// the peaks seen beside the limits, and the time-optimal S-curve's time for
// a single rest-to-rest move (models/feed_profile_model.h).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "tb/base/text_table.h"
#include "tb/cli/subcommand.h"
#include "tb/lockstep/feed_profile_run.h"

namespace hwinterp::cli {
namespace {

double positive(const Args& args, const std::string& name) {
  const double v = args.real(name);
  if (!(v > 0)) throw UsageError("--" + name + ": " + args.str(name) + " must be > 0");
  return v;
}

// CSV with the header ops,target_speed,end_speed (ops/s; 0 or empty: none).
std::vector<tb::ProfileMove> read_moves(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("--moves: cannot read '" + path + "'");
  std::string line;
  if (!std::getline(in, line) || line.rfind("ops,target_speed,end_speed", 0) != 0)
    throw UsageError("--moves: " + path + ": the first line must be 'ops,target_speed,end_speed'");
  std::vector<tb::ProfileMove> moves;
  for (int n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    std::istringstream row(line);
    std::string f[3];
    for (auto& s : f) std::getline(row, s, ',');
    const std::string where = "--moves: " + path + ":" + std::to_string(n);
    tb::ProfileMove m;
    const double ops = parse_real(f[0], where + " ops");
    if (!(ops >= 1 && ops < 268435456 && ops == static_cast<uint64_t>(ops)))
      throw UsageError(where + ": ops '" + f[0] + "' is not a whole number in 1..2^28-1");
    m.ops = static_cast<uint64_t>(ops);
    m.target_speed = f[1].empty() ? 0 : parse_real(f[1], where + " target_speed");
    m.end_speed = f[2].empty() ? 0 : parse_real(f[2], where + " end_speed");
    if (m.target_speed < 0 || m.end_speed < 0) throw UsageError(where + ": a speed is negative");
    moves.push_back(m);
  }
  if (moves.empty()) throw UsageError("--moves: " + path + " holds no move");
  return moves;
}

int run_profile(int argc, char** argv, int first) {
  Args args("profile",
            "Moves through the jerk-limited feed profile (hls/feed_profile.h): a level trapezoid\n"
            "with an exact braking rule, then a moving sum of L ticks. Units are engine\n"
            "operations (steps along the path) and seconds.");
  args.option("max-velocity", "OPS/S", "the path's velocity limit");
  args.option("max-accel", "OPS/S2", "the path's acceleration limit");
  args.option("max-jerk", "OPS/S3", "the path's jerk limit");
  args.option("clock-hz", "HZ", "the clock", "50e6");
  args.option("ops", "N", "one move of N operations (or --moves)");
  args.option("end-speed", "OPS/S", "with --ops: the speed at its last operation", "0");
  args.option("moves", "FILE", "CSV of moves: ops,target_speed,end_speed");
  args.option("csv", "FILE", "write the speed per tick: tick,seconds,speed");
  args.option("feed-override", "AT:PCT[,AT:PCT...]",
              "the feed override (0..200 %, resolution 1/128) from AT seconds on; a move's "
              "speed above 100 % is capped at the velocity limit (hls/feed_profile.h)");
  args.option("max-clocks", "N",
              "the ceiling on the run's clocks: moves estimated to take more exit 2 before they "
              "run",
              "1e11");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;
  stage_outputs(args, {"csv"}, {"moves"});
  for (const char* n : {"max-velocity", "max-accel", "max-jerk"})
    if (!args.given(n)) throw UsageError(std::string("--") + n + " is required");
  const models::PathLimits limits{positive(args, "max-velocity"), positive(args, "max-accel"),
                                  positive(args, "max-jerk")};
  const double clock_hz = positive(args, "clock-hz");
  if (args.given("ops") == args.given("moves"))
    throw UsageError("give one of --ops N and --moves FILE");
  std::vector<tb::ProfileMove> moves;
  if (args.given("moves")) {
    moves = read_moves(args.str("moves"));
  } else {
    tb::ProfileMove m;
    m.ops = static_cast<uint64_t>(args.integer("ops", 1, (int64_t(1) << 28) - 1));
    m.end_speed = args.real("end-speed", 0, limits.velocity);
    moves.push_back(m);
  }
  std::vector<tb::OverridePoint> ovr;
  if (args.given("feed-override")) {
    try {
      ovr = tb::parse_feed_override(args.str("feed-override"));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--feed-override: ") + e.what());
    }
  }
  tb::ProfileRunResult r;
  try {
    r = tb::run_feed_profile(limits, clock_hz, moves, args.given("csv"),
                             tb::override_steps(ovr, clock_hz), args.real("max-clocks", 1, 1e15));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--max-velocity/--max-accel/--max-jerk/--clock-hz: ") + e.what());
  }
  if (args.given("csv")) {
    std::ostringstream csv;
    csv << "tick,seconds,speed\n";
    for (size_t i = 0; i < r.tick_speed.size(); ++i)
      csv << i << ',' << fmt("%.9g", i * r.tick_seconds) << ',' << fmt("%.9g", r.tick_speed[i])
          << '\n';
    write_text_file(output_path("csv"), csv.str(), "--csv");
  }
  const double last_s = r.move_end_clock.back() / clock_hz, rest_s = r.rest_clock / clock_hz;
  const bool single_rest = moves.size() == 1 && moves[0].end_speed == 0;
  // The optimum at the limits the registers really give (each <= the limit).
  const models::PathLimits real{r.regs.level_speed * r.regs.max_level, r.regs.accel, r.regs.jerk};
  const double opt = single_rest ? models::optimal_move_time(moves[0].ops, real) : 0;
  const double opt_limits = single_rest ? models::optimal_move_time(moves[0].ops, limits) : 0;
  if (r.regs.accel < 0.99 * limits.accel)
    std::cout << "note: the moving sum is capped at " << r.regs.len
              << " ticks, so the acceleration is " << fmt("%.6g", r.regs.accel) << " of "
              << fmt("%.6g", limits.accel) << " (A/J is longer than the build's L * tick)\n";

  TextTable t({"figure", "value", "limit"});
  t.add_row({"registers q, L", std::to_string(r.regs.q) + ", " + std::to_string(r.regs.len), ""});
  t.add_row({"level speed (ops/s), levels",
             fmt("%.6g", r.regs.level_speed) + ", " + std::to_string(r.regs.max_level), ""});
  t.add_row({"peak speed (ops/s)", fmt("%.6g", r.peak_speed), fmt("%.6g", limits.velocity)});
  t.add_row(
      {"peak accel (ops/s^2, per tick)", fmt("%.6g", r.peak_accel), fmt("%.6g", limits.accel)});
  t.add_row({"peak jerk (ops/s^3, per tick)", fmt("%.6g", r.peak_jerk), fmt("%.6g", limits.jerk)});
  t.add_row({"last operation (s)", fmt("%.6f", last_s), ""});
  t.add_row({"speed at the last operation (ops/s)", fmt("%.6g", r.move_end_speed.back()),
             fmt("%.6g", moves.back().end_speed)});
  t.add_row({"at rest (s)", fmt("%.6f", rest_s), ""});
  if (single_rest) {
    t.add_row({"time-optimal S-curve (s)", fmt("%.6f", opt), ""});
    t.add_row({"ours / optimal at the registers' limits", fmt("%.5f", rest_s / opt), ""});
    t.add_row({"ours / optimal at the given limits", fmt("%.5f", rest_s / opt_limits), ""});
  }
  std::cout << t.render();

  Json report = Json::object();
  report["clock_hz"] = clock_hz;
  report["limits"] = {
      {"velocity", limits.velocity}, {"accel", limits.accel}, {"jerk", limits.jerk}};
  report["registers"] = {{"q", r.regs.q},
                         {"len", r.regs.len},
                         {"level_speed", r.regs.level_speed},
                         {"max_level", r.regs.max_level},
                         {"accel", r.regs.accel},
                         {"jerk", r.regs.jerk}};
  Json ends = Json::array();
  for (uint64_t c : r.move_end_clock) ends.push_back(c);
  report["move_end_clocks"] = std::move(ends);
  report["move_end_speeds"] = r.move_end_speed;
  report["rest_clock"] = r.rest_clock;
  Json jovr = Json::array();
  for (const tb::OverridePoint& o : ovr)
    jovr.push_back(
        {{"at_s", o.at_s}, {"percent", o.percent}, {"word", models::override_word(o.percent)}});
  report["feed_override"] = std::move(jovr);
  report["ops"] = r.ops;
  report["peak"] = {{"speed", r.peak_speed}, {"accel", r.peak_accel}, {"jerk", r.peak_jerk}};
  report["seconds_last_op"] = last_s;
  report["seconds_at_rest"] = rest_s;
  report["optimal_seconds"] = single_rest ? Json(opt) : Json();
  report["optimal_seconds_given_limits"] = single_rest ? Json(opt_limits) : Json();
  maybe_write_json(args, report);
  return kExitOk;
}

}  // namespace

HWINTERP_SUBCOMMAND("profile", "moves through the jerk-limited feed profile", 35, run_profile);

}  // namespace hwinterp::cli
