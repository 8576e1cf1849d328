#include "tb/board/faults.h"

#include "tb/base/args.h"

namespace hwinterp::board {

FaultSpec parse_faults(const std::string& text) {
  FaultSpec s;
  for (const std::string& item : cli::split_commas(text)) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos)
      throw cli::UsageError("--faults: '" + item + "' is not KIND=P (drop, corrupt, dup, reorder)");
    const std::string kind = item.substr(0, eq);
    const double p = cli::parse_real(item.substr(eq + 1), "--faults " + kind);
    if (!(p >= 0 && p <= 1))
      throw cli::UsageError("--faults: " + kind + "=" + item.substr(eq + 1) +
                            " is not a probability in [0, 1]");
    if (kind == "drop")
      s.drop = p;
    else if (kind == "corrupt")
      s.corrupt = p;
    else if (kind == "dup")
      s.dup = p;
    else if (kind == "reorder")
      s.reorder = p;
    else
      throw cli::UsageError("--faults: unknown fault '" + kind + "' (drop, corrupt, dup, reorder)");
  }
  return s;
}

Json FaultCounts::to_json() const {
  return Json{{"units", units},
              {"dropped", dropped},
              {"corrupted", corrupted},
              {"duplicated", duplicated},
              {"reordered", reordered}};
}

FaultAction FaultInjector::next(FaultCounts& counts) {
  FaultAction a;
  ++counts.units;
  if (draw(spec_.drop)) {
    a.drop = true;
    ++counts.dropped;
    return a;
  }
  if (draw(spec_.corrupt)) {
    a.corrupt = true;
    ++counts.corrupted;
  } else if (draw(spec_.reorder)) {
    a.reorder = true;
    ++counts.reordered;
  }
  if (draw(spec_.dup)) {
    a.dup = true;
    ++counts.duplicated;
  }
  return a;
}

}  // namespace hwinterp::board
