#include "dda_line_cosim.h"

#include <functional>
#include <memory>

#include "cli_args.h"
#include "dda_line_direct.h"
#include "dda_line_systemc.h"

namespace hwinterp::tb {

namespace {

struct Variant {
  std::string name;
  DdaLineLimits limits;
  std::function<void(DdaLineBench&)> direct;
  std::function<std::unique_ptr<sc_core::sc_module>(DdaLineBench&, ScRunControl&)> systemc;
};

template <class Cfg>
Variant make_variant() {
  DdaLineLimits l;
  l.variant = Cfg::kVariant;
  l.axes = Cfg::AXES;
  l.acc_w = Cfg::ACC_W;
  l.pos_w = Cfg::POS_W;
  l.tim_w = Cfg::TIM_W;
  l.feed_w = Cfg::FEED_W;
  l.default_timing = {Cfg::DEFAULT_STEP_LEN, Cfg::DEFAULT_STEP_SPACE, Cfg::DEFAULT_DIR_SETUP,
                      Cfg::DEFAULT_DIR_HOLD};
  static_assert(Cfg::AXES <= kMaxAxes, "raise kMaxAxes in tb/dda_line_pins.h");
  return {Cfg::kVariant, l, [](DdaLineBench& b) { DdaLineDirect<Cfg>::run(b); },
          [](DdaLineBench& b, ScRunControl& c) -> std::unique_ptr<sc_core::sc_module> {
            return std::make_unique<DdaLineScBench<Cfg>>(sc_core::sc_gen_unique_name(Cfg::kVariant),
                                                         b, c);
          }};
}

const std::vector<Variant>& variants() {
#define HWINTERP_MAKE_VARIANT(v) make_variant<v##_cfg>(),
  static const std::vector<Variant> all = {HWINTERP_DDA_LINE_VARIANTS(HWINTERP_MAKE_VARIANT)};
#undef HWINTERP_MAKE_VARIANT
  return all;
}

const Variant& find(const std::string& name) {
  for (const auto& v : variants())
    if (v.name == name) return v;
  std::string known;
  for (const auto& v : variants()) known += (known.empty() ? "" : ", ") + v.name;
  throw cli::UsageError("unknown dda_line variant '" + name + "' (there are: " + known + ")");
}

}  // namespace

std::vector<std::string> dda_line_variants() {
  std::vector<std::string> names;
  for (const auto& v : variants()) names.push_back(v.name);
  return names;
}

std::string dda_line_variant_for_axes(int axes) {
  std::string known;
  for (const auto& v : variants()) {
    if (v.limits.axes == axes) return v.name;
    known += (known.empty() ? "" : ", ") + std::to_string(v.limits.axes);
  }
  throw cli::UsageError("--axes: no dda_line variant has " + std::to_string(axes) +
                        " axes (built: " + known + ")");
}

DdaLineLimits dda_line_limits(const std::string& variant) { return find(variant).limits; }

void run_dda_line_direct(const std::string& variant, DdaLineBench& bench) {
  find(variant).direct(bench);
}

void run_dda_line_systemc(const std::vector<std::pair<std::string, DdaLineBench*>>& benches) {
  ScRunControl control;
  std::vector<std::unique_ptr<sc_core::sc_module>> modules;
  for (const auto& [variant, bench] : benches)
    if (!bench->finished()) modules.push_back(find(variant).systemc(*bench, control));
  if (modules.empty()) return;
  // sc_stop() is how a finished run ends, not news: keep it out of reports.
  // (SystemC 2.3.4 reports it as an info of message type "/OSCI/SystemC".)
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  sc_core::sc_start();
}

}  // namespace hwinterp::tb
