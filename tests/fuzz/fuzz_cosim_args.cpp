// libFuzzer target: `hwinterp cosim`'s command line, from the options to the
// validated cases, for every core: the input is argv, NUL-separated, whose
// first byte picks the core. It goes through the same declarations and
// functions as the real command (declare_cosim_options, the core's own
// options, select_variant, cases_from_args). Bad input must end in
// cli::UsageError; anything else is a finding. Nothing is simulated, no
// file is read or written (--job and the output options are left to the
// job fuzzer and the tests), and random streams are capped for speed.
#include <cstdint>
#include <string>
#include <vector>

#include "hwinterp_configs.h"
#include "tb/lockstep/payload_pins.h"
#include "tb/stimulus/from_args.h"
// After the stimulus templates, which the adapters use.
#include "hwinterp_core_adapters.h"

namespace {

using namespace hwinterp;
using namespace hwinterp::tb;

template <class A>
void run_core(const std::vector<std::string>& words, const std::vector<VariantSpec>& variants) {
  std::vector<std::string> owned = {"hwinterp", "cosim"};
  owned.insert(owned.end(), words.begin(), words.end());
  std::vector<char*> argv;
  for (auto& w : owned) argv.push_back(w.data());
  try {
    cli::Args args("cosim", "fuzz");
    declare_cosim_options(args);
    A::declare_options(args);
    args.parse(static_cast<int>(argv.size()), argv.data(), 2);
    for (const char* skip : {"job", "vcd", "fst", "path-csv", "dump-frames", "json", "help"})
      if (args.given(skip)) return;
    if (args.given("random") && args.integer("random", 1, 100000000) > 2000) return;
    const VariantSpec& l = variants[select_variant(A::kName, variants, args)];
    (void)args.choice("mode", {"systemc", "direct"});
    (void)cases_from_args<A>(args, l, args.given("seed") ? args.seed("seed") : 1);
  } catch (const cli::UsageError&) {
    // refused, with a message: what bad input must get
  }
}

struct CoreEntry {
  std::string name;
  std::vector<VariantSpec> variants;
  void (*run)(const std::vector<std::string>&, const std::vector<VariantSpec>&);
};

const std::vector<CoreEntry>& fuzz_cores() {
  static const std::vector<CoreEntry> all = [] {
    std::vector<CoreEntry> t;
#define HWINTERP_FUZZ_CORE(core) t.push_back({#core, {}, &run_core<cores::core::Adapter>});
    HWINTERP_CORES(HWINTERP_FUZZ_CORE)
#undef HWINTERP_FUZZ_CORE
#define HWINTERP_FUZZ_VARIANT(core, variant) \
  for (auto& e : t)                          \
    if (e.name == #core) e.variants.push_back(spec_of<cores::core::Adapter, variant##_cfg>());
    HWINTERP_VARIANTS(HWINTERP_FUZZ_VARIANT)
#undef HWINTERP_FUZZ_VARIANT
    return t;
  }();
  return all;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::vector<std::string> words(1);
  for (size_t i = 1; i < size; ++i) {
    if (data[i] == 0)
      words.emplace_back();
    else
      words.back() += static_cast<char>(data[i]);
  }
  if (words.size() > 24) return 0;
  const CoreEntry& core = fuzz_cores()[data[0] % fuzz_cores().size()];
  core.run(words, core.variants);
  return 0;
}
