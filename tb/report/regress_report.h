// The report of `hwinterp regress`, built from the cases' JSON, so that
// `hwinterp merge` builds the very same report from the reports of
// regression shards (--shard K/N): merging every shard gives the unsharded
// run's report, timings aside. Also its JUnit form and its summary table.
#pragma once

#include <string>
#include <vector>

#include "tb/base/json.h"

namespace hwinterp::tb {

// One lockstep run of one variant in one mode.
struct RegressRun {
  std::string core, variant, mode;
  uint64_t first_case = 0;  // the number of its first case, all runs' cases numbered in order
  double seconds = 0;       // wall time (SystemC runs: the shared elaboration's)
  std::vector<Json> cases;  // CaseResult::to_json, ordered by "ordinal"
};

// {seed, random_commands, shards, passed, cores: {core: {passed, runs, cases,
// cycles}}, runs: [aggregate_json(cases) + first_case, seconds,
// cycles_per_second]}, the runs in the order of their first_case;
// `shards` lists the shards it holds ("1/1" for an unsharded run).
Json regress_report(const std::vector<RegressRun>& runs, uint64_t seed, uint64_t commands,
                    const std::vector<std::string>& shards);

// JUnit XML of a regress report: a testsuite per run, a testcase per case
// (with a failure element for a failed one).
std::string junit_xml(const Json& report);

// One row per run: core, variant, mode, cases, cycles, seconds, clocks/s, result.
std::string runs_table(const Json& report);

}  // namespace hwinterp::tb
