// The papers' figures from the hardware: runs a core's first variant (as
// cmake/cores.cmake lists it) on a job, HLS core and RTL in lockstep in the
// direct mode, both checked against the core's reference model, and keeps
// every visited lattice point. The reproductions name cores only here.
#pragma once

#include <string>

#include "tb/lockstep/registry.h"
#include "tb/reproduce/figure_rows.h"

namespace hwinterp::cli {

struct HardwareRun {
  std::string variant;
  tb::CaseResult result;  // the job's one case; result.visited holds the path
};

// `job` in the job-file format, one case. Throws std::logic_error when the
// job does not give exactly one case.
inline HardwareRun run_hardware(const std::string& core, const std::string& job) {
  const tb::VariantEntry& v = tb::find_core(core).variants.front();
  tb::BenchOptions o;
  o.mode = "direct";
  o.record_path = true;
  const auto run = v.from_job(job, o);
  run->run_direct();
  if (run->results().size() != 1) throw std::logic_error("run_hardware: one case expected");
  return {v.spec.variant, run->results().front()};
}

// "(x,y)(x,y)..." of the points after the first (the moves).
inline std::string moves_text(const tb::CaseResult& r) {
  std::string s;
  for (size_t k = 1; k < r.visited.size(); ++k)
    s += "(" + std::to_string(r.visited[k][0]) + "," + std::to_string(r.visited[k][1]) + ")";
  return s;
}

}  // namespace hwinterp::cli
