// Entry points of the dda_line co-simulation, per variant (cmake/cores.cmake):
// its limits, the direct mode, and the SystemC mode. The SystemC kernel
// elaborates once per process, so run_dda_line_systemc takes every bench
// the process will run and clocks them side by side in one elaboration.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "dda_line_bench.h"
#include "dda_line_stimulus.h"

namespace hwinterp::tb {

// Names of the dda_line variants, in cores.cmake order.
std::vector<std::string> dda_line_variants();

// The variant with `axes` axes (the CLI's --axes); throws cli::UsageError
// naming the value and the axis counts there are.
std::string dda_line_variant_for_axes(int axes);

// Limits of a variant; throws cli::UsageError for an unknown name.
DdaLineLimits dda_line_limits(const std::string& variant);

// Runs `bench` to its end in the direct mode.
void run_dda_line_direct(const std::string& variant, DdaLineBench& bench);

// Runs every bench to its end in one SystemC elaboration (once per process).
void run_dda_line_systemc(const std::vector<std::pair<std::string, DdaLineBench*>>& benches);

}  // namespace hwinterp::tb
