// A core's stimulus as the command line asks for it (`hwinterp cosim`):
// the shared settings options and the core's own, and the cases from --job,
// --random (with --with-aborts / --with-holds) or the core's own sources.
// The registry calls these; so does the command-line fuzzer
// (tests/fuzz/fuzz_cosim_args.cpp), which fuzzes exactly this path.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tb/base/args.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb {

// --variant NAME, else the first variant with --axes N axes, else the first:
// an index into `variants` (one core's, cores.cmake order). Throws
// cli::UsageError naming the value and listing the variants.
size_t select_variant(const std::string& core, const std::vector<VariantSpec>& variants,
                      const cli::Args& args);

// Declares the options every core shares (the core's own come from
// A::declare_options). Output and run options are declared here too, so
// that help and parsing are one list.
void declare_cosim_options(cli::Args& args);

// Settings from --feed, the timing options and the core's own setup options.
template <class A>
RunSettings<A> settings_from_args(const cli::Args& args, const VariantSpec& l) {
  RunSettings<A> s = default_settings<A>(l);
  if (args.given("feed")) {
    s.feed = parse_feed(args.str("feed"), l, "--feed");
    if (s.feed == 0) throw cli::UsageError("--feed: 0 holds the move forever; give a feed > 0");
  }
  const auto tmax = static_cast<int64_t>(l.tim_max());
  if (args.given("step-len"))
    s.timing.step_len = static_cast<uint32_t>(args.integer("step-len", 0, tmax));
  if (args.given("step-space"))
    s.timing.step_space = static_cast<uint32_t>(args.integer("step-space", 0, tmax));
  if (args.given("dir-setup"))
    s.timing.dir_setup = static_cast<uint32_t>(args.integer("dir-setup", 0, tmax));
  if (args.given("dir-hold"))
    s.timing.dir_hold = static_cast<uint32_t>(args.integer("dir-hold", 0, tmax));
  A::setup_from_options(args, s.setup);
  validate_feed_and_timing(s.feed, s.timing, l, "command line");
  return s;
}

// --profile, --profile-level, --profile-ticks: the case profile the cases
// run behind, or none (off, or not given). Throws cli::UsageError naming the
// bad value.
std::optional<CaseProfile> profile_from_args(const cli::Args& args);

// The validated cases; `seed` is --random's. Throws cli::UsageError naming
// the bad value.
template <class A>
std::vector<Case<A>> cases_from_args(const cli::Args& args, const VariantSpec& l, uint64_t seed) {
  const RunSettings<A> settings = settings_from_args<A>(args, l);
  std::vector<Case<A>> cases;
  if (args.given("job")) {
    cases = parse_job<A>(args.str("job"), l, settings);
  } else if (args.given("random")) {
    cases.push_back(random_case<A>(l, static_cast<uint64_t>(args.integer("random", 1, 100000000)),
                                   seed, {args.given("with-aborts"), args.given("with-holds")}));
  } else {
    cases = A::cases_from_options(args, l, settings);
  }
  for (const auto& c : cases) validate_case(c, l);
  if (const std::optional<CaseProfile> p = profile_from_args(args)) {
    for (auto& c : cases) {
      for (const auto& it : c.items)
        if (it.kind == Item<A>::Kind::kAbort ||
            (it.kind == Item<A>::Kind::kSettings && it.settings.feed == 0))
          throw cli::UsageError(
              "--profile: case '" + c.name + "' has " +
              (it.kind == Item<A>::Kind::kAbort ? "an abort" : "a feed hold") +
              (it.source_line ? " (line " + std::to_string(it.source_line) + ")" : std::string()) +
              ": the profile's moves are the commands, each run to its end");
      put_behind_profile(c, *p);
    }
  }
  return cases;
}

}  // namespace hwinterp::tb
