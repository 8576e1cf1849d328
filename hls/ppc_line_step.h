// The PPC line engine shared by ppc_line and ppc_arc's closing line: the
// cycle behaviour of rtl/ppc_line_step.sv (see there for the rule and the
// widths). Synthesizable subset: SystemC integers, no floats, no heap.
#pragma once

#include <systemc>

namespace hwinterp::hls {

template <int MAG_W>
class PpcLineStep {
 public:
  static_assert(MAG_W >= 2 && MAG_W <= 62, "MAG_W out of range");
  using mag_t = sc_dt::sc_uint<MAG_W>;
  using f_t = sc_dt::sc_int<MAG_W + 1>;  // F, in [-|dy|, |dx|)

  void reset() {
    ax_q_ = ay_q_ = xl_q_ = yl_q_ = 0;
    f_q_ = 0;
  }

  // Combinational outputs, from the registers.
  bool x_left() const { return xl_q_ != 0; }
  bool y_left() const { return yl_q_ != 0; }
  bool step_x() const { return pick_x() && x_left(); }
  bool step_y() const { return !pick_x(); }  // implies y_left()
  // This operation is the line's last (at most one step left; none: zero length).
  bool last() const { return !(x_left() && y_left()) && (xl_q_ >> 1) == 0 && (yl_q_ >> 1) == 0; }

  // One rising clock edge: `load` starts a line (and wins over `advance`),
  // `advance` does this clock's operation.
  void clock(bool load, const mag_t& ax, const mag_t& ay, bool advance) {
    if (load) {
      ax_q_ = ax;
      ay_q_ = ay;
      xl_q_ = ax;
      yl_q_ = ay;
      f_q_ = 0;
      return;
    }
    if (!advance) return;
    if (step_x()) {
      f_q_ = f_q_ - ay_q_;
      xl_q_ = xl_q_ - 1;
    } else if (step_y()) {
      f_q_ = f_q_ + ax_q_;
      yl_q_ = yl_q_ - 1;
    }
  }

 private:
  bool pick_x() const { return (f_q_ >= 0 && x_left()) || !y_left(); }

  mag_t ax_q_ = 0, ay_q_ = 0;  // |dx|, |dy| of the running line
  mag_t xl_q_ = 0, yl_q_ = 0;  // steps left per axis
  f_t f_q_ = 0;
};

}  // namespace hwinterp::hls
