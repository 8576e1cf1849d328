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
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

int64_t hwi_now_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

// --- the UART's framing ---------------------------------------------------------

enum { SLIP_END = 0xC0, SLIP_ESC = 0xDB, SLIP_ESC_END = 0xDC, SLIP_ESC_ESC = 0xDD };

uint32_t hwi_crc32(const uint8_t* data, size_t len) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < len; ++i) {
    c ^= data[i];
    for (int k = 0; k < 8; ++k) c = c >> 1 ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

static size_t put_escaped(uint8_t* out, size_t n, uint8_t b) {
  if (b == SLIP_END || b == SLIP_ESC) {
    out[n++] = SLIP_ESC;
    out[n++] = b == SLIP_END ? SLIP_ESC_END : SLIP_ESC_ESC;
  } else {
    out[n++] = b;
  }
  return n;
}

size_t hwi_slip_frame(uint8_t* out, size_t cap, const uint8_t* packet, size_t len) {
  if (cap < 2 * len + 10) return 0;
  const uint32_t crc = hwi_crc32(packet, len);
  size_t n = 0;
  out[n++] = SLIP_END;
  for (size_t i = 0; i < len; ++i) n = put_escaped(out, n, packet[i]);
  for (int k = 0; k < 4; ++k) n = put_escaped(out, n, (uint8_t)(crc >> 8 * k));
  out[n++] = SLIP_END;
  return n;
}

size_t hwi_deframe(hwi_deframer_t* d, uint8_t b) {
  if (b == SLIP_END) {
    const size_t len = d->len;
    const int bad = d->bad || d->esc, too_long = d->too_long;
    d->len = 0;
    d->esc = d->bad = d->too_long = 0;
    if (!len && !bad && !too_long) return 0;  // an empty frame
    if (bad) {
      ++d->bad_escape;
      return 0;
    }
    if (too_long) {
      ++d->too_long_frames;
      return 0;
    }
    if (len < HWI_MIN_FRAME + 4) {
      ++d->too_short;
      return 0;
    }
    const uint8_t* c = d->buf + len - 4;
    const uint32_t crc =
        (uint32_t)c[0] | (uint32_t)c[1] << 8 | (uint32_t)c[2] << 16 | (uint32_t)c[3] << 24;
    if (hwi_crc32(d->buf, len - 4) != crc) {
      ++d->bad_crc;
      return 0;
    }
    ++d->frames;
    return len - 4;
  }
  if (d->esc) {
    d->esc = 0;
    if (b == SLIP_ESC_END)
      b = SLIP_END;
    else if (b == SLIP_ESC_ESC)
      b = SLIP_ESC;
    else {
      d->bad = 1;
      return 0;
    }
  } else if (b == SLIP_ESC) {
    d->esc = 1;
    return 0;
  }
  if (d->len >= HWI_MAX_FRAME) {
    d->too_long = 1;
    return 0;
  }
  d->buf[d->len++] = b;
  return 0;
}

// --- the link ------------------------------------------------------------------

static speed_t speed_of(uint32_t baud) {
  static const struct {
    uint32_t baud;
    speed_t speed;
  } rates[] = {{9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
               {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
               {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000},
               {1500000, B1500000}, {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000},
               {4000000, B4000000}};
  for (size_t i = 0; i < sizeof rates / sizeof rates[0]; ++i)
    if (rates[i].baud == baud) return rates[i].speed;
  return B0;
}

// A rate termios has no constant for (the simulated boards' 250 kbaud):
// Linux's termios2 with BOTHER, declared here as <asm/termbits.h> does
// (that header cannot be included beside <termios.h>).
struct hwi_termios2 {
  tcflag_t c_iflag, c_oflag, c_cflag, c_lflag;
  cc_t c_line;
  cc_t c_cc[19];
  speed_t c_ispeed, c_ospeed;
};
#define HWI_TCGETS2 _IOR('T', 0x2A, struct hwi_termios2)
#define HWI_TCSETS2 _IOW('T', 0x2B, struct hwi_termios2)
#define HWI_BOTHER 0010000

static int set_any_rate(int fd, uint32_t baud) {
  struct hwi_termios2 t;
  if (ioctl(fd, HWI_TCGETS2, &t) != 0) return -1;
  t.c_cflag &= ~(tcflag_t)CBAUD;
  t.c_cflag |= HWI_BOTHER;
  t.c_ispeed = t.c_ospeed = baud;
  return ioctl(fd, HWI_TCSETS2, &t);
}

static int open_udp(hwi_link_t* l, const char* uri, const char* rest, char* err, size_t errlen) {
  char host[64];
  int port = HWI_DEFAULT_UDP_PORT;
  const char* colon = strchr(rest, ':');
  const size_t hl = colon ? (size_t)(colon - rest) : strlen(rest);
  if (hl == 0 || hl >= sizeof host) {
    snprintf(err, errlen, "link URI '%s': no host (give udp:HOST[:PORT] or serial:DEV[@BAUD])",
             uri);
    return -1;
  }
  memcpy(host, rest, hl);
  host[hl] = 0;
  if (colon) {
    char* end;
    const long p = strtol(colon + 1, &end, 10);
    if (!colon[1] || *end || p < 1 || p > 65535) {
      snprintf(err, errlen, "link URI '%s': port '%s' is not 1..65535", uri, colon + 1);
      return -1;
    }
    port = (int)p;
  }
  struct sockaddr_in a;
  memset(&a, 0, sizeof a);
  a.sin_family = AF_INET;
  a.sin_port = htons((uint16_t)port);
  if (inet_pton(AF_INET, host, &a.sin_addr) != 1) {
    snprintf(err, errlen, "link URI '%s': '%s' is not an IPv4 address", uri, host);
    return -1;
  }
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0 || connect(fd, (struct sockaddr*)&a, sizeof a) != 0) {
    snprintf(err, errlen, "link URI '%s': %s", uri, strerror(errno));
    if (fd >= 0) close(fd);
    return -1;
  }
  l->fd = fd;
  snprintf(l->name, sizeof l->name, "udp:%s:%d", host, port);
  return 0;
}

static int open_serial(hwi_link_t* l, const char* uri, const char* rest, char* err, size_t errlen) {
  char dev[128];
  uint32_t baud = HWI_DEFAULT_BAUD;
  const char* at = strrchr(rest, '@');
  const size_t dl = at ? (size_t)(at - rest) : strlen(rest);
  if (dl == 0 || dl >= sizeof dev) {
    snprintf(err, errlen, "link URI '%s': no device (give udp:HOST[:PORT] or serial:DEV[@BAUD])",
             uri);
    return -1;
  }
  memcpy(dev, rest, dl);
  dev[dl] = 0;
  if (at) {
    char* end;
    const long b = strtol(at + 1, &end, 10);
    if (!at[1] || *end || b <= 0) {
      snprintf(err, errlen, "link URI '%s': baud rate '%s' is not a positive integer", uri, at + 1);
      return -1;
    }
    baud = (uint32_t)b;
  }
  const speed_t speed = speed_of(baud);
  const int fd = open(dev, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    snprintf(err, errlen, "link URI '%s': %s: %s", uri, dev, strerror(errno));
    return -1;
  }
  struct termios t;
  if (tcgetattr(fd, &t) != 0) {
    snprintf(err, errlen, "link URI '%s': %s is not a serial device (%s)", uri, dev,
             strerror(errno));
    close(fd);
    return -1;
  }
  cfmakeraw(&t);  // 8N1, no echo, no flow control
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~(tcflag_t)(CSTOPB | PARENB | CRTSCTS);
  t.c_iflag &= ~(tcflag_t)(IXON | IXOFF | IXANY);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  cfsetispeed(&t, speed == B0 ? B38400 : speed);
  cfsetospeed(&t, speed == B0 ? B38400 : speed);
  if (tcsetattr(fd, TCSANOW, &t) != 0 || (speed == B0 && set_any_rate(fd, baud) != 0)) {
    snprintf(err, errlen, "link URI '%s': %s refuses the settings (8N1 raw, %u baud): %s", uri, dev,
             baud, strerror(errno));
    close(fd);
    return -1;
  }
  tcflush(fd, TCIOFLUSH);
  l->fd = fd;
  l->serial = 1;
  l->baud = baud;
  snprintf(l->name, sizeof l->name, "serial:%s@%u", dev, baud);
  return 0;
}

int hwi_link_open(hwi_link_t* l, const char* uri, char* err, size_t errlen) {
  memset(l, 0, sizeof *l);
  l->fd = -1;
  if (!strncmp(uri, "udp:", 4)) return open_udp(l, uri, uri + 4, err, errlen);
  if (!strncmp(uri, "serial:", 7)) return open_serial(l, uri, uri + 7, err, errlen);
  snprintf(err, errlen,
           "link URI '%s': no scheme udp: or serial: (give udp:HOST[:PORT] or "
           "serial:DEV[@BAUD])",
           uri);
  return -1;
}

void hwi_link_close(hwi_link_t* l) {
  if (l->fd >= 0) close(l->fd);
  l->fd = -1;
}

static int write_all(int fd, const uint8_t* p, size_t n) {
  const int64_t end = hwi_now_ns() + 100000000;  // 100 ms
  while (n) {
    const ssize_t w = write(fd, p, n);
    if (w > 0) {
      p += w;
      n -= (size_t)w;
      continue;
    }
    if (w < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return -1;
    const int64_t left = end - hwi_now_ns();
    if (left <= 0) return -1;
    struct pollfd q = {fd, POLLOUT, 0};
    poll(&q, 1, (int)((left + 999999) / 1000000));
  }
  return 0;
}

int hwi_link_send(hwi_link_t* l, const uint8_t* data, size_t len) {
  if (!l->serial) return send(l->fd, data, len, 0) == (ssize_t)len ? 0 : -1;
  uint8_t frame[2 * HWI_MAX_PACKET + 10];
  const size_t n = hwi_slip_frame(frame, sizeof frame, data, len);
  return n ? write_all(l->fd, frame, n) : -1;
}

// The next good frame among the bytes read: its length, 0 when none.
static int next_frame(hwi_link_t* l, uint8_t* buf, size_t cap) {
  while (l->raw_pos < l->raw_len) {
    const size_t n = hwi_deframe(&l->deframer, l->raw[l->raw_pos++]);
    if (n && n <= cap) {
      memcpy(buf, l->deframer.buf, n);
      return (int)n;
    }
  }
  return 0;
}

int hwi_link_recv(hwi_link_t* l, uint8_t* buf, size_t cap, int64_t timeout_us) {
  const int64_t end = hwi_now_ns() + timeout_us * 1000;
  for (;;) {
    if (l->serial) {
      const int n = next_frame(l, buf, cap);
      if (n) return n;
      const ssize_t r = read(l->fd, l->raw, sizeof l->raw);
      if (r > 0) {
        l->raw_pos = 0;
        l->raw_len = (size_t)r;
        continue;
      }
      if (r < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return -1;
    } else {
      const ssize_t n = recv(l->fd, buf, cap, 0);
      if (n >= 0) return (int)n;
      if (errno == ECONNREFUSED) continue;  // an ICMP of an earlier send: nobody listened then
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return -1;
    }
    const int64_t left = end - hwi_now_ns();
    if (left <= 0) return 0;
    struct pollfd p = {l->fd, POLLIN, 0};
    const int ms = (int)((left + 999999) / 1000000);
    if (poll(&p, 1, ms) < 0 && errno != EINTR) return -1;
  }
}

uint64_t hwi_link_wire_ns(const hwi_link_t* l, size_t len) {
  if (!l->serial || !l->baud) return 0;
  return (uint64_t)(len + 6) * 10 * 1000000000ull / l->baud;  // END, CRC, END: 6 bytes
}

void hwi_link_configure(const hwi_link_t* l, hwi_config_t* cfg) {
  cfg->window = l->serial ? 1 : 0;
  cfg->byte_ns = l->serial && l->baud ? 1e10 / l->baud : 0;
  // On the UART a byte spoilt spoils its frame: a backlog goes in packets
  // of a few commands (at most about 420 bytes), not in one lost whole.
  cfg->max_commands = l->serial ? HWI_UART_COMMANDS : 0;
}

uint64_t hwi_link_period_wire_ns(const hwi_link_t* l, uint32_t axes) {
  return hwi_link_wire_ns(l, hwi_period_packet_bytes(axes, 1)) +
         hwi_link_wire_ns(l, hwi_period_reply_bytes(0));
}

int hwi_link_exchange(hwi_link_t* l, const uint8_t* pkt, size_t len, uint32_t tag, uint32_t* words,
                      uint32_t nwords, int64_t timeout_us, int tries) {
  uint8_t buf[HWI_MAX_PACKET];
  for (int t = 0; t < tries; ++t) {
    if (hwi_link_send(l, pkt, len) != 0) return -1;
    const int64_t end = hwi_now_ns() + timeout_us * 1000;
    for (;;) {
      const int64_t left_us = (end - hwi_now_ns()) / 1000;
      if (left_us <= 0) break;
      const int n = hwi_link_recv(l, buf, sizeof buf, left_us);
      if (n < 0) return -1;
      if (n == 0) break;
      uint32_t got;
      if (hwi_eb_reply(buf, (size_t)n, &got, words, nwords) == (int)nwords && got == tag) return 0;
    }
  }
  return -1;
}

int64_t hwi_link_rtt(hwi_link_t* l, uint32_t session, int n, int64_t timeout_us) {
  uint8_t pkt[64];
  const uint32_t a[2] = {hwi_addr_time_lo(), hwi_addr_time_lo() + 4};
  int64_t worst = 0;
  int answered = 0;
  for (int i = 0; i < n; ++i) {
    const uint32_t tag = (session & 0xF) << 28 | (0x1000u + (uint32_t)i) << 8;
    const size_t len = hwi_eb_reads(pkt, sizeof pkt, tag, a, 2);
    uint32_t w[2];
    const int64_t t0 = hwi_now_ns();
    if (hwi_link_exchange(l, pkt, len, tag, w, 2, timeout_us, 1) != 0) continue;
    const int64_t rtt = hwi_now_ns() - t0;
    if (rtt > worst) worst = rtt;
    ++answered;
  }
  return 2 * answered >= n ? worst : -1;
}

int hwi_open_run(hwi_link_t* l, hwi_servo_t* s, const hwi_config_t* cfg, uint32_t session,
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
  if (hwi_link_exchange(l, pkt, len, tag, words, n, timeout_us, tries) != 0) {
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
  if (hwi_link_exchange(l, pkt, len, tag, words, 1, timeout_us, tries) != 0) {
    snprintf(err, errlen, "no reply to the snapshot's EVENTS write");
    return -1;
  }
  const uint32_t arm[3] = {0, 0, 1};  // SNAP_AT = 0 (passed: at once), SNAP_CTRL.arm
  for (uint32_t k = 3;; ++k) {
    tag = (session & 0xF) << 28 | k << 8;
    len = k == 3 ? hwi_eb_writes(pkt, sizeof pkt, hwi_addr_snap_at(), arm, 3, tag, reads, nr)
                 : hwi_eb_reads(pkt, sizeof pkt, tag, reads, nr);
    if (hwi_link_exchange(l, pkt, len, tag, words, nr, timeout_us, tries) != 0) {
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

void hwi_link_take_replies(hwi_link_t* l, hwi_servo_t* s, int64_t wait_us) {
  uint8_t buf[HWI_MAX_PACKET];
  const int64_t end = hwi_now_ns() + wait_us * 1000;
  for (;;) {
    const int64_t left_us = s->in_flight ? (end - hwi_now_ns()) / 1000 : 0;
    const int n = hwi_link_recv(l, buf, sizeof buf, left_us > 0 ? left_us : 0);
    if (n <= 0) return;
    hwi_servo_reply(s, buf, (size_t)n, hwi_now_ns());
  }
}

static int send_link(void* ctx, const uint8_t* data, size_t len) {
  return hwi_link_send((hwi_link_t*)ctx, data, len);
}

int hwi_link_period(hwi_link_t* l, hwi_servo_t* s, const int64_t* lattice, int64_t wait_us) {
  hwi_link_take_replies(l, s, wait_us);
  return hwi_servo_period(s, hwi_now_ns(), lattice, send_link, l) < 0 ? -1 : 0;
}

int hwi_link_abort(hwi_link_t* l, hwi_servo_t* s, int64_t timeout_us, int tries) {
  // CTRL.abort_motion as a plain write (outside the guard's window it passes
  // unchanged): the same when repeated, and independent of the packet in
  // flight, which may never be answered (on the UART the bridge may drop
  // it while it runs that packet: the next try gets through).
  uint8_t pkt[HWI_MAX_PACKET];
  uint32_t word;
  const uint32_t addr = hwi_abort_write(&word);
  const uint32_t tag = (s->session & 0xF) << 28 | 0x7FFFFu << 8;
  uint32_t expect;
  const uint32_t read = hwi_addr_expect();
  const size_t len = hwi_eb_writes(pkt, sizeof pkt, addr, &word, 1, tag, &read, 1);
  s->state = HWI_IDLE;
  s->outbox_len = 0;
  return hwi_link_exchange(l, pkt, len, tag, &expect, 1, timeout_us, tries);
}
