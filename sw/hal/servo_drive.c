// hwinterp_servo_drive: the LinuxCNC driver's servo loop (hwinterp_servo.c,
// hwinterp_link.c) without LinuxCNC: it streams joint positions, one line
// of steps per servo period, to a board and prints the driver's figures as
// JSON. tests/hal/ run it against the simulated board; scripts/linuxcnc/
// replays LinuxCNC's sampled positions through it.
//
// usage: hwinterp_servo_drive --board URI --positions FILE
//          [--period-us P] [--latency-us L] [--clock board|wall]
//          [--step-ns LEN,SPACE,SETUP,HOLD] [--hold-periods N] [--json FILE]
//          [--boundaries-csv FILE]
//
// URI: the board's link, udp:HOST[:PORT] or serial:DEV[@BAUD] (hwinterp_link.h).
// FILE: one line a period, the joints' lattice positions (steps), space
// separated; every line has the same number of joints (1..6).
// --clock board: the host's clock is the board's TIME: each period runs, at
// its own time, once the board's TIME is known to have reached it (from a
// reply of the servo's, or a read of TIME while none is unanswered: on a
// UART a read would collide with the servo's packet): for a board that runs
// slower than real time, as a simulated one may. --clock wall: real time
// (a real board, or a simulated one that keeps up).
// --boundaries-csv: every period's boundary (the board's clock at which its
// command starts) and the lattice point the board must hold there (the last
// period's), period,clock,<axis>... : the whole run's following error is the
// board's position at each boundary against it.
// Exit: 0 when every checked boundary had no following error, no command
// was late and the link stayed up; 1 otherwise; 2 for bad arguments.
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hwinterp_link.h"

static void usage(const char* why) {
  fprintf(stderr, "hwinterp_servo_drive: %s\n", why);
  fprintf(stderr,
          "usage: hwinterp_servo_drive --board URI --positions FILE [--period-us P]\n"
          "         [--latency-us L] [--clock board|wall] [--step-ns LEN,SPACE,SETUP,HOLD]\n"
          "         [--hold-periods N] [--json FILE] [--boundaries-csv FILE]\n");
  exit(2);
}

static long parse_long(const char* what, const char* v, long lo, long hi) {
  char* end;
  const long x = strtol(v, &end, 10);
  if (!*v || *end || x < lo || x > hi) {
    char msg[256];
    snprintf(msg, sizeof msg, "%s '%s' is not a whole number in %ld..%ld", what, v, lo, hi);
    usage(msg);
  }
  return x;
}

// Positions: rows of `axes` steps.
static int64_t* read_positions(const char* path, uint32_t* axes, size_t* rows) {
  FILE* f = fopen(path, "r");
  if (!f) {
    char msg[512];
    snprintf(msg, sizeof msg, "--positions '%s' cannot be read", path);
    usage(msg);
  }
  size_t cap = 1024, n = 0;
  int64_t* v = malloc(cap * HWI_MAX_AXES * sizeof *v);
  char line[1024];
  *axes = 0;
  size_t lineno = 0;
  while (fgets(line, sizeof line, f)) {
    ++lineno;
    uint32_t k = 0;
    char* p = line;
    for (;;) {
      char* end;
      const long long x = strtoll(p, &end, 10);
      if (end == p) break;
      if (k == HWI_MAX_AXES) {
        fprintf(stderr, "hwinterp_servo_drive: %s:%zu: more than %d joints\n", path, lineno,
                HWI_MAX_AXES);
        exit(2);
      }
      if (n == cap) {
        cap *= 2;
        v = realloc(v, cap * HWI_MAX_AXES * sizeof *v);
      }
      v[n * HWI_MAX_AXES + k++] = x;
      p = end;
    }
    if (k == 0) continue;
    if (*axes == 0) *axes = k;
    if (k != *axes) {
      fprintf(stderr, "hwinterp_servo_drive: %s:%zu: %u joints, the first line has %u\n", path,
              lineno, k, *axes);
      exit(2);
    }
    ++n;
  }
  fclose(f);
  if (!n) usage("--positions holds no line of positions");
  *rows = n;
  return v;
}

