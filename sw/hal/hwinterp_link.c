// The board's link for hwinterp's LinuxCNC driver: see hwinterp_link.h.
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "hwinterp_link.h"

#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

int64_t hwi_now_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

int hwi_udp_open(const char* host, int port, char* err, size_t errlen) {
  struct sockaddr_in a;
  memset(&a, 0, sizeof a);
  a.sin_family = AF_INET;
  a.sin_port = htons((uint16_t)port);
  if (port < 1 || port > 65535 || inet_pton(AF_INET, host, &a.sin_addr) != 1) {
    snprintf(err, errlen, "board address '%s' port %d: give an IPv4 address and a port 1..65535",
             host, port);
    return -1;
  }
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0 || connect(fd, (struct sockaddr*)&a, sizeof a) != 0) {
    snprintf(err, errlen, "udp %s:%d: %s", host, port, strerror(errno));
    if (fd >= 0) close(fd);
    return -1;
  }
  return fd;
}

void hwi_udp_close(int fd) {
  if (fd >= 0) close(fd);
}

int hwi_udp_send(int fd, const uint8_t* data, size_t len) {
  return send(fd, data, len, 0) == (ssize_t)len ? 0 : -1;
}

int hwi_udp_recv(int fd, uint8_t* buf, size_t cap, int64_t timeout_us) {
  const int64_t end = hwi_now_ns() + timeout_us * 1000;
  for (;;) {
    const ssize_t n = recv(fd, buf, cap, 0);
    if (n >= 0) return (int)n;
    if (errno == ECONNREFUSED) continue;  // an ICMP of an earlier send: nobody listened then
    if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return -1;
    const int64_t left = end - hwi_now_ns();
    if (left <= 0) return 0;
    struct pollfd p = {fd, POLLIN, 0};
    const int ms = (int)((left + 999999) / 1000000);
    if (poll(&p, 1, ms) < 0 && errno != EINTR) return -1;
  }
}

// A plain exchange: sends `pkt` (tagged `tag`) until its reply comes; the
// words read. 0, or -1.
static int exchange(int fd, const uint8_t* pkt, size_t len, uint32_t tag, uint32_t* words,
                    uint32_t nwords, int64_t timeout_us, int tries) {
  uint8_t buf[HWI_MAX_PACKET];
  for (int t = 0; t < tries; ++t) {
    if (hwi_udp_send(fd, pkt, len) != 0) return -1;
    const int64_t end = hwi_now_ns() + timeout_us * 1000;
    for (;;) {
      const int64_t left_us = (end - hwi_now_ns()) / 1000;
      if (left_us <= 0) break;
      const int n = hwi_udp_recv(fd, buf, sizeof buf, left_us);
      if (n < 0) return -1;
      if (n == 0) break;
      uint32_t got;
      if (hwi_eb_reply(buf, (size_t)n, &got, words, nwords) == (int)nwords && got == tag) return 0;
    }
  }
  return -1;
}

