// libFuzzer target: the job-file reader of every core and variant, and what
// follows a parsed job before any clock runs: validation against the
// variant's widths, the hang budget, and each command's reference model
// walked move by move (the scoreboard's view), with its deviation metric,
// bound and ideal path. Bad input must end in cli::UsageError; anything else
// (a crash, a sanitizer report, another exception, a model that refuses a
// validated command) is a finding.
#include <cstdint>
#include <sstream>
#include <string>

#include "hwinterp_configs.h"
#include "tb/lockstep/payload_pins.h"
#include "tb/stimulus/stimulus.h"
// After the stimulus templates, which the adapters use.
#include "hwinterp_core_adapters.h"

namespace {

using namespace hwinterp;
using namespace hwinterp::tb;

constexpr uint64_t kMovesPerCommand = 20000;  // keeps one input fast

template <class A, class Cfg>
void run_job(const std::string& text) {
  const VariantSpec l = spec_of<A, Cfg>();
  std::istringstream in(text);
  std::vector<Case<A>> cases;
  try {
    cases = parse_job<A>(in, "fuzz.job", l, default_settings<A>(l));
    for (const auto& c : cases) validate_case(c, l);
  } catch (const cli::UsageError&) {
    return;  // refused, with a message: what bad input must get
  }
  for (const auto& c : cases) {
    (void)cycle_budget(c, l);
    models::LatticePoint at = c.start;
    RunSettings<A> s = c.settings;
    for (const auto& it : c.items) {
      if (it.kind == Item<A>::Kind::kSettings) s = it.settings;
      if (it.kind != Item<A>::Kind::kCommand) continue;
      typename A::Reference ref(at, it.cmd, s.setup, l);
      (void)ref.bound();
      (void)ref.ideal();
      models::LatticePoint p = at;
      Move m;
      for (uint64_t k = 0; k < kMovesPerCommand && ref.next(m); ++k) {
        for (size_t i = 0; i < p.size(); ++i) p[i] += m.step[i];
        (void)ref.error(p);
      }
      A::apply(it.cmd, at);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
#define HWINTERP_FUZZ_VARIANT(core, variant) \
  run_job<hwinterp::tb::cores::core::Adapter, variant##_cfg>(text);
  HWINTERP_VARIANTS(HWINTERP_FUZZ_VARIANT)
#undef HWINTERP_FUZZ_VARIANT
  return 0;
}