static int send_link(void* ctx, const uint8_t* data, size_t len) {
  return hwi_link_send((hwi_link_t*)ctx, data, len);
}

static int64_t clocks_to_ns(uint64_t t, uint32_t clock_hz) {
  return (int64_t)((double)t * 1e9 / clock_hz);
}

// The board's TIME in ns by a plain read: the host's clock with --clock
// board, and the latency's measure. Replies to the servo's packets that
// arrive meanwhile go to the servo, at host time `host_ns`.
static int64_t read_board_ns(hwi_link_t* l, hwi_servo_t* s, uint32_t session, uint32_t clock_hz,
                             int64_t host_ns) {
  static uint32_t count = 0;
  uint8_t pkt[64], buf[HWI_MAX_PACKET];
  const uint32_t a[2] = {hwi_addr_time_lo(), hwi_addr_time_lo() + 4};
  // A read lost is sent again after 20 ms, so that a board running free
  // does not run far past the host's time meanwhile.
  for (int tries = 0; tries < 1000; ++tries) {
    const uint32_t tag = (session & 0xF) << 28 | ((0x40000u + ++count) & 0x7FFFFu) << 8;
    hwi_link_send(l, pkt, hwi_eb_reads(pkt, sizeof pkt, tag, a, 2));
    for (;;) {
      const int n = hwi_link_recv(l, buf, sizeof buf, 20000);
      if (n <= 0) break;
      uint32_t got, w[2];
      if (hwi_eb_reply(buf, (size_t)n, &got, w, 2) == 2 && got == tag)
        return clocks_to_ns((uint64_t)w[1] << 32 | w[0], clock_hz);
      if (s && s->state == HWI_RUN) hwi_servo_reply(s, buf, (size_t)n, host_ns);
    }
  }
  fprintf(stderr, "hwinterp_servo_drive: the board does not answer reads of TIME\n");
  exit(1);
}

// --clock board: the board's TIME known to have reached `next` (ns), from
// the servo's replies or reads; `*known` the latest TIME known.
static void wait_board(hwi_link_t* l, hwi_servo_t* s, uint32_t session, int64_t next,
                       int64_t* known) {
  const uint32_t hz = s->id.clock_hz;
  uint8_t buf[HWI_MAX_PACKET];
  while (*known < next) {
    if (l->serial && s->state == HWI_RUN && s->in_flight) {
      // The bridge runs one frame at a time: the servo's reply first (none
      // within 200 ms: lost; TIME is read).
      const int n = hwi_link_recv(l, buf, sizeof buf, 200000);
      if (n > 0 && hwi_servo_reply(s, buf, (size_t)n, *known) == 1) {
        const int64_t t = clocks_to_ns(s->stats.board_time, hz);
        if (t > *known) *known = t;
      } else if (n == 0) {
        *known = read_board_ns(l, s, session, hz, *known);  // lost: the servo retries
      }
    } else {
      const int64_t t = read_board_ns(l, s, session, hz, *known);
      if (t > *known) *known = t;
    }
  }
}

