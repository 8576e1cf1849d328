// The servo side of hwinterp's LinuxCNC driver: see hwinterp_servo.h.
#include "hwinterp_servo.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "board_regs.h"  // sw/board_regs.h

#define REG(field) ((uint32_t)offsetof(hwinterp_board_t, field))
#define MOTION(reg) REG(motion.reg)
#define BIT(reg, field) (1u << MOTION_SOC_REGS__##reg##__##field##_bp)

enum {
  EB_MAGIC = 0x4E6F,
  EB_VERSION_FLAGS = 0x10,  // version 1, no flags
  EB_SIZES = 0x44,
  EB_BYTE_ENABLE = 0x0F,
  EB_MAX_WORDS = 248,  // a record's words every board takes (docs/link.md)
  MAX_READS = 32,
  CHUNK_MAX = 255,
};

// --- Etherbone ---------------------------------------------------------------

static void put32(uint8_t* p, uint32_t v) {
  p[0] = (uint8_t)(v >> 24);
  p[1] = (uint8_t)(v >> 16);
  p[2] = (uint8_t)(v >> 8);
  p[3] = (uint8_t)v;
}

static uint32_t get32(const uint8_t* p) {
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | (uint32_t)p[3];
}

// One packet of one record: writes to consecutive addresses from `base`,
// then reads of `addrs` answered to `tag`.
static size_t eb_record(uint8_t* buf, size_t cap, uint32_t base, const uint32_t* words, uint32_t nw,
                        uint32_t tag, const uint32_t* addrs, uint32_t nr) {
  const size_t len = 12 + (nw ? 4 + 4 * (size_t)nw : 0) + (nr ? 4 + 4 * (size_t)nr : 0);
  if (nw > 255 || nr > 255 || nw + nr > EB_MAX_WORDS || len > cap) return 0;
  buf[0] = EB_MAGIC >> 8;
  buf[1] = EB_MAGIC & 0xFF;
  buf[2] = EB_VERSION_FLAGS;
  buf[3] = EB_SIZES;
  put32(buf + 4, 0);
  buf[8] = 0;
  buf[9] = EB_BYTE_ENABLE;
  buf[10] = (uint8_t)nw;
  buf[11] = (uint8_t)nr;
  uint8_t* p = buf + 12;
  if (nw) {
    put32(p, base);
    p += 4;
    for (uint32_t i = 0; i < nw; ++i, p += 4) put32(p, words[i]);
  }
  if (nr) {
    put32(p, tag);
    p += 4;
    for (uint32_t i = 0; i < nr; ++i, p += 4) put32(p, addrs[i]);
  }
  return len;
}

size_t hwi_eb_reads(uint8_t* buf, size_t cap, uint32_t tag, const uint32_t* addrs, uint32_t n) {
  return eb_record(buf, cap, 0, NULL, 0, tag, addrs, n);
}

size_t hwi_eb_writes(uint8_t* buf, size_t cap, uint32_t base, const uint32_t* words, uint32_t nw,
                     uint32_t tag, const uint32_t* addrs, uint32_t nr) {
  return eb_record(buf, cap, base, words, nw, tag, addrs, nr);
}

int hwi_eb_reply(const uint8_t* data, size_t len, uint32_t* tag, uint32_t* words, uint32_t cap) {
  if (len < 12 || data[0] != (EB_MAGIC >> 8) || data[1] != (EB_MAGIC & 0xFF) ||
      (data[2] >> 4) != 1 || data[3] != EB_SIZES)
    return -1;
  const uint32_t nw = data[10], nr = data[11];
  if (nr != 0 || nw == 0 || len != 16 + 4 * (size_t)nw || nw > cap) return -1;
  *tag = get32(data + 12);
  for (uint32_t i = 0; i < nw; ++i) words[i] = get32(data + 16 + 4 * i);
  return (int)nw;
}

// --- addresses ---------------------------------------------------------------

