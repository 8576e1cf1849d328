// Generated from rtl/regs/motion_soc.rdl by scripts/regs/generate.py (scripts/regs/cpp_model.py); do not edit.
// The register block's C++ face (scripts/regs/cpp_model.py): PeakRDL-regblock's
// register block from the same description, behind its internal CPU interface
// (one request a clock; no bus protocol).
#pragma once

#include <cstdint>

namespace hwinterp::hls::motion_soc_regs {

inline constexpr int kAddrWidth = 10;  // byte address bits
inline constexpr uint32_t kSize = 0x250;  // bytes

// Access of a register or field from software.
enum class Sw { kR, kW, kRw };
struct RegDesc {
  const char* name;
  uint32_t addr;    // byte address of element 0
  uint32_t count;   // array elements (1: not an array)
  uint32_t stride;  // bytes between elements
  uint32_t words;   // 32-bit words per element
  Sw sw;
};
struct FieldDesc {
  int reg;          // index into kRegs
  const char* name;
  int lsb, width;   // in the register (64-bit registers: lsb up to 63)
  Sw sw;
  bool hw_writes;   // its value comes from (or is set by) the hardware
  uint64_t reset;
  bool woclr, singlepulse;
};
inline constexpr RegDesc kRegs[] = {
    {"id_magic", 0x0, 1, 0, 1, Sw::kR},
    {"id_version", 0x4, 1, 0, 1, Sw::kR},
    {"id_build", 0x8, 1, 0, 1, Sw::kR},
    {"id_widths", 0xc, 1, 0, 1, Sw::kR},
    {"id_widths2", 0x10, 1, 0, 1, Sw::kR},
    {"id_clock", 0x14, 1, 0, 1, Sw::kR},
    {"id_profile", 0x18, 1, 0, 1, Sw::kR},
    {"ctrl", 0x20, 1, 0, 1, Sw::kW},
    {"status", 0x24, 1, 0, 1, Sw::kR},
    {"events", 0x28, 1, 0, 1, Sw::kRw},
    {"irq_en", 0x2c, 1, 0, 1, Sw::kRw},
    {"fifo_level", 0x30, 1, 0, 1, Sw::kR},
    {"fifo_low", 0x34, 1, 0, 1, Sw::kRw},
    {"feed", 0x40, 1, 0, 1, Sw::kRw},
    {"step_len", 0x44, 1, 0, 1, Sw::kRw},
    {"step_space", 0x48, 1, 0, 1, Sw::kRw},
    {"dir_setup", 0x4c, 1, 0, 1, Sw::kRw},
    {"dir_hold", 0x50, 1, 0, 1, Sw::kRw},
    {"step_type", 0x54, 1, 0, 1, Sw::kRw},
    {"time_lo", 0x60, 1, 0, 1, Sw::kR},
    {"time_hi", 0x64, 1, 0, 1, Sw::kR},
    {"wdog_period", 0x70, 1, 0, 1, Sw::kRw},
    {"wdog_kick", 0x74, 1, 0, 1, Sw::kW},
    {"wdog_left", 0x78, 1, 0, 1, Sw::kR},
    {"snap_at", 0x80, 1, 0, 2, Sw::kRw},
    {"snap_ctrl", 0x88, 1, 0, 1, Sw::kW},
    {"snap_time", 0x90, 1, 0, 2, Sw::kR},
    {"snap_pos0", 0xa0, 1, 0, 2, Sw::kR},
    {"snap_pos1", 0xa8, 1, 0, 2, Sw::kR},
    {"snap_pos2", 0xb0, 1, 0, 2, Sw::kR},
    {"snap_pos3", 0xb8, 1, 0, 2, Sw::kR},
    {"snap_pos4", 0xc0, 1, 0, 2, Sw::kR},
    {"snap_pos5", 0xc8, 1, 0, 2, Sw::kR},
    {"snap_speed0", 0xd0, 1, 0, 1, Sw::kR},
    {"snap_speed1", 0xd4, 1, 0, 1, Sw::kR},
    {"snap_speed2", 0xd8, 1, 0, 1, Sw::kR},
    {"snap_speed3", 0xdc, 1, 0, 1, Sw::kR},
    {"snap_speed4", 0xe0, 1, 0, 1, Sw::kR},
    {"snap_speed5", 0xe4, 1, 0, 1, Sw::kR},
    {"prof_q", 0xf0, 1, 0, 2, Sw::kRw},
    {"prof_len", 0xf8, 1, 0, 1, Sw::kRw},
    {"prof_ctrl", 0xfc, 1, 0, 1, Sw::kRw},
    {"probe_cfg", 0x100, 1, 0, 1, Sw::kRw},
    {"latch_ctrl", 0x104, 1, 0, 1, Sw::kW},
    {"latch_time", 0x108, 1, 0, 2, Sw::kR},
    {"latch_pos0", 0x110, 1, 0, 2, Sw::kR},
    {"latch_pos1", 0x118, 1, 0, 2, Sw::kR},
    {"latch_pos2", 0x120, 1, 0, 2, Sw::kR},
    {"latch_pos3", 0x128, 1, 0, 2, Sw::kR},
    {"latch_pos4", 0x130, 1, 0, 2, Sw::kR},
    {"latch_pos5", 0x138, 1, 0, 2, Sw::kR},
    {"prof_level", 0x140, 1, 0, 1, Sw::kR},
    {"prof_speed", 0x148, 1, 0, 2, Sw::kR},
    {"cmd_delta0", 0x200, 1, 0, 1, Sw::kW},
    {"cmd_delta1", 0x204, 1, 0, 1, Sw::kW},
    {"cmd_delta2", 0x208, 1, 0, 1, Sw::kW},
    {"cmd_delta3", 0x20c, 1, 0, 1, Sw::kW},
    {"cmd_delta4", 0x210, 1, 0, 1, Sw::kW},
    {"cmd_delta5", 0x214, 1, 0, 1, Sw::kW},
    {"cmd_center0", 0x218, 1, 0, 1, Sw::kW},
    {"cmd_center1", 0x21c, 1, 0, 1, Sw::kW},
    {"cmd_end0", 0x220, 1, 0, 1, Sw::kW},
    {"cmd_end1", 0x224, 1, 0, 1, Sw::kW},
    {"cmd_ops", 0x228, 1, 0, 1, Sw::kW},
    {"cmd_feed", 0x22c, 1, 0, 1, Sw::kW},
    {"cmd_at", 0x230, 1, 0, 2, Sw::kW},
    {"cmd_flags", 0x238, 1, 0, 1, Sw::kW},
    {"cmd_push", 0x23c, 1, 0, 1, Sw::kW},
    {"cmd_mv_ops", 0x240, 1, 0, 1, Sw::kW},
    {"cmd_mv_target", 0x244, 1, 0, 1, Sw::kW},
    {"cmd_mv_end", 0x248, 1, 0, 1, Sw::kW},
    {"cmd_mv_max", 0x24c, 1, 0, 1, Sw::kW},
};
inline constexpr FieldDesc kFields[] = {
    {0, "magic", 0, 32, Sw::kR, false, 0x484d5331ull, false, false},
    {1, "minor", 0, 16, Sw::kR, false, 0x1ull, false, false},
    {1, "major", 16, 16, Sw::kR, false, 0x1ull, false, false},
    {2, "axes", 0, 4, Sw::kR, true, 0x0ull, false, false},
    {2, "core", 4, 4, Sw::kR, true, 0x0ull, false, false},
    {2, "bus", 8, 2, Sw::kR, true, 0x0ull, false, false},
    {2, "profile", 10, 1, Sw::kR, true, 0x0ull, false, false},
    {2, "step_types", 12, 3, Sw::kR, true, 0x0ull, false, false},
    {2, "fifo_depth", 16, 16, Sw::kR, true, 0x0ull, false, false},
    {3, "acc_w", 0, 8, Sw::kR, true, 0x0ull, false, false},
    {3, "coord_w", 8, 8, Sw::kR, true, 0x0ull, false, false},
    {3, "ops_w", 16, 8, Sw::kR, true, 0x0ull, false, false},
    {3, "pos_w", 24, 8, Sw::kR, true, 0x0ull, false, false},
    {4, "tim_w", 0, 8, Sw::kR, true, 0x0ull, false, false},
    {4, "feed_w", 8, 8, Sw::kR, true, 0x0ull, false, false},
    {5, "hz", 0, 32, Sw::kR, true, 0x0ull, false, false},
    {6, "spd_w", 0, 8, Sw::kR, true, 0x0ull, false, false},
    {6, "tick_w", 8, 8, Sw::kR, true, 0x0ull, false, false},
    {6, "len_w", 16, 8, Sw::kR, true, 0x0ull, false, false},
    {6, "lvl_w", 24, 8, Sw::kR, true, 0x0ull, false, false},
    {7, "abort_motion", 0, 1, Sw::kW, false, 0x0ull, false, true},
    {8, "busy", 0, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "fifo_empty", 1, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "fifo_full", 2, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "low", 3, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "probe", 4, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "wdog_run", 5, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "stopped", 6, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "snap_armed", 7, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "latch_armed", 8, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "waiting", 9, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "prof_busy", 10, 1, Sw::kR, true, 0x0ull, false, false},
    {8, "wdog_stopping", 11, 1, Sw::kR, true, 0x0ull, false, false},
    {9, "overflow", 0, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "refused", 1, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "late", 2, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "wdog", 3, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "snap", 4, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "latch", 5, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "low_water", 6, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "estop", 7, 1, Sw::kRw, true, 0x0ull, true, false},
    {9, "done", 8, 1, Sw::kRw, true, 0x0ull, true, false},
    {10, "overflow", 0, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "refused", 1, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "late", 2, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "wdog", 3, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "snap", 4, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "latch", 5, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "low_water", 6, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "estop", 7, 1, Sw::kRw, false, 0x0ull, false, false},
    {10, "done", 8, 1, Sw::kRw, false, 0x0ull, false, false},
    {11, "fill", 0, 16, Sw::kR, true, 0x0ull, false, false},
    {11, "room", 16, 16, Sw::kR, true, 0x0ull, false, false},
    {12, "mark", 0, 16, Sw::kRw, false, 0x0ull, false, false},
    {13, "value", 0, 32, Sw::kRw, false, 0xffffffffull, false, false},
    {14, "value", 0, 32, Sw::kRw, false, 0x0ull, false, false},
    {15, "value", 0, 32, Sw::kRw, false, 0x0ull, false, false},
    {16, "value", 0, 32, Sw::kRw, false, 0x0ull, false, false},
    {17, "value", 0, 32, Sw::kRw, false, 0x0ull, false, false},
    {18, "axis0", 0, 2, Sw::kRw, false, 0x0ull, false, false},
    {18, "axis1", 2, 2, Sw::kRw, false, 0x0ull, false, false},
    {18, "axis2", 4, 2, Sw::kRw, false, 0x0ull, false, false},
    {18, "axis3", 6, 2, Sw::kRw, false, 0x0ull, false, false},
    {18, "axis4", 8, 2, Sw::kRw, false, 0x0ull, false, false},
    {18, "axis5", 10, 2, Sw::kRw, false, 0x0ull, false, false},
    {19, "count", 0, 32, Sw::kR, true, 0x0ull, false, false},
    {20, "count", 0, 32, Sw::kR, true, 0x0ull, false, false},
    {21, "period", 0, 32, Sw::kRw, false, 0x0ull, false, false},
    {22, "kick", 0, 1, Sw::kW, false, 0x0ull, false, false},
    {23, "left", 0, 32, Sw::kR, true, 0x0ull, false, false},
    {24, "lo", 0, 32, Sw::kRw, false, 0x0ull, false, false},
    {24, "hi", 32, 32, Sw::kRw, false, 0x0ull, false, false},
    {25, "arm", 0, 1, Sw::kW, false, 0x0ull, false, true},
    {26, "count", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {27, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {28, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {29, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {30, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {31, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {32, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {33, "period", 0, 31, Sw::kR, true, 0x0ull, false, false},
    {33, "neg", 31, 1, Sw::kR, true, 0x0ull, false, false},
    {34, "period", 0, 31, Sw::kR, true, 0x0ull, false, false},
    {34, "neg", 31, 1, Sw::kR, true, 0x0ull, false, false},
    {35, "period", 0, 31, Sw::kR, true, 0x0ull, false, false},
    {35, "neg", 31, 1, Sw::kR, true, 0x0ull, false, false},
    {36, "period", 0, 31, Sw::kR, true, 0x0ull, false, false},
    {36, "neg", 31, 1, Sw::kR, true, 0x0ull, false, false},
    {37, "period", 0, 31, Sw::kR, true, 0x0ull, false, false},
    {37, "neg", 31, 1, Sw::kR, true, 0x0ull, false, false},
    {38, "period", 0, 31, Sw::kR, true, 0x0ull, false, false},
    {38, "neg", 31, 1, Sw::kR, true, 0x0ull, false, false},
    {39, "lo", 0, 32, Sw::kRw, false, 0x0ull, false, false},
    {39, "hi", 32, 32, Sw::kRw, false, 0x0ull, false, false},
    {40, "value", 0, 32, Sw::kRw, false, 0x1ull, false, false},
    {41, "hold", 0, 1, Sw::kRw, false, 0x0ull, false, false},
    {41, "ovr", 16, 9, Sw::kRw, false, 0x80ull, false, false},
    {42, "filter", 0, 16, Sw::kRw, false, 0x0ull, false, false},
    {42, "falling", 16, 1, Sw::kRw, false, 0x0ull, false, false},
    {42, "stop", 17, 1, Sw::kRw, false, 0x0ull, false, false},
    {43, "arm", 0, 1, Sw::kW, false, 0x0ull, false, true},
    {44, "count", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {45, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {46, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {47, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {48, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {49, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {50, "pos", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {51, "c", 0, 32, Sw::kR, true, 0x0ull, false, false},
    {52, "speed", 0, 64, Sw::kR, true, 0x0ull, false, false},
    {53, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {54, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {55, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {56, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {57, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {58, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {59, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {60, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {61, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {62, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {63, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {64, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {65, "lo", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {65, "hi", 32, 32, Sw::kW, false, 0x0ull, false, false},
    {66, "arc", 0, 1, Sw::kW, false, 0x0ull, false, false},
    {66, "plane", 1, 2, Sw::kW, false, 0x0ull, false, false},
    {66, "ccw", 3, 1, Sw::kW, false, 0x0ull, false, false},
    {66, "timed", 4, 1, Sw::kW, false, 0x0ull, false, false},
    {67, "push", 0, 1, Sw::kW, false, 0x0ull, false, false},
    {68, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {69, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {70, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
    {71, "value", 0, 32, Sw::kW, false, 0x0ull, false, false},
};

// Byte addresses.
inline constexpr uint32_t kIdMagic = 0x0;
inline constexpr uint32_t kIdVersion = 0x4;
inline constexpr uint32_t kIdBuild = 0x8;
inline constexpr uint32_t kIdWidths = 0xc;
inline constexpr uint32_t kIdWidths2 = 0x10;
inline constexpr uint32_t kIdClock = 0x14;
inline constexpr uint32_t kIdProfile = 0x18;
inline constexpr uint32_t kCtrl = 0x20;
inline constexpr uint32_t kStatus = 0x24;
inline constexpr uint32_t kEvents = 0x28;
inline constexpr uint32_t kIrqEn = 0x2c;
inline constexpr uint32_t kFifoLevel = 0x30;
inline constexpr uint32_t kFifoLow = 0x34;
inline constexpr uint32_t kFeed = 0x40;
inline constexpr uint32_t kStepLen = 0x44;
inline constexpr uint32_t kStepSpace = 0x48;
inline constexpr uint32_t kDirSetup = 0x4c;
inline constexpr uint32_t kDirHold = 0x50;
inline constexpr uint32_t kStepType = 0x54;
inline constexpr uint32_t kTimeLo = 0x60;
inline constexpr uint32_t kTimeHi = 0x64;
inline constexpr uint32_t kWdogPeriod = 0x70;
inline constexpr uint32_t kWdogKick = 0x74;
inline constexpr uint32_t kWdogLeft = 0x78;
inline constexpr uint32_t kSnapAt = 0x80;
inline constexpr uint32_t kSnapCtrl = 0x88;
inline constexpr uint32_t kSnapTime = 0x90;
inline constexpr uint32_t kSnapPos0 = 0xa0;
inline constexpr uint32_t kSnapPos1 = 0xa8;
inline constexpr uint32_t kSnapPos2 = 0xb0;
inline constexpr uint32_t kSnapPos3 = 0xb8;
inline constexpr uint32_t kSnapPos4 = 0xc0;
inline constexpr uint32_t kSnapPos5 = 0xc8;
inline constexpr uint32_t kSnapSpeed0 = 0xd0;
inline constexpr uint32_t kSnapSpeed1 = 0xd4;
inline constexpr uint32_t kSnapSpeed2 = 0xd8;
inline constexpr uint32_t kSnapSpeed3 = 0xdc;
inline constexpr uint32_t kSnapSpeed4 = 0xe0;
inline constexpr uint32_t kSnapSpeed5 = 0xe4;
inline constexpr uint32_t kProfQ = 0xf0;
inline constexpr uint32_t kProfLen = 0xf8;
inline constexpr uint32_t kProfCtrl = 0xfc;
inline constexpr uint32_t kProbeCfg = 0x100;
inline constexpr uint32_t kLatchCtrl = 0x104;
inline constexpr uint32_t kLatchTime = 0x108;
inline constexpr uint32_t kLatchPos0 = 0x110;
inline constexpr uint32_t kLatchPos1 = 0x118;
inline constexpr uint32_t kLatchPos2 = 0x120;
inline constexpr uint32_t kLatchPos3 = 0x128;
inline constexpr uint32_t kLatchPos4 = 0x130;
inline constexpr uint32_t kLatchPos5 = 0x138;
inline constexpr uint32_t kProfLevel = 0x140;
inline constexpr uint32_t kProfSpeed = 0x148;
inline constexpr uint32_t kCmdDelta0 = 0x200;
inline constexpr uint32_t kCmdDelta1 = 0x204;
inline constexpr uint32_t kCmdDelta2 = 0x208;
inline constexpr uint32_t kCmdDelta3 = 0x20c;
inline constexpr uint32_t kCmdDelta4 = 0x210;
inline constexpr uint32_t kCmdDelta5 = 0x214;
inline constexpr uint32_t kCmdCenter0 = 0x218;
inline constexpr uint32_t kCmdCenter1 = 0x21c;
inline constexpr uint32_t kCmdEnd0 = 0x220;
inline constexpr uint32_t kCmdEnd1 = 0x224;
inline constexpr uint32_t kCmdOps = 0x228;
inline constexpr uint32_t kCmdFeed = 0x22c;
inline constexpr uint32_t kCmdAt = 0x230;
inline constexpr uint32_t kCmdFlags = 0x238;
inline constexpr uint32_t kCmdPush = 0x23c;
inline constexpr uint32_t kCmdMvOps = 0x240;
inline constexpr uint32_t kCmdMvTarget = 0x244;
inline constexpr uint32_t kCmdMvEnd = 0x248;
inline constexpr uint32_t kCmdMvMax = 0x24c;

// regblock's hwif_in: what the hardware drives (hw-writable fields' next).
struct HwifIn {
  struct {
    struct { uint64_t next = 0; } axes;
    struct { uint64_t next = 0; } core;
    struct { uint64_t next = 0; } bus;
    struct { uint64_t next = 0; } profile;
    struct { uint64_t next = 0; } step_types;
    struct { uint64_t next = 0; } fifo_depth;
  } id_build;
  struct {
    struct { uint64_t next = 0; } acc_w;
    struct { uint64_t next = 0; } coord_w;
    struct { uint64_t next = 0; } ops_w;
    struct { uint64_t next = 0; } pos_w;
  } id_widths;
  struct {
    struct { uint64_t next = 0; } tim_w;
    struct { uint64_t next = 0; } feed_w;
  } id_widths2;
  struct {
    struct { uint64_t next = 0; } hz;
  } id_clock;
  struct {
    struct { uint64_t next = 0; } spd_w;
    struct { uint64_t next = 0; } tick_w;
    struct { uint64_t next = 0; } len_w;
    struct { uint64_t next = 0; } lvl_w;
  } id_profile;
  struct {
    struct { uint64_t next = 0; } busy;
    struct { uint64_t next = 0; } fifo_empty;
    struct { uint64_t next = 0; } fifo_full;
    struct { uint64_t next = 0; } low;
    struct { uint64_t next = 0; } probe;
    struct { uint64_t next = 0; } wdog_run;
    struct { uint64_t next = 0; } stopped;
    struct { uint64_t next = 0; } snap_armed;
    struct { uint64_t next = 0; } latch_armed;
    struct { uint64_t next = 0; } waiting;
    struct { uint64_t next = 0; } prof_busy;
    struct { uint64_t next = 0; } wdog_stopping;
  } status;
  struct {
    struct { uint64_t next = 0; } overflow;
    struct { uint64_t next = 0; } refused;
    struct { uint64_t next = 0; } late;
    struct { uint64_t next = 0; } wdog;
    struct { uint64_t next = 0; } snap;
    struct { uint64_t next = 0; } latch;
    struct { uint64_t next = 0; } low_water;
    struct { uint64_t next = 0; } estop;
    struct { uint64_t next = 0; } done;
  } events;
  struct {
    struct { uint64_t next = 0; } fill;
    struct { uint64_t next = 0; } room;
  } fifo_level;
  struct {
    struct { uint64_t next = 0; } count;
  } time_lo;
  struct {
    struct { uint64_t next = 0; } count;
  } time_hi;
  struct {
    struct { uint64_t next = 0; } left;
  } wdog_left;
  struct {
    struct { uint64_t next = 0; } count;
  } snap_time;
  struct {
    struct { uint64_t next = 0; } pos;
  } snap_pos0;
  struct {
    struct { uint64_t next = 0; } pos;
  } snap_pos1;
  struct {
    struct { uint64_t next = 0; } pos;
  } snap_pos2;
  struct {
    struct { uint64_t next = 0; } pos;
  } snap_pos3;
  struct {
    struct { uint64_t next = 0; } pos;
  } snap_pos4;
  struct {
    struct { uint64_t next = 0; } pos;
  } snap_pos5;
  struct {
    struct { uint64_t next = 0; } period;
    struct { uint64_t next = 0; } neg;
  } snap_speed0;
  struct {
    struct { uint64_t next = 0; } period;
    struct { uint64_t next = 0; } neg;
  } snap_speed1;
  struct {
    struct { uint64_t next = 0; } period;
    struct { uint64_t next = 0; } neg;
  } snap_speed2;
  struct {
    struct { uint64_t next = 0; } period;
    struct { uint64_t next = 0; } neg;
  } snap_speed3;
  struct {
    struct { uint64_t next = 0; } period;
    struct { uint64_t next = 0; } neg;
  } snap_speed4;
  struct {
    struct { uint64_t next = 0; } period;
    struct { uint64_t next = 0; } neg;
  } snap_speed5;
  struct {
    struct { uint64_t next = 0; } count;
  } latch_time;
  struct {
    struct { uint64_t next = 0; } pos;
  } latch_pos0;
  struct {
    struct { uint64_t next = 0; } pos;
  } latch_pos1;
  struct {
    struct { uint64_t next = 0; } pos;
  } latch_pos2;
  struct {
    struct { uint64_t next = 0; } pos;
  } latch_pos3;
  struct {
    struct { uint64_t next = 0; } pos;
  } latch_pos4;
  struct {
    struct { uint64_t next = 0; } pos;
  } latch_pos5;
  struct {
    struct { uint64_t next = 0; } c;
  } prof_level;
  struct {
    struct { uint64_t next = 0; } speed;
  } prof_speed;
};

// regblock's hwif_out: field values the hardware reads, strobes, interrupts.
struct HwifOut {
  struct {
    struct { uint64_t value = 0; } abort_motion;
  } ctrl;
  struct {
    struct { uint64_t value = 0; } overflow;
    struct { uint64_t value = 0; } refused;
    struct { uint64_t value = 0; } late;
    struct { uint64_t value = 0; } wdog;
    struct { uint64_t value = 0; } snap;
    struct { uint64_t value = 0; } latch;
    struct { uint64_t value = 0; } low_water;
    struct { uint64_t value = 0; } estop;
    struct { uint64_t value = 0; } done;
    bool intr = false;
  } events;
  struct {
    struct { uint64_t value = 0; } overflow;
    struct { uint64_t value = 0; } refused;
    struct { uint64_t value = 0; } late;
    struct { uint64_t value = 0; } wdog;
    struct { uint64_t value = 0; } snap;
    struct { uint64_t value = 0; } latch;
    struct { uint64_t value = 0; } low_water;
    struct { uint64_t value = 0; } estop;
    struct { uint64_t value = 0; } done;
  } irq_en;
  struct {
    struct { uint64_t value = 0; } mark;
  } fifo_low;
  struct {
    struct { uint64_t value = 0; } value;
  } feed;
  struct {
    struct { uint64_t value = 0; } value;
  } step_len;
  struct {
    struct { uint64_t value = 0; } value;
  } step_space;
  struct {
    struct { uint64_t value = 0; } value;
  } dir_setup;
  struct {
    struct { uint64_t value = 0; } value;
  } dir_hold;
  struct {
    struct { uint64_t value = 0; } axis0;
    struct { uint64_t value = 0; } axis1;
    struct { uint64_t value = 0; } axis2;
    struct { uint64_t value = 0; } axis3;
    struct { uint64_t value = 0; } axis4;
    struct { uint64_t value = 0; } axis5;
  } step_type;
  struct {
    struct { bool swacc = false; } count;
  } time_lo;
  struct {
    struct { uint64_t value = 0; bool swmod = false; } period;
  } wdog_period;
  struct {
    struct { bool swmod = false; } kick;
  } wdog_kick;
  struct {
    struct { uint64_t value = 0; } lo;
    struct { uint64_t value = 0; } hi;
  } snap_at;
  struct {
    struct { uint64_t value = 0; } arm;
  } snap_ctrl;
  struct {
    struct { uint64_t value = 0; } lo;
    struct { uint64_t value = 0; } hi;
  } prof_q;
  struct {
    struct { uint64_t value = 0; } value;
  } prof_len;
  struct {
    struct { uint64_t value = 0; } hold;
    struct { uint64_t value = 0; } ovr;
  } prof_ctrl;
  struct {
    struct { uint64_t value = 0; } filter;
    struct { uint64_t value = 0; } falling;
    struct { uint64_t value = 0; } stop;
  } probe_cfg;
  struct {
    struct { uint64_t value = 0; } arm;
  } latch_ctrl;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_delta0;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_delta1;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_delta2;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_delta3;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_delta4;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_delta5;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_center0;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_center1;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_end0;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_end1;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_ops;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_feed;
  struct {
    struct { uint64_t value = 0; } lo;
    struct { uint64_t value = 0; } hi;
  } cmd_at;
  struct {
    struct { uint64_t value = 0; } arc;
    struct { uint64_t value = 0; } plane;
    struct { uint64_t value = 0; } ccw;
    struct { uint64_t value = 0; } timed;
  } cmd_flags;
  struct {
    struct { bool swmod = false; } push;
  } cmd_push;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_mv_ops;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_mv_target;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_mv_end;
  struct {
    struct { uint64_t value = 0; } value;
  } cmd_mv_max;
};

// One request on regblock's internal CPU interface (its cpuif_* signals).
struct Request {
  bool req = false, is_wr = false;
  uint32_t addr = 0;      // byte address
  uint32_t wr_data = 0;
  uint32_t wr_biten = 0;  // bit enables (byte strobes widened)
};
struct Response {
  bool rd_ack = false, rd_err = false, wr_ack = false, wr_err = false;
  uint32_t rd_data = 0;
};

class Block {
 public:
  // The registers: every field with storage.
  struct Storage {
    struct {
      uint64_t abort_motion = 0x0ull;
    } ctrl;
    struct {
      uint64_t overflow = 0x0ull;
      uint64_t refused = 0x0ull;
      uint64_t late = 0x0ull;
      uint64_t wdog = 0x0ull;
      uint64_t snap = 0x0ull;
      uint64_t latch = 0x0ull;
      uint64_t low_water = 0x0ull;
      uint64_t estop = 0x0ull;
      uint64_t done = 0x0ull;
    } events;
    struct {
      uint64_t overflow = 0x0ull;
      uint64_t refused = 0x0ull;
      uint64_t late = 0x0ull;
      uint64_t wdog = 0x0ull;
      uint64_t snap = 0x0ull;
      uint64_t latch = 0x0ull;
      uint64_t low_water = 0x0ull;
      uint64_t estop = 0x0ull;
      uint64_t done = 0x0ull;
    } irq_en;
    struct {
      uint64_t mark = 0x0ull;
    } fifo_low;
    struct {
      uint64_t value = 0xffffffffull;
    } feed;
    struct {
      uint64_t value = 0x0ull;
    } step_len;
    struct {
      uint64_t value = 0x0ull;
    } step_space;
    struct {
      uint64_t value = 0x0ull;
    } dir_setup;
    struct {
      uint64_t value = 0x0ull;
    } dir_hold;
    struct {
      uint64_t axis0 = 0x0ull;
      uint64_t axis1 = 0x0ull;
      uint64_t axis2 = 0x0ull;
      uint64_t axis3 = 0x0ull;
      uint64_t axis4 = 0x0ull;
      uint64_t axis5 = 0x0ull;
    } step_type;
    struct {
      uint64_t period = 0x0ull;
    } wdog_period;
    struct {
      uint64_t kick = 0x0ull;
    } wdog_kick;
    struct {
      uint64_t lo = 0x0ull;
      uint64_t hi = 0x0ull;
    } snap_at;
    struct {
      uint64_t arm = 0x0ull;
    } snap_ctrl;
    struct {
      uint64_t lo = 0x0ull;
      uint64_t hi = 0x0ull;
    } prof_q;
    struct {
      uint64_t value = 0x1ull;
    } prof_len;
    struct {
      uint64_t hold = 0x0ull;
      uint64_t ovr = 0x80ull;
    } prof_ctrl;
    struct {
      uint64_t filter = 0x0ull;
      uint64_t falling = 0x0ull;
      uint64_t stop = 0x0ull;
    } probe_cfg;
    struct {
      uint64_t arm = 0x0ull;
    } latch_ctrl;
    struct {
      uint64_t value = 0x0ull;
    } cmd_delta0;
    struct {
      uint64_t value = 0x0ull;
    } cmd_delta1;
    struct {
      uint64_t value = 0x0ull;
    } cmd_delta2;
    struct {
      uint64_t value = 0x0ull;
    } cmd_delta3;
    struct {
      uint64_t value = 0x0ull;
    } cmd_delta4;
    struct {
      uint64_t value = 0x0ull;
    } cmd_delta5;
    struct {
      uint64_t value = 0x0ull;
    } cmd_center0;
    struct {
      uint64_t value = 0x0ull;
    } cmd_center1;
    struct {
      uint64_t value = 0x0ull;
    } cmd_end0;
    struct {
      uint64_t value = 0x0ull;
    } cmd_end1;
    struct {
      uint64_t value = 0x0ull;
    } cmd_ops;
    struct {
      uint64_t value = 0x0ull;
    } cmd_feed;
    struct {
      uint64_t lo = 0x0ull;
      uint64_t hi = 0x0ull;
    } cmd_at;
    struct {
      uint64_t arc = 0x0ull;
      uint64_t plane = 0x0ull;
      uint64_t ccw = 0x0ull;
      uint64_t timed = 0x0ull;
    } cmd_flags;
    struct {
      uint64_t push = 0x0ull;
    } cmd_push;
    struct {
      uint64_t value = 0x0ull;
    } cmd_mv_ops;
    struct {
      uint64_t value = 0x0ull;
    } cmd_mv_target;
    struct {
      uint64_t value = 0x0ull;
    } cmd_mv_end;
    struct {
      uint64_t value = 0x0ull;
    } cmd_mv_max;
  };
  Storage q;  // after the last edge

  void reset() { q = Storage(); d_ = q; }
  void commit() { q = d_; }

  // hwif_out from the registers alone (no request): values and interrupts.
  void outputs(HwifOut& o) const {
    o.ctrl.abort_motion.value = q.ctrl.abort_motion;
    o.events.overflow.value = q.events.overflow;
    o.events.refused.value = q.events.refused;
    o.events.late.value = q.events.late;
    o.events.wdog.value = q.events.wdog;
    o.events.snap.value = q.events.snap;
    o.events.latch.value = q.events.latch;
    o.events.low_water.value = q.events.low_water;
    o.events.estop.value = q.events.estop;
    o.events.done.value = q.events.done;
    o.events.intr = q.events.overflow != 0 || q.events.refused != 0 || q.events.late != 0 || q.events.wdog != 0 || q.events.snap != 0 || q.events.latch != 0 || q.events.low_water != 0 || q.events.estop != 0 || q.events.done != 0;
    o.irq_en.overflow.value = q.irq_en.overflow;
    o.irq_en.refused.value = q.irq_en.refused;
    o.irq_en.late.value = q.irq_en.late;
    o.irq_en.wdog.value = q.irq_en.wdog;
    o.irq_en.snap.value = q.irq_en.snap;
    o.irq_en.latch.value = q.irq_en.latch;
    o.irq_en.low_water.value = q.irq_en.low_water;
    o.irq_en.estop.value = q.irq_en.estop;
    o.irq_en.done.value = q.irq_en.done;
    o.fifo_low.mark.value = q.fifo_low.mark;
    o.feed.value.value = q.feed.value;
    o.step_len.value.value = q.step_len.value;
    o.step_space.value.value = q.step_space.value;
    o.dir_setup.value.value = q.dir_setup.value;
    o.dir_hold.value.value = q.dir_hold.value;
    o.step_type.axis0.value = q.step_type.axis0;
    o.step_type.axis1.value = q.step_type.axis1;
    o.step_type.axis2.value = q.step_type.axis2;
    o.step_type.axis3.value = q.step_type.axis3;
    o.step_type.axis4.value = q.step_type.axis4;
    o.step_type.axis5.value = q.step_type.axis5;
    o.time_lo.count.swacc = false;
    o.wdog_period.period.value = q.wdog_period.period;
    o.wdog_period.period.swmod = false;
    o.wdog_kick.kick.swmod = false;
    o.snap_at.lo.value = q.snap_at.lo;
    o.snap_at.hi.value = q.snap_at.hi;
    o.snap_ctrl.arm.value = q.snap_ctrl.arm;
    o.prof_q.lo.value = q.prof_q.lo;
    o.prof_q.hi.value = q.prof_q.hi;
    o.prof_len.value.value = q.prof_len.value;
    o.prof_ctrl.hold.value = q.prof_ctrl.hold;
    o.prof_ctrl.ovr.value = q.prof_ctrl.ovr;
    o.probe_cfg.filter.value = q.probe_cfg.filter;
    o.probe_cfg.falling.value = q.probe_cfg.falling;
    o.probe_cfg.stop.value = q.probe_cfg.stop;
    o.latch_ctrl.arm.value = q.latch_ctrl.arm;
    o.cmd_delta0.value.value = q.cmd_delta0.value;
    o.cmd_delta1.value.value = q.cmd_delta1.value;
    o.cmd_delta2.value.value = q.cmd_delta2.value;
    o.cmd_delta3.value.value = q.cmd_delta3.value;
    o.cmd_delta4.value.value = q.cmd_delta4.value;
    o.cmd_delta5.value.value = q.cmd_delta5.value;
    o.cmd_center0.value.value = q.cmd_center0.value;
    o.cmd_center1.value.value = q.cmd_center1.value;
    o.cmd_end0.value.value = q.cmd_end0.value;
    o.cmd_end1.value.value = q.cmd_end1.value;
    o.cmd_ops.value.value = q.cmd_ops.value;
    o.cmd_feed.value.value = q.cmd_feed.value;
    o.cmd_at.lo.value = q.cmd_at.lo;
    o.cmd_at.hi.value = q.cmd_at.hi;
    o.cmd_flags.arc.value = q.cmd_flags.arc;
    o.cmd_flags.plane.value = q.cmd_flags.plane;
    o.cmd_flags.ccw.value = q.cmd_flags.ccw;
    o.cmd_flags.timed.value = q.cmd_flags.timed;
    o.cmd_push.push.swmod = false;
    o.cmd_mv_ops.value.value = q.cmd_mv_ops.value;
    o.cmd_mv_target.value.value = q.cmd_mv_target.value;
    o.cmd_mv_end.value.value = q.cmd_mv_end.value;
    o.cmd_mv_max.value.value = q.cmd_mv_max.value;
  }

  // One clock: the request and the hardware inputs give the response and
  // hwif_out of this clock (before the edge); the next state waits for commit().
  void eval(const Request& rq, const HwifIn& in, Response& rsp, HwifOut& o) {
    outputs(o);
    d_ = q;
    const bool rd = rq.req && !rq.is_wr, wr = rq.req && rq.is_wr;
    bool valid_addr = false, valid_rw = false;
    uint32_t data = 0;
    const uint32_t a = rq.addr;
    const uint64_t wd = rq.wr_data, be = rq.wr_biten;
    (void)wd;
    (void)be;
    if (a == 0x0) {  // id_magic
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((0x484d5331ull >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x4) {  // id_version
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((0x1ull >> 0) & 0xffffull) << 0);
      data |= static_cast<uint32_t>(((0x1ull >> 0) & 0xffffull) << 16);
    }
    if (a == 0x8) {  // id_build
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.id_build.axes.next >> 0) & 0xfull) << 0);
      data |= static_cast<uint32_t>(((in.id_build.core.next >> 0) & 0xfull) << 4);
      data |= static_cast<uint32_t>(((in.id_build.bus.next >> 0) & 0x3ull) << 8);
      data |= static_cast<uint32_t>(((in.id_build.profile.next >> 0) & 0x1ull) << 10);
      data |= static_cast<uint32_t>(((in.id_build.step_types.next >> 0) & 0x7ull) << 12);
      data |= static_cast<uint32_t>(((in.id_build.fifo_depth.next >> 0) & 0xffffull) << 16);
    }
    if (a == 0xc) {  // id_widths
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.id_widths.acc_w.next >> 0) & 0xffull) << 0);
      data |= static_cast<uint32_t>(((in.id_widths.coord_w.next >> 0) & 0xffull) << 8);
      data |= static_cast<uint32_t>(((in.id_widths.ops_w.next >> 0) & 0xffull) << 16);
      data |= static_cast<uint32_t>(((in.id_widths.pos_w.next >> 0) & 0xffull) << 24);
    }
    if (a == 0x10) {  // id_widths2
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.id_widths2.tim_w.next >> 0) & 0xffull) << 0);
      data |= static_cast<uint32_t>(((in.id_widths2.feed_w.next >> 0) & 0xffull) << 8);
    }
    if (a == 0x14) {  // id_clock
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.id_clock.hz.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x18) {  // id_profile
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.id_profile.spd_w.next >> 0) & 0xffull) << 0);
      data |= static_cast<uint32_t>(((in.id_profile.tick_w.next >> 0) & 0xffull) << 8);
      data |= static_cast<uint32_t>(((in.id_profile.len_w.next >> 0) & 0xffull) << 16);
      data |= static_cast<uint32_t>(((in.id_profile.lvl_w.next >> 0) & 0xffull) << 24);
    }
    if (a == 0x20) {  // ctrl
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x24) {  // status
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.status.busy.next >> 0) & 0x1ull) << 0);
      data |= static_cast<uint32_t>(((in.status.fifo_empty.next >> 0) & 0x1ull) << 1);
      data |= static_cast<uint32_t>(((in.status.fifo_full.next >> 0) & 0x1ull) << 2);
      data |= static_cast<uint32_t>(((in.status.low.next >> 0) & 0x1ull) << 3);
      data |= static_cast<uint32_t>(((in.status.probe.next >> 0) & 0x1ull) << 4);
      data |= static_cast<uint32_t>(((in.status.wdog_run.next >> 0) & 0x1ull) << 5);
      data |= static_cast<uint32_t>(((in.status.stopped.next >> 0) & 0x1ull) << 6);
      data |= static_cast<uint32_t>(((in.status.snap_armed.next >> 0) & 0x1ull) << 7);
      data |= static_cast<uint32_t>(((in.status.latch_armed.next >> 0) & 0x1ull) << 8);
      data |= static_cast<uint32_t>(((in.status.waiting.next >> 0) & 0x1ull) << 9);
      data |= static_cast<uint32_t>(((in.status.prof_busy.next >> 0) & 0x1ull) << 10);
      data |= static_cast<uint32_t>(((in.status.wdog_stopping.next >> 0) & 0x1ull) << 11);
    }
    if (a == 0x28) {  // events
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.events.overflow >> 0) & 0x1ull) << 0);
      data |= static_cast<uint32_t>(((q.events.refused >> 0) & 0x1ull) << 1);
      data |= static_cast<uint32_t>(((q.events.late >> 0) & 0x1ull) << 2);
      data |= static_cast<uint32_t>(((q.events.wdog >> 0) & 0x1ull) << 3);
      data |= static_cast<uint32_t>(((q.events.snap >> 0) & 0x1ull) << 4);
      data |= static_cast<uint32_t>(((q.events.latch >> 0) & 0x1ull) << 5);
      data |= static_cast<uint32_t>(((q.events.low_water >> 0) & 0x1ull) << 6);
      data |= static_cast<uint32_t>(((q.events.estop >> 0) & 0x1ull) << 7);
      data |= static_cast<uint32_t>(((q.events.done >> 0) & 0x1ull) << 8);
    }
    if (a == 0x2c) {  // irq_en
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.irq_en.overflow >> 0) & 0x1ull) << 0);
      data |= static_cast<uint32_t>(((q.irq_en.refused >> 0) & 0x1ull) << 1);
      data |= static_cast<uint32_t>(((q.irq_en.late >> 0) & 0x1ull) << 2);
      data |= static_cast<uint32_t>(((q.irq_en.wdog >> 0) & 0x1ull) << 3);
      data |= static_cast<uint32_t>(((q.irq_en.snap >> 0) & 0x1ull) << 4);
      data |= static_cast<uint32_t>(((q.irq_en.latch >> 0) & 0x1ull) << 5);
      data |= static_cast<uint32_t>(((q.irq_en.low_water >> 0) & 0x1ull) << 6);
      data |= static_cast<uint32_t>(((q.irq_en.estop >> 0) & 0x1ull) << 7);
      data |= static_cast<uint32_t>(((q.irq_en.done >> 0) & 0x1ull) << 8);
    }
    if (a == 0x30) {  // fifo_level
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.fifo_level.fill.next >> 0) & 0xffffull) << 0);
      data |= static_cast<uint32_t>(((in.fifo_level.room.next >> 0) & 0xffffull) << 16);
    }
    if (a == 0x34) {  // fifo_low
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.fifo_low.mark >> 0) & 0xffffull) << 0);
    }
    if (a == 0x40) {  // feed
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.feed.value >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x44) {  // step_len
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.step_len.value >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x48) {  // step_space
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.step_space.value >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x4c) {  // dir_setup
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.dir_setup.value >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x50) {  // dir_hold
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.dir_hold.value >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x54) {  // step_type
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.step_type.axis0 >> 0) & 0x3ull) << 0);
      data |= static_cast<uint32_t>(((q.step_type.axis1 >> 0) & 0x3ull) << 2);
      data |= static_cast<uint32_t>(((q.step_type.axis2 >> 0) & 0x3ull) << 4);
      data |= static_cast<uint32_t>(((q.step_type.axis3 >> 0) & 0x3ull) << 6);
      data |= static_cast<uint32_t>(((q.step_type.axis4 >> 0) & 0x3ull) << 8);
      data |= static_cast<uint32_t>(((q.step_type.axis5 >> 0) & 0x3ull) << 10);
    }
    if (a == 0x60) {  // time_lo
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.time_lo.count.next >> 0) & 0xffffffffull) << 0);
      o.time_lo.count.swacc = strb;
    }
    if (a == 0x64) {  // time_hi
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.time_hi.count.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x70) {  // wdog_period
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.wdog_period.period >> 0) & 0xffffffffull) << 0);
      o.wdog_period.period.swmod = strb && rq.is_wr && (be & 0xffffffffull) != 0;
    }
    if (a == 0x74) {  // wdog_kick
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
      o.wdog_kick.kick.swmod = strb && rq.is_wr && (be & 0x1ull) != 0;
    }
    if (a == 0x78) {  // wdog_left
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.wdog_left.left.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x80) {  // snap_at word 0
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.snap_at.lo >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x84) {  // snap_at word 1
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.snap_at.hi >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x88) {  // snap_ctrl
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x90) {  // snap_time word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_time.count.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x94) {  // snap_time word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_time.count.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0xa0) {  // snap_pos0 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos0.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xa4) {  // snap_pos0 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos0.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0xa8) {  // snap_pos1 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos1.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xac) {  // snap_pos1 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos1.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0xb0) {  // snap_pos2 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos2.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xb4) {  // snap_pos2 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos2.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0xb8) {  // snap_pos3 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos3.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xbc) {  // snap_pos3 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos3.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0xc0) {  // snap_pos4 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos4.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xc4) {  // snap_pos4 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos4.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0xc8) {  // snap_pos5 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos5.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xcc) {  // snap_pos5 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_pos5.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0xd0) {  // snap_speed0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_speed0.period.next >> 0) & 0x7fffffffull) << 0);
      data |= static_cast<uint32_t>(((in.snap_speed0.neg.next >> 0) & 0x1ull) << 31);
    }
    if (a == 0xd4) {  // snap_speed1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_speed1.period.next >> 0) & 0x7fffffffull) << 0);
      data |= static_cast<uint32_t>(((in.snap_speed1.neg.next >> 0) & 0x1ull) << 31);
    }
    if (a == 0xd8) {  // snap_speed2
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_speed2.period.next >> 0) & 0x7fffffffull) << 0);
      data |= static_cast<uint32_t>(((in.snap_speed2.neg.next >> 0) & 0x1ull) << 31);
    }
    if (a == 0xdc) {  // snap_speed3
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_speed3.period.next >> 0) & 0x7fffffffull) << 0);
      data |= static_cast<uint32_t>(((in.snap_speed3.neg.next >> 0) & 0x1ull) << 31);
    }
    if (a == 0xe0) {  // snap_speed4
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_speed4.period.next >> 0) & 0x7fffffffull) << 0);
      data |= static_cast<uint32_t>(((in.snap_speed4.neg.next >> 0) & 0x1ull) << 31);
    }
    if (a == 0xe4) {  // snap_speed5
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.snap_speed5.period.next >> 0) & 0x7fffffffull) << 0);
      data |= static_cast<uint32_t>(((in.snap_speed5.neg.next >> 0) & 0x1ull) << 31);
    }
    if (a == 0xf0) {  // prof_q word 0
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.prof_q.lo >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xf4) {  // prof_q word 1
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.prof_q.hi >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xf8) {  // prof_len
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.prof_len.value >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0xfc) {  // prof_ctrl
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.prof_ctrl.hold >> 0) & 0x1ull) << 0);
      data |= static_cast<uint32_t>(((q.prof_ctrl.ovr >> 0) & 0x1ffull) << 16);
    }
    if (a == 0x100) {  // probe_cfg
      valid_addr = true;
      valid_rw = true;
      const bool strb = rq.req;
      (void)strb;
      data |= static_cast<uint32_t>(((q.probe_cfg.filter >> 0) & 0xffffull) << 0);
      data |= static_cast<uint32_t>(((q.probe_cfg.falling >> 0) & 0x1ull) << 16);
      data |= static_cast<uint32_t>(((q.probe_cfg.stop >> 0) & 0x1ull) << 17);
    }
    if (a == 0x104) {  // latch_ctrl
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x108) {  // latch_time word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_time.count.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x10c) {  // latch_time word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_time.count.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x110) {  // latch_pos0 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos0.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x114) {  // latch_pos0 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos0.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x118) {  // latch_pos1 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos1.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x11c) {  // latch_pos1 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos1.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x120) {  // latch_pos2 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos2.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x124) {  // latch_pos2 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos2.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x128) {  // latch_pos3 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos3.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x12c) {  // latch_pos3 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos3.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x130) {  // latch_pos4 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos4.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x134) {  // latch_pos4 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos4.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x138) {  // latch_pos5 word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos5.pos.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x13c) {  // latch_pos5 word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.latch_pos5.pos.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x140) {  // prof_level
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.prof_level.c.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x148) {  // prof_speed word 0
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.prof_speed.speed.next >> 0) & 0xffffffffull) << 0);
    }
    if (a == 0x14c) {  // prof_speed word 1
      valid_addr = true;
      valid_rw = rd;
      const bool strb = rd;
      (void)strb;
      data |= static_cast<uint32_t>(((in.prof_speed.speed.next >> 32) & 0xffffffffull) << 0);
    }
    if (a == 0x200) {  // cmd_delta0
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x204) {  // cmd_delta1
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x208) {  // cmd_delta2
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x20c) {  // cmd_delta3
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x210) {  // cmd_delta4
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x214) {  // cmd_delta5
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x218) {  // cmd_center0
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x21c) {  // cmd_center1
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x220) {  // cmd_end0
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x224) {  // cmd_end1
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x228) {  // cmd_ops
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x22c) {  // cmd_feed
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x230) {  // cmd_at word 0
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x234) {  // cmd_at word 1
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x238) {  // cmd_flags
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x23c) {  // cmd_push
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
      o.cmd_push.push.swmod = strb && rq.is_wr && (be & 0x1ull) != 0;
    }
    if (a == 0x240) {  // cmd_mv_ops
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x244) {  // cmd_mv_target
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x248) {  // cmd_mv_end
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    if (a == 0x24c) {  // cmd_mv_max
      valid_addr = true;
      valid_rw = wr;
      const bool strb = wr;
      (void)strb;
    }
    // Field logic.
    if (wr && a == 0x20) {
      d_.ctrl.abort_motion = ((q.ctrl.abort_motion & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    } else if (true) {
      d_.ctrl.abort_motion = (0) & 0x1ull;
    }
    if ((in.events.overflow.next & 1) != 0) {
      d_.events.overflow = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.overflow = (q.events.overflow & ~(((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.refused.next & 1) != 0) {
      d_.events.refused = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.refused = (q.events.refused & ~(((wd >> 1) & 0x1ull) & ((be >> 1) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.late.next & 1) != 0) {
      d_.events.late = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.late = (q.events.late & ~(((wd >> 2) & 0x1ull) & ((be >> 2) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.wdog.next & 1) != 0) {
      d_.events.wdog = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.wdog = (q.events.wdog & ~(((wd >> 3) & 0x1ull) & ((be >> 3) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.snap.next & 1) != 0) {
      d_.events.snap = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.snap = (q.events.snap & ~(((wd >> 4) & 0x1ull) & ((be >> 4) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.latch.next & 1) != 0) {
      d_.events.latch = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.latch = (q.events.latch & ~(((wd >> 5) & 0x1ull) & ((be >> 5) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.low_water.next & 1) != 0) {
      d_.events.low_water = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.low_water = (q.events.low_water & ~(((wd >> 6) & 0x1ull) & ((be >> 6) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.estop.next & 1) != 0) {
      d_.events.estop = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.estop = (q.events.estop & ~(((wd >> 7) & 0x1ull) & ((be >> 7) & 0x1ull))) & 0x1ull;
    }
    if ((in.events.done.next & 1) != 0) {
      d_.events.done = (1) & 0x1ull;
    } else if (wr && a == 0x28) {
      d_.events.done = (q.events.done & ~(((wd >> 8) & 0x1ull) & ((be >> 8) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.overflow = ((q.irq_en.overflow & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.refused = ((q.irq_en.refused & ~((be >> 1) & 0x1ull)) | (((wd >> 1) & 0x1ull) & ((be >> 1) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.late = ((q.irq_en.late & ~((be >> 2) & 0x1ull)) | (((wd >> 2) & 0x1ull) & ((be >> 2) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.wdog = ((q.irq_en.wdog & ~((be >> 3) & 0x1ull)) | (((wd >> 3) & 0x1ull) & ((be >> 3) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.snap = ((q.irq_en.snap & ~((be >> 4) & 0x1ull)) | (((wd >> 4) & 0x1ull) & ((be >> 4) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.latch = ((q.irq_en.latch & ~((be >> 5) & 0x1ull)) | (((wd >> 5) & 0x1ull) & ((be >> 5) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.low_water = ((q.irq_en.low_water & ~((be >> 6) & 0x1ull)) | (((wd >> 6) & 0x1ull) & ((be >> 6) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.estop = ((q.irq_en.estop & ~((be >> 7) & 0x1ull)) | (((wd >> 7) & 0x1ull) & ((be >> 7) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x2c) {
      d_.irq_en.done = ((q.irq_en.done & ~((be >> 8) & 0x1ull)) | (((wd >> 8) & 0x1ull) & ((be >> 8) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x34) {
      d_.fifo_low.mark = ((q.fifo_low.mark & ~((be >> 0) & 0xffffull)) | (((wd >> 0) & 0xffffull) & ((be >> 0) & 0xffffull))) & 0xffffull;
    }
    if (wr && a == 0x40) {
      d_.feed.value = ((q.feed.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x44) {
      d_.step_len.value = ((q.step_len.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x48) {
      d_.step_space.value = ((q.step_space.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x4c) {
      d_.dir_setup.value = ((q.dir_setup.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x50) {
      d_.dir_hold.value = ((q.dir_hold.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x54) {
      d_.step_type.axis0 = ((q.step_type.axis0 & ~((be >> 0) & 0x3ull)) | (((wd >> 0) & 0x3ull) & ((be >> 0) & 0x3ull))) & 0x3ull;
    }
    if (wr && a == 0x54) {
      d_.step_type.axis1 = ((q.step_type.axis1 & ~((be >> 2) & 0x3ull)) | (((wd >> 2) & 0x3ull) & ((be >> 2) & 0x3ull))) & 0x3ull;
    }
    if (wr && a == 0x54) {
      d_.step_type.axis2 = ((q.step_type.axis2 & ~((be >> 4) & 0x3ull)) | (((wd >> 4) & 0x3ull) & ((be >> 4) & 0x3ull))) & 0x3ull;
    }
    if (wr && a == 0x54) {
      d_.step_type.axis3 = ((q.step_type.axis3 & ~((be >> 6) & 0x3ull)) | (((wd >> 6) & 0x3ull) & ((be >> 6) & 0x3ull))) & 0x3ull;
    }
    if (wr && a == 0x54) {
      d_.step_type.axis4 = ((q.step_type.axis4 & ~((be >> 8) & 0x3ull)) | (((wd >> 8) & 0x3ull) & ((be >> 8) & 0x3ull))) & 0x3ull;
    }
    if (wr && a == 0x54) {
      d_.step_type.axis5 = ((q.step_type.axis5 & ~((be >> 10) & 0x3ull)) | (((wd >> 10) & 0x3ull) & ((be >> 10) & 0x3ull))) & 0x3ull;
    }
    if (wr && a == 0x70) {
      d_.wdog_period.period = ((q.wdog_period.period & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x74) {
      d_.wdog_kick.kick = ((q.wdog_kick.kick & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x80) {
      d_.snap_at.lo = ((q.snap_at.lo & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x84) {
      d_.snap_at.hi = ((q.snap_at.hi & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x88) {
      d_.snap_ctrl.arm = ((q.snap_ctrl.arm & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    } else if (true) {
      d_.snap_ctrl.arm = (0) & 0x1ull;
    }
    if (wr && a == 0xf0) {
      d_.prof_q.lo = ((q.prof_q.lo & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0xf4) {
      d_.prof_q.hi = ((q.prof_q.hi & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0xf8) {
      d_.prof_len.value = ((q.prof_len.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0xfc) {
      d_.prof_ctrl.hold = ((q.prof_ctrl.hold & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0xfc) {
      d_.prof_ctrl.ovr = ((q.prof_ctrl.ovr & ~((be >> 16) & 0x1ffull)) | (((wd >> 16) & 0x1ffull) & ((be >> 16) & 0x1ffull))) & 0x1ffull;
    }
    if (wr && a == 0x100) {
      d_.probe_cfg.filter = ((q.probe_cfg.filter & ~((be >> 0) & 0xffffull)) | (((wd >> 0) & 0xffffull) & ((be >> 0) & 0xffffull))) & 0xffffull;
    }
    if (wr && a == 0x100) {
      d_.probe_cfg.falling = ((q.probe_cfg.falling & ~((be >> 16) & 0x1ull)) | (((wd >> 16) & 0x1ull) & ((be >> 16) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x100) {
      d_.probe_cfg.stop = ((q.probe_cfg.stop & ~((be >> 17) & 0x1ull)) | (((wd >> 17) & 0x1ull) & ((be >> 17) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x104) {
      d_.latch_ctrl.arm = ((q.latch_ctrl.arm & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    } else if (true) {
      d_.latch_ctrl.arm = (0) & 0x1ull;
    }
    if (wr && a == 0x200) {
      d_.cmd_delta0.value = ((q.cmd_delta0.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x204) {
      d_.cmd_delta1.value = ((q.cmd_delta1.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x208) {
      d_.cmd_delta2.value = ((q.cmd_delta2.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x20c) {
      d_.cmd_delta3.value = ((q.cmd_delta3.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x210) {
      d_.cmd_delta4.value = ((q.cmd_delta4.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x214) {
      d_.cmd_delta5.value = ((q.cmd_delta5.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x218) {
      d_.cmd_center0.value = ((q.cmd_center0.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x21c) {
      d_.cmd_center1.value = ((q.cmd_center1.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x220) {
      d_.cmd_end0.value = ((q.cmd_end0.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x224) {
      d_.cmd_end1.value = ((q.cmd_end1.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x228) {
      d_.cmd_ops.value = ((q.cmd_ops.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x22c) {
      d_.cmd_feed.value = ((q.cmd_feed.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x230) {
      d_.cmd_at.lo = ((q.cmd_at.lo & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x234) {
      d_.cmd_at.hi = ((q.cmd_at.hi & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x238) {
      d_.cmd_flags.arc = ((q.cmd_flags.arc & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x238) {
      d_.cmd_flags.plane = ((q.cmd_flags.plane & ~((be >> 1) & 0x3ull)) | (((wd >> 1) & 0x3ull) & ((be >> 1) & 0x3ull))) & 0x3ull;
    }
    if (wr && a == 0x238) {
      d_.cmd_flags.ccw = ((q.cmd_flags.ccw & ~((be >> 3) & 0x1ull)) | (((wd >> 3) & 0x1ull) & ((be >> 3) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x238) {
      d_.cmd_flags.timed = ((q.cmd_flags.timed & ~((be >> 4) & 0x1ull)) | (((wd >> 4) & 0x1ull) & ((be >> 4) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x23c) {
      d_.cmd_push.push = ((q.cmd_push.push & ~((be >> 0) & 0x1ull)) | (((wd >> 0) & 0x1ull) & ((be >> 0) & 0x1ull))) & 0x1ull;
    }
    if (wr && a == 0x240) {
      d_.cmd_mv_ops.value = ((q.cmd_mv_ops.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x244) {
      d_.cmd_mv_target.value = ((q.cmd_mv_target.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x248) {
      d_.cmd_mv_end.value = ((q.cmd_mv_end.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    if (wr && a == 0x24c) {
      d_.cmd_mv_max.value = ((q.cmd_mv_max.value & ~((be >> 0) & 0xffffffffull)) | (((wd >> 0) & 0xffffffffull) & ((be >> 0) & 0xffffffffull))) & 0xffffffffull;
    }
    const bool err = rq.req && (!valid_addr || !valid_rw);
    rsp.rd_ack = rd;
    rsp.rd_err = rd && err;
    rsp.rd_data = data;
    rsp.wr_ack = wr;
    rsp.wr_err = wr && err;
  }

 private:
  Storage d_;
};

}  // namespace hwinterp::hls::motion_soc_regs
