// A small ordered JSON value for the reports `hwinterp --json` writes.
// Objects keep insertion order so reports diff cleanly. Non-finite doubles
// are written as null (JSON has no NaN).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace hwinterp {

class Json {
 public:
  enum class Kind { kNull, kBool, kInt, kUint, kReal, kString, kArray, kObject };

  Json() = default;  // null
  Json(std::nullptr_t) {}
  Json(bool b) : kind_(Kind::kBool), b_(b) {}
  Json(int v) : kind_(Kind::kInt), i_(v) {}
  Json(long v) : kind_(Kind::kInt), i_(v) {}
  Json(long long v) : kind_(Kind::kInt), i_(v) {}
  Json(unsigned v) : kind_(Kind::kUint), u_(v) {}
  Json(unsigned long v) : kind_(Kind::kUint), u_(v) {}
  Json(unsigned long long v) : kind_(Kind::kUint), u_(v) {}
  Json(double v) : kind_(Kind::kReal), d_(v) {}
  Json(const char* s) : kind_(Kind::kString), s_(s) {}
  Json(std::string s) : kind_(Kind::kString), s_(std::move(s)) {}

  static Json array() {
    Json j;
    j.kind_ = Kind::kArray;
    return j;
  }
  static Json object() {
    Json j;
    j.kind_ = Kind::kObject;
    return j;
  }
  template <typename T>
  static Json array_of(const std::vector<T>& items) {
    Json j = array();
    for (const auto& x : items) j.push(Json(x));
    return j;
  }

  Json& push(Json v);                         // array append
  Json& set(const std::string& key, Json v);  // object insert or replace
  const Json* find(const std::string& key) const;

  Kind kind() const { return kind_; }
  bool is_null() const { return kind_ == Kind::kNull; }
  size_t size() const { return kind_ == Kind::kArray ? items_.size() : members_.size(); }

  std::string dump(int indent = 2) const;

 private:
  void write(std::string& out, int indent, int depth) const;

  Kind kind_ = Kind::kNull;
  bool b_ = false;
  int64_t i_ = 0;
  uint64_t u_ = 0;
  double d_ = 0;
  std::string s_;
  std::vector<Json> items_;
  std::vector<std::pair<std::string, Json>> members_;
};

// Writes `j` to `path` (with a trailing newline). Throws std::runtime_error
// naming the path when it cannot be written.
void write_json_file(const std::string& path, const Json& j);

}  // namespace hwinterp
