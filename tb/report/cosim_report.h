// Human and JSON reports over CaseResults, shared by `hwinterp cosim` and
// `hwinterp regress`.
#pragma once

#include <string>
#include <vector>

#include "tb/base/case_result.h"
#include "tb/base/json.h"

namespace hwinterp::tb {

// One row per case: cycles, commands, steps, end point check, path error
// against its bound, mismatches, timing violations, scoreboard errors, verdict.
std::string case_table(const std::vector<CaseResult>& results);

// The findings behind failed cases (first mismatch, violations, scoreboard
// errors), a few lines each; empty when everything passed.
std::string failure_details(const std::vector<CaseResult>& results);

// The contract's top-level keys summed over `results` (steps per axis summed,
// the worst path error, end positions of the last case, the first abort),
// plus "cases".
Json aggregate_json(const std::vector<CaseResult>& results);
// The same from the cases' JSON (CaseResult::to_json), e.g. read back from
// the reports of regression shards.
Json aggregate_json(const std::vector<Json>& cases);

bool all_passed(const std::vector<CaseResult>& results);

}  // namespace hwinterp::tb
