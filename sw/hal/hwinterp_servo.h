// The servo side of hwinterp's LinuxCNC driver (docs/linuxcnc.md): each
// servo period's joint positions become one timed line command on the
// board, so that every joint reaches its commanded lattice position at the
// period's boundary. Plain C99, no HAL and no sockets: sw/hal/hwinterp.comp
// wraps it in a HAL component, tests/hal/ drive it against a simulated board.
//
// The period's command. LinuxCNC's positions of period k, in steps
// (hwi_lattice: position x scale, rounded), are lattice point p_k; the
// command of period k moves from p_{k-1} to p_k as one line (motion_top's
// DDA: 2^n operations, n the bit length of the largest |delta|) and is
// taken by the board at its boundary at_k (CMD_AT, CMD_FLAGS.timed). Its
// feed word makes it end before at_{k+1}: budget = the least boundary
// spacing minus the margin (direction set-up and hold, a step, the core's
// load clocks), feed = ceil(2^n 2^FEED_W / budget), never faster than one
// operation each step_len + step_space clocks (the step stage's rate).
// A period whose line does not fit at that rate is sent at the fastest
// feed and counted (too_fast): its boundary will be late.
//
// The boundaries. at_k = board_time(host time of period k) + latency,
// board_time tracked from the TIME each reply carries (the midpoint of its
// round trip, filtered), and at_k - at_{k-1} kept within P +- P/64 (P the
// period in clocks) so that a line never has less than its budget.
//
// The link. Guarded Etherbone packets (docs/link.md), one a period, up to
// HWI_WINDOW of them unanswered (the board runs them in SEQ order; a reply
// says whether its packet was taken): a period whose window is full keeps
// its command for the next packet (a missed slot); when the oldest packet
// has no reply for retry_periods it is sent again, and when a reply says its
// packet was refused (an earlier one was lost) every unanswered packet is
// sent again from the first the guard expects (go-back-N: the guard runs
// each once); no reply for dead_periods: the link is down (no more
// commands). Every packet kicks
// the watchdog and reads EXPECT, TIME, FIFO_LEVEL and EVENTS; the packet
// after a reply that showed the snapshot taken reads it too.
//
// Following error. The snapshot is armed at a future boundary; when it
// fires, its position is compared with the lattice point the board must
// hold there (p_{j-1} at at_j): the difference is the following error in
// steps at that boundary (goal 0).
#ifndef HWINTERP_SERVO_H
#define HWINTERP_SERVO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HWI_MAX_AXES 6
#define HWI_RING 64          // boundaries remembered (for the snapshot's check)
#define HWI_OUTBOX 64        // commands waiting for a packet (full: the link is down)
#define HWI_MAX_PACKET 1100  // bytes: one Etherbone record of at most 248 words
#define HWI_WINDOW 8         // packets unanswered at most

// What the board says of itself (the ID registers).
typedef struct {
  uint32_t magic, major, axes, profile, fifo_depth, feed_w, clock_hz;
} hwi_board_id_t;

// The driver's settings.
typedef struct {
  uint32_t axes;              // joints driven: 1..the board's axes
  uint64_t period_ns;         // the servo period
  uint64_t boundary_lead_ns;  // host time of a period to its boundary on the board: the latency
  uint32_t step_len_ns, step_space_ns, dir_setup_ns, dir_hold_ns;  // rounded up to clocks
  uint32_t output_type;         // STEP_TYPE: 0 step/dir, 1 up/down, 2 quadrature
  uint64_t watchdog_period_ns;  // WDOG_PERIOD (0: off)
  uint32_t retry_periods;       // send again after this many periods without a reply
  uint32_t dead_periods;        // the link is down after this many
  uint32_t window;              // packets unanswered at most: 1..HWI_WINDOW (0: HWI_WINDOW)
  double byte_ns;               // a byte's time on the wire (a UART's; 0: none): a packet's
                                // retry waits for its and its reply's bytes too
  uint32_t max_commands;        // line commands a packet at most (0: as many as fit)
} hwi_config_t;

