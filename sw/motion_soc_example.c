/* Bring-up of motion_soc from a CPU, with the generated header
 * (sw/motion_soc_regs.h). docs/soc.md walks through it; tests/CMakeLists.txt
 * compiles it (-Wall -Wextra -Werror) so it stays in step with the header.
 *
 * The bus is 32 bits wide: 64-bit registers (CMD_AT, SNAP_POS ...) are read
 * and written as two 32-bit words, low word first. */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "motion_soc_regs.h"

/* Word i of a register from its byte offset in the map (the struct is packed:
 * addresses are taken with offsetof, never from a packed member). */
#define REG32_AT(base, field, i) \
  (((volatile uint32_t *)((uintptr_t)(base) + offsetof(motion_soc_regs_t, field)))[i])
#define REG32(base, field) REG32_AT(base, field, 0)
#define REG32_HI(base, field) REG32_AT(base, field, 1)

/* Checks the ID and sets the step timing; 0 when the core is a motion_soc of
 * this map's major version with at least `axes` axes. */
int soc_init(volatile motion_soc_regs_t *soc, unsigned axes, uint32_t wdog_clocks) {
  if (REG32(soc, id_magic) != MOTION_SOC_REGS__ID_MAGIC__MAGIC_reset) return -1;
  if ((REG32(soc, id_version) & MOTION_SOC_REGS__ID_VERSION__MAJOR_bm) >>
          MOTION_SOC_REGS__ID_VERSION__MAJOR_bp != 1)
    return -2;
  if (((REG32(soc, id_build) & MOTION_SOC_REGS__ID_BUILD__AXES_bm) >>
       MOTION_SOC_REGS__ID_BUILD__AXES_bp) < axes)
    return -3;
  REG32(soc, step_len) = 100;   /* clocks */
  REG32(soc, step_space) = 100;
  REG32(soc, dir_setup) = 50;
  REG32(soc, dir_hold) = 50;
  REG32(soc, events) = 0xFFFFFFFFu; /* clear every sticky event */
  REG32(soc, fifo_low) = 2;
  REG32(soc, irq_en) = MOTION_SOC_REGS__IRQ_EN__LOW_WATER_bm | MOTION_SOC_REGS__IRQ_EN__WDOG_bm |
                       MOTION_SOC_REGS__IRQ_EN__OVERFLOW_bm;
  REG32(soc, wdog_period) = wdog_clocks; /* writing it also kicks */
  return 0;
}

/* The 64-bit TIME: reading TIME_LO latches TIME_HI. */
uint64_t soc_time(volatile motion_soc_regs_t *soc) {
  uint32_t lo = REG32(soc, time_lo);
  return (uint64_t)REG32(soc, time_hi) << 32 | lo;
}

/* Pushes a line of `delta` steps per axis at feed word `feed`, started at
 * TIME `at` (0: at once). false when the FIFO did not take it (full, or
 * stopped by the watchdog or estop: EVENTS says which). */
bool soc_push_line(volatile motion_soc_regs_t *soc, const int32_t *delta, unsigned axes,
                   uint32_t feed, uint64_t at) {
  for (unsigned i = 0; i < axes; i++) REG32_AT(soc, cmd_delta0, i) = (uint32_t)delta[i];
  REG32(soc, cmd_feed) = feed;
  REG32(soc, cmd_at) = (uint32_t)at;
  REG32_HI(soc, cmd_at) = (uint32_t)(at >> 32);
  REG32(soc, cmd_flags) = at ? MOTION_SOC_REGS__CMD_FLAGS__TIMED_bm : 0;
  REG32(soc, cmd_push) = 1;
  uint32_t ev = REG32(soc, events);
  uint32_t bad = MOTION_SOC_REGS__EVENTS__OVERFLOW_bm | MOTION_SOC_REGS__EVENTS__REFUSED_bm;
  if (ev & bad) {
    REG32(soc, events) = ev & bad;
    return false;
  }
  REG32(soc, wdog_kick) = 1;
  return true;
}

/* Positions of the first `axes` axes sampled together at TIME `at` (a
 * passed time: at once). */
uint64_t soc_snapshot(volatile motion_soc_regs_t *soc, uint64_t at, int64_t *pos, unsigned axes) {
  REG32(soc, events) = MOTION_SOC_REGS__EVENTS__SNAP_bm;
  REG32(soc, snap_at) = (uint32_t)at;
  REG32_HI(soc, snap_at) = (uint32_t)(at >> 32);
  REG32(soc, snap_ctrl) = MOTION_SOC_REGS__SNAP_CTRL__ARM_bm;
  while (!(REG32(soc, events) & MOTION_SOC_REGS__EVENTS__SNAP_bm)) {
  }
  for (unsigned i = 0; i < axes; i++) {
    uint32_t lo = REG32_AT(soc, snap_pos0, 2 * i);
    pos[i] = (int64_t)((uint64_t)REG32_AT(soc, snap_pos0, 2 * i + 1) << 32 | lo);
  }
  return (uint64_t)REG32_HI(soc, snap_time) << 32 | REG32(soc, snap_time);
}

/* Builds with the feed profile (ID_BUILD.profile): its registers, taken while
 * it is at rest; false without the profile. q and L from the machine's limits
 * (models/feed_profile_model.h: speed quantum and moving sum). */
bool soc_profile_init(volatile motion_soc_regs_t *soc, uint64_t q, uint32_t len) {
  if (!(REG32(soc, id_build) & MOTION_SOC_REGS__ID_BUILD__PROFILE_bm)) return false;
  REG32(soc, prof_q) = (uint32_t)q;
  REG32_HI(soc, prof_q) = (uint32_t)(q >> 32);
  REG32(soc, prof_len) = len;
  return true;
}

/* The profile move of the next soc_push_line (its engine operations and the
 * planned levels; end level 0: an exact stop), and a line following the
 * profile (feed word 0). */
bool soc_push_profiled_line(volatile motion_soc_regs_t *soc, const int32_t *delta, unsigned axes,
                            uint32_t ops, uint32_t target, uint32_t end, uint32_t max) {
  REG32(soc, cmd_mv_ops) = ops;
  REG32(soc, cmd_mv_target) = target;
  REG32(soc, cmd_mv_end) = end;
  REG32(soc, cmd_mv_max) = max;
  return soc_push_line(soc, delta, axes, 0, 0);
}

/* Feed hold (a controlled stop along the path) and the feed override in
 * percent (0..200, steps of 1/128). */
void soc_feed_hold(volatile motion_soc_regs_t *soc, bool hold, unsigned percent) {
  uint32_t ovr = (percent * 128u + 50u) / 100u;
  REG32(soc, prof_ctrl) = (ovr << MOTION_SOC_REGS__PROF_CTRL__OVR_bp) |
                          (hold ? MOTION_SOC_REGS__PROF_CTRL__HOLD_bm : 0);
}
