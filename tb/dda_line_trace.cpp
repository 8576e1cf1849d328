#include "dda_line_trace.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

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

DdaLineTrace::DdaLineTrace(const std::string& path, const DdaLineLimits& limits, uint64_t window)
    : path_(path), limits_(limits), window_(window) {
  vcd_path_ = ends_with(path, ".fst") ? path + ".tmp.vcd" : path;
  vcd_ = std::make_unique<VcdWriter>(vcd_path_);
  declare();
}

DdaLineTrace::~DdaLineTrace() {
  try {
    close();
  } catch (...) {
    // Destructors must not throw; close() explicitly to see errors.
  }
}

void DdaLineTrace::declare() {
  VcdWriter& v = *vcd_;
  clk_ = v.add("tb", "clk_i", 1);
  rst_ = v.add("tb", "rst_ni", 1);
  valid_ = v.add("tb", "cmd_valid_i", 1);
  for (int i = 0; i < limits_.axes; ++i)
    delta_[i] = v.add("tb", "cmd_delta_i_" + std::to_string(i), limits_.acc_w);
  feed_ = v.add("tb", "feed_i", limits_.feed_w + 1);
  half_ = v.add("tb", "half_preload_i", 1);
  len_ = v.add("tb", "step_len_i", limits_.tim_w);
  space_ = v.add("tb", "step_space_i", limits_.tim_w);
  setup_ = v.add("tb", "dir_setup_i", limits_.tim_w);
  hold_ = v.add("tb", "dir_hold_i", limits_.tim_w);
  for (auto [scope, o] : {std::pair{"tb.hls", &hls_}, std::pair{"tb.rtl", &rtl_}}) {
    o->ready = v.add(scope, "cmd_ready_o", 1);
    o->busy = v.add(scope, "busy_o", 1);
    o->done = v.add(scope, "done_o", 1);
    for (int i = 0; i < limits_.axes; ++i) {
      const std::string n = std::to_string(i);
      o->step[i] = v.add(scope, "step_o_" + n, 1);
      o->dir[i] = v.add(scope, "dir_o_" + n, 1);
      o->pos[i] = v.add(scope, "pos_o_" + n, limits_.pos_w);
    }
  }
  v.begin("1ns");
}

void DdaLineTrace::write(const Sample& s) {
  VcdWriter& v = *vcd_;
  // Inputs are shown from the edge that samples them, outputs from the edge
  // that produces them: one time stamp per edge, clk low half a period later.
  v.at(s.cycle * kPeriodNs);
  v.set(clk_, 1);
  v.set(rst_, s.in.rst_n);
  v.set(valid_, s.in.cmd_valid);
  for (int i = 0; i < limits_.axes; ++i)
    v.set(delta_[i], static_cast<uint64_t>(s.in.cmd_delta[static_cast<size_t>(i)]));
  v.set(feed_, s.in.feed);
  v.set(half_, s.in.half_preload);
  v.set(len_, s.in.timing.step_len);
  v.set(space_, s.in.timing.step_space);
  v.set(setup_, s.in.timing.dir_setup);
  v.set(hold_, s.in.timing.dir_hold);
  for (auto [o, p] : {std::pair{&hls_, &s.hls}, std::pair{&rtl_, &s.rtl}}) {
    v.set(o->ready, p->cmd_ready);
    v.set(o->busy, p->busy);
    v.set(o->done, p->done);
    for (int i = 0; i < limits_.axes; ++i) {
      v.set(o->step[i], (p->step >> i) & 1);
      v.set(o->dir[i], (p->dir >> i) & 1);
      v.set(o->pos[i], p->pos[static_cast<size_t>(i)]);
    }
  }
  v.at(s.cycle * kPeriodNs + kPeriodNs / 2);
  v.set(clk_, 0);
}

void DdaLineTrace::record(uint64_t cycle, const DdaLineFrame& in, const DdaLinePins& hls,
                          const DdaLinePins& rtl) {
  if (window_ == 0) {
    write({cycle, in, hls, rtl});
    return;
  }
  buffer_.push_back({cycle, in, hls, rtl});
  if (buffer_.size() > window_) buffer_.pop_front();
}

void DdaLineTrace::close() {
  if (closed_) return;
  closed_ = true;
  for (const auto& s : buffer_) write(s);
  buffer_.clear();
  vcd_->close();
  if (vcd_path_ != path_) {
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