// Figures the driver reports (HAL pins, the closing JSON).
typedef struct {
  uint64_t periods;         // periods run while enabled
  uint64_t commands;        // line commands made (periods with motion)
  uint64_t commands_taken;  // ... acknowledged by the board (the guard took their packet)
  uint64_t packets;         // guarded packets taken
  uint64_t sends;           // packets sent, retransmissions included
  uint64_t retransmits;
  uint64_t missed_slots;   // periods whose command waited for an earlier packet's reply
  uint64_t stale_replies;  // replies with another tag (dropped)
  uint64_t too_fast;       // periods beyond the step stage's rate
  uint64_t late_events;    // replies showing EVENTS.late (cleared each time)
  uint64_t overflow_events, refused_events;
  uint64_t boundary_checks;  // snapshots taken exactly at a boundary
  uint64_t boundary_misses;  // snapshots that fired elsewhere (armed too late)
  uint64_t boundary_errors;  // checks with a nonzero following error
  int64_t max_ferror;        // largest |following error| at a boundary, steps
  int64_t last_ferror[HWI_MAX_AXES];
  uint64_t bytes_sent_max, bytes_received_max;  // one burst each way
  uint64_t bytes_sent, bytes_received;
  uint32_t fifo_fill, fifo_fill_max;
  uint32_t events;      // EVENTS as last read
  uint64_t board_time;  // TIME as last read
  double rtt_ns_max, rtt_ns_last;
  double rtt_ns_smooth, rtt_ns_var;  // the round trips, filtered as TCP does (RFC 6298)
  uint32_t retry_periods;            // the retry now: the smoothed round trip and four
                                     // deviations, not below the configured one
  double offset_clocks;              // board time - host time, filtered (clocks)
  int watchdog_bitten, estop;        // EVENTS.wdog / EVENTS.estop seen
} hwi_stats_t;

typedef enum { HWI_IDLE = 0, HWI_RUN, HWI_DOWN } hwi_state_t;

typedef struct {
  int64_t at;                  // the boundary (board clocks)
  int64_t hold[HWI_MAX_AXES];  // the lattice point the board holds there
} hwi_boundary_t;

typedef struct {
  int64_t delta[HWI_MAX_AXES];
  uint32_t feed;
  int64_t at;
} hwi_line_t;

// A packet sent and not answered yet.
typedef struct {
  uint8_t bytes[HWI_MAX_PACKET];
  size_t len;
  uint32_t seq, attempt, reads, commands;
  int arms_snap;
  int64_t sent_ns;  // its first send
  uint64_t sent_period;
} hwi_packet_t;

typedef struct {
  hwi_config_t cfg;
  hwi_board_id_t id;
  hwi_state_t state;
  uint32_t session;   // the tag's session number (4 bits)
  uint32_t expect;    // the first SEQ not known to be taken
  uint32_t next_seq;  // the next new packet's SEQ
  // Time.
  int64_t host0_ns;  // host time of the pairing
  double clocks_per_ns;
  int64_t period_clocks, slew_clocks, budget_clocks;
  uint32_t step_len, step_space, dir_setup, dir_hold;  // the step timing in clocks
  int64_t last_at;                                     // the latest boundary made
  int have_boundary;
  // Positions.
  int64_t lattice[HWI_MAX_AXES];  // the latest commanded lattice point
  hwi_boundary_t ring[HWI_RING];
  uint64_t ring_next;  // boundaries made so far
  // Commands not in a packet yet.
  hwi_line_t outbox[HWI_OUTBOX];
  uint32_t outbox_len;
  // The packets unanswered: window[(first + i) % HWI_WINDOW], i < in_flight.
  hwi_packet_t window[HWI_WINDOW];
  uint32_t first, in_flight;
  int go_back;  // a reply said its packet was refused
  // Snapshot.
  int snap_armed;     // a packet arms it (sent or taken), not read back yet
  int snap_fired;     // a reply showed it taken: the next packet reads it
  uint32_t snap_seq;  // that packet's SEQ
  hwi_boundary_t snap_boundary;
  // EVENTS' sticky bits (late, overflow, refused): each counted once when
  // seen, then cleared (write 1) by the next packet; counted again only
  // when seen by a packet after that clear ran.
  uint32_t events_to_clear;        // seen, to be cleared by the next packet
  uint32_t events_seen;            // counted since the last clear that ran
  uint32_t clear_mask, clear_seq;  // the last clearing packet: its bits, its SEQ
  int clear_pending;               // ... not known to have run yet
  uint32_t cleared_seq;            // the SEQ of the last clear that ran
  int setup_pending;               // the first packet carries the settings
  hwi_stats_t stats;
} hwi_servo_t;

// Lattice coordinate of a position: llround(position x scale); 0 for a
// position that is not finite.
int64_t hwi_lattice(double position, double scale);

// The bit length of max |delta| over the axes: the line runs 2^n operations.
int hwi_line_exponent(const int64_t* delta, uint32_t axes);

