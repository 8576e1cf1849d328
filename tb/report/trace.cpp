#include "tb/report/trace.h"

#include "tb/report/output_path.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

extern char** environ;

namespace hwinterp::tb {

namespace {
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
constexpr uint64_t kPeriodNs = 10;  // one clock: the trace's time unit is 1 ns
}  // namespace

Trace::Trace(const std::string& path, std::vector<PortSpec> inputs, int axes, int pos_w,
             uint64_t window)
    : path_(path), inputs_(std::move(inputs)), axes_(axes), pos_w_(pos_w), window_(window) {
  for (const auto& p : inputs_) input_count_ += p.count;
  if (input_count_ > kMaxInputs) throw std::logic_error("Trace: raise kMaxInputs");
  // The last `window` clocks live in memory until the end: refuse a window
  // that would take more than a quarter of this machine's memory, now.
  if (window_) {
    const uint64_t bytes = window_ * sizeof(Sample);
    const uint64_t memory = static_cast<uint64_t>(sysconf(_SC_PHYS_PAGES)) *
                            static_cast<uint64_t>(sysconf(_SC_PAGE_SIZE));
    if (bytes > memory / 4)
      throw std::runtime_error("--trace-window " + std::to_string(window_) + " would keep " +
                               std::to_string(bytes >> 20) + " MiB of samples, more than a " +
                               "quarter of this machine's " + std::to_string(memory >> 20) +
                               " MiB");
    ring_.reserve(window_);
  }
  // The trace is written under a partial name and renamed (or converted) only
  // when complete; the final name must be writable before the run starts.
  check_writable(path_);
  vcd_path_ = path + (ends_with(path, ".fst") ? ".partial.vcd" : ".partial");
  vcd_ = std::make_unique<VcdWriter>(vcd_path_);
  declare();
}

Trace::~Trace() {
  // Not closed: the run did not end normally. Leave no partial file behind.
  if (!closed_) {
    vcd_.reset();
    std::remove(vcd_path_.c_str());
  }
}

void Trace::declare() {
  VcdWriter& v = *vcd_;
  clk_ = v.add("tb", "clk_i", 1);
  for (const auto& p : inputs_)
    for (int e = 0; e < p.count; ++e)
      in_ids_.push_back(
          v.add("tb", p.count == 1 ? p.name : p.name + "_" + std::to_string(e), p.width));
  for (auto [scope, o] : {std::pair{"tb.hls", &hls_}, std::pair{"tb.rtl", &rtl_}}) {
    o->ready = v.add(scope, "cmd_ready_o", 1);
    o->busy = v.add(scope, "busy_o", 1);
    o->done = v.add(scope, "done_o", 1);
    for (int i = 0; i < axes_; ++i) {
      const std::string n = std::to_string(i);
      o->step[i] = v.add(scope, "step_o_" + n, 1);
      o->dir[i] = v.add(scope, "dir_o_" + n, 1);
      o->pos[i] = v.add(scope, "pos_o_" + n, pos_w_);
    }
  }
  v.begin("1ns");
}

void Trace::write(const Sample& s) {
  VcdWriter& v = *vcd_;
  // Inputs are shown from the edge that samples them, outputs from the edge
  // that produces them: one time stamp per edge, clk low half a period later.
  v.at(s.cycle * kPeriodNs);
  v.set(clk_, 1);
  for (size_t k = 0; k < in_ids_.size(); ++k) v.set(in_ids_[k], s.in[k]);
  for (auto [o, p] : {std::pair{&hls_, &s.hls}, std::pair{&rtl_, &s.rtl}}) {
    v.set(o->ready, p->cmd_ready);
    v.set(o->busy, p->busy);
    v.set(o->done, p->done);
    for (int i = 0; i < axes_; ++i) {
      v.set(o->step[i], (p->step >> i) & 1);
      v.set(o->dir[i], (p->dir >> i) & 1);
      v.set(o->pos[i], p->pos[static_cast<size_t>(i)]);
    }
  }
  v.at(s.cycle * kPeriodNs + kPeriodNs / 2);
  v.set(clk_, 0);
}

void Trace::record(uint64_t cycle, const uint64_t* in, const OutPins& hls, const OutPins& rtl) {
  Sample s;
  s.cycle = cycle;
  std::copy(in, in + input_count_, s.in);
  s.hls = hls;
  s.rtl = rtl;
  if (window_ == 0) {
    write(s);
    return;
  }
  if (ring_.size() < window_) {
    ring_.push_back(s);
  } else {
    ring_[next_] = s;
    next_ = (next_ + 1) % window_;
  }
}

void Trace::close() {
  if (closed_) return;
  closed_ = true;
  // The ring, oldest first.
  for (size_t k = 0; k < ring_.size(); ++k) write(ring_[(next_ + k) % ring_.size()]);
  ring_.clear();
  try {
    vcd_->close();
  } catch (...) {
    std::remove(vcd_path_.c_str());
    throw;
  }
  if (!ends_with(path_, ".fst")) {
    if (std::rename(vcd_path_.c_str(), path_.c_str()) != 0) {
      std::remove(vcd_path_.c_str());
      throw std::runtime_error("cannot write trace '" + path_ + "'");
    }
  } else {
    // Run vcd2fst directly (no shell): any path works, quotes included.
    std::string in = vcd_path_, out = path_, tool = "vcd2fst";
    char* argv[] = {tool.data(), in.data(), out.data(), nullptr};
    posix_spawn_file_actions_t quiet;
    posix_spawn_file_actions_init(&quiet);
    posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    int status = -1;
    const bool spawned = posix_spawnp(&pid, "vcd2fst", &quiet, nullptr, argv, environ) == 0;
    posix_spawn_file_actions_destroy(&quiet);
    if (spawned) waitpid(pid, &status, 0);
    std::remove(vcd_path_.c_str());
    if (!spawned || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
      throw std::runtime_error("vcd2fst could not write '" + path_ +
                               "' (is gtkwave installed? scripts/setup.sh installs it)");
  }
}

}  // namespace hwinterp::tb
