component hwinterp "LinuxCNC driver for a hwinterp motion_soc board: position-mode step generators whose every servo period is one timed line command, over Etherbone on UDP or a UART";

description """
Drives the step generators of a hwinterp board (docs/linuxcnc.md) built
without the feed profile. Each servo period the joints' position-cmd,
times position-scale and rounded, is a lattice point; the move from the
last period's point is one line command that the board takes at the
period's boundary (CMD_AT: the period's host time mapped to the board's
TIME, plus latency) and ends before the next, so every joint is at its
commanded lattice point at every boundary: no following error by
construction. The board's snapshot, armed at a coming boundary, checks it.

Load with the board's link and the joints:
  loadrt hwinterp board=udp:192.168.1.50:1234 personality=3
  loadrt hwinterp board=serial:/dev/ttyUSB1@1000000 personality=3
  addf hwinterp.update servo-thread

On a UART one packet is unanswered at a time (the board's bridge runs one
frame at a time): the commands of the periods its exchange takes go
together in the next packet.

While any driven stepgen's enable is false the board is stopped
(CTRL.abort_motion) and position-fb is the board's position; on enable
the driver reads the board's position and starts when position-cmd is
within half a step of it (else it sets fault: turn the machine off and
on again, LinuxCNC then commands from the board's position).
""";

license "GPL";
author "hwinterp";

pin in float stepgen.##.position_cmd[6 : personality] "commanded position (machine units)";
pin out float stepgen.##.position_fb[6 : personality] "the commanded position plus the following error measured at the last checked boundary";
pin out float stepgen.##.position_board[6 : personality] "the board's position at the last checked boundary (machine units)";
pin out s32 stepgen.##.ferror_steps[6 : personality] "following error at the last checked boundary (steps)";
pin out s32 stepgen.##.steps_cmd[6 : personality] "this period's lattice point: position-cmd x position-scale, rounded (steps)";
pin in bit stepgen.##.enable[6 : personality] "run the stepgens while every one of them is enabled";
param rw float stepgen.##.position_scale[6 : personality] = 1.0 "steps per machine unit";

param rw u32 steplen = 5000 "step pulse length (ns, rounded up to board clocks)";
param rw u32 stepspace = 5000 "least time between step pulses (ns)";
param rw u32 dirsetup = 10000 "direction set-up before a step (ns)";
param rw u32 dirhold = 10000 "direction hold after a step (ns)";
param rw u32 step_type = 0 "0 step/dir, 1 up/down, 2 quadrature";
param rw u32 latency_ns = 0 "host period to board boundary; 0: measured at load (three times the largest of 20 round trips plus two periods, at least five periods)";
param rw u32 watchdog_ns = 20000000 "the board stops this long after the last packet (0: off)";

pin out u32 fifo_level "commands in the board's FIFO";
pin out u32 late_count "commands the board took after their boundary (EVENTS.late)";
pin out bit watchdog_bit "the board's watchdog has bitten";
pin out u32 link_errors "times the link went down";
pin out bit fault "the link is down, the board refused, or position-cmd was not the board's position at enable";
pin out u32 stats.periods "servo periods run";
pin out u32 stats.commands "line commands sent";
pin out u32 stats.missed_slots "periods whose command waited for a place in the window";
pin out u32 stats.retransmits "packets sent again";
pin out u32 stats.sends "packets sent, the ones sent again included";
pin out u32 stats.packets "packets the board took";
pin out u32 stats.boundary_checks "boundaries checked by a snapshot";
pin out u32 stats.boundary_errors "checked boundaries with a following error";
pin out s32 ferror_max "largest |following error| at a checked boundary (steps)";
pin out float latency_us "the latency in use (us)";
pin out bit running "the stepgens run (enabled, the board at position-cmd)";
pin out float boundary_clock "this period's boundary: the board's TIME at which its command starts (the board holds the last period's point there)";
pin out float rtt_us "the last round trip (us)";
pin out u32 stats.bytes_sent_max "largest packet sent (bytes)";
pin out u32 stats.bytes_received_max "largest reply (bytes)";
pin out u32 stats.too_fast "periods beyond the board's step rate";

function update fp "once per servo period, after motion";

// The driver's code (no HAL in it), before the pins' names are defined.
include "hwinterp_servo.c";
include "hwinterp_link.c";

option personality yes;
option extra_setup yes;
option extra_cleanup yes;
option singleton yes;

;;

#include <stdio.h>

static char* board = "udp:127.0.0.1:1234";
RTAPI_MP_STRING(board, "the board's link: udp:HOST[:PORT] (Etherbone) or serial:DEV[@BAUD] (a UART)");

static hwi_link_t board_link;
static hwi_servo_t servo;
static int active, refused;
static uint64_t measured_latency_ns;
static uint32_t session;

