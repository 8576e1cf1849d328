#include "tb/cores/log_stepper/log_stepper_adapter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "models/common.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb::cores::log_stepper {

using cli::UsageError;

namespace {
using models::kPi;

double steps_per_rad(const models::LogStepScale& s) { return s.a_per_deg * 180 / kPi; }

// A uniformly drawn real in [lo, hi).
double uniform(Rng& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng.next() >> 11) * 0x1.0p-53;
}

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

}  // namespace

models::LogFixedFormat word_format(const VariantSpec& l) {
  return {l.param("INT_W"), l.param("FRAC_W")};
}

Adapter::Command Adapter::make_command(const models::LogCurveParams& curve,
                                       const models::LogStepScale& scale, const VariantSpec& l,
                                       const std::string& where) {
  try {
    models::validate(curve);
  } catch (const std::invalid_argument& e) {
    throw UsageError(where + ": " + e.what());
  }
  const auto positive = [&](double v, const char* what) {
    if (!(std::isfinite(v) && v > 0))
      throw UsageError(where + ": " + what + " " + num(v) + " must be > 0");
  };
  positive(scale.x_per_mm, "steps per mm");
  positive(scale.a_per_deg, "steps per deg");
  Command c;
  c.curve = curve;
  c.scale = scale;
  const models::LogFixedFormat f = word_format(l);
  c.words = models::log_fixed_command(curve, scale, f);
  const std::string why = models::log_fixed_check(c.words, f, l.param("SEG_W"), l.pos_w);
  if (!why.empty()) throw UsageError(where + ": the curve does not fit " + l.variant + ": " + why);
  // Where it ends, its points and its work (coarse clocks per point from the
  // program, hls/log_stepper.h; DDA iterations per segment).
  const int w = f.width(), k = l.param("MUL_K");
  const uint64_t mul = static_cast<uint64_t>((w + k - 1) / k);
  const uint64_t cycle_clocks = 25 * (mul + 1) + static_cast<uint64_t>((w + f.frac_w + 1) / 2) +
                                2 * static_cast<uint64_t>(f.frac_w + 1) + 13;
  models::LogFixedStream s(c.words, f);
  models::LogFixedPoint p;
  std::array<int64_t, 4> prev{};
  c.work = 2 * (mul + 1) + 4;
  while (s.next(p)) {
    ++c.points;
    std::vector<int64_t> d(4);
    for (size_t i = 0; i < 4; ++i) d[i] = p.pos[i] - prev[i];
    c.operations += models::dda_iterations(d);
    c.work += models::dda_iterations(d) + cycle_clocks / 2 + 1;
    prev = p.pos;
  }
  c.end = prev;
  return c;
}

// --- reference model ----------------------------------------------------------

Adapter::Reference::Reference(const models::LatticePoint& start, const Command& c, const Setup&,
                              const VariantSpec& l)
    : start_(start),
      seg_start_(start),
      seg_end_(start),
      points_(c.words, word_format(l)),
      exact_(std::make_shared<const models::LogRun>(models::run_log_interpolation(c.curve))),
      scale_(c.scale) {}

bool Adapter::Reference::next(Move& m) {
  for (;;) {
    if (seg_) {
      models::DdaMove dm;
      if (seg_->next(dm)) {
        m.index = base_ + dm.iteration;
        m.step = {};
        for (size_t i = 0; i < 4; ++i) {
          m.step[i] = static_cast<int8_t>(dm.step[i]);
          last_step_[i] = dm.step[i];
        }
        return true;
      }
      pending_.push_back(point_.index);
      seg_.reset();
      base_ += seg_iterations_;
    }
    if (!points_.next(point_)) return false;
    seg_start_ = seg_end_;
    std::vector<int64_t> delta(4);
    for (size_t i = 0; i < 4; ++i) {
      seg_end_[i] = start_[i] + point_.pos[i];
      delta[i] = seg_end_[i] - seg_start_[i];
    }
    seg_iterations_ = models::dda_iterations(delta);
    seg_.emplace(seg_start_, delta, models::Preload::kHalf);
  }
}

double Adapter::Reference::error(const models::LatticePoint& p) const {
  return models::point_line_distance(p, seg_start_, seg_end_);
}

std::vector<std::vector<double>> Adapter::Reference::ideal() const {
  const double k[4] = {scale_.x_per_mm, scale_.y_per_mm, scale_.z_per_mm, steps_per_rad(scale_)};
  std::vector<std::vector<double>> out;
  for (const auto& p : exact_->points) {
    const double v[4] = {p.x, p.y, p.z, p.a};
    std::vector<double> row(start_.size());
    for (size_t i = 0; i < row.size(); ++i)
      row[i] = static_cast<double>(start_[i]) + (i < 4 ? v[i] * k[i] : 0.0);
    out.push_back(std::move(row));
  }
  return out;
}

