// A minimal Value Change Dump writer for the testbench's cycle traces: inputs
// and both DUTs' outputs side by side, so a mismatch is read in GTKWave.
// Signals are at most 64 bits wide; scalars are written as 0/1.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace hwinterp::tb {

class VcdWriter {
 public:
  // Opens `path` for writing; throws std::runtime_error naming it on failure.
  explicit VcdWriter(const std::string& path);

  // Declares a signal in `scope` (dotted scopes nest: "tb.rtl"). Only before begin().
  int add(const std::string& scope, const std::string& name, int width);
  // Writes the header; `timescale` like "1ns".
  void begin(const std::string& timescale);
  // Sets the current time (non-decreasing) and records value changes at it.
  void at(uint64_t time);
  void set(int id, uint64_t value);
  void close();
  const std::string& path() const { return path_; }

 private:
  struct Signal {
    std::string scope, name, code;
    int width;
    uint64_t value;
    bool written;
  };
  std::string path_;
  std::ofstream out_;
  std::vector<Signal> signals_;
  uint64_t time_ = 0;
  bool time_written_ = false;
  bool begun_ = false;
};

}  // namespace hwinterp::tb
