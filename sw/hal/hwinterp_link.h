// The board's link for hwinterp's LinuxCNC driver (docs/link.md), named by
// a URI as the host package names it (sw/host/hwinterp_host/transport.py):
//
//   udp:HOST[:PORT]     Etherbone over UDP (LiteEth), PORT 1234 by default;
//                       HOST an IPv4 address
//   serial:DEV[@BAUD]   Etherbone in SLIP frames with a CRC-32 over a UART
//                       (rtl/link/uart_etherbone.sv), 8N1, BAUD 1000000 by
//                       default; DEV a serial device or a pseudo terminal
//
// The UART's bridge runs one frame at a time and drops a frame that arrives
// while it is busy: on it the servo keeps one packet unanswered
// (hwi_link_configure), and every packet's time on the wire counts in its
// retry and in the latency (hwi_link_wire_ns).
//
// Also the plain exchanges of the start (the ID, the guard's EXPECT, TIME,
// a snapshot of the position) and the run's packets. POSIX, no HAL:
// sw/hal/hwinterp.comp, sw/hal/servo_drive.c and tests/hal/ use it.
#ifndef HWINTERP_LINK_H
#define HWINTERP_LINK_H

#include <stddef.h>
#include <stdint.h>

#include "hwinterp_servo.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HWI_DEFAULT_UDP_PORT 1234
#define HWI_DEFAULT_BAUD 1000000
#define HWI_MAX_FRAME 2048   // a received frame's bytes, the CRC included (framing.py's MAX_FRAME)
#define HWI_MIN_FRAME 12     // an Etherbone header and a record header
#define HWI_UART_COMMANDS 8  // line commands a packet at most on a UART

// CLOCK_MONOTONIC in nanoseconds.
int64_t hwi_now_ns(void);

// --- the UART's framing (docs/link.md, sw/host/hwinterp_host/framing.py) -----

// CRC-32/IEEE 802.3 (reflected, initial and final XOR 0xFFFFFFFF).
uint32_t hwi_crc32(const uint8_t* data, size_t len);

// END, the packet and its CRC-32 (least significant byte first) escaped,
// END: the frame's length, 0 when it does not fit in `cap` (2 * len + 10
// always does).
size_t hwi_slip_frame(uint8_t* out, size_t cap, const uint8_t* packet, size_t len);

// Bytes in, whole packets out: a frame is kept only when it has no bad
// escape, holds HWI_MIN_FRAME bytes and more before its CRC, at most
// HWI_MAX_FRAME in all, and its CRC is right; each kind dropped is counted.
// An empty frame (the END a sender puts before a frame) is no frame.
typedef struct {
  uint8_t buf[HWI_MAX_FRAME];
  size_t len;
  int esc, bad, too_long;
  uint64_t frames, bad_crc, bad_escape, too_short, too_long_frames;
} hwi_deframer_t;

// One byte: the packet's length (in d->buf, the CRC stripped) when it
// closed a good frame, 0 otherwise.
size_t hwi_deframe(hwi_deframer_t* d, uint8_t byte);

// --- the link ------------------------------------------------------------------

typedef struct {
  int fd;
  int serial;      // 1: the UART (SLIP frames), 0: UDP datagrams
  uint32_t baud;   // the UART's
  char name[160];  // the URI, normalised (udp:HOST:PORT, serial:DEV@BAUD)
  // The UART's receiver: bytes read and not looked at yet, and the frame.
  uint8_t raw[4096];
  size_t raw_pos, raw_len;
  hwi_deframer_t deframer;
} hwi_link_t;

// Opens the link a URI names. 0, or -1 with the reason in err (the URI
// named): a bad URI, a serial rate termios has no constant for, a device or
// socket that cannot be opened.
int hwi_link_open(hwi_link_t* l, const char* uri, char* err, size_t errlen);
void hwi_link_close(hwi_link_t* l);

// Sends a packet (framed on the UART): 0, or -1.
int hwi_link_send(hwi_link_t* l, const uint8_t* data, size_t len);

// Waits up to timeout_us for a packet: its length, 0 on timeout, -1 on error.
int hwi_link_recv(hwi_link_t* l, uint8_t* buf, size_t cap, int64_t timeout_us);

// The time a packet of `len` bytes takes on the wire, framed (10 bits a
// byte, escapes not counted); 0 on UDP.
uint64_t hwi_link_wire_ns(const hwi_link_t* l, size_t len);

// What the link asks of the servo's settings: on the UART one packet
// unanswered, the wire's time a byte, at most HWI_UART_COMMANDS commands a
// packet; nothing on UDP.
void hwi_link_configure(const hwi_link_t* l, hwi_config_t* cfg);

// The wire's time of one period's exchange: a packet of one line command
// for `axes` joints and its reply (0 on UDP): hwi_link_timing's wire_ns.
uint64_t hwi_link_period_wire_ns(const hwi_link_t* l, uint32_t axes);

// The largest round trip of n plain reads of TIME, one at a time (each
// waits up to timeout_us for its reply), in ns; -1 when fewer than half
// were answered. `session` tags them.
int64_t hwi_link_rtt(hwi_link_t* l, uint32_t session, int n, int64_t timeout_us);

// Opens a run: reads the board's ID, the guard's EXPECT and TIME, checks
// the board (hwi_id_problem), takes a snapshot of the position at once, and
// starts the servo (hwi_servo_start). Each exchange waits `timeout_us` for
// its reply and is tried `tries` times. 0, or -1 with the reason in err.
int hwi_open_run(hwi_link_t* l, hwi_servo_t* s, const hwi_config_t* cfg, uint32_t session,
                 int64_t timeout_us, int tries, char* err, size_t errlen);

// One servo period: takes every reply that has arrived (waiting up to
// wait_us while packets are unanswered: 0 waits for none), then runs the
// period (hwi_servo_period), sending what it gives. Returns 0, -1 when the
// link is down (s->state HWI_DOWN) or a send failed.
int hwi_link_period(hwi_link_t* l, hwi_servo_t* s, const int64_t* lattice, int64_t wait_us);

// The replies waiting (up to wait_us while packets are unanswered) into the
// servo.
void hwi_link_take_replies(hwi_link_t* l, hwi_servo_t* s, int64_t wait_us);

// The immediate stop: CTRL.abort_motion as a plain write, tried `tries`
// times; the servo goes idle (commands waiting dropped). 0, or -1 when no
// reply came.
int hwi_link_abort(hwi_link_t* l, hwi_servo_t* s, int64_t timeout_us, int tries);

// A plain exchange: sends `pkt` (tagged `tag`) until its reply comes, up to
// `tries` times; the `nwords` words read. 0, or -1.
int hwi_link_exchange(hwi_link_t* l, const uint8_t* pkt, size_t len, uint32_t tag, uint32_t* words,
                      uint32_t nwords, int64_t timeout_us, int tries);

#ifdef __cplusplus
}
#endif

#endif
