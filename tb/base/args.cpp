#include "tb/base/args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace hwinterp::cli {

// The whole text was read: strto* stop at a NUL byte inside a std::string,
// which must not pass for its end ("7\0999" is not 7).
static bool whole(const std::string& text, const char* end) {
  return end != text.c_str() && end == text.c_str() + text.size();
}

int64_t parse_integer(const std::string& text, const std::string& what) {
  if (text.empty()) throw UsageError(what + ": empty value where an integer was expected");
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (!whole(text, end)) throw UsageError(what + ": '" + text + "' is not an integer");
  if (errno == ERANGE) throw UsageError(what + ": '" + text + "' does not fit in 64 bits");
  return v;
}

double parse_real(const std::string& text, const std::string& what) {
  if (text.empty()) throw UsageError(what + ": empty value where a number was expected");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (!whole(text, end)) throw UsageError(what + ": '" + text + "' is not a number");
  if (errno == ERANGE || !std::isfinite(v))
    throw UsageError(what + ": '" + text + "' is out of range");
  return v;
}

Args::Args(std::string command, std::string summary)
    : command_(std::move(command)), summary_(std::move(summary)) {
  flag("help", "show this help and exit");
  option("json", "FILE", "write the machine-readable report to FILE");
}

Args& Args::option(const std::string& name, const std::string& metavar, const std::string& help,
                   std::optional<std::string> default_value) {
  order_.push_back(name);
  specs_[name] = Spec{metavar, help, false, std::move(default_value)};
  return *this;
}

Args& Args::flag(const std::string& name, const std::string& help) {
  order_.push_back(name);
  specs_[name] = Spec{"", help, true, std::nullopt};
  return *this;
}

void Args::parse(int argc, char** argv, int first) {
  for (int i = first; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "-h") a = "--help";
    if (a.rfind("--", 0) != 0) throw UsageError("unexpected argument '" + a + "'");
    std::string name = a.substr(2);
    std::optional<std::string> inline_value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    const auto it = specs_.find(name);
    if (it == specs_.end())
      throw UsageError("unknown option '--" + name + "' for '" + command_ + "' (see --help)");
    if (values_.count(name)) throw UsageError("option '--" + name + "' given twice");
    if (it->second.is_flag) {
      if (inline_value) throw UsageError("option '--" + name + "' takes no value");
      values_[name] = "1";
      if (name == "help") help_ = true;
      continue;
    }
    if (inline_value) {
      values_[name] = *inline_value;
    } else {
      if (i + 1 >= argc) throw UsageError("option '--" + name + "' needs a value");
      values_[name] = argv[++i];
    }
    // An empty value is never meant: an empty --vcd would silently trace
    // nothing, an empty --json lose the report.
    if (values_[name].empty())
      throw UsageError("option '--" + name + "' needs a value, got an empty one");
  }
}

std::string Args::help_text() const {
  std::ostringstream os;
  os << "usage: hwinterp " << command_ << " [options]\n" << summary_ << "\n\noptions:\n";
  for (const auto& name : order_) {
    const Spec& s = specs_.at(name);
    std::string left = "  --" + name + (s.is_flag ? "" : " " + s.metavar);
    if (left.size() < 30)
      left.resize(30, ' ');
    else
      left += "\n" + std::string(30, ' ');
    os << left << s.help;
    if (s.default_value) os << " (default " << *s.default_value << ")";
    os << "\n";
  }
  return os.str();
}

bool Args::has(const std::string& name) const {
  if (values_.count(name)) return true;
  const auto it = specs_.find(name);
  return it != specs_.end() && it->second.default_value.has_value();
}

bool Args::given(const std::string& name) const { return values_.count(name) != 0; }

std::string Args::str(const std::string& name) const {
  if (const auto it = values_.find(name); it != values_.end()) return it->second;
  const auto it = specs_.find(name);
  if (it != specs_.end() && it->second.default_value) return *it->second.default_value;
  throw UsageError("option '--" + name + "' is required");
}

int64_t Args::integer(const std::string& name, int64_t lo, int64_t hi) const {
  const std::string text = str(name);
  const int64_t v = parse_integer(text, "--" + name);
  if (v < lo || v > hi)
    throw UsageError("--" + name + ": " + text + " is outside [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
  return v;
}

uint64_t Args::seed(const std::string& name) const {
  const std::string text = str(name);
  if (text.empty() || text[0] == '-')
    throw UsageError("--" + name + ": '" + text + "' is not a non-negative integer");
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (!whole(text, end) || errno == ERANGE)
    throw UsageError("--" + name + ": '" + text + "' is not a 64-bit unsigned integer");
  return v;
}

double Args::real(const std::string& name, double lo, double hi) const {
  const std::string text = str(name);
  const double v = parse_real(text, "--" + name);
  if (v < lo || v > hi) {
    std::ostringstream os;
    os << "--" << name << ": " << text << " is outside [" << lo << ", " << hi << "]";
    throw UsageError(os.str());
  }
  return v;
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  size_t from = 0;
  while (true) {
    const size_t comma = text.find(',', from);
    out.push_back(text.substr(from, comma == std::string::npos ? comma : comma - from));
    if (comma == std::string::npos) return out;
    from = comma + 1;
  }
}

std::vector<int64_t> Args::integer_list(const std::string& name) const {
  const std::string text = str(name);
  std::vector<int64_t> out;
  size_t n = 0;
  for (const std::string& item : split_commas(text)) {
    const std::string where =
        "--" + name + ": element " + std::to_string(++n) + " of '" + text + "'";
    if (item.empty()) throw UsageError(where + " is empty");
    out.push_back(parse_integer(item, where));
  }
  return out;
}

std::string Args::choice(const std::string& name, const std::vector<std::string>& allowed) const {
  const std::string v = str(name);
  for (const auto& a : allowed)
    if (a == v) return v;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw UsageError("--" + name + ": unknown value '" + v + "' (one of: " + list + ")");
}

std::string one_line(const std::string& text) {
  static const char* kHex = "0123456789abcdef";
  std::string out;
  for (const unsigned char c : text) {
    if (c == '\n') {
      out += "\\n";
    } else if (c < 0x20 || c == 0x7f) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

}  // namespace hwinterp::cli
