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
  // replication, not '1: yosys 0.23 reads a '1 localparam initialiser as 1
  localparam logic [PulseTimeW-1:0] CntMax = {PulseTimeW{1'b1}};
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

`ifdef FORMAL
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // Input contract: reset in the first clock only; the four timing values
  // constant for the whole proof, cfg_high_i and cfg_low_i >= 1. The other
  // inputs are free. Shadow flops (f_*) observe the pins; the properties are
  // stated on the pins, the inv_* assertions tie the shadows to the internal
  // counters so that induction closes (k = 2).
  localparam int FHiW = PulseTimeW + 1;   // one bit more: a too-long pulse cannot wrap

  logic                      f_init_q = 1'b1;  // the first clock of every trace
  logic                      f_step_prev_q, f_dir_prev_q, f_req_prev_q, f_fwd_prev_q;
  logic                      f_clear_prev_q, f_overrun_prev_q;
  logic [FHiW-1:0]           f_hi_q;        // clocks STEP was high before this one, this pulse
  logic [PulseTimeW-1:0]     f_lo_q;        // clocks STEP was low before this one (saturating)
  logic [PulseTimeW-1:0]     f_dir_age_q;   // clocks DIR held its value before this one
  logic [PulseTimeW-1:0]     f_rise_age_q;  // clocks since the last STEP rising edge
  logic signed [PendW-1:0]   f_pend_prev_q;
  logic signed [PosIntW-1:0] f_count_prev_q;
  logic [PulseTimeW-1:0]     f_high_q, f_low_q, f_setup_q, f_hold_q;

  logic                      f_rise, f_fall, f_dir_chg;
  logic signed [PendW+1:0]   f_pend_exp;    // pending after this clock's rise, before the request
  logic signed [PendW+1:0]   f_pend_req;    // ... and with the last clock's request added
  logic                      f_req_fits;
  logic signed [PosIntW-1:0] f_count_exp;

  // Queue bound: with requests at least f_gap_min clocks apart, an owed step
  // is taken (its rise decided) before the next request comes. f_rem: the
  // clocks until the generator can decide the rise, from its counters (the
  // worst direction when nothing is owed).
  localparam int FW = PulseTimeW + 3;
  logic [FW-1:0]             f_gap_q;       // clocks since the last request (saturating)
  logic                      f_last_fwd_q;  // direction of the last request
  logic [FW-1:0]             f_gap_min, f_lo_wait, f_setup_wait, f_flip_wait, f_rem;

  // Drain: an owed step is taken within f_take_max clocks of the last rising
  // edge or request. With no request, the at most 8 owed steps are all taken
  // and STEP is low within 8 x f_take_max + cfg_high clocks (with
  // sc_axis_core's p_abort_2: the e-stop's bound).
  logic [FW-1:0]             f_event_q;     // clocks since the last rise or request (saturating)
  logic [FW-1:0]             f_take_max;

  assign f_rise    = step_q && !f_step_prev_q;
  assign f_fall    = !step_q && f_step_prev_q;
  assign f_dir_chg = dir_q != f_dir_prev_q;

  // input contract
  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
      a_cfg_stable: assume (cfg_high_i == f_high_q && cfg_low_i == f_low_q &&
                            cfg_setup_i == f_setup_q && cfg_hold_i == f_hold_q);
    end
    a_cfg_min: assume (cfg_high_i != '0 && cfg_low_i != '0);
    // the rate contract of the overrun group only (formal.py drops it elsewhere)
    a_rate_gap: assume (!step_req_i || f_gap_q >= f_gap_min);
  end

  always_ff @(posedge clk_i) begin
    f_init_q  <= 1'b0;
    f_high_q  <= cfg_high_i;
    f_low_q   <= cfg_low_i;
    f_setup_q <= cfg_setup_i;
    f_hold_q  <= cfg_hold_i;
    if (!rst_ni) begin
      f_step_prev_q    <= 1'b0;
      f_dir_prev_q     <= 1'b1;
      f_req_prev_q     <= 1'b0;
      f_fwd_prev_q     <= 1'b0;
      f_clear_prev_q   <= 1'b0;
      f_overrun_prev_q <= 1'b0;
      f_hi_q           <= '0;
      f_lo_q           <= CntMax;
      f_dir_age_q      <= CntMax;
      f_rise_age_q     <= CntMax;
      f_pend_prev_q    <= '0;
      f_count_prev_q   <= '0;
    end else begin
      f_step_prev_q    <= step_o;
      f_dir_prev_q     <= dir_o;
      f_req_prev_q     <= step_req_i;
      f_fwd_prev_q     <= step_fwd_i;
      f_clear_prev_q   <= clear_i;
      f_overrun_prev_q <= overrun_o;
      f_hi_q           <= step_o ? f_hi_q + FHiW'(1) : '0;
      f_lo_q           <= step_o ? '0 : sat_inc(f_lo_q);
      f_dir_age_q      <= f_dir_chg ? PulseTimeW'(1) : sat_inc(f_dir_age_q);
      f_rise_age_q     <= f_rise ? PulseTimeW'(1) : sat_inc(f_rise_age_q);
      f_pend_prev_q    <= pending_o;
      f_count_prev_q   <= count_o;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni || step_req_i || rise) begin
      f_event_q <= FW'(1);
    end else if (f_event_q != '1) begin
      f_event_q <= f_event_q + FW'(1);
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      f_gap_q      <= '1;
      f_last_fwd_q <= 1'b1;
    end else if (step_req_i) begin
      f_gap_q      <= FW'(1);
      f_last_fwd_q <= step_fwd_i;
    end else if (f_gap_q != '1) begin
      f_gap_q      <= f_gap_q + FW'(1);
    end
  end

  function automatic logic [FW-1:0] f_sub0(input logic [FW-1:0] a, input logic [FW-1:0] b);
    f_sub0 = (a > b) ? a - b : '0;
  endfunction
  function automatic logic [FW-1:0] f_max(input logic [FW-1:0] a, input logic [FW-1:0] b);
    f_max = (a > b) ? a : b;
  endfunction

  always_comb begin
    f_gap_min    = FW'(cfg_high_i) + FW'(cfg_low_i) + FW'(cfg_setup_i) + FW'(cfg_hold_i) + FW'(1);
    // STEP low long enough
    f_lo_wait    = step_q ? FW'(high_left_q) + FW'(cfg_low_i) - FW'(1) : f_sub0(FW'(cfg_low_i), FW'(low_cnt_q));
    // DIR held long enough (right direction)
    f_setup_wait = f_sub0(FW'(cfg_setup_i), FW'(since_dir_q));
    // wrong direction: the flip waits for STEP low and the hold time, then the setup time
    f_flip_wait  = f_max(step_q ? FW'(high_left_q) : '0, f_sub0(FW'(cfg_hold_i), FW'(since_rise_q))) +
                   f_max(FW'(cfg_setup_i), FW'(1));
    f_rem        = (pend_q == '0 || !dir_ok) ? f_max(f_flip_wait, f_lo_wait) : f_max(f_lo_wait, f_setup_wait);
    // the worst f_rem (DIR to turn: high or hold, then setup; or high, then low), and one clock
    f_take_max   = f_max(FW'(cfg_high_i), FW'(cfg_hold_i)) + f_max(FW'(cfg_setup_i), FW'(1)) +
                   FW'(cfg_high_i) + FW'(cfg_low_i);
  end

  // expected queue and count after this clock, from the pins of the last one
  always_comb begin
    f_pend_exp = (PendW+2)'(f_pend_prev_q);
    if (f_rise) f_pend_exp = dir_o ? f_pend_exp - (PendW+2)'(1) : f_pend_exp + (PendW+2)'(1);
    f_pend_req = f_pend_exp;
    if (f_req_prev_q) f_pend_req = f_fwd_prev_q ? f_pend_exp + (PendW+2)'(1) : f_pend_exp - (PendW+2)'(1);
    f_req_fits = f_pend_req <= (PendW+2)'(PendMax) && f_pend_req >= (PendW+2)'(PendMin);
    f_count_exp = f_count_prev_q;
    if (f_rise) f_count_exp = dir_o ? f_count_prev_q + PosIntW'(1) : f_count_prev_q - PosIntW'(1);
    if (f_clear_prev_q) f_count_exp = '0;
  end

  always_comb begin
    if (!f_init_q) begin
      // -- group pulse_timing: STEP high exactly cfg_high clocks, low >= cfg_low clocks
      p_high_not_longer: assert (!step_o || f_hi_q < FHiW'(cfg_high_i));
      p_high_not_shorter: assert (!f_fall || f_hi_q == FHiW'(cfg_high_i));
      p_low_min: assert (!f_rise || f_lo_q >= cfg_low_i);
      // -- group dir_timing: DIR changes only with STEP low, cfg_hold clocks after
      // a rising edge at the earliest, and then holds cfg_setup clocks before the next
      p_dir_step_low: assert (!f_dir_chg || (!step_o && !f_step_prev_q));
      p_dir_hold: assert (!f_dir_chg || f_rise_age_q >= cfg_hold_i);
      p_dir_setup: assert (!f_rise || (!f_dir_chg && f_dir_age_q >= cfg_setup_i));
      // -- group count: every rising edge is a step owed in the DIR direction;
      // count_o moves by exactly one per edge, in the DIR direction, else not
      // (clear_i zeroes it); the queue keeps every request it has room for and
      // raises overrun_o (sticky until clear_i) for one it drops
      p_step_owed: assert (!f_rise || (dir_o ? f_pend_prev_q > 0 : f_pend_prev_q < 0));
      p_count_step: assert (count_o == f_count_exp);
      p_pend_account: assert (pending_o == PendW'(f_req_prev_q && f_req_fits ? f_pend_req : f_pend_exp));
      p_overrun_flag: assert (overrun_o == (!f_clear_prev_q &&
                                           (f_overrun_prev_q || (f_req_prev_q && !f_req_fits))));
      p_busy: assert (busy_o == (pending_o != '0 || step_o));
      // -- group overrun: under a_rate_gap the queue holds at most one step,
      // of the last request's direction, taken before the next request: no overrun
      p_no_overrun: assert (!overrun_o);
      inv_queue_one: assert (pending_o == '0 ||
                             pending_o == (f_last_fwd_q ? PendW'(1) : {PendW{1'b1}}));
      inv_queue_deadline: assert (pending_o == '0 ||
                                  (FW+1)'(f_gap_q) + (FW+1)'(f_rem) <= (FW+1)'(f_gap_min));
      // -- group drain: an owed step is taken within f_take_max clocks of the
      // last rise or request; why: the clocks still needed fall by one per clock
      p_take_within: assert (pending_o == '0 || f_event_q <= f_take_max);
      inv_take_deadline: assert (pending_o == '0 ||
                                 (FW+1)'(f_event_q) + (FW+1)'(f_rem) <= (FW+1)'(f_take_max));
      // -- helper invariants (internal counters against the pin shadows)
      inv_high: assert (step_q ? (f_hi_q < FHiW'(cfg_high_i) && high_left_q != '0 &&
                                  FHiW'(high_left_q) == FHiW'(cfg_high_i) - f_hi_q)
                               : f_hi_q == (f_step_prev_q ? FHiW'(cfg_high_i) : '0));
      inv_low: assert (low_cnt_q == (step_q ? '0 : sat_inc(f_lo_q)));
      inv_prev: assert (f_step_prev_q == (f_lo_q == '0) && f_step_prev_q == (f_hi_q != '0));
      inv_dir_age: assert (since_dir_q == (f_dir_chg ? PulseTimeW'(1) : sat_inc(f_dir_age_q)) &&
                           f_dir_age_q != '0);
      inv_rise_age: assert (since_rise_q == (f_rise ? PulseTimeW'(1) : sat_inc(f_rise_age_q)) &&
                            f_rise_age_q != '0);
    end
  end
`endif

endmodule
