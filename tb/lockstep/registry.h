// Every core and variant the testbench can run, generated from
// cmake/cores.cmake (hwinterp_variants.h, hwinterp_core_adapters.h): the
// command line finds them here by name. Type erasure happens once per run
// (BenchRun), never per clock: each run is a Bench<A> clocked by the typed
// runners of tb/lockstep/direct.h and tb/lockstep/systemc.h.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tb/base/args.h"
#include "tb/base/case_result.h"
#include "tb/base/variant_spec.h"
#include "tb/lockstep/bench_options.h"

namespace sc_core {
class sc_module;
}

namespace hwinterp::tb {

class ScRunControl;

// One lockstep run of one variant: its stimulus is fixed at creation.
class BenchRun {
 public:
  virtual ~BenchRun() = default;
  virtual const VariantSpec& spec() const = 0;
  virtual size_t case_count() const = 0;
  // Runs to the end in the direct mode.
  virtual void run_direct() = 0;
  // The SystemC bench module (run_systemc clocks it).
  virtual std::unique_ptr<sc_core::sc_module> systemc_module(ScRunControl& control) = 0;
  virtual bool finished() const = 0;
  virtual const std::vector<CaseResult>& results() const = 0;
  virtual uint64_t cycles() const = 0;
  // Closes traces and dumps; throws std::runtime_error on a write error.
  virtual void close() = 0;
};

// Runs every unfinished run to its end in one SystemC elaboration (a process
// may elaborate once).
void run_systemc(const std::vector<BenchRun*>& runs);

struct VariantEntry {
  VariantSpec spec;
  // The stimulus the command line asks for: --job, --random/--seed, or the
  // core's own sources; settings from --feed, the timing flags and the
  // core's own. Validated; throws cli::UsageError naming the bad value.
  std::function<std::unique_ptr<BenchRun>(const cli::Args&, const BenchOptions&)> from_args;
  // A job given as text (the job-file format), default settings: how code
  // that knows a core only by name (the paper reproductions) runs it.
  std::function<std::unique_ptr<BenchRun>(const std::string& job, const BenchOptions&)> from_job;
  // The core's regression cases with random streams of `commands`, each
  // numbered by its position in the variant's list (Case::ordinal); `keep`
  // picks some by that number (all when empty; regress --shard). Null when
  // `keep` keeps none.
  std::function<std::unique_ptr<BenchRun>(uint64_t commands, uint64_t seed, const BenchOptions&,
                                          const std::function<bool(uint64_t)>& keep)>
      regression;
  // How many regression cases the variant has with random streams of `commands`.
  std::function<uint64_t(uint64_t commands)> regression_size;
};

struct CoreEntry {
  std::string name;
  std::string summary;
  std::vector<VariantEntry> variants;  // cores.cmake order
  // Declares the core's own `hwinterp cosim` options.
  std::function<void(cli::Args&)> declare_options;
  std::vector<std::string> sources;  // its own stimulus options (e.g. line, arc)

  // --variant NAME, else the first variant with --axes N axes, else the
  // first variant. Throws cli::UsageError listing the variants.
  const VariantEntry& select(const cli::Args& args) const;
};

const std::vector<CoreEntry>& all_cores();
// Throws cli::UsageError naming `name` and listing the cores.
const CoreEntry& find_core(const std::string& name);
// "dda_line (dda_line_n2, dda_line_n4), ppc_line (...)": for help texts.
std::string core_list();

}  // namespace hwinterp::tb