int main(int argc, char** argv) {
  const char *board = NULL, *positions = NULL, *json = NULL, *clock = "wall", *bcsv = NULL;
  long period_us = 1000, latency_us = 0, hold = 20;
  uint32_t step[4] = {8000, 8000, 12000, 12000};
  for (int i = 1; i < argc; ++i) {
    const char* o = argv[i];
    if (i + 1 >= argc) usage("every option takes a value");
    const char* v = argv[++i];
    if (!strcmp(o, "--board"))
      board = v;
    else if (!strcmp(o, "--positions"))
      positions = v;
    else if (!strcmp(o, "--json"))
      json = v;
    else if (!strcmp(o, "--boundaries-csv"))
      bcsv = v;
    else if (!strcmp(o, "--period-us"))
      period_us = parse_long("--period-us", v, 100, 100000);
    else if (!strcmp(o, "--latency-us"))
      latency_us = parse_long("--latency-us", v, 0, 10000000);
    else if (!strcmp(o, "--hold-periods"))
      hold = parse_long("--hold-periods", v, 0, 1000000);
    else if (!strcmp(o, "--clock")) {
      if (strcmp(v, "board") && strcmp(v, "wall")) usage("--clock is board or wall");
      clock = v;
    } else if (!strcmp(o, "--step-ns")) {
      if (sscanf(v, "%u,%u,%u,%u", &step[0], &step[1], &step[2], &step[3]) != 4)
        usage("--step-ns takes LEN,SPACE,SETUP,HOLD in ns");
    } else {
      char msg[256];
      snprintf(msg, sizeof msg, "unknown option '%s'", o);
      usage(msg);
    }
  }
  if (!board || !positions) usage("--board and --positions are required");
  uint32_t axes;
  size_t rows;
  const int64_t* pos = read_positions(positions, &axes, &rows);

  char err[256];
  static hwi_link_t link;
  if (hwi_link_open(&link, board, err, sizeof err) != 0) usage(err);
  const uint32_t session = (uint32_t)hwi_now_ns() & 0xF;
  const int use_board = !strcmp(clock, "board");
  const int64_t period_ns = period_us * 1000;

  hwi_config_t cfg;
  memset(&cfg, 0, sizeof cfg);
  cfg.axes = axes;
  cfg.period_ns = (uint64_t)period_ns;
  cfg.step_len_ns = step[0];
  cfg.step_space_ns = step[1];
  cfg.dir_setup_ns = step[2];
  cfg.dir_hold_ns = step[3];
  cfg.watchdog_period_ns = (uint64_t)period_ns * 200;
  cfg.retry_periods = 8;  // until the link's timing is measured, below
  cfg.dead_periods = 400;
  hwi_link_configure(&link, &cfg);
  static hwi_servo_t s;
  if (hwi_open_run(&link, &s, &cfg, session, 200000, 10, err, sizeof err) != 0) {
    fprintf(stderr, "hwinterp_servo_drive: %s: %s\n", board, err);
    return 1;
  }
  const uint32_t hz = s.id.clock_hz;
  // The latency: given, or the largest of 20 round trips plus two periods.
  double rtt_max = 0;
  for (int i = 0; i < 20; ++i) {
    const int64_t w0 = hwi_now_ns();
    const int64_t b0 = read_board_ns(&link, NULL, session, hz, 0);
    const int64_t rtt =
        use_board ? read_board_ns(&link, NULL, session, hz, 0) - b0 : hwi_now_ns() - w0;
    if ((double)rtt > rtt_max) rtt_max = (double)rtt;
  }
  const hwi_link_timing_t timing =
      hwi_link_timing((uint64_t)rtt_max, (uint64_t)period_ns, (uint64_t)latency_us * 1000,
                      hwi_link_period_wire_ns(&link, axes));
  cfg.boundary_lead_ns = timing.lead_ns;
  cfg.retry_periods = timing.retry_periods;
  cfg.dead_periods = timing.dead_periods;
  // The run again from the board's position, its time paired with the host's now.
  int64_t origin[HWI_MAX_AXES];
  memcpy(origin, s.lattice, sizeof origin);
  const int64_t w0 = hwi_now_ns();
  const int64_t b0 = read_board_ns(&link, NULL, session, hz, 0);
  const int64_t w1 = hwi_now_ns();
  const int64_t host0 = use_board ? b0 : w0 + (w1 - w0) / 2;
  hwi_servo_start(&s, &cfg, &s.id, session, s.expect, origin, (uint64_t)((double)b0 * hz / 1e9),
                  host0);

  FILE* bf = NULL;
  if (bcsv) {
    bf = fopen(bcsv, "w");
    if (!bf) usage("--boundaries-csv cannot be written");
    fprintf(bf, "period,clock");
    for (uint32_t a = 0; a < axes; ++a) fprintf(bf, ",axis%u", a);
    fprintf(bf, "\n");
  }
  int64_t next = host0, known = host0;
  int down = 0;
  const size_t total = rows + (size_t)hold;
  for (size_t k = 0; k < total && !down; ++k) {
    next += period_ns;
    int64_t now = next;
    if (use_board) {
      // The period runs at its time once the board is known to be past it
      // (several at once when the link held the loop up: their commands
      // then wait for a packet, as a real servo thread's would).
      wait_board(&link, &s, session, next, &known);
    } else {
      struct timespec ts = {(time_t)(next / 1000000000), (long)(next % 1000000000)};
      clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL);
      now = hwi_now_ns();
    }
    const size_t r = k < rows ? k : rows - 1;
    int64_t lat[HWI_MAX_AXES];
    for (uint32_t a = 0; a < axes; ++a) lat[a] = origin[a] + pos[r * HWI_MAX_AXES + a];
    uint8_t buf[HWI_MAX_PACKET];
    for (;;) {
      const int n = hwi_link_recv(&link, buf, sizeof buf, 0);
      if (n <= 0) break;
      hwi_servo_reply(&s, buf, (size_t)n, use_board ? known : now);
    }
    if (hwi_servo_period(&s, now, lat, send_link, &link) < 0) down = 1;
    if (bf && !down) {
      const hwi_boundary_t* b = &s.ring[(s.ring_next - 1) % HWI_RING];
      fprintf(bf, "%zu,%" PRId64, k, b->at);
      for (uint32_t a = 0; a < axes; ++a) fprintf(bf, ",%" PRId64, b->hold[a]);
      fprintf(bf, "\n");
    }
  }
  if (bf) fclose(bf);
  const hwi_stats_t* st = &s.stats;
  FILE* out = json ? fopen(json, "w") : stdout;
  if (!out) usage("--json cannot be written");
  fprintf(
      out,
      "{\"board\": \"%s\", \"clock\": \"%s\", \"clock_hz\": %u, \"axes\": %u, \"period_us\": %ld,"
      " \"latency_us\": %.1f, \"rtt_us_max\": %.1f, \"rows\": %zu, \"link_down\": %s,\n"
      " \"periods\": %" PRIu64 ", \"commands\": %" PRIu64 ", \"commands_taken\": %" PRIu64
      ", \"packets\": %" PRIu64 ", \"sends\": %" PRIu64 ", \"retransmits\": %" PRIu64
      ", \"missed_slots\": %" PRIu64 ", \"stale_replies\": %" PRIu64 ", \"too_fast\": %" PRIu64
      ",\n \"late_events\": %" PRIu64 ", \"overflow_events\": %" PRIu64
      ", \"refused_events\": %" PRIu64 ", \"boundary_checks\": %" PRIu64
      ", \"boundary_misses\": %" PRIu64 ", \"boundary_errors\": %" PRIu64
      ", \"max_ferror_steps\": %" PRId64 ",\n \"bytes_sent_max\": %" PRIu64
      ", \"bytes_received_max\": %" PRIu64
      ", \"fifo_fill_max\": %u, \"window\": %u,"
      " \"frames_bad\": %" PRIu64 ", \"end\": [",
      link.name, clock, hz, axes, period_us, (double)cfg.boundary_lead_ns / 1000,
      st->rtt_ns_max / 1000, rows, down ? "true" : "false", st->periods, st->commands,
      st->commands_taken, st->packets, st->sends, st->retransmits, st->missed_slots,
      st->stale_replies, st->too_fast, st->late_events, st->overflow_events, st->refused_events,
      st->boundary_checks, st->boundary_misses, st->boundary_errors, st->max_ferror,
      st->bytes_sent_max, st->bytes_received_max, st->fifo_fill_max, s.cfg.window,
      link.deframer.bad_crc + link.deframer.bad_escape + link.deframer.too_short +
          link.deframer.too_long_frames);
  for (uint32_t a = 0; a < axes; ++a) fprintf(out, "%s%" PRId64, a ? ", " : "", s.lattice[a]);
  fprintf(out, "], \"origin\": [");
  for (uint32_t a = 0; a < axes; ++a) fprintf(out, "%s%" PRId64, a ? ", " : "", origin[a]);
  fprintf(out, "]}\n");
  if (json) fclose(out);
  hwi_link_close(&link);
  const int ok = !down && st->max_ferror == 0 && st->late_events == 0 && st->boundary_checks > 0;
  return ok ? 0 : 1;
}
