// A simulated board: the board's gateware (boards/hwinterp_litex/sim.py:
// everything but the pads, the PHY and the PLL) Verilated, clocked here,
// serving its host link on this machine (tb/board/links.h), its step pins
// checked as the lockstep checks them.
//
// Each clock: the link's wire drives the board's input pins, the clock edge,
// the board's outputs go to the wire and to the pin monitors
// (tb/monitor/step_output_monitor.h: every axis against the step timing and
// step types in effect, read from motion_soc). Every few hundred clocks the
// link moves bytes between its endpoint and the wire. The run ends on
// SIGINT/SIGTERM, after --max-clocks or --max-seconds, and reports what it
// saw (`--json`): clocks, the link's traffic and faults, steps and position
// per axis, the commands completed (and where each ended: --commands-csv),
// timing violations, the watchdog's bites and where the machine came to rest
// after each.
//
// Cfg is a board's generated configuration (board_<name>_cfg.h,
// rtl/CMakeLists.txt): its Verilated top and how to read it.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "tb/base/json.h"
#include "tb/base/stepdir_timing.h"
#include "tb/board/faults.h"
#include "tb/board/links.h"
#include "tb/monitor/step_output_monitor.h"
#include "tb/report/step_times.h"

namespace hwinterp::board {

struct BoardSimOptions {
  uint16_t port = 0;  // Etherbone boards: the UDP port on 127.0.0.1 (0: a free one)
  FaultSpec faults_to_board, faults_to_host;
  uint64_t fault_seed = 1;
  bool realtime = false;     // never run ahead of the wall clock
  uint64_t max_clocks = 0;   // 0: no limit
  double max_seconds = 0;    // wall; 0: no limit
  std::string uri_file;      // the URI is also written there once serving
  std::string steps_csv;     // clock,axis,dir per step (as hwinterp gcode --step-times)
  std::string commands_csv;  // per completed command: its clock and where every axis was
  int progress = 1;          // seconds between progress lines (0: none)
};

// Set by the signal handler: stop after the current clock.
std::atomic<bool>& board_sim_stop();
// Installs SIGINT/SIGTERM handlers that set board_sim_stop().
void install_stop_handlers();

// The parts of the run every board shares (not templated): what the pins
// did, the report.
class BoardRun {
 public:
  BoardRun(std::string board, int axes, uint64_t sys_hz, const BoardSimOptions& o);
  // One clock's outputs after its edge (pins as bit masks, axis i bit i).
  void observe(uint64_t clock, uint32_t a, uint32_t b, const tb::StepdirTiming& t,
               const std::vector<tb::StepType>& types, bool done, bool bite, bool stopping);
  Json report(const Json& link, double seconds, uint64_t clocks) const;
  bool passed(uint64_t bad_link_units) const;
  void close();

 private:
  std::string board_;
  int axes_;
  uint64_t sys_hz_;
  std::unique_ptr<tb::StepOutputMonitors> monitors_;
  std::vector<tb::StepType> types_;
  std::vector<int64_t> pos_;
  std::vector<uint64_t> steps_;
  uint64_t step_count_ = 0;
  std::vector<tb::TimingViolation> violations_;
  uint64_t violation_count_ = 0;
  uint64_t commands_ = 0;
  bool done_pending_ = false;  // done rose on the clock before
  std::unique_ptr<tb::StepTimesCsv> steps_csv_;
  std::unique_ptr<std::ofstream> commands_csv_;
  // The watchdog: each bite, the clock the controlled stop ended (the FIFO
  // dropped), the steps in between and after.
  struct Bite {
    uint64_t clock = 0, rest_clock = 0;
    bool rested = false;
    uint64_t steps_to_rest = 0, steps_after_rest = 0;
  };
  std::vector<Bite> bites_;
  bool was_stopping_ = false;
  uint64_t last_step_clock_ = 0;
};

template <class Cfg>
class BoardSim {
 public:
  using Top = typename Cfg::Top;

  explicit BoardSim(const BoardSimOptions& o)
      : o_(o), run_(Cfg::kBoard, Cfg::kAxes, Cfg::kSysHz, o) {
    if constexpr (Cfg::kEthernet)
      eth_ = std::make_unique<EthLink>(o.port, o.faults_to_board, o.faults_to_host, o.fault_seed);
    else
      uart_ = std::make_unique<UartLink>(Cfg::kSysHz, Cfg::kBaud, o.faults_to_board,
                                         o.faults_to_host, o.fault_seed);
  }

