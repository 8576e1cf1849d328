// hwinterp gcode: a part program through motion_top in lockstep. The program
// (an RS274/NGC subset, tb/gcode/ngc_reader.h, or LinuxCNC's `rs274 -g`
// canonical commands with --canon, tb/gcode/canon_reader.h) is compiled move
// by move into motion_top commands (tb/gcode/motion_compiler.h: lattice
// points rounded from absolute coordinates, arcs on the arc engine, feed
// words) and streamed into the lockstep bench: the HLS core against the RTL
// on every clock, both against the reference model (every move, every end
// point, every visited point within its bound), the step/dir timing on every
// axis. On top, every visited lattice point is measured against the
// programmed path of its move (tb/gcode/contour.h): the contour error.
// Memory does not grow with the program: moves, commands and checks stream.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <type_traits>

#include "hwinterp_configs.h"
#include "hwinterp_core_adapters.h"
#include "hwinterp_variants.h"
#include "tb/cli/subcommand.h"
#include "tb/cli/text_table.h"
#include "tb/cores/motion_top/motion_top_adapter.h"
#include "tb/gcode/contour.h"
#include "tb/gcode/machine.h"
#include "tb/gcode/motion_compiler.h"
#include "tb/gcode/program_file.h"
#include "tb/lockstep/bench_run.h"
#include "tb/report/cosim_report.h"
#include "tb/report/output_path.h"

namespace hwinterp::cli {

namespace {

using MotionAdapter = tb::cores::motion_top::Adapter;

constexpr const char* kAxisName[] = {"x", "y", "z", "a", "b", "c"};

// One command on its way to the core, and the move it belongs to.
struct Pending {
  uint64_t command = 0;  // 0-based, as the scoreboard counts
  uint64_t move = 0;     // MoveReport::index
  uint64_t line = 0;     // the move's source line
  std::shared_ptr<const gcode::ContourPath> path;
};

// The worst contour error, and where.
struct ContourMax {
  double mm = 0, steps = 0;
  uint64_t move = 0, line = 0;
};

// Streams the compiler's commands into the bench, and follows the moves the
// core makes: contour error per visited point, the lattice point each
// G-code move ends on, the moves CSV.
class Program final : public tb::ItemSource<MotionAdapter>, public tb::MoveObserver {
 public:
  Program(std::unique_ptr<gcode::MoveSource> source, const gcode::Machine& machine,
          const gcode::MotionWidths& widths, gcode::FeedMode mode, const std::string& name,
          std::ostream* moves_csv, std::ostream* points_csv)
      : source_(std::move(source)),
        machine_(machine),
        compiler_(*source_, machine, widths, mode, name,
                  [this](const gcode::MoveReport& r) { reports_.push_back(r); }),
        axes_(widths.axes),
        moves_csv_(moves_csv),
        points_csv_(points_csv),
        last_reached_(static_cast<size_t>(widths.axes), 0) {
    if (moves_csv_) {
      *moves_csv_ << "move,line,kind,x_mm,y_mm,z_mm,a_deg";
      for (int i = 0; i < axes_; ++i) *moves_csv_ << ',' << kAxisName[i] << "_steps";
      *moves_csv_ << ",commands,chords,programmed_s,feed_words_s,max_contour_mm\n";
    }
    if (points_csv_) *points_csv_ << "move,x_mm,y_mm,z_mm,error_mm\n";
  }

  // tb::ItemSource: the next command of the program.
  bool next(tb::Item<MotionAdapter>& it) override {
    models::MotionCommand c;
    if (!compiler_.next(c)) {
      flush_rows();
      return false;
    }
    const gcode::CommandInfo& info = compiler_.info();
    if (!path_ || path_move_ != info.move_index) {
      path_ =
          std::make_shared<gcode::ContourPath>(machine_, compiler_.move_start(), compiler_.move());
      path_move_ = info.move_index;
    }
    pending_.push_back({commands_++, info.move_index, info.line, path_});
    it = tb::command_item<MotionAdapter>(c);
    flush_rows();
    return true;
  }

