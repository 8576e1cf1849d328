#include "tb/base/variant_spec.h"

#include "tb/base/args.h"

namespace hwinterp::tb {

bool PortSpec::fits(int64_t v) const {
  if (width >= 64) return is_signed || v >= 0;
  if (is_signed) {
    const int64_t max = (int64_t{1} << (width - 1)) - 1;
    return v >= -max - 1 && v <= max;
  }
  return v >= 0 && static_cast<uint64_t>(v) <= (uint64_t{1} << width) - 1;
}

std::string PortSpec::range_text() const {
  if (width >= 64) return is_signed ? "64-bit signed" : "64-bit unsigned";
  if (is_signed) {
    const int64_t max = (int64_t{1} << (width - 1)) - 1;
    return std::to_string(-max - 1) + ".." + std::to_string(max);
  }
  return "0.." + std::to_string((uint64_t{1} << width) - 1);
}

void VariantSpec::check_fits(const std::string& port, int64_t value, const std::string& what,
                             const std::string& where, const std::string& detail) const {
  const PortSpec& p = own_port(port);
  if (!p.fits(value))
    throw cli::UsageError(where + ": " + what + " " + std::to_string(value) + detail +
                          " is wider than the " + std::to_string(p.width) + "-bit " + p.name +
                          " of " + variant + " (limit " + p.range_text() + ")");
}

std::size_t choose_variant(const std::string& core, const std::vector<VariantSpec>& variants,
                           const VariantChoice& choice) {
  std::string names;
  for (const auto& v : variants)
    names += (names.empty() ? "" : ", ") + v.variant + " (" + std::to_string(v.axes) + " axes)";
  if (!choice.name.empty()) {
    for (std::size_t i = 0; i < variants.size(); ++i)
      if (variants[i].variant == choice.name) return i;
    throw cli::UsageError("--variant: " + core + " has no variant '" + choice.name +
                          "' (there are: " + names + ")");
  }
  if (choice.axes > 0) {
    for (std::size_t i = 0; i < variants.size(); ++i)
      if (choice.at_least ? variants[i].axes >= choice.axes : variants[i].axes == choice.axes)
        return i;
    throw cli::UsageError((choice.at_least ? "" : "--axes: ") + std::string("no ") + core +
                          " variant has " + std::to_string(choice.axes) + " axes" +
                          (choice.at_least ? " or more" : "") + " (there are: " + names + ")");
  }
  if (variants.empty()) throw cli::UsageError(core + " has no variants");
  return 0;
}

}  // namespace hwinterp::tb
