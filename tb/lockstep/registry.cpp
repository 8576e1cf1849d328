#include "tb/lockstep/registry.h"

#include <random>
#include <sstream>

#include "hwinterp_core_adapters.h"
#include "hwinterp_variants.h"
#include "tb/lockstep/bench_run.h"
#include "tb/stimulus/from_args.h"

namespace hwinterp::tb {

namespace {

template <class A, class Cfg>
VariantEntry make_variant() {
  VariantEntry v;
  v.spec = spec_of<A, Cfg>();
  v.from_args = [l = v.spec](const cli::Args& args, const BenchOptions& options) {
    return make_run<A, Cfg>(l, cases_from_args<A>(args, l, options.seed), options);
  };
  v.from_job = [l = v.spec](const std::string& job, const BenchOptions& options) {
    std::istringstream in(job);
    return make_run<A, Cfg>(l, parse_job<A>(in, "job", l, default_settings<A>(l)), options);
  };
  v.regression = [l = v.spec](
                     uint64_t commands, uint64_t seed, const BenchOptions& options,
                     const std::function<bool(uint64_t)>& keep) -> std::unique_ptr<BenchRun> {
    std::vector<Case<A>> all = A::regression_cases(l, commands, seed), kept;
    for (uint64_t i = 0; i < all.size(); ++i) {
      all[i].ordinal = i;
      if (!keep || keep(i)) kept.push_back(std::move(all[i]));
    }
    if (kept.empty()) return nullptr;
    return make_run<A, Cfg>(l, std::move(kept), options);
  };
  v.regression_size = [l = v.spec](uint64_t commands) {
    return static_cast<uint64_t>(A::regression_cases(l, commands, 0).size());
  };
  return v;
}

template <class A, class Cfg>
void add_variant(std::vector<CoreEntry>& all) {
  auto it =
      std::find_if(all.begin(), all.end(), [](const CoreEntry& e) { return e.name == A::kName; });
  if (it == all.end()) {
    CoreEntry e;
    e.name = A::kName;
    e.summary = A::kSummary;
    e.declare_options = [](cli::Args& args) { A::declare_options(args); };
    e.sources = A::sources();
    all.push_back(std::move(e));
    it = all.end() - 1;
  }
  it->variants.push_back(make_variant<A, Cfg>());
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

const std::vector<CoreEntry>& all_cores() {
  static const std::vector<CoreEntry> all = [] {
    std::vector<CoreEntry> v;
#define HWINTERP_ADD_VARIANT(core, variant) add_variant<cores::core::Adapter, variant##_cfg>(v);
    HWINTERP_VARIANTS(HWINTERP_ADD_VARIANT)
#undef HWINTERP_ADD_VARIANT
    return v;
  }();
  return all;
}

const CoreEntry& find_core(const std::string& name) {
  for (const auto& c : all_cores())
    if (c.name == name) return c;
  throw cli::UsageError("--core: unknown core '" + name + "' (cores: " + core_list() + ")");
}

std::string core_list() {
  std::vector<std::string> items;
  for (const auto& c : all_cores()) {
    std::vector<std::string> vs;
    for (const auto& v : c.variants) vs.push_back(v.spec.variant);
    items.push_back(c.name + " (" + join(vs) + ")");
  }
  return join(items);
}

const VariantEntry& CoreEntry::select(const cli::Args& args) const {
  std::vector<VariantSpec> specs;
  for (const auto& v : variants) specs.push_back(v.spec);
  return variants[select_variant(name, specs, args)];
}

void run_systemc(const std::vector<BenchRun*>& runs) {
  ScRunControl control;
  std::vector<std::unique_ptr<sc_core::sc_module>> modules;
  for (BenchRun* r : runs)
    if (!r->finished()) modules.push_back(r->systemc_module(control));
  if (modules.empty()) return;
  // sc_stop() is how a finished run ends, not news: keep it out of reports.
  // (SystemC 2.3.4 reports it as an info of message type "/OSCI/SystemC".)
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  sc_core::sc_start();
}

}  // namespace hwinterp::tb