uint32_t hwi_addr_expect(void) { return REG(link.seq); }
uint32_t hwi_addr_time_lo(void) { return MOTION(time_lo); }
uint32_t hwi_addr_events(void) { return MOTION(events); }
uint32_t hwi_addr_snap_at(void) { return MOTION(snap_at); }
uint32_t hwi_event_snap(void) { return BIT(EVENTS, SNAP); }

uint32_t hwi_snap_reads(uint32_t axes, uint32_t* addrs) {
  uint32_t n = 0;
  addrs[n++] = MOTION(events);
  addrs[n++] = MOTION(snap_time);
  addrs[n++] = MOTION(snap_time) + 4;
  const uint32_t pos0 = MOTION(snap_pos0);
  for (uint32_t a = 0; a < axes; ++a) {
    addrs[n++] = pos0 + 8 * a;
    addrs[n++] = pos0 + 8 * a + 4;
  }
  return n;
}

size_t hwi_id_reads(uint32_t* addrs) {
  size_t n = 0;
  addrs[n++] = MOTION(id_magic);
  addrs[n++] = MOTION(id_version);
  addrs[n++] = MOTION(id_build);
  addrs[n++] = MOTION(id_widths2);
  addrs[n++] = MOTION(id_clock);
  return n;
}

#define FIELD(word, reg, field) \
  (((word)&MOTION_SOC_REGS__##reg##__##field##_bm) >> MOTION_SOC_REGS__##reg##__##field##_bp)

void hwi_id_decode(const uint32_t* w, hwi_board_id_t* id) {
  id->magic = w[0];
  id->major = FIELD(w[1], ID_VERSION, MAJOR);
  id->axes = FIELD(w[2], ID_BUILD, AXES);
  id->profile = FIELD(w[2], ID_BUILD, PROFILE);
  id->fifo_depth = FIELD(w[2], ID_BUILD, FIFO_DEPTH);
  id->feed_w = FIELD(w[3], ID_WIDTHS2, FEED_W);
  id->clock_hz = FIELD(w[4], ID_CLOCK, HZ);
}

const char* hwi_id_problem(const hwi_board_id_t* id, const hwi_config_t* cfg) {
  if (id->magic != MOTION_SOC_REGS__ID_MAGIC__MAGIC_reset)
    return "ID_MAGIC is not \"HMS1\": not a hwinterp motion_soc";
  if (id->major != MOTION_SOC_REGS__ID_VERSION__MAJOR_reset)
    return "ID_VERSION: another major version of the register map";
  if (id->profile)
    return "the board is built with the feed profile (PROFILE = 1), which refuses timed "
           "commands: flash the build without it (LinuxCNC plans the motion)";
  if (cfg->axes < 1 || cfg->axes > id->axes || cfg->axes > HWI_MAX_AXES)
    return "more joints than the board has axes";
  if (id->clock_hz == 0 || id->feed_w < 1 || id->feed_w > 30)
    return "ID_CLOCK or ID_WIDTHS2.feed_w out of range";
  return NULL;
}

hwi_link_timing_t hwi_link_timing(uint64_t rtt_ns, uint64_t period_ns, uint64_t latency_ns,
                                  uint64_t wire_ns) {
  hwi_link_timing_t t;
  if (period_ns < 1) period_ns = 1;
  t.lead_ns = latency_ns;
  if (!t.lead_ns) {
    t.lead_ns = 3 * rtt_ns + 2 * period_ns + 4 * wire_ns;
    if (t.lead_ns < 5 * period_ns) t.lead_ns = 5 * period_ns;
  }
  const uint64_t retry = (2 * rtt_ns + 2 * wire_ns) / period_ns + 1;
  t.retry_periods = retry < 4 ? 4 : retry > 1000 ? 1000 : (uint32_t)retry;
  t.dead_periods = 25 * t.retry_periods < 100 ? 100 : 25 * t.retry_periods;
  return t;
}

// --- the period's line ---------------------------------------------------------

int64_t hwi_lattice(double position, double scale) {
  const double v = position * scale;
  if (!isfinite(v) || fabs(v) > 9.0e18) return 0;
  return llround(v);
}

int hwi_line_exponent(const int64_t* delta, uint32_t axes) {
  uint64_t m = 0;
  for (uint32_t a = 0; a < axes; ++a) {
    const uint64_t v = delta[a] < 0 ? (uint64_t)0 - (uint64_t)delta[a] : (uint64_t)delta[a];
    if (v > m) m = v;
  }
  int n = 0;
  while (m) {
    ++n;
    m >>= 1;
  }
  return n;
}

uint32_t hwi_line_feed(int n, int64_t budget, uint32_t feed_w, uint32_t step_clocks,
                       int* too_fast) {
  const uint64_t one = (uint64_t)1 << feed_w;  // one operation a clock
  const uint64_t fastest = step_clocks > 1 ? one / step_clocks : one;
  *too_fast = 0;
  if (budget < 1) budget = 1;
  // ceil(2^n 2^FEED_W / budget) in 128 bits.
  const unsigned __int128 num = (unsigned __int128)1 << (n + (int)feed_w);
  unsigned __int128 feed = (num + (unsigned __int128)budget - 1) / (unsigned __int128)budget;
  if (feed > fastest) {
    *too_fast = 1;
    feed = fastest;
  }
  if (feed < 1) feed = 1;
  return (uint32_t)feed;
}

// --- the servo ---------------------------------------------------------------

static uint32_t tag_of(const hwi_servo_t* s, uint32_t seq, uint32_t attempt) {
  return (s->session & 0xF) << 28 | 1u << 27 | (seq & 0x7FFFF) << 8 | (attempt & 0xFF);
}

static int64_t board_now(const hwi_servo_t* s, int64_t host_ns) {
  return (int64_t)llround((double)(host_ns - s->host0_ns) * s->clocks_per_ns +
                          s->stats.offset_clocks);
}

static int64_t ns_to_clocks(const hwi_servo_t* s, uint64_t ns) {
  return (int64_t)llround((double)ns * s->clocks_per_ns);
}

// ns in clocks of a `hz` clock, rounded up; at least `least`.
static uint32_t ceil_clocks(uint32_t hz, uint32_t ns, uint32_t least) {
  const uint64_t c = ((uint64_t)ns * hz + 999999999u) / 1000000000u;
  return c < least ? least : c > 0xFFFFFFu ? 0xFFFFFFu : (uint32_t)c;
}

void hwi_servo_start(hwi_servo_t* s, const hwi_config_t* cfg, const hwi_board_id_t* id,
                     uint32_t session, uint32_t seq, const int64_t* position, uint64_t board_time,
                     int64_t host_ns) {
  // cfg, id and position may point into *s (a run started again).
  const hwi_config_t c = *cfg;
  const hwi_board_id_t i = *id;
  int64_t at[HWI_MAX_AXES] = {0};
  for (uint32_t a = 0; a < c.axes && a < HWI_MAX_AXES; ++a) at[a] = position[a];
  memset(s, 0, sizeof *s);
  cfg = &c;
  id = &i;
  position = at;
  s->cfg = *cfg;
  if (s->cfg.retry_periods < 1) s->cfg.retry_periods = 1;
  if (s->cfg.dead_periods <= s->cfg.retry_periods) s->cfg.dead_periods = s->cfg.retry_periods + 1;
  if (s->cfg.window < 1 || s->cfg.window > HWI_WINDOW) s->cfg.window = HWI_WINDOW;
  s->stats.retry_periods = s->cfg.retry_periods;
  s->id = *id;
  s->state = HWI_RUN;
  s->session = session;
  s->expect = s->next_seq = seq;
  s->cleared_seq = seq - 1;  // the first packet clears every event
  s->host0_ns = host_ns;
  s->clocks_per_ns = (double)id->clock_hz / 1e9;
  s->stats.offset_clocks = (double)board_time;
  s->period_clocks = ns_to_clocks(s, cfg->period_ns);
  s->slew_clocks = s->period_clocks / 64 > 1 ? s->period_clocks / 64 : 1;
  s->step_len = ceil_clocks(id->clock_hz, cfg->step_len_ns, 1);
  s->step_space = ceil_clocks(id->clock_hz, cfg->step_space_ns, 1);
  s->dir_setup = ceil_clocks(id->clock_hz, cfg->dir_setup_ns, 0);
  s->dir_hold = ceil_clocks(id->clock_hz, cfg->dir_hold_ns, 0);
  // The line's budget: the least spacing of two boundaries, less the
  // direction's set-up and hold, a step, and the core's load (8 clocks).
  s->budget_clocks = s->period_clocks - s->slew_clocks - s->dir_setup - s->dir_hold - s->step_len -
                     s->step_space - 8;
  for (uint32_t a = 0; a < cfg->axes; ++a) s->lattice[a] = position[a];
  s->setup_pending = 1;
}

// Stream words: a chunk header {count, word address} and its data.
typedef struct {
  uint32_t w[EB_MAX_WORDS];
  uint32_t n;
} stream_t;

static void chunk(stream_t* st, uint32_t addr, const uint32_t* words, uint32_t count) {
  st->w[st->n++] = count << 24 | (addr >> 2);
  for (uint32_t i = 0; i < count; ++i) st->w[st->n++] = words[i];
}

static void chunk1(stream_t* st, uint32_t addr, uint32_t word) { chunk(st, addr, &word, 1); }

// Stream words of a line command: the deltas' chunk, then CMD_FEED, CMD_AT
// (two words), CMD_FLAGS (a timed line) and CMD_PUSH, consecutive.
static uint32_t line_words_of(uint32_t axes) { return 1 + axes + 1 + 5; }
static uint32_t line_words(const hwi_servo_t* s) { return line_words_of(s->cfg.axes); }

// The words of a period's packet before its commands: SEQ, the kick's chunk.
enum { PERIOD_HEAD_WORDS = 1 + 2, PERIOD_READS = 5 };

size_t hwi_period_packet_bytes(uint32_t axes, uint32_t commands) {
  const size_t nw = PERIOD_HEAD_WORDS + (size_t)commands * line_words_of(axes);
  return 12 + 4 + 4 * nw + 4 + 4 * PERIOD_READS;
}

size_t hwi_period_reply_bytes(uint32_t snap_axes) {
  const size_t nr = snap_axes ? PERIOD_READS - 1 + 3 + 2 * (size_t)snap_axes : PERIOD_READS;
  return 16 + 4 * nr;
}

static void put_line(const hwi_servo_t* s, stream_t* st, const hwi_line_t* l) {
  uint32_t d[HWI_MAX_AXES];
  for (uint32_t a = 0; a < s->cfg.axes; ++a) d[a] = (uint32_t)l->delta[a];
  chunk(st, MOTION(cmd_delta0), d, s->cfg.axes);
  const uint32_t tail[5] = {l->feed, (uint32_t)l->at, (uint32_t)((uint64_t)l->at >> 32),
                            BIT(CMD_FLAGS, TIMED), BIT(CMD_PUSH, PUSH)};
  chunk(st, MOTION(cmd_feed), tail, 5);
}

static hwi_packet_t* slot(hwi_servo_t* s, uint32_t i) {
  return &s->window[(s->first + i) % HWI_WINDOW];
}

// The period's new packet (SEQ next_seq) into the window.
static hwi_packet_t* build_packet(hwi_servo_t* s, int64_t host_ns) {
  hwi_packet_t* p = slot(s, s->in_flight);
  stream_t st;
  st.n = 0;
  st.w[st.n++] = s->next_seq;  // SEQ, then the stream
  if (s->setup_pending) {
    const uint32_t timing[6] = {
        (uint32_t)1 << s->id.feed_w, s->step_len, s->step_space, s->dir_setup, s->dir_hold,
        s->cfg.output_type};
    chunk(&st, MOTION(feed), timing, 6);  // FEED .. STEP_TYPE are consecutive
    chunk1(&st, MOTION(cmd_ops), 0);
    chunk1(&st, MOTION(events), 0xFFFFFFFFu);
    const uint64_t wd = (uint64_t)ns_to_clocks(s, s->cfg.watchdog_period_ns);
    chunk1(&st, MOTION(wdog_period), wd > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)wd);
    s->setup_pending = 0;
  }
  chunk1(&st, MOTION(wdog_kick), BIT(WDOG_KICK, KICK));
  // The snapshot, one at a time: armed at a boundary the board will not
  // have reached when the packet arrives.
  p->arms_snap = 0;
  uint32_t clear = s->events_to_clear;
  if (!s->snap_armed && s->ring_next > 0) {
    // Past a round trip and a half, within the quarter to three quarters of
    // the boundaries queued ahead.
    const double lead = (double)s->cfg.boundary_lead_ns;
    double ahead = 1.5 * s->stats.rtt_ns_max;
    ahead = ahead < lead / 4 ? lead / 4 : ahead > 3 * lead / 4 ? 3 * lead / 4 : ahead;
    const int64_t arrive = board_now(s, host_ns) + ns_to_clocks(s, (uint64_t)ahead);
    const uint64_t oldest = s->ring_next > HWI_RING ? s->ring_next - HWI_RING : 0;
    for (uint64_t j = oldest; j < s->ring_next; ++j) {
      const hwi_boundary_t* b = &s->ring[j % HWI_RING];
      if (b->at > arrive) {
        s->snap_boundary = *b;
        p->arms_snap = 1;
        s->snap_armed = 1;
        s->snap_seq = s->next_seq;
        clear |= BIT(EVENTS, SNAP);
        break;
      }
    }
  }
  // The reads: EXPECT, TIME, FIFO_LEVEL, EVENTS; the snapshot's once a
  // reply has shown it taken.
  uint32_t reads[MAX_READS];
  uint32_t nr = 0;
  reads[nr++] = REG(link.seq);
  reads[nr++] = MOTION(time_lo);
  reads[nr++] = MOTION(time_hi);
  reads[nr++] = MOTION(fifo_level);
  if (s->snap_armed && s->snap_fired)
    nr += hwi_snap_reads(s->cfg.axes, reads + nr);  // EVENTS, SNAP_TIME, SNAP_POS
  else
    reads[nr++] = MOTION(events);
  // The commands waiting, as many as the record holds beside the snapshot's
  // and EVENTS' chunks and the reads.
  const uint32_t reserve = 2 + 4 + 2 + 1;
  uint32_t taken = 0;
  const uint32_t most = s->cfg.max_commands ? s->cfg.max_commands : HWI_OUTBOX;
  while (taken < s->outbox_len && taken < most &&
         st.n + line_words(s) + reserve + nr <= EB_MAX_WORDS)
    put_line(s, &st, &s->outbox[taken++]);
  memmove(s->outbox, s->outbox + taken, sizeof(hwi_line_t) * (s->outbox_len - taken));
  s->outbox_len -= taken;
  if (clear) {
    chunk1(&st, MOTION(events), clear);
    s->clear_seq = s->next_seq;
    s->clear_mask = clear;
    s->clear_pending = 1;
    s->events_to_clear = 0;
  }
  if (p->arms_snap) {
    const uint32_t arm[3] = {(uint32_t)s->snap_boundary.at,
                             (uint32_t)((uint64_t)s->snap_boundary.at >> 32), BIT(SNAP_CTRL, ARM)};
    chunk(&st, MOTION(snap_at), arm, 3);  // SNAP_AT (two words), SNAP_CTRL
  }
  p->seq = s->next_seq++;
  p->attempt = 0;
  p->len = eb_record(p->bytes, sizeof p->bytes, REG(link.seq), st.w, st.n, tag_of(s, p->seq, 0),
                     reads, nr);
  p->reads = nr;
  p->commands = taken;
  p->sent_ns = host_ns;
  p->sent_period = s->stats.periods;
  ++s->in_flight;
  return p;
}

static void add_boundary(hwi_servo_t* s, int64_t host_ns) {
  const int64_t want = board_now(s, host_ns) + ns_to_clocks(s, s->cfg.boundary_lead_ns);
  int64_t at = want;
  if (s->have_boundary) {
    const int64_t lo = s->last_at + s->period_clocks - s->slew_clocks;
    const int64_t hi = s->last_at + s->period_clocks + s->slew_clocks;
    at = want < lo ? lo : want > hi ? hi : want;
  }
  s->last_at = at;
  s->have_boundary = 1;
  hwi_boundary_t* b = &s->ring[s->ring_next % HWI_RING];
  b->at = at;
  memcpy(b->hold, s->lattice, sizeof b->hold);
  ++s->ring_next;
}

static int send_packet(hwi_servo_t* s, hwi_packet_t* p, hwi_send_fn send, void* ctx) {
  ++s->stats.sends;
  s->stats.bytes_sent += p->len;
  if (p->len > s->stats.bytes_sent_max) s->stats.bytes_sent_max = p->len;
  return send(ctx, p->bytes, p->len);
}

int hwi_servo_period(hwi_servo_t* s, int64_t host_ns, const int64_t* lattice, hwi_send_fn send,
                     void* ctx) {
  if (s->state != HWI_RUN) return -1;
  ++s->stats.periods;
  // This period's boundary: the board holds the last period's point there.
  add_boundary(s, host_ns);
  hwi_line_t l;
  memset(&l, 0, sizeof l);
  int moves = 0;
  for (uint32_t a = 0; a < s->cfg.axes; ++a) {
    l.delta[a] = lattice[a] - s->lattice[a];
    moves |= l.delta[a] != 0;
  }
  if (moves) {
    if (s->outbox_len == HWI_OUTBOX) {  // no packet has been sent for 16 periods
      s->state = HWI_DOWN;
      return -1;
    }
    int too_fast = 0;
    l.feed = hwi_line_feed(hwi_line_exponent(l.delta, s->cfg.axes), s->budget_clocks, s->id.feed_w,
                           s->step_len + s->step_space, &too_fast);
    l.at = s->last_at;
    s->stats.too_fast += (uint64_t)too_fast;
    s->outbox[s->outbox_len++] = l;
    ++s->stats.commands;
    memcpy(s->lattice, lattice, sizeof(int64_t) * s->cfg.axes);
  }
  int sent = 0;
  if (s->in_flight) {
    const hwi_packet_t* oldest = slot(s, 0);
    const uint64_t age = s->stats.periods - oldest->sent_period;
    if (age >= s->cfg.dead_periods) {
      s->state = HWI_DOWN;
      return -1;
    }
    // The first retry waits for the packet's and its reply's bytes on the
    // wire too (a UART's), then one every retry_periods.
    const double wire = (double)(oldest->len + 16 + 4 * oldest->reads + 12) * s->cfg.byte_ns;
    const uint32_t retry = s->stats.retry_periods;
    const uint64_t wait = retry + (uint64_t)ceil(wire / (double)s->cfg.period_ns);
    if (s->go_back || (age >= wait && (age - wait) % retry == 0)) {
      // A refusal (an earlier packet was lost): every unanswered packet
      // again, in order; a timeout: the oldest (the later ones may have
      // been taken; their replies say), each with its next attempt's tag.
      const uint32_t n = s->go_back ? s->in_flight : 1;
      s->go_back = 0;
      for (uint32_t i = 0; i < n; ++i) {
        hwi_packet_t* p = slot(s, i);
        ++p->attempt;
        put32(p->bytes + 12 + 4 + 4 * (size_t)p->bytes[10], tag_of(s, p->seq, p->attempt));
        ++s->stats.retransmits;
        if (send_packet(s, p, send, ctx) != 0) return -1;
        ++sent;
      }
    }
  }
  if (s->in_flight >= s->cfg.window) {
    if (moves) ++s->stats.missed_slots;
    return sent;
  }
  hwi_packet_t* p = build_packet(s, host_ns);
  if (!p->len) {
    s->state = HWI_DOWN;
    return -1;
  }
  if (send_packet(s, p, send, ctx) != 0) return -1;
  return sent + 1;
}

uint32_t hwi_abort_write(uint32_t* word) {
  *word = BIT(CTRL, ABORT_MOTION);
  return MOTION(ctrl);
}

static int64_t s64(uint32_t lo, uint32_t hi) { return (int64_t)((uint64_t)hi << 32 | lo); }

// The reads of a reply: time, FIFO, events, the snapshot.
static void take_reads(hwi_servo_t* s, const hwi_packet_t* p, const uint32_t* words,
                       int64_t host_ns, uint32_t attempt) {
  const uint64_t t = (uint64_t)s64(words[1], words[2]);
  s->stats.board_time = t;
  if (attempt == 0) {  // the answer to the first send: its round trip is known
    const double rtt = (double)(host_ns - p->sent_ns);
    s->stats.rtt_ns_last = rtt;
    if (rtt > s->stats.rtt_ns_max) s->stats.rtt_ns_max = rtt;
    if (s->stats.rtt_ns_smooth == 0) {
      s->stats.rtt_ns_smooth = rtt;
      s->stats.rtt_ns_var = rtt / 2;
    } else {
      s->stats.rtt_ns_var += (fabs(s->stats.rtt_ns_smooth - rtt) - s->stats.rtt_ns_var) / 4;
      s->stats.rtt_ns_smooth += (rtt - s->stats.rtt_ns_smooth) / 8;
    }
    const double want =
        ceil((s->stats.rtt_ns_smooth + 4 * s->stats.rtt_ns_var) / (double)s->cfg.period_ns) + 1;
    // At most half the latency: a packet lost once is sent again in time
    // for its commands' boundaries.
    const uint64_t half_lead = s->cfg.boundary_lead_ns / s->cfg.period_ns / 2;
    const uint64_t cap = half_lead < s->cfg.dead_periods / 2 ? half_lead : s->cfg.dead_periods / 2;
    const double most = (double)(cap > s->cfg.retry_periods ? cap : s->cfg.retry_periods);
    s->stats.retry_periods = want < (double)s->cfg.retry_periods ? s->cfg.retry_periods
                             : want > most                       ? (uint32_t)most
                                                                 : (uint32_t)want;
    const double mid = (double)(p->sent_ns - s->host0_ns) + rtt / 2;
    const double sample = (double)t - mid * s->clocks_per_ns;
    s->stats.offset_clocks += (sample - s->stats.offset_clocks) / 16;
  }
  const uint32_t fill = FIELD(words[3], FIFO_LEVEL, FILL);
  s->stats.fifo_fill = fill;
  if (fill > s->stats.fifo_fill_max) s->stats.fifo_fill_max = fill;
  const uint32_t ev = words[4];
  s->stats.events = ev;
  if (ev & BIT(EVENTS, WDOG)) s->stats.watchdog_bitten = 1;
  if (ev & BIT(EVENTS, ESTOP)) s->stats.estop = 1;
  // The sticky bits: a bit not counted since the last clear that ran (and
  // read after it) is a new event.
  const uint32_t sticky = BIT(EVENTS, LATE) | BIT(EVENTS, OVERFLOW) | BIT(EVENTS, REFUSED);
  const uint32_t fresh = ev & sticky & ~s->events_seen;
  if (fresh && (int32_t)(p->seq - s->cleared_seq) > 0) {
    if (fresh & BIT(EVENTS, LATE)) ++s->stats.late_events;
    if (fresh & BIT(EVENTS, OVERFLOW)) ++s->stats.overflow_events;
    if (fresh & BIT(EVENTS, REFUSED)) ++s->stats.refused_events;
    s->events_seen |= fresh;
    s->events_to_clear |= fresh;
  }
  // The snapshot: seen taken by a packet at or after the one that armed
  // it, then read by the next.
  if (s->snap_armed && (int32_t)(p->seq - s->snap_seq) >= 0 && (ev & BIT(EVENTS, SNAP))) {
    if (p->reads <= PERIOD_READS) {
      s->snap_fired = 1;
      return;
    }
    s->snap_armed = 0;
    s->snap_fired = 0;
    const int64_t when = s64(words[5], words[6]);
    if (when != s->snap_boundary.at) {
      ++s->stats.boundary_misses;
      return;
    }
    ++s->stats.boundary_checks;
    int wrong = 0;
    for (uint32_t a = 0; a < s->cfg.axes; ++a) {
      const int64_t e = s64(words[7 + 2 * a], words[8 + 2 * a]) - s->snap_boundary.hold[a];
      s->stats.last_ferror[a] = e;
      const int64_t m = e < 0 ? -e : e;
      if (m > s->stats.max_ferror) s->stats.max_ferror = m;
      wrong |= e != 0;
    }
    s->stats.boundary_errors += (uint64_t)wrong;
  }
}

int hwi_servo_reply(hwi_servo_t* s, const uint8_t* data, size_t len, int64_t host_ns) {
  uint32_t words[MAX_READS];
  uint32_t tag;
  const int n = hwi_eb_reply(data, len, &tag, words, MAX_READS);
  // Which unanswered packet it answers (any attempt: the guard's EXPECT
  // says the same of every copy).
  hwi_packet_t* p = NULL;
  for (uint32_t i = 0; n > 0 && i < s->in_flight; ++i)
    if ((tag_of(s, slot(s, i)->seq, 0) ^ tag) <= 0xFFu) p = slot(s, i);
  const uint32_t attempt = tag & 0xFFu;
  if (!p || (uint32_t)n != p->reads || attempt > (p->attempt & 0xFFu)) {
    ++s->stats.stale_replies;
    return 0;
  }
  s->stats.bytes_received += len;
  if (len > s->stats.bytes_received_max) s->stats.bytes_received_max = len;
  const uint32_t expect = words[0];
  if ((int32_t)(expect - s->expect) < 0) {  // read before a reply already taken: old news
    ++s->stats.stale_replies;
    return 0;
  }
  const uint32_t taken = expect - s->expect;  // packets of the window the guard has taken
  if (taken > s->in_flight) {
    s->state = HWI_DOWN;
    return -1;
  }
  const uint32_t mine = p->seq - s->expect;
  // The packets taken leave the window (the board runs them in SEQ order).
  for (uint32_t i = 0; i < taken; ++i) {
    ++s->stats.packets;
    s->stats.commands_taken += slot(s, i)->commands;
  }
  s->first = (s->first + taken) % HWI_WINDOW;
  s->in_flight -= taken;
  s->expect = expect;
  if (s->clear_pending && (int32_t)(expect - s->clear_seq) > 0) {  // the clear ran
    s->clear_pending = 0;
    s->cleared_seq = s->clear_seq;
    s->events_seen &= ~s->clear_mask;
  }
  if (mine >= taken) {
    // Refused: an earlier packet was lost. Sent again from it, unless this
    // is the answer to a copy older than the last one sent.
    if (attempt == (p->attempt & 0xFFu)) s->go_back = 1;
    return 1;
  }
  take_reads(s, p, words, host_ns, attempt);
  return 1;
}
