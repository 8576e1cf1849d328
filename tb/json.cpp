#include "json.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace hwinterp {

Json& Json::push(Json v) {
  if (kind_ != Kind::kArray) throw std::logic_error("Json::push on a non-array");
  items_.push_back(std::move(v));
  return items_.back();
}

Json& Json::set(const std::string& key, Json v) {
  if (kind_ != Kind::kObject) throw std::logic_error("Json::set on a non-object");
  for (auto& m : members_)
    if (m.first == key) return m.second = std::move(v);
  members_.emplace_back(key, std::move(v));
  return members_.back().second;
}

const Json* Json::find(const std::string& key) const {
  for (const auto& m : members_)
    if (m.first == key) return &m.second;
  return nullptr;
}

namespace {

void write_string(std::string& out, const std::string& s) {
  out += '"';
  for (const unsigned char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  out += '"';
}

void newline(std::string& out, int indent, int depth) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<size_t>(indent * depth), ' ');
}

}  // namespace

void Json::write(std::string& out, int indent, int depth) const {
  switch (kind_) {
    case Kind::kNull:
      out += "null";
      break;
    case Kind::kBool:
      out += b_ ? "true" : "false";
      break;
    case Kind::kInt:
      out += std::to_string(i_);
      break;
    case Kind::kUint:
      out += std::to_string(u_);
      break;
    case Kind::kReal: {
      if (!std::isfinite(d_)) {
        out += "null";
        break;
      }
      // Shortest text that reads back to the same double.
      char buf[32];
      for (int prec = 15; prec <= 17; ++prec) {
        std::snprintf(buf, sizeof buf, "%.*g", prec, d_);
        if (std::strtod(buf, nullptr) == d_) break;
      }
      out += buf;
      break;
    }
    case Kind::kString:
      write_string(out, s_);
      break;
    case Kind::kArray: {
      out += '[';
      // Arrays of scalars stay on one line: per-axis vectors read better that way.
      bool scalars = true;
      for (const auto& x : items_)
        if (x.kind_ == Kind::kArray || x.kind_ == Kind::kObject) scalars = false;
      for (size_t i = 0; i < items_.size(); ++i) {
        if (i) out += scalars ? ", " : ",";
        if (!scalars) newline(out, indent, depth + 1);
        items_[i].write(out, indent, depth + 1);
      }
      if (!scalars && !items_.empty()) newline(out, indent, depth);
      out += ']';
      break;
    }
    case Kind::kObject: {
      out += '{';
      for (size_t i = 0; i < members_.size(); ++i) {
        if (i) out += ',';
        newline(out, indent, depth + 1);
        write_string(out, members_[i].first);
        out += indent > 0 ? ": " : ":";
        members_[i].second.write(out, indent, depth + 1);
      }
      if (!members_.empty()) newline(out, indent, depth);
      out += '}';
      break;
    }
  }
}

std::string Json::dump(int indent) const {
  std::string out;
  write(out, indent, 0);
  return out;
}

void write_json_file(const std::string& path, const Json& j) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write JSON report '" + path + "'");
  f << j.dump() << '\n';
  if (!f) throw std::runtime_error("error writing JSON report '" + path + "'");
}

}  // namespace hwinterp