  std::string uri() const { return eth_ ? eth_->uri() : uart_->uri(); }

  // Runs until stopped; returns the report.
  Json run() {
    top_ = std::make_unique<Top>();
    Top& t = *top_;
    t.estop = 0;
    t.probe = 0;
    t.sys_rst = 1;
    for (int i = 0; i < 8; ++i) edge(t);
    t.sys_rst = 0;
    const auto start = std::chrono::steady_clock::now();
    auto last_progress = start;
    uint64_t clock = 0;
    std::vector<tb::StepType> types(static_cast<size_t>(Cfg::kAxes), tb::StepType::kStepDir);
    while (!board_sim_stop().load(std::memory_order_relaxed)) {
      // The link's wire onto the input pins.
      if constexpr (Cfg::kEthernet) {
        bool valid = false;
        uint8_t data = 0;
        eth_->wire().drive(valid, data);
        t.eth_sink_valid = valid;
        t.eth_sink_data = data;
      } else {
        t.serial_rx = uart_->wire().drive();
      }
      edge(t);
      ++clock;
      if constexpr (Cfg::kEthernet)
        eth_->wire().observe(t.eth_source_valid, t.eth_source_data, eth_->delivered());
      else
        uart_->wire().observe(t.serial_tx, uart_->delivered());
      const tb::StepdirTiming timing = Cfg::timing(t);
      for (int i = 0; i < Cfg::kAxes; ++i)
        types[static_cast<size_t>(i)] = static_cast<tb::StepType>(Cfg::step_type(t, i) & 3);
      run_.observe(clock, Cfg::out_a(t), Cfg::out_b(t), timing, types, Cfg::done(t), Cfg::bite(t),
                   Cfg::stopping(t));
      if ((clock & 255) == 0) {
        if constexpr (Cfg::kEthernet)
          eth_->poll(clock);
        else
          uart_->poll();
        if (o_.realtime) {
          // Board time at most 0.5 ms ahead of the wall clock, checked as
          // often as the link is polled (a host's servo loop sees the board
          // keep time within that, not in bursts).
          const double wall =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const double ahead = static_cast<double>(clock) / Cfg::kSysHz - wall;
          if (ahead > 0.0005) std::this_thread::sleep_for(std::chrono::duration<double>(ahead));
        }
        if ((clock & 4095) == 0) {
          const auto now = std::chrono::steady_clock::now();
          const double wall = std::chrono::duration<double>(now - start).count();
          if (o_.max_seconds > 0 && wall >= o_.max_seconds) break;
          if (o_.progress > 0 &&
              std::chrono::duration<double>(now - last_progress).count() >= o_.progress) {
            last_progress = now;
            progress(clock, wall);
          }
        }
      }
      if (o_.max_clocks && clock >= o_.max_clocks) break;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run_.close();
    top_->final();
    Json link = eth_ ? eth_->stats() : uart_->stats();
    Json r = run_.report(link, seconds, clock);
    const uint64_t bad = eth_ ? eth_->board_bad_frames()
                              : link["framing_errors_from_board"].template get<uint64_t>();
    r["passed"] = run_.passed(bad);
    return r;
  }

 private:
  static void edge(Top& t) {
    t.sys_clk = 0;
    t.eval();
    t.sys_clk = 1;
    t.eval();
  }
  void progress(uint64_t clock, double wall) const;

  BoardSimOptions o_;
  BoardRun run_;
  std::unique_ptr<EthLink> eth_;
  std::unique_ptr<UartLink> uart_;
  std::unique_ptr<Top> top_;
};

// A progress line; `share` (0..1; negative: the run has no bound) is how
// far the run is towards --max-clocks or --max-seconds, whichever is nearer.
void board_sim_progress(const std::string& board, uint64_t clock, uint64_t sys_hz, double wall,
                        double share);

template <class Cfg>
void BoardSim<Cfg>::progress(uint64_t clock, double wall) const {
  double share = -1;
  if (o_.max_clocks) share = static_cast<double>(clock) / static_cast<double>(o_.max_clocks);
  if (o_.max_seconds > 0) share = std::max(share, wall / o_.max_seconds);
  board_sim_progress(Cfg::kBoard, clock, Cfg::kSysHz, wall, share);
}

}  // namespace hwinterp::board
