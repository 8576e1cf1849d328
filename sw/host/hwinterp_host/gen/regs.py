"""Generated from rtl/regs/motion_soc.rdl, rtl/regs/link_guard.rdl, rtl/regs/board.rdl by scripts/regs/generate.py (scripts/regs/py_model.py); do not edit.

The register map of hwinterp_board (hwinterp board):
motion_soc and the link's sequence guard on a board's Wishbone bus (byte addresses).

Blocks (absolute byte addresses):
  motion   0x00040000, 592 bytes (motion_soc_regs)
  link     0x00080000, 1040 bytes (link_guard_regs)
"""
from hwinterp_host.regmap import Block, Field, Mem, Reg

MAP = "hwinterp_board"
MOTION_BASE = 0x00040000
LINK_BASE = 0x00080000

motion = Block(
    "motion", "motion_soc_regs", base=0x00040000, size=0x250,
    regs=(
        Reg("ID_MAGIC", 0x00040000, 0x000, 32, "r", False, (
            Field("magic", 0, 32, "r", 0x484d5331, False, False, False),
        )),
        Reg("ID_VERSION", 0x00040004, 0x004, 32, "r", False, (
            Field("minor", 0, 16, "r", 0x1, False, False, False),
            Field("major", 16, 16, "r", 0x1, False, False, False),
        )),
        Reg("ID_BUILD", 0x00040008, 0x008, 32, "r", False, (
            Field("axes", 0, 4, "r", 0x0, True, False, False),
            Field("core", 4, 4, "r", 0x0, True, False, False),
            Field("bus", 8, 2, "r", 0x0, True, False, False),
            Field("profile", 10, 1, "r", 0x0, True, False, False),
            Field("step_types", 12, 3, "r", 0x0, True, False, False),
            Field("fifo_depth", 16, 16, "r", 0x0, True, False, False),
        )),
        Reg("ID_WIDTHS", 0x0004000c, 0x00c, 32, "r", False, (
            Field("acc_w", 0, 8, "r", 0x0, True, False, False),
            Field("coord_w", 8, 8, "r", 0x0, True, False, False),
            Field("ops_w", 16, 8, "r", 0x0, True, False, False),
            Field("pos_w", 24, 8, "r", 0x0, True, False, False),
        )),
        Reg("ID_WIDTHS2", 0x00040010, 0x010, 32, "r", False, (
            Field("tim_w", 0, 8, "r", 0x0, True, False, False),
            Field("feed_w", 8, 8, "r", 0x0, True, False, False),
        )),
        Reg("ID_CLOCK", 0x00040014, 0x014, 32, "r", False, (
            Field("hz", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("ID_PROFILE", 0x00040018, 0x018, 32, "r", False, (
            Field("spd_w", 0, 8, "r", 0x0, True, False, False),
            Field("tick_w", 8, 8, "r", 0x0, True, False, False),
            Field("len_w", 16, 8, "r", 0x0, True, False, False),
            Field("lvl_w", 24, 8, "r", 0x0, True, False, False),
        )),
        Reg("CTRL", 0x00040020, 0x020, 32, "w", False, (
            Field("abort_motion", 0, 1, "w", 0x0, False, False, True),
        )),
        Reg("STATUS", 0x00040024, 0x024, 32, "r", False, (
            Field("busy", 0, 1, "r", 0x0, True, False, False),
            Field("fifo_empty", 1, 1, "r", 0x0, True, False, False),
            Field("fifo_full", 2, 1, "r", 0x0, True, False, False),
            Field("low", 3, 1, "r", 0x0, True, False, False),
            Field("probe", 4, 1, "r", 0x0, True, False, False),
            Field("wdog_run", 5, 1, "r", 0x0, True, False, False),
            Field("stopped", 6, 1, "r", 0x0, True, False, False),
            Field("snap_armed", 7, 1, "r", 0x0, True, False, False),
            Field("latch_armed", 8, 1, "r", 0x0, True, False, False),
            Field("waiting", 9, 1, "r", 0x0, True, False, False),
            Field("prof_busy", 10, 1, "r", 0x0, True, False, False),
            Field("wdog_stopping", 11, 1, "r", 0x0, True, False, False),
        )),
        Reg("EVENTS", 0x00040028, 0x028, 32, "rw", False, (
            Field("overflow", 0, 1, "rw", 0x0, True, True, False),
            Field("refused", 1, 1, "rw", 0x0, True, True, False),
            Field("late", 2, 1, "rw", 0x0, True, True, False),
            Field("wdog", 3, 1, "rw", 0x0, True, True, False),
            Field("snap", 4, 1, "rw", 0x0, True, True, False),
            Field("latch", 5, 1, "rw", 0x0, True, True, False),
            Field("low_water", 6, 1, "rw", 0x0, True, True, False),
            Field("estop", 7, 1, "rw", 0x0, True, True, False),
            Field("done", 8, 1, "rw", 0x0, True, True, False),
        )),
        Reg("IRQ_EN", 0x0004002c, 0x02c, 32, "rw", False, (
            Field("overflow", 0, 1, "rw", 0x0, False, False, False),
            Field("refused", 1, 1, "rw", 0x0, False, False, False),
            Field("late", 2, 1, "rw", 0x0, False, False, False),
            Field("wdog", 3, 1, "rw", 0x0, False, False, False),
            Field("snap", 4, 1, "rw", 0x0, False, False, False),
            Field("latch", 5, 1, "rw", 0x0, False, False, False),
            Field("low_water", 6, 1, "rw", 0x0, False, False, False),
            Field("estop", 7, 1, "rw", 0x0, False, False, False),
            Field("done", 8, 1, "rw", 0x0, False, False, False),
        )),
        Reg("FIFO_LEVEL", 0x00040030, 0x030, 32, "r", False, (
            Field("fill", 0, 16, "r", 0x0, True, False, False),
            Field("room", 16, 16, "r", 0x0, True, False, False),
        )),
        Reg("FIFO_LOW", 0x00040034, 0x034, 32, "rw", False, (
            Field("mark", 0, 16, "rw", 0x0, False, False, False),
        )),
        Reg("FEED", 0x00040040, 0x040, 32, "rw", False, (
            Field("value", 0, 32, "rw", 0xffffffff, False, False, False),
        )),
        Reg("STEP_LEN", 0x00040044, 0x044, 32, "rw", False, (
            Field("value", 0, 32, "rw", 0x0, False, False, False),
        )),
        Reg("STEP_SPACE", 0x00040048, 0x048, 32, "rw", False, (
            Field("value", 0, 32, "rw", 0x0, False, False, False),
        )),
        Reg("DIR_SETUP", 0x0004004c, 0x04c, 32, "rw", False, (
            Field("value", 0, 32, "rw", 0x0, False, False, False),
        )),
        Reg("DIR_HOLD", 0x00040050, 0x050, 32, "rw", False, (
            Field("value", 0, 32, "rw", 0x0, False, False, False),
        )),
        Reg("STEP_TYPE", 0x00040054, 0x054, 32, "rw", False, (
            Field("axis0", 0, 2, "rw", 0x0, False, False, False),
            Field("axis1", 2, 2, "rw", 0x0, False, False, False),
            Field("axis2", 4, 2, "rw", 0x0, False, False, False),
            Field("axis3", 6, 2, "rw", 0x0, False, False, False),
            Field("axis4", 8, 2, "rw", 0x0, False, False, False),
            Field("axis5", 10, 2, "rw", 0x0, False, False, False),
        )),
        Reg("TIME_LO", 0x00040060, 0x060, 32, "r", False, (
            Field("count", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("TIME_HI", 0x00040064, 0x064, 32, "r", False, (
            Field("count", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("WDOG_PERIOD", 0x00040070, 0x070, 32, "rw", False, (
            Field("period", 0, 32, "rw", 0x0, False, False, False),
        )),
        Reg("WDOG_KICK", 0x00040074, 0x074, 32, "w", False, (
            Field("kick", 0, 1, "w", 0x0, False, False, False),
        )),
        Reg("WDOG_LEFT", 0x00040078, 0x078, 32, "r", False, (
            Field("left", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_AT", 0x00040080, 0x080, 64, "rw", False, (
            Field("lo", 0, 32, "rw", 0x0, False, False, False),
            Field("hi", 32, 32, "rw", 0x0, False, False, False),
        )),
        Reg("SNAP_CTRL", 0x00040088, 0x088, 32, "w", False, (
            Field("arm", 0, 1, "w", 0x0, False, False, True),
        )),
        Reg("SNAP_TIME", 0x00040090, 0x090, 64, "r", False, (
            Field("count", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_POS0", 0x000400a0, 0x0a0, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_POS1", 0x000400a8, 0x0a8, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_POS2", 0x000400b0, 0x0b0, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_POS3", 0x000400b8, 0x0b8, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_POS4", 0x000400c0, 0x0c0, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_POS5", 0x000400c8, 0x0c8, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_SPEED0", 0x000400d0, 0x0d0, 32, "r", False, (
            Field("period", 0, 31, "r", 0x0, True, False, False),
            Field("neg", 31, 1, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_SPEED1", 0x000400d4, 0x0d4, 32, "r", False, (
            Field("period", 0, 31, "r", 0x0, True, False, False),
            Field("neg", 31, 1, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_SPEED2", 0x000400d8, 0x0d8, 32, "r", False, (
            Field("period", 0, 31, "r", 0x0, True, False, False),
            Field("neg", 31, 1, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_SPEED3", 0x000400dc, 0x0dc, 32, "r", False, (
            Field("period", 0, 31, "r", 0x0, True, False, False),
            Field("neg", 31, 1, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_SPEED4", 0x000400e0, 0x0e0, 32, "r", False, (
            Field("period", 0, 31, "r", 0x0, True, False, False),
            Field("neg", 31, 1, "r", 0x0, True, False, False),
        )),
        Reg("SNAP_SPEED5", 0x000400e4, 0x0e4, 32, "r", False, (
            Field("period", 0, 31, "r", 0x0, True, False, False),
            Field("neg", 31, 1, "r", 0x0, True, False, False),
        )),
        Reg("PROF_Q", 0x000400f0, 0x0f0, 64, "rw", False, (
            Field("lo", 0, 32, "rw", 0x0, False, False, False),
            Field("hi", 32, 32, "rw", 0x0, False, False, False),
        )),
        Reg("PROF_LEN", 0x000400f8, 0x0f8, 32, "rw", False, (
            Field("value", 0, 32, "rw", 0x1, False, False, False),
        )),
        Reg("PROF_CTRL", 0x000400fc, 0x0fc, 32, "rw", False, (
            Field("hold", 0, 1, "rw", 0x0, False, False, False),
            Field("ovr", 16, 9, "rw", 0x80, False, False, False),
        )),
        Reg("PROBE_CFG", 0x00040100, 0x100, 32, "rw", False, (
            Field("filter", 0, 16, "rw", 0x0, False, False, False),
            Field("falling", 16, 1, "rw", 0x0, False, False, False),
            Field("stop", 17, 1, "rw", 0x0, False, False, False),
        )),
        Reg("LATCH_CTRL", 0x00040104, 0x104, 32, "w", False, (
            Field("arm", 0, 1, "w", 0x0, False, False, True),
        )),
        Reg("LATCH_TIME", 0x00040108, 0x108, 64, "r", False, (
            Field("count", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("LATCH_POS0", 0x00040110, 0x110, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("LATCH_POS1", 0x00040118, 0x118, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("LATCH_POS2", 0x00040120, 0x120, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("LATCH_POS3", 0x00040128, 0x128, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("LATCH_POS4", 0x00040130, 0x130, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("LATCH_POS5", 0x00040138, 0x138, 64, "r", False, (
            Field("pos", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("PROF_LEVEL", 0x00040140, 0x140, 32, "r", False, (
            Field("c", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("PROF_SPEED", 0x00040148, 0x148, 64, "r", False, (
            Field("speed", 0, 64, "r", 0x0, True, False, False),
        )),
        Reg("CMD_DELTA0", 0x00040200, 0x200, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_DELTA1", 0x00040204, 0x204, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_DELTA2", 0x00040208, 0x208, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_DELTA3", 0x0004020c, 0x20c, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_DELTA4", 0x00040210, 0x210, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_DELTA5", 0x00040214, 0x214, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_CENTER0", 0x00040218, 0x218, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_CENTER1", 0x0004021c, 0x21c, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_END0", 0x00040220, 0x220, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_END1", 0x00040224, 0x224, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_OPS", 0x00040228, 0x228, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_FEED", 0x0004022c, 0x22c, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_AT", 0x00040230, 0x230, 64, "w", False, (
            Field("lo", 0, 32, "w", 0x0, False, False, False),
            Field("hi", 32, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_FLAGS", 0x00040238, 0x238, 32, "w", False, (
            Field("arc", 0, 1, "w", 0x0, False, False, False),
            Field("plane", 1, 2, "w", 0x0, False, False, False),
            Field("ccw", 3, 1, "w", 0x0, False, False, False),
            Field("timed", 4, 1, "w", 0x0, False, False, False),
        )),
        Reg("CMD_PUSH", 0x0004023c, 0x23c, 32, "w", False, (
            Field("push", 0, 1, "w", 0x0, False, False, False),
        )),
        Reg("CMD_MV_OPS", 0x00040240, 0x240, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_MV_TARGET", 0x00040244, 0x244, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_MV_END", 0x00040248, 0x248, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
        Reg("CMD_MV_MAX", 0x0004024c, 0x24c, 32, "w", False, (
            Field("value", 0, 32, "w", 0x0, False, False, False),
        )),
    ),
    mems=(
    ),
    arrays={
        "CMD_CENTER": ("CMD_CENTER0", "CMD_CENTER1"),
        "CMD_DELTA": ("CMD_DELTA0", "CMD_DELTA1", "CMD_DELTA2", "CMD_DELTA3", "CMD_DELTA4", "CMD_DELTA5"),
        "CMD_END": ("CMD_END0", "CMD_END1"),
        "LATCH_POS": ("LATCH_POS0", "LATCH_POS1", "LATCH_POS2", "LATCH_POS3", "LATCH_POS4", "LATCH_POS5"),
        "SNAP_POS": ("SNAP_POS0", "SNAP_POS1", "SNAP_POS2", "SNAP_POS3", "SNAP_POS4", "SNAP_POS5"),
        "SNAP_SPEED": ("SNAP_SPEED0", "SNAP_SPEED1", "SNAP_SPEED2", "SNAP_SPEED3", "SNAP_SPEED4", "SNAP_SPEED5"),
    },
)

link = Block(
    "link", "link_guard_regs", base=0x00080000, size=0x410,
    regs=(
        Reg("SEQ", 0x00080000, 0x000, 32, "rw", True, (
            Field("value", 0, 32, "rw", 0x0, True, False, False),
        )),
        Reg("ACCEPTED", 0x00080400, 0x400, 32, "r", True, (
            Field("count", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("STALE", 0x00080404, 0x404, 32, "r", True, (
            Field("count", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("DROPPED", 0x00080408, 0x408, 32, "r", True, (
            Field("count", 0, 32, "r", 0x0, True, False, False),
        )),
        Reg("ERRORS", 0x0008040c, 0x40c, 32, "r", True, (
            Field("count", 0, 32, "r", 0x0, True, False, False),
        )),
    ),
    mems=(
        Mem("STREAM", 0x00080004, 0x004, 255, 32, "w"),
    ),
    arrays={
    },
)

BLOCKS = (motion, link,)
