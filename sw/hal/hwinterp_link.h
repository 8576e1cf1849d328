// The board's link for hwinterp's LinuxCNC driver: Etherbone over UDP
// (docs/link.md), the plain exchanges of the start (the ID, the guard's
// EXPECT, TIME, a snapshot of the position) and the run's datagrams.
// POSIX sockets, no HAL: sw/hal/hwinterp.comp and tests/hal/ use it.
#ifndef HWINTERP_LINK_H
#define HWINTERP_LINK_H

#include <stddef.h>
#include <stdint.h>

#include "hwinterp_servo.h"

#ifdef __cplusplus
extern "C" {
#endif

// CLOCK_MONOTONIC in nanoseconds.
int64_t hwi_now_ns(void);

// A UDP socket connected to HOST:PORT (an IPv4 address), non-blocking.
// The descriptor, or -1 with the reason in err.
int hwi_udp_open(const char* host, int port, char* err, size_t errlen);
void hwi_udp_close(int fd);

// Sends a datagram: 0, or -1 (errno kept).
int hwi_udp_send(int fd, const uint8_t* data, size_t len);

// Waits up to timeout_us for a datagram: its length, 0 on timeout, -1 on error.
int hwi_udp_recv(int fd, uint8_t* buf, size_t cap, int64_t timeout_us);

// Opens a run: reads the board's ID, the guard's EXPECT and TIME, checks
// the board (hwi_id_problem), takes a snapshot of the position at once, and
// starts the servo (hwi_servo_start). Each exchange waits `timeout_us` for
// its reply and is tried `tries` times. 0, or -1 with the reason in err.
int hwi_open_run(int fd, hwi_servo_t* s, const hwi_config_t* cfg, uint32_t session,
                 int64_t timeout_us, int tries, char* err, size_t errlen);

// One servo period: takes every reply that has arrived (waiting up to
// wait_us while packets are unanswered: 0 waits for none), then runs the
// period (hwi_servo_period), sending what it gives. Returns 0, -1 when the
// link is down (s->state HWI_DOWN) or a send failed.
int hwi_link_period(int fd, hwi_servo_t* s, const int64_t* lattice, int64_t wait_us);

// The immediate stop: CTRL.abort_motion as a plain write, tried `tries`
// times; the servo goes idle (commands waiting dropped). 0, or -1 when no
// reply came.
int hwi_link_abort(int fd, hwi_servo_t* s, int64_t timeout_us, int tries);

#ifdef __cplusplus
}
#endif

#endif