  // tb::MoveObserver: a move of command `command`.
  void move(const models::LatticePoint& at, uint64_t command) override {
    const Pending* p = find(command);
    if (!p) return;
    const gcode::ContourError e = p->path->error(lattice6(at));
    move_max_[p->move] = std::max(move_max_[p->move], e.mm);
    if (e.mm > max_.mm) {
      max_.mm = e.mm;
      max_.steps = e.steps;
      max_.move = p->move;
      max_.line = p->line;
    }
    if (points_csv_) {
      *points_csv_ << p->move;
      for (int i = 0; i < 3; ++i)
        *points_csv_ << ','
                     << (i < axes_ ? static_cast<double>(at[static_cast<size_t>(i)]) /
                                         static_cast<double>(machine_.steps_per_unit[i])
                                   : 0.0);
      *points_csv_ << ',' << e.mm << '\n';
    }
    ++points_;
  }

  // tb::MoveObserver: command `command` completed at `at`.
  void done(uint64_t command, const models::LatticePoint& at) override {
    while (!pending_.empty() && pending_.front().command < command) pending_.pop_front();
    if (!pending_.empty() && pending_.front().command == command) {
      reached_[pending_.front().move] = at;
      last_reached_ = at;
      pending_.pop_front();
    }
    flush_rows();
  }

  const gcode::MotionCompiler& compiler() const { return compiler_; }
  const gcode::ReaderStats& reader_stats() const { return source_->stats(); }
  const ContourMax& max() const { return max_; }
  uint64_t points() const { return points_; }

  // The rows of every reported move whose last command the core completed.
  void flush_rows() {
    while (!reports_.empty()) {
      const gcode::MoveReport& r = reports_.front();
      std::optional<models::LatticePoint> at;  // where the move ended, once known
      if (r.commands == 0) {
        at = last_reached_;
      } else if (auto f = reached_.find(r.index); f != reached_.end() && !still_pending(r.index)) {
        at = f->second;
      }
      if (!at) return;
      if (moves_csv_) {
        *moves_csv_ << r.index << ',' << r.line << ',' << gcode::to_string(r.kind);
        for (int i = 0; i < 4; ++i) *moves_csv_ << ',' << r.end[static_cast<size_t>(i)];
        for (int i = 0; i < axes_; ++i)
          *moves_csv_ << ',' << (at->empty() ? 0 : (*at)[static_cast<size_t>(i)]);
        *moves_csv_ << ',' << r.commands << ',' << r.chords << ',' << r.programmed_s << ','
                    << r.programmed_words_s << ',' << move_max_[r.index] << '\n';
      }
      if (!at->empty()) {
        for (int i = 0; i < axes_; ++i)
          if ((*at)[static_cast<size_t>(i)] != r.end_steps[static_cast<size_t>(i)])
            end_mismatches_.push_back(r.index);
      }
      reached_.erase(r.index);
      move_max_.erase(r.index);
      reports_.pop_front();
    }
  }
  const std::vector<uint64_t>& end_mismatches() const { return end_mismatches_; }
  bool all_rows_written() const { return reports_.empty(); }

 private:
  static std::array<int64_t, 6> lattice6(const models::LatticePoint& at) {
    std::array<int64_t, 6> a{};
    for (size_t i = 0; i < at.size() && i < a.size(); ++i) a[i] = at[i];
    return a;
  }
  const Pending* find(uint64_t command) const {
    for (const Pending& p : pending_)
      if (p.command == command) return &p;
    return nullptr;
  }
  bool still_pending(uint64_t move) const {
    return std::any_of(pending_.begin(), pending_.end(),
                       [&](const Pending& p) { return p.move == move; });
  }