EXTRA_SETUP() {
  char err[256];
  if (hwi_link_open(&board_link, board, err, sizeof err) != 0) {
    rtapi_print_msg(RTAPI_MSG_ERR, "hwinterp: %s\n", err);
    return -EINVAL;
  }
  session = (uint32_t)hwi_now_ns() & 0xF;
  // The round trip, from 20 reads of TIME: the latency's measure.
  const int64_t worst = hwi_link_rtt(&board_link, session, 20, 200000);
  if (worst < 0) {
    rtapi_print_msg(RTAPI_MSG_ERR, "hwinterp: %s: fewer than 10 of 20 reads of TIME answered\n",
                    board_link.name);
    hwi_link_close(&board_link);
    return -EIO;
  }
  measured_latency_ns = (uint64_t)worst;
  rtapi_print_msg(RTAPI_MSG_INFO, "hwinterp: %s, largest round trip %.0f us\n", board_link.name,
                  (double)worst / 1000);
  return 0;
}

EXTRA_CLEANUP() { hwi_link_close(&board_link); }

FUNCTION(update) {
  const int axes = personality < 1 ? 1 : personality > HWI_MAX_AXES ? HWI_MAX_AXES : personality;
  int enabled = 1;
  for (int i = 0; i < axes; ++i) enabled &= stepgen_enable(i);
  running = 0;
  if (!enabled) {
    // Machine off, e-stop: the board stops at once.
    if (active && hwi_link_abort(&board_link, &servo, 20000, 5) != 0) {
      ++link_errors;
      fault = 1;
    }
    active = 0;
    refused = 0;
    return;
  }
  if (refused) return;  // until the stepgens are disabled again
  const hwi_link_timing_t timing =
      hwi_link_timing(measured_latency_ns, (uint64_t)period, latency_ns,
                      hwi_link_period_wire_ns(&board_link, (uint32_t)axes));
  const uint64_t latency = timing.lead_ns;
  if (!active) {
    char err[256];
    hwi_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.axes = (uint32_t)axes;
    cfg.period_ns = (uint64_t)period;
    cfg.boundary_lead_ns = latency;
    cfg.watchdog_period_ns = watchdog_ns;
    cfg.output_type = step_type;
    cfg.retry_periods = timing.retry_periods;
    cfg.dead_periods = timing.dead_periods;
    cfg.step_len_ns = steplen;
    cfg.step_space_ns = stepspace;
    cfg.dir_setup_ns = dirsetup;
    cfg.dir_hold_ns = dirhold;
    hwi_link_configure(&board_link, &cfg);
    if (hwi_open_run(&board_link, &servo, &cfg, session, 50000, 5, err, sizeof err) != 0) {
      rtapi_print_msg(RTAPI_MSG_ERR, "hwinterp: %s\n", err);
      ++link_errors;
      fault = 1;
      refused = 1;
      return;
    }
    for (int i = 0; i < axes; ++i) {
      const int64_t at = servo.lattice[i];
      stepgen_position_board(i) = (double)at / stepgen_position_scale(i);
      stepgen_position_fb(i) = stepgen_position_board(i);
      const int64_t want = hwi_lattice(stepgen_position_cmd(i), stepgen_position_scale(i));
      if (want != at) {
        rtapi_print_msg(RTAPI_MSG_ERR,
                        "hwinterp: stepgen %d: position-cmd is %lld steps, the board is at %lld: "
                        "turn the machine off and on again\n",
                        i, (long long)want, (long long)at);
        refused = 1;
      }
    }
    fault = refused;
    if (refused) return;
    active = 1;
    latency_us = (double)latency / 1000;
  }
  int64_t lattice[HWI_MAX_AXES];
  for (int i = 0; i < axes; ++i) {
    lattice[i] = hwi_lattice(stepgen_position_cmd(i), stepgen_position_scale(i));
    stepgen_steps_cmd(i) = (int32_t)lattice[i];
  }
  if (hwi_link_period(&board_link, &servo, lattice, 0) != 0) {
    rtapi_print_msg(RTAPI_MSG_ERR, "hwinterp: the link %s is down\n", board_link.name);
    ++link_errors;
    fault = 1;
    refused = 1;
    active = 0;
  }
  running = active;
  const hwi_stats_t* st = &servo.stats;
  boundary_clock = (double)servo.last_at;
  for (int i = 0; i < axes; ++i) {
    const double scale = stepgen_position_scale(i);
    stepgen_ferror_steps(i) = (int32_t)st->last_ferror[i];
    stepgen_position_fb(i) = (double)(lattice[i] + st->last_ferror[i]) / scale;
  }
  fifo_level = st->fifo_fill;
  late_count = (uint32_t)st->late_events;
  watchdog_bit = st->watchdog_bitten;
  stats_periods = (uint32_t)st->periods;
  stats_commands = (uint32_t)st->commands;
  stats_missed_slots = (uint32_t)st->missed_slots;
  stats_retransmits = (uint32_t)st->retransmits;
  stats_sends = (uint32_t)st->sends;
  stats_packets = (uint32_t)st->packets;
  stats_boundary_checks = (uint32_t)st->boundary_checks;
  stats_boundary_errors = (uint32_t)st->boundary_errors;
  ferror_max = (int32_t)st->max_ferror;
  rtt_us = st->rtt_ns_last / 1000;
  stats_bytes_sent_max = (uint32_t)st->bytes_sent_max;
  stats_bytes_received_max = (uint32_t)st->bytes_received_max;
  stats_too_fast = (uint32_t)st->too_fast;
}
