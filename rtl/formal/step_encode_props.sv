// Formal properties of step_encode (scripts/formal.sh --blocks step_encode).
//
// Free step_i, dir_i and type_i on every clock; the monitors count the
// steps on the inputs and keep the type a pulse started with, and read the
// block's outputs only:
//   a_stepdir type 0 or 3 in use: a_o = step_i, b_o = dir_i;
//   a_updown  type 1: a_o = step_i && !dir_i, b_o = step_i && dir_i (never
//             both high: one pulse per step, on the line of its direction);
//   a_quad    type 2: (a_o, b_o) is the Gray state of the net step count n
//             since reset, mod 4 (n = 0: 00, 1: 10, 2: 11, 3: 01), whatever
//             types were in use before: a quadrature decoder counts exactly
//             the pulses the stage gave;
//   a_gray    type 2 on two clocks running: the outputs changed in at most
//             one bit, and only on the clock after a rising step_i.
// The type in use: type_i of the last clock step_i was low on (from reset:
// 0). Assumptions: reset in the first cycle only; dir_i steady while step_i
// is high (the step stage's rule, rtl/formal/stepdir_axis_props.sv a_dir_hi).
// The invariant that closes the induction (the block's state is the
// monitors': a_state), through the `// link:` line (scripts/formal.sh):
// link: f_phase=u_dut.phase_q f_type=u_dut.type_q f_step=u_dut.step_q
module step_encode_props (
  input logic       clk_i,
  input logic       rst_ni,
  input logic [1:0] type_i,
  input logic       step_i,
  input logic       dir_i
);
  logic a, b;
  logic [1:0] f_phase, f_type;  // linked to the block's registers
  logic       f_step;

  step_encode u_dut (
    .clk_i,
    .rst_ni,
    .type_i,
    .step_i,
    .dir_i,
    .a_o(a),
    .b_o(b)
  );

  logic       p_step, p_dir, p_a, p_b;
  logic [1:0] m_type, p_type, n;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      p_step <= 1'b0;
      p_dir  <= 1'b0;
      p_a    <= 1'b0;
      p_b    <= 1'b0;
      m_type <= 2'd0;
      p_type <= 2'd0;
      n      <= 2'd0;
    end else begin
      p_step <= step_i;
      p_dir  <= dir_i;
      p_a    <= a;
      p_b    <= b;
      m_type <= step_i ? m_type : type_i;
      p_type <= m_type;
      n      <= (step_i && !p_step) ? (dir_i ? n - 2'd1 : n + 2'd1) : n;
    end
  end

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  logic [1:0] gray;
  assign gray = {n[1] ^ n[0], n[1]};

  always_comb begin
    assume(rst_ni == !f_init);
    if (!f_init && p_step && step_i) assume(dir_i == p_dir);
    if (!f_init) begin
      a_state: assert(f_phase == n && f_type == m_type && f_step == p_step);
      if (m_type == 2'd0 || m_type == 2'd3) a_stepdir: assert(a == step_i && b == dir_i);
      if (m_type == 2'd1) a_updown: assert(a == (step_i && !dir_i) && b == (step_i && dir_i));
      if (m_type == 2'd2) a_quad: assert({a, b} == gray);
      if (m_type == 2'd2 && p_type == 2'd2)
        a_gray: assert(({a, b} == {p_a, p_b}) || (!(a != p_a && b != p_b) && p_step));
    end
  end
endmodule