void Adapter::Reference::check_point(size_t index, const models::LatticePoint& at, CaseResult& r,
                                     std::vector<std::string>& failures) {
  ++checked_;
  if (!r.visited.empty()) r.checkpoints.push_back(at);
  CoreCheck& pe = r.core_check("point_error_steps", "points", 1.0);
  ++pe.count;
  if (index >= exact_->points.size()) {
    failures.push_back("coarse point " + std::to_string(index) + ": the double model stops at " +
                       std::to_string(exact_->count()) + " points");
    return;
  }
  const models::LogPoint& p = exact_->points[index];
  const auto want = models::log_lattice(p, exact_->params, scale_);
  int64_t worst = 0;
  size_t axis = 0;
  for (size_t i = 0; i < 4; ++i) {
    const int64_t d = std::llabs(at[i] - start_[i] - want[i]);
    if (d > worst) {
      worst = d;
      axis = i;
    }
  }
  pe.max = std::max(pe.max, static_cast<double>(worst));
  if (worst > 1) {
    static const char* const names[] = {"X", "Y", "Z", "A"};
    failures.push_back("coarse point " + std::to_string(index) + ": axis " + names[axis] + " at " +
                       std::to_string(at[axis] - start_[axis]) + " steps, the double model's " +
                       std::to_string(want[axis]) + " (limit 1 step)");
  }
  // ErPA of the lattice point, converted back to mm and rad.
  CoreCheck& erpa = r.core_check("erpa_rad", "", -1);
  ++erpa.count;
  const double x = static_cast<double>(at[0] - start_[0]) / scale_.x_per_mm;
  const double a = static_cast<double>(at[3] - start_[3]) / steps_per_rad(scale_);
  erpa.max = std::max(erpa.max, std::abs(exact_->a * std::log1p(exact_->b * x) - a));
}

void Adapter::Reference::check(const models::LatticePoint& at, CaseResult& r,
                               std::vector<std::string>& failures) {
  if (pending_.empty()) return;
  // The segments passed ended before the move just made.
  models::LatticePoint before = at;
  for (size_t i = 0; i < 4; ++i) before[i] -= last_step_[i];
  for (const size_t index : pending_) check_point(index, before, r, failures);
  pending_.clear();
}

void Adapter::Reference::finish(const models::LatticePoint& at, CaseResult& r,
                                std::vector<std::string>& failures) {
  Move m;
  if (next(m)) failures.push_back("done_o before the curve's last move");
  for (const size_t index : pending_) check_point(index, at, r, failures);
  pending_.clear();
  if (checked_ != exact_->count())
    failures.push_back("the curve made " + std::to_string(checked_) +
                       " coarse points, the double model " + std::to_string(exact_->count()));
}

// --- stimulus -------------------------------------------------------------------

void Adapter::validate(const Command& c, const models::LatticePoint& from, const VariantSpec& l,
                       const std::string& where) {
  const models::LogFixedFormat f = word_format(l);
  const std::string why = models::log_fixed_check(c.words, f, l.param("SEG_W"), l.pos_w);
  if (!why.empty()) throw UsageError(where + ": the curve does not fit " + l.variant + ": " + why);
  for (size_t i = 0; i < 4; ++i)
    if (from[i] + c.end[i] > l.pos_max())
      throw UsageError(where + ": the curve takes axis " + std::to_string(i) + " to " +
                       std::to_string(from[i] + c.end[i]) + ", past the " +
                       std::to_string(l.pos_w) + "-bit position counter");
}

Adapter::Command Adapter::random_command(Rng& rng, const VariantSpec& l,
                                         const models::LatticePoint& at, const Command&) {
  for (int attempt = 0;; ++attempt) {
    models::LogCurveParams p;
    p.d1_mm = uniform(rng, 4, 20);
    p.spiral_deg = uniform(rng, 15, 40);
    p.cone_deg = uniform(rng, 2, 15);
    p.rake_deg = uniform(rng, 2, 20);
    p.dl_mm = uniform(rng, 0.1, 0.5);
    p.x_end_mm = uniform(rng, p.dl_mm, 3);
    models::LogStepScale s;
    s.x_per_mm = s.y_per_mm = s.z_per_mm = std::round(uniform(rng, 20, 400));
    s.a_per_deg = std::round(uniform(rng, 5, 50));
    try {
      Command c = make_command(p, s, l, "random curve");
      bool room = true;
      for (size_t i = 0; i < 4; ++i) room = room && at[i] + c.end[i] <= l.pos_max() / 2;
      if (room || attempt > 1000) return c;
    } catch (const UsageError&) {
      if (attempt > 1000) throw;
    }
  }
}