// The feed word of a line of 2^n operations that must end within `budget`
// clocks; *too_fast set when the step stage's rate (one operation every
// step_clocks) does not allow it (the word is then the fastest allowed).
uint32_t hwi_line_feed(int n, int64_t budget, uint32_t feed_w, uint32_t step_clocks, int* too_fast);

// The link's timing from the largest round trip measured (rtt_ns, e.g. of 20
// reads of TIME), the servo period and the wire's time of one period's
// exchange (wire_ns: a UART's bytes, 0 on UDP): the latency (three round
// trips, two periods and four exchanges on the wire, at least five
// periods), the periods before a packet is sent again (two round trips and
// two exchanges, at least 4) and before the link is down (25 of those, at
// least 100). A latency given (latency_ns > 0) is kept.
typedef struct {
  uint64_t lead_ns;  // the latency (hwi_config_t's boundary_lead_ns)
  uint32_t retry_periods, dead_periods;
} hwi_link_timing_t;
hwi_link_timing_t hwi_link_timing(uint64_t rtt_ns, uint64_t period_ns, uint64_t latency_ns,
                                  uint64_t wire_ns);

// The bytes of a period's packet carrying `commands` line commands for
// `axes` joints (no settings, snapshot or EVENTS clear in it), and of the
// reply to a packet reading the snapshot of `snap_axes` axes (0: none).
size_t hwi_period_packet_bytes(uint32_t axes, uint32_t commands);
size_t hwi_period_reply_bytes(uint32_t snap_axes);

// Reads a board's ID registers (the words of hwi_id_reads, in order).
size_t hwi_id_reads(uint32_t* addrs);
void hwi_id_decode(const uint32_t* words, hwi_board_id_t* id);
// Why this driver cannot drive the board (NULL: it can).
const char* hwi_id_problem(const hwi_board_id_t* id, const hwi_config_t* cfg);

// Starts a run: the board's position (steps) at board time `board_time`,
// seen at host time `host_ns`; `seq` the guard's EXPECT. The first packet
// writes the settings (step timing, FEED, watchdog, EVENTS cleared).
void hwi_servo_start(hwi_servo_t* s, const hwi_config_t* cfg, const hwi_board_id_t* id,
                     uint32_t session, uint32_t seq, const int64_t* position, uint64_t board_time,
                     int64_t host_ns);

// One servo period at host time `host_ns` with the joints' lattice points.
// Calls send(ctx, bytes, len) for every packet to send now (the period's
// new packet, or the unanswered ones again); the number sent, -1 when a
// send failed or the link is down (s->state HWI_DOWN).
typedef int (*hwi_send_fn)(void* ctx, const uint8_t* data, size_t len);
int hwi_servo_period(hwi_servo_t* s, int64_t host_ns, const int64_t* lattice, hwi_send_fn send,
                     void* ctx);

// A datagram from the board at host time `host_ns`. Returns 1 when it
// answered an unanswered packet (the stats and the following error
// updated), 0 when it was dropped (another tag, an earlier attempt,
// malformed), -1 when the guard's EXPECT is outside the window (another
// host, or the board was reset: the link is down).
int hwi_servo_reply(hwi_servo_t* s, const uint8_t* data, size_t len, int64_t host_ns);

// The write that stops the board at once: its address, the word in *word.
uint32_t hwi_abort_write(uint32_t* word);

// Plain reads (no SEQ): an Etherbone packet reading `n` addresses, tagged
// with `tag`. Its length.
size_t hwi_eb_reads(uint8_t* buf, size_t cap, uint32_t tag, const uint32_t* addrs, uint32_t n);
// Plain writes to consecutive addresses from `base`, then reads.
size_t hwi_eb_writes(uint8_t* buf, size_t cap, uint32_t base, const uint32_t* words, uint32_t nw,
                     uint32_t tag, const uint32_t* addrs, uint32_t nr);
// A reply: its tag and up to `cap` words; the number of words, -1 if malformed.
int hwi_eb_reply(const uint8_t* data, size_t len, uint32_t* tag, uint32_t* words, uint32_t cap);

// The addresses hwi_servo_* use (the board map's, sw/board_regs.h).
uint32_t hwi_addr_expect(void);
uint32_t hwi_addr_time_lo(void);
uint32_t hwi_addr_events(void);
uint32_t hwi_addr_snap_at(void);
uint32_t hwi_snap_reads(uint32_t axes, uint32_t* addrs);  // EVENTS, SNAP_TIME, SNAP_POS
uint32_t hwi_event_snap(void);

#ifdef __cplusplus
}
#endif

#endif
