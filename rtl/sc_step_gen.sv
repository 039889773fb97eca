// sc_step_gen: turns one-clock step requests into STEP/DIR pin timing.
//
// Requests are queued in a small signed counter (net steps still owed), so a
// request that arrives while a pulse is being shaped is delayed, never lost.
// Timing, all in clocks (values >= 1 for high and low):
//   STEP high for exactly cfg_high_i clocks;
//   STEP low for at least cfg_low_i clocks between pulses;
//   DIR changes only while STEP is low and >= cfg_hold_i clocks after the
//   last STEP rising edge;
//   STEP rises >= cfg_setup_i clocks after a DIR change.
// With no step owed, DIR is pre-positioned to dir_hint_i (the sign of the
// commanded velocity) so the first step after a reversal or at the start of
// a move is not delayed by the setup time.
// A request that would overflow the queue sets overrun_o (sticky until
// clear_i); the planner's step-rate limit (v <= 1/(high+low)) keeps the
// queue at <= 1 in open loop.
module sc_step_gen (
  input  logic                        clk_i,
  input  logic                        rst_ni,

  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_high_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_low_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_setup_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_hold_i,

  input  logic                        clear_i,     // zero count_o and overrun_o
  input  logic                        step_req_i,
  input  logic                        step_fwd_i,
  input  logic                        dir_hint_valid_i,
  input  logic                        dir_hint_i,   // 1 = forward

  output logic                        step_o,
  output logic                        dir_o,       // 1 = forward
  output logic                        busy_o,      // steps owed or pulse high
  output logic                        overrun_o,
  output logic signed [sc_pkg::PendW-1:0]     pending_o,
  output logic signed [sc_pkg::PosIntW-1:0]   count_o      // net steps emitted
);

  localparam int PulseTimeW = sc_pkg::PulseTimeW;
  localparam int PendW      = sc_pkg::PendW;
  localparam int PosIntW    = sc_pkg::PosIntW;
  localparam logic [PulseTimeW-1:0] CntMax = '1;
  localparam logic signed [PendW-1:0] PendMax = {1'b0, {(PendW-1){1'b1}}};
  localparam logic signed [PendW-1:0] PendMin = {1'b1, {(PendW-1){1'b0}}};

  logic                      step_q, step_d;
  logic                      dir_q, dir_d;
  logic [PulseTimeW-1:0]     high_left_q, high_left_d;
  logic [PulseTimeW-1:0]     low_cnt_q, low_cnt_d;      // clocks STEP has been low
  logic [PulseTimeW-1:0]     since_rise_q, since_rise_d;
  logic [PulseTimeW-1:0]     since_dir_q, since_dir_d;
  logic signed [PendW-1:0]   pend_q, pend_d;
  logic                      overrun_q, overrun_d;
  logic signed [PosIntW-1:0] count_q, count_d;

  logic want_fwd, have_steps, dir_ok, rise, flip_dir;
  logic req_blocked;

  assign have_steps = pend_q != '0;
  assign want_fwd   = !pend_q[PendW-1];
  assign dir_ok     = dir_q == want_fwd;
  assign rise       = have_steps && dir_ok && !step_q &&
                      low_cnt_q >= cfg_low_i && since_dir_q >= cfg_setup_i;
  assign flip_dir   = !step_q && since_rise_q >= cfg_hold_i &&
                      (have_steps ? !dir_ok : (dir_hint_valid_i && dir_hint_i != dir_q));

  function automatic logic [PulseTimeW-1:0] sat_inc(input logic [PulseTimeW-1:0] v);
    sat_inc = (v == CntMax) ? v : v + PulseTimeW'(1);
  endfunction

  always_comb begin
    step_d       = step_q;
    high_left_d  = high_left_q;
    dir_d        = dir_q;
    since_dir_d  = sat_inc(since_dir_q);
    since_rise_d = sat_inc(since_rise_q);
    overrun_d    = overrun_q;
    count_d      = count_q;
    pend_d       = pend_q;
    req_blocked  = 1'b0;

    if (rise) begin
      step_d       = 1'b1;
      high_left_d  = cfg_high_i;
      since_rise_d = PulseTimeW'(1);
      pend_d       = dir_q ? pend_q - PendW'(1) : pend_q + PendW'(1);
      count_d      = dir_q ? count_q + PosIntW'(1) : count_q - PosIntW'(1);
    end else if (step_q) begin
      high_left_d = high_left_q - PulseTimeW'(1);
      if (high_left_q <= PulseTimeW'(1)) begin
        step_d = 1'b0;
      end
    end

    if (flip_dir) begin
      dir_d       = !dir_q;
      since_dir_d = PulseTimeW'(1);
    end

    if (step_req_i) begin
      if (step_fwd_i) begin
        req_blocked = pend_d == PendMax;
        if (!req_blocked) pend_d = pend_d + PendW'(1);
      end else begin
        req_blocked = pend_d == PendMin;
        if (!req_blocked) pend_d = pend_d - PendW'(1);
      end
      if (req_blocked) overrun_d = 1'b1;
    end

    // low_cnt counts low clocks including the current one, so "low for
    // cfg_low clocks" is simply low_cnt_q >= cfg_low.
    low_cnt_d = step_d ? '0 : sat_inc(low_cnt_q);

    if (clear_i) begin
      overrun_d = 1'b0;
      count_d   = '0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      step_q       <= 1'b0;
      dir_q        <= 1'b1;
      high_left_q  <= '0;
      low_cnt_q    <= CntMax;
      since_rise_q <= CntMax;
      since_dir_q  <= CntMax;
      pend_q       <= '0;
      overrun_q    <= 1'b0;
      count_q      <= '0;
    end else begin
      step_q       <= step_d;
      dir_q        <= dir_d;
      high_left_q  <= high_left_d;
      low_cnt_q    <= low_cnt_d;
      since_rise_q <= since_rise_d;
      since_dir_q  <= since_dir_d;
      pend_q       <= pend_d;
      overrun_q    <= overrun_d;
      count_q      <= count_d;
    end
  end

  assign step_o    = step_q;
  assign dir_o     = dir_q;
  assign busy_o    = have_steps || step_q;
  assign overrun_o = overrun_q;
  assign pending_o = pend_q;
  assign count_o   = count_q;

endmodule