int hwi_open_run(int fd, hwi_servo_t* s, const hwi_config_t* cfg, uint32_t session,
                 int64_t timeout_us, int tries, char* err, size_t errlen) {
  uint8_t pkt[HWI_MAX_PACKET];
  uint32_t addrs[40], words[40];
  uint32_t n = (uint32_t)hwi_id_reads(addrs);
  addrs[n++] = hwi_addr_expect();
  addrs[n++] = hwi_addr_time_lo();
  addrs[n++] = hwi_addr_time_lo() + 4;
  // Plain tags: bit 27 clear, the session, a count in bits 26:8.
  uint32_t tag = (session & 0xF) << 28 | 1u << 8;
  int64_t sent = hwi_now_ns();
  size_t len = hwi_eb_reads(pkt, sizeof pkt, tag, addrs, n);
  if (exchange(fd, pkt, len, tag, words, n, timeout_us, tries) != 0) {
    snprintf(err, errlen, "no reply to the ID reads (%d tries of %lld us)", tries,
             (long long)timeout_us);
    return -1;
  }
  const int64_t mid = sent + (hwi_now_ns() - sent) / 2;
  hwi_board_id_t id;
  hwi_id_decode(words, &id);
  const char* problem = hwi_id_problem(&id, cfg);
  if (problem) {
    snprintf(err, errlen, "%s (ID_MAGIC 0x%08x, axes %u, profile %u)", problem, id.magic, id.axes,
             id.profile);
    return -1;
  }
  const uint32_t expect = words[n - 3];
  const uint64_t board_time = (uint64_t)words[n - 1] << 32 | words[n - 2];
  // The position: a snapshot at once (EVENTS.snap cleared, SNAP_AT 0, arm;
  // the same when repeated), read until it is taken.
  const uint32_t snap = hwi_event_snap();
  tag = (session & 0xF) << 28 | 2u << 8;
  uint32_t reads[2 + 2 + 2 * HWI_MAX_AXES];
  const uint32_t nr = hwi_snap_reads(cfg->axes, reads);
  len = hwi_eb_writes(pkt, sizeof pkt, hwi_addr_events(), &snap, 1, tag, reads, 1);
  if (exchange(fd, pkt, len, tag, words, 1, timeout_us, tries) != 0) {
    snprintf(err, errlen, "no reply to the snapshot's EVENTS write");
    return -1;
  }
  const uint32_t arm[3] = {0, 0, 1};  // SNAP_AT = 0 (passed: at once), SNAP_CTRL.arm
  for (uint32_t k = 3;; ++k) {
    tag = (session & 0xF) << 28 | k << 8;
    len = k == 3 ? hwi_eb_writes(pkt, sizeof pkt, hwi_addr_snap_at(), arm, 3, tag, reads, nr)
                 : hwi_eb_reads(pkt, sizeof pkt, tag, reads, nr);
    if (exchange(fd, pkt, len, tag, words, nr, timeout_us, tries) != 0) {
      snprintf(err, errlen, "no reply to the snapshot");
      return -1;
    }
    if (words[0] & snap) break;
    if (k > 100) {
      snprintf(err, errlen, "the snapshot was not taken (EVENTS.snap stays clear)");
      return -1;
    }
  }
  int64_t pos[HWI_MAX_AXES] = {0};
  for (uint32_t a = 0; a < cfg->axes; ++a)
    pos[a] = (int64_t)((uint64_t)words[4 + 2 * a] << 32 | words[3 + 2 * a]);
  hwi_servo_start(s, cfg, &id, session, expect, pos, board_time, mid);
  return 0;
}

static void take_replies(int fd, hwi_servo_t* s, int64_t wait_us) {
  uint8_t buf[HWI_MAX_PACKET];
  const int64_t end = hwi_now_ns() + wait_us * 1000;
  for (;;) {
    const int64_t left_us = s->in_flight ? (end - hwi_now_ns()) / 1000 : 0;
    const int n = hwi_udp_recv(fd, buf, sizeof buf, left_us > 0 ? left_us : 0);
    if (n <= 0) return;
    hwi_servo_reply(s, buf, (size_t)n, hwi_now_ns());
  }
}

static int send_udp(void* ctx, const uint8_t* data, size_t len) {
  return hwi_udp_send(*(const int*)ctx, data, len);
}

int hwi_link_period(int fd, hwi_servo_t* s, const int64_t* lattice, int64_t wait_us) {
  take_replies(fd, s, wait_us);
  return hwi_servo_period(s, hwi_now_ns(), lattice, send_udp, &fd) < 0 ? -1 : 0;
}

int hwi_link_abort(int fd, hwi_servo_t* s, int64_t timeout_us, int tries) {
  // CTRL.abort_motion as a plain write (outside the guard's window it passes
  // unchanged): the same when repeated, and independent of the packet in
  // flight, which may never be answered.
  uint8_t pkt[HWI_MAX_PACKET];
  uint32_t word;
  const uint32_t addr = hwi_abort_write(&word);
  const uint32_t tag = (s->session & 0xF) << 28 | 0x7FFFFu << 8;
  uint32_t expect;
  const uint32_t read = hwi_addr_expect();
  const size_t len = hwi_eb_writes(pkt, sizeof pkt, addr, &word, 1, tag, &read, 1);
  s->state = HWI_IDLE;
  s->outbox_len = 0;
  return exchange(fd, pkt, len, tag, &expect, 1, timeout_us, tries);
}