  std::unique_ptr<gcode::MoveSource> source_;
  gcode::Machine machine_;
  gcode::MotionCompiler compiler_;
  int axes_;
  std::ostream* moves_csv_;
  std::ostream* points_csv_;
  std::deque<Pending> pending_;                       // commands made and not yet completed
  std::deque<gcode::MoveReport> reports_;             // moves compiled, rows not yet written
  std::map<uint64_t, models::LatticePoint> reached_;  // move -> where its last command ended
  std::map<uint64_t, double> move_max_;               // move -> its worst contour error
  models::LatticePoint last_reached_;  // where the last completed command ended (the origin first)
  std::shared_ptr<const gcode::ContourPath> path_;
  uint64_t path_move_ = 0;
  uint64_t commands_ = 0, points_ = 0;
  ContourMax max_;
  std::vector<uint64_t> end_mismatches_;
};

// This process's peak resident memory in KiB (VmHWM: since exec, so not the
// parent's), 0 where /proc does not say.
uint64_t peak_rss_kib() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::strtoull(line.c_str() + 6, nullptr, 10);
  return 0;
}

// The motion_top variant with this many axes or the one named, as a typed run.
using RunMaker = std::function<std::unique_ptr<tb::BenchRun>(std::vector<tb::Case<MotionAdapter>>,
                                                             const tb::BenchOptions&)>;
struct VariantChoice {
  tb::CoreLimits limits;
  RunMaker make;
};

template <class Cfg>
void offer_variant(std::vector<VariantChoice>& out) {
  const tb::CoreLimits l = tb::limits_of<Cfg>();
  out.push_back({l, [l](std::vector<tb::Case<MotionAdapter>> cases, const tb::BenchOptions& o) {
                   return tb::make_run<MotionAdapter, Cfg>(l, std::move(cases), o);
                 }});
}

template <class A, class Cfg>
void collect(std::vector<VariantChoice>& out) {
  if constexpr (std::is_same_v<A, MotionAdapter>) offer_variant<Cfg>(out);
}

std::vector<VariantChoice> motion_variants() {
  std::vector<VariantChoice> v;
#define HWINTERP_GCODE_VARIANT(core, variant) collect<tb::cores::core::Adapter, variant##_cfg>(v);
  HWINTERP_VARIANTS(HWINTERP_GCODE_VARIANT)
#undef HWINTERP_GCODE_VARIANT
  return v;
}

std::string join_variants(const std::vector<VariantChoice>& v) {
  std::string s;
  for (const auto& c : v) s += (s.empty() ? "" : ", ") + c.limits.variant;
  return s;
}

int run_gcode(int argc, char** argv, int first) {
  Args args(
      "gcode",
      "A part program through motion_top in lockstep (HLS vs RTL on every clock, both\n"
      "against the reference model), with the contour error of every visited lattice\n"
      "point against the programmed path.\n"
      "Usage: hwinterp gcode FILE.ngc [options]   or   hwinterp gcode --canon FILE [options]\n"
      "FILE.ngc: an RS274/NGC subset (G0-G3 with IJK or R, G17-G19, G20/G21, G90/G91,\n"
      "G90.1/G91.1, F; words that do not change the path are counted). Anything else\n"
      "exits 2 naming file, line and word: run the program through LinuxCNC's\n"
      "interpreter (rs274 -g FILE out.canon) and use --canon.");
  args.option("canon", "FILE", "read LinuxCNC's canonical commands (rs274 -g output) from FILE")
      .option("machine", "FILE",
              "machine description, JSON (tb/gcode/machine.h; default 1000 steps/mm, 50 MHz)")
      .option("variant", "NAME", "motion_top variant (default: the first with the machine's axes)")
      .option("mode", "systemc|direct", "lockstep mode", "systemc")
      .option("feed", "full|programmed",
              "full: every move at full feed (the lattice points are the same; machining time "
              "computed from the feed words); programmed: simulate the programmed feeds",
              "full")
      .option("moves-csv", "FILE", "one row per motion move: programmed end, lattice end reached")
      .option("plot", "FILE.png", "the path, coloured by contour error (matplotlib)")
      .option("vcd", "FILE", "VCD trace of the run")
      .option("fst", "FILE", "FST trace of the run")
      .option("trace-window", "N", "keep only the last N clocks in the trace")
      .option("progress", "N", "progress line every N clocks (0: none)", "5000000");

  // The program: the first argument, unless --canon names it.
  std::string program;
  int from = first;
  if (from < argc && argv[from][0] != '-') program = argv[from++];
  if (parse_or_help(args, argc, argv, from)) return kExitOk;
  if (program.empty() == !args.given("canon"))
    throw UsageError(program.empty() ? "give a program: hwinterp gcode FILE.ngc, or --canon FILE"
                                     : "give one program: FILE.ngc or --canon FILE, not both");
  const bool canon = args.given("canon");
  if (canon) program = args.str("canon");
  const std::string mode = args.choice("mode", {"systemc", "direct"});
  const gcode::FeedMode feed_mode = args.choice("feed", {"full", "programmed"}) == "full"
                                        ? gcode::FeedMode::kFull
                                        : gcode::FeedMode::kProgrammed;
  const gcode::Machine machine =
      args.given("machine") ? gcode::load_machine(args.str("machine")) : gcode::Machine{};

  // The variant: named, or the first with at least the machine's axes.
  const std::vector<VariantChoice> variants = motion_variants();
  int machine_axes = 0;
  for (int i = 0; i < 6; ++i)
    if (machine.has_axis[i]) machine_axes = i + 1;
  const VariantChoice* chosen = nullptr;
  for (const auto& v : variants) {
    if (args.given("variant") ? v.limits.variant == args.str("variant")
                              : v.limits.axes >= machine_axes) {
      chosen = &v;
      break;
    }
  }
  if (!chosen)
    throw UsageError(args.given("variant")
                         ? "--variant: '" + args.str("variant") +
                               "' is not a motion_top variant (" + join_variants(variants) + ")"
                         : "the machine has " + std::to_string(machine_axes) +
                               " axes; no motion_top variant has that many (" +
                               join_variants(variants) + ")");
  const tb::CoreLimits& l = chosen->limits;
  if (l.axes < machine_axes)
    throw UsageError("--variant: " + l.variant + " has " + std::to_string(l.axes) +
                     " axes, the machine " + std::to_string(machine_axes));
  gcode::MotionWidths widths;
  widths.axes = l.axes;
  widths.acc_w = l.param("ACC_W");
  widths.coord_w = l.param("COORD_W");
  widths.ops_w = l.param("OPS_W");
  widths.feed_w = l.feed_w;

  // Every output can be written, or nothing runs.
  tb::BenchOptions options;
  trace_from_args(args, options);
  check_outputs_writable(args, {"moves-csv", "plot", "vcd", "fst"});
  std::unique_ptr<std::ofstream> moves_csv, points_csv;
  if (args.given("moves-csv")) moves_csv = std::make_unique<std::ofstream>(args.str("moves-csv"));
  const std::string points_path = args.given("plot") ? args.str("plot") + ".points.csv" : "";
  if (!points_path.empty()) points_csv = std::make_unique<std::ofstream>(points_path);

  auto source = canon ? gcode::open_canon(program) : gcode::open_ngc(program);
  auto prog = std::make_shared<Program>(std::move(source), machine, widths, feed_mode, program,
                                        moves_csv.get(), points_csv.get());

  // One case from the origin, the machine's step/dir timing, feed_i running.
  tb::Case<MotionAdapter> c;
  c.name = program;
  c.start.assign(static_cast<size_t>(l.axes), 0);
  c.settings = tb::default_settings<MotionAdapter>(l);
  c.settings.feed = l.full_feed();
  c.settings.timing = {static_cast<uint32_t>(machine.timing.step_len),
                       static_cast<uint32_t>(machine.timing.step_space),
                       static_cast<uint32_t>(machine.timing.dir_setup),
                       static_cast<uint32_t>(machine.timing.dir_hold)};
  c.more = prog;

  options.mode = mode;
  options.progress_every = static_cast<uint64_t>(args.integer("progress", 0, INT64_MAX));
  options.observer = prog.get();
  std::vector<tb::Case<MotionAdapter>> cases;
  cases.push_back(std::move(c));
  const std::unique_ptr<tb::BenchRun> run = chosen->make(std::move(cases), options);

  std::cout << "hwinterp gcode: " << program << (canon ? " (canon)" : "") << " on " << l.variant
            << ", mode " << mode << ", feed " << args.str("feed") << "\n"
            << std::flush;
  if (mode == "direct")
    run->run_direct();
  else
    tb::run_systemc({run.get()});
  run->close();
  prog->flush_rows();

  const auto& results = run->results();
  const tb::CaseResult& r = results.front();
  const gcode::CompileTotals& t = prog->compiler().totals();
  bool ok = tb::all_passed(results) && r.completed && prog->end_mismatches().empty() &&
            prog->all_rows_written();
  const double clock = static_cast<double>(machine.clock_hz);
  const double simulated_s = static_cast<double>(r.cycles) / clock;
  const ContourMax& m = prog->max();

  std::cout << tb::case_table(results) << tb::failure_details(results);
  TextTable s({"", "value"});
  const gcode::ReaderStats& rs = prog->reader_stats();
  s.add_row({"moves (traverse / feed / arc)",
             std::to_string(t.moves) + " (" + std::to_string(rs.traverses) + " / " +
                 std::to_string(rs.feeds) + " / " + std::to_string(rs.arcs) + ")"});
  s.add_row({"commands (lines / arcs)", std::to_string(t.commands) + " (" +
                                            std::to_string(t.line_commands) + " / " +
                                            std::to_string(t.arc_commands) + ")"});
  s.add_row({"arcs run as chords / split arcs",
             std::to_string(t.chord_arcs) + " / " + std::to_string(t.split_arcs)});
  std::string steps;
  for (int i = 0; i < l.axes; ++i)
    steps += (i ? " " : "") + std::string(kAxisName[i]) + "=" +
             std::to_string(r.steps[static_cast<size_t>(i)]);
  s.add_row({"steps per axis", steps});
  s.add_row({"programmed machining time (F, rapids)", fmt("%.3f", t.programmed_s) + " s"});
  s.add_row({"machining time from the feed words", fmt("%.3f", t.programmed_words_s) + " s"});
  s.add_row({"simulated (" + args.str("feed") + " feed, " + fmt("%.3f", clock / 1e6) + " MHz)",
             std::to_string(r.cycles) + " clocks = " + fmt("%.6f", simulated_s) + " s"});
  s.add_row({"max contour error", fmt("%.6f", m.mm) + " mm = " + fmt("%.3f", m.steps) +
                                      " steps (move " + std::to_string(m.move) + ", line " +
                                      std::to_string(m.line) + ")"});
  s.add_row({"visited lattice points", std::to_string(prog->points())});
  std::cout << s.render();
  if (!prog->end_mismatches().empty())
    std::cout << "FAIL: " << prog->end_mismatches().size()
              << " moves ended off their rounded programmed end (first: move "
              << prog->end_mismatches().front() << ")\n";

  Json report = tb::aggregate_json(results);
  report["program"] = program;
  report["canon"] = canon;
  report["variant"] = l.variant;
  report["feed_mode"] = args.str("feed");
  report["moves"] = t.moves;
  report["traverses"] = rs.traverses;
  report["feeds"] = rs.feeds;
  report["arcs"] = rs.arcs;
  report["commands"] = t.commands;
  report["line_commands"] = t.line_commands;
  report["arc_commands"] = t.arc_commands;
  report["chord_arcs"] = t.chord_arcs;
  report["chords"] = t.chords;
  report["split_arcs"] = t.split_arcs;
  report["programmed_time_s"] = t.programmed_s;
  report["feed_word_time_s"] = t.programmed_words_s;
  report["simulated_clocks"] = r.cycles;
  report["simulated_time_s"] = simulated_s;
  report["clock_hz"] = machine.clock_hz;
  report["max_contour_error_mm"] = m.mm;
  report["max_contour_error_steps"] = m.steps;
  report["max_contour_error_move"] = m.move;
  report["max_contour_error_line"] = m.line;
  report["visited_points"] = prog->points();
  report["end_mismatches"] = prog->end_mismatches().size();
  report["peak_rss_kib"] = peak_rss_kib();

  if (moves_csv) {
    moves_csv->close();
    if (!*moves_csv) throw UsageError("--moves-csv: error writing '" + args.str("moves-csv") + "'");
  }
  if (points_csv) {
    points_csv->close();
    if (!*points_csv) throw UsageError("--plot: error writing '" + points_path + "'");
    const std::string cmd = "'" HWINTERP_PYTHON "' '" HWINTERP_SCRIPTS_DIR "/plot_gcode.py' '" +
                            points_path + "' -o '" + args.str("plot") + "' --title '" + program +
                            "' > /dev/null";
    if (std::system(cmd.c_str()) != 0) {
      std::cout << "plot: failed (" << cmd << ")\n";
      ok = false;
    } else {
      std::cout << "plot: " << args.str("plot") << "\n";
      std::remove(points_path.c_str());
    }
  }
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  report["passed"] = ok;
  maybe_write_json(args, report);
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("gcode", "a part program (G-code or rs274 canon) through motion_top", 15,
                    run_gcode);

}  // namespace hwinterp::cli