bool Adapter::job_directive(JobLine<Adapter>& line) {
  if (line.words[0] != "curve") return false;
  const auto& w = line.words;
  if (w.size() < 7 || w.size() > 9)
    throw UsageError(
        line.where +
        ": 'curve' takes D1 SPIRAL CONE RAKE DL XEND [STEPS_PER_MM [STEPS_PER_DEG]] (" +
        std::to_string(w.size() - 1) + " values given)");
  models::LogCurveParams p;
  double* fields[] = {&p.d1_mm, &p.spiral_deg, &p.cone_deg, &p.rake_deg, &p.dl_mm, &p.x_end_mm};
  for (size_t i = 0; i < 6; ++i) *fields[i] = cli::parse_real(w[i + 1], line.where);
  models::LogStepScale s;
  if (w.size() > 7)
    s.x_per_mm = s.y_per_mm = s.z_per_mm = cli::parse_real(w[7], line.where + " steps per mm");
  if (w.size() > 8) s.a_per_deg = cli::parse_real(w[8], line.where + " steps per deg");
  line.command(make_command(p, s, line.spec, line.where));
  return true;
}

namespace {

Case<Adapter> curve_case(const VariantSpec& l, const std::string& name,
                         const models::LogCurveParams& p, const models::LogStepScale& s,
                         const RunSettings<Adapter>& settings, const std::string& where) {
  Case<Adapter> c;
  c.name = name;
  c.start.assign(static_cast<size_t>(l.axes), 0);
  c.settings = settings;
  c.items.push_back(command_item<Adapter>(Adapter::make_command(p, s, l, where)));
  return c;
}

// The paper's steps per unit where the variant's segments hold them, else
// the largest round scale that fits (the _edge variant's narrow deltas).
models::LogStepScale paper_scale(const VariantSpec& l) {
  models::LogStepScale s;
  const models::LogCurveParams p;
  for (double spm : {1000.0, 500.0, 200.0, 100.0, 50.0, 20.0}) {
    s.x_per_mm = s.y_per_mm = s.z_per_mm = s.a_per_deg = spm;
    const auto words = models::log_fixed_command(p, s, word_format(l));
    if (models::log_fixed_check(words, word_format(l), l.param("SEG_W"), l.pos_w).empty()) break;
  }
  return s;
}

}  // namespace

std::vector<Case<Adapter>> Adapter::paper_cases(const VariantSpec& l,
                                                const RunSettings<Adapter>& settings) {
  return {curve_case(l, "001_log", models::LogCurveParams{}, paper_scale(l), settings,
                     "the paper's curve")};
}

std::vector<Case<Adapter>> Adapter::regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed) {
  std::vector<Case<Adapter>> cases = paper_cases(l, default_settings<Adapter>(l));
  append_random_streams(cases, l, commands, seed);
  return cases;
}

void Adapter::declare_options(cli::Args& args) {
  args.option("d1", "MM",
              "one curve: end diameter D1 of the cutter (the other curve options "
              "default to the paper's case)")
      .option("spiral", "DEG", "spiral angle S, in (0, 90)", "30")
      .option("cone", "DEG", "cone angle C, in (0, 90)", "5")
      .option("rake", "DEG", "rake r, in (0, 90)", "8")
      .option("dl", "MM", "instruction interpolation length", "0.2")
      .option("x-end", "MM", "X at which the run stops (after a whole cycle)", "30")
      .option("steps-per-mm", "N", "steps per mm of X, Y and Z", "1000")
      .option("steps-per-deg", "N", "steps per degree of A", "1000")
      .flag("paper-log",
            "the curve of 001_46110e999325a38e.txt (D1 10, S 30, C 5, r 8, dl 0.2, "
            "X to 30 mm)");
}

std::vector<Case<Adapter>> Adapter::cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings) {
  if (args.given("paper-log")) return paper_cases(l, settings);
  models::LogCurveParams p;
  p.d1_mm = args.real("d1");
  p.spiral_deg = args.real("spiral");
  p.cone_deg = args.real("cone");
  p.rake_deg = args.real("rake");
  p.dl_mm = args.real("dl");
  p.x_end_mm = args.real("x-end");
  models::LogStepScale s;
  s.x_per_mm = s.y_per_mm = s.z_per_mm = args.real("steps-per-mm");
  s.a_per_deg = args.real("steps-per-deg");
  return {curve_case(l, "curve", p, s, settings, "command line")};
}

}  // namespace hwinterp::tb::cores::log_stepper
