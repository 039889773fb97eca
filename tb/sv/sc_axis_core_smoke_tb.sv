// sc_axis_core_smoke_tb: a self-checking smoke test of the open-loop axis for
// any Verilog simulator (the FuseSoC `sim` target runs it on Icarus). Two
// moves at a stepper's start/stop speed (one row each: constant velocity of
// exactly 1/Period pulse per clock, so a move of N pulses takes N * Period
// clocks), forward then backward. A pin monitor here, independent of the
// RTL's own counters, checks every STEP pulse (high exactly PulseHigh clocks,
// low at least PulseLow, DIR steady from PulseSetup clocks before a rising
// edge to PulseHold clocks after it) and counts the steps in the DIR
// direction; each move must end done with that count, the core's
// pulse_count_o and its reference position equal to the move's distance.
// Ends with $finish on success and $fatal on the first failure.
module sc_axis_core_smoke_tb;
  localparam int FracBits   = sc_pkg::FracBits;
  localparam int Period     = 64;   // clocks per pulse
  localparam int PulseHigh  = 5;
  localparam int PulseLow   = 5;
  localparam int PulseSetup = 3;
  localparam int PulseHold  = 3;
  localparam int FwdPulses  = 100;
  localparam int RevPulses  = 37;

  logic clk = 1'b0;
  logic rst_n = 1'b0;
  always #25 clk = ~clk;  // 20 MHz

  logic                                 row_push = 1'b0;
  logic [sc_pkg::RowFlagW-1:0]          row_flags;
  logic [sc_pkg::SegClkW-1:0]           row_clocks;
  logic signed [sc_pkg::VelW-1:0]       row_vel0;
  logic                                 start = 1'b0;
  logic step, dir, en, busy, done, fifo_full;
  logic signed [sc_pkg::PosIntW-1:0]    pulse_count, ref_pos_int;
  logic [sc_pkg::FracBits-1:0]          ref_pos_frac;

  sc_axis_core #(.ExtStep(1'b0)) dut (
    .clk_i(clk), .rst_ni(rst_n),
    .enable_i(1'b1),
    .cfg_high_i(sc_pkg::PulseTimeW'(PulseHigh)), .cfg_low_i(sc_pkg::PulseTimeW'(PulseLow)),
    .cfg_setup_i(sc_pkg::PulseTimeW'(PulseSetup)), .cfg_hold_i(sc_pkg::PulseTimeW'(PulseHold)),
    .row_push_i(row_push), .row_replace_i(1'b0), .retarget_row_i('0), .row_flags_i(row_flags),
    .row_phase_i(sc_pkg::PhCruise),
    .row_clocks_i(row_clocks), .row_jerk_i('0), .row_acc0_i('0), .row_vel0_i(row_vel0),
    .fifo_flush_i(1'b0), .pos_frac0_i('0),
    .start_i(start), .abort_i(1'b0), .stop_i(1'b0),
    .stop_jerk_i(sc_pkg::JerkW'(1) << 20), .stop_acc_i(sc_pkg::AccW'(1) << 50),
    .guard_vel_i('0), .guard_acc_i('0), .guard_jerk_i('0),
    .soft_en_i(1'b0), .soft_min_i('0), .soft_max_i('0),
    .lim_fwd_i(1'b0), .lim_rev_i(1'b0), .lim_hard_i(1'b0),
    .ext_sel_i(1'b0), .ext_req_i(1'b0), .ext_fwd_i(1'b0), .ext_hint_valid_i(1'b0),
    .ext_hint_i(1'b0), .ext_busy_i(1'b0), .ext_abort_i(1'b0), .ext_done_i(1'b0),
    .sync_start_ok_i(1'b0), .sync_go_i(1'b0), .sync_drop_i(1'b0), .sync_reach_veto_i(1'b0), .reach_bad_o(),
    .start_able_o(), .arm_ready_o(), .arm_drop_o(), .fault_abort_o(), .arming_o(),
    .exec_start_o(), .abort_o(), .ref_done_o(), .ref_running_o(), .step_busy_o(),
    .lim_trip_fwd_o(), .lim_trip_rev_o(),
    .step_o(step), .dir_o(dir), .en_o(en),
    .busy_o(busy), .done_o(done), .phase_o(), .fault_table_o(), .fault_overrun_o(),
    .underrun_o(), .discont_o(), .guard_o(), .reach_o(), .stopping_o(), .overshoot_o(), .move_done_o(),
    .move_idx_o(), .boundary_pos_o(), .fifo_level_o(), .fifo_full_o(fifo_full), .row_count_o(), .retarget_refused_o(),
    .pulse_count_o(pulse_count),
    .ref_pos_int_o(ref_pos_int), .ref_pos_frac_o(ref_pos_frac), .ref_vel_o(), .ref_acc_o(),
    .ref_jerk_o(), .seg_idx_o(), .step_pending_o(),
    .rc_start_o(), .rc_abort_o(), .rc_clocks_o(), .rc_jerk_o(), .rc_acc0_o(), .rc_vel0_o(),
    .rc_busy_i(1'b0), .rc_done_i(1'b0), .rc_fwd_i('0), .rc_rev_i('0)
  );

  // ---- pin monitor ---------------------------------------------------------
  int  monitor_steps = 0;      // net steps seen on the pins, + in DIR = 1
  int  high_clocks = 0, low_clocks = PulseLow, dir_steady = PulseSetup;
  int  since_rise = PulseHold;
  logic step_q = 1'b0, dir_q = 1'b0;
  always @(posedge clk) begin
    if (rst_n) begin
      if (dir != dir_q) begin
        if (since_rise < PulseHold) $fatal(1, "DIR changed %0d clocks after a STEP edge (hold %0d)", since_rise, PulseHold);
        dir_steady = 0;
      end
      if (step && !step_q) begin
        if (low_clocks < PulseLow) $fatal(1, "STEP low for %0d clocks (minimum %0d)", low_clocks, PulseLow);
        if (dir_steady < PulseSetup) $fatal(1, "DIR steady for %0d clocks before STEP (setup %0d)", dir_steady, PulseSetup);
        monitor_steps += dir ? 1 : -1;
        since_rise = 0;
        high_clocks = 0;
      end
      if (!step && step_q) begin
        if (high_clocks != PulseHigh) $fatal(1, "STEP high for %0d clocks (want %0d)", high_clocks, PulseHigh);
        low_clocks = 0;
      end
      if (step) high_clocks++; else low_clocks++;
      if (dir == dir_q) dir_steady++;
      since_rise++;
      step_q <= step;
      dir_q  <= dir;
    end
  end

  // ---- stimulus --------------------------------------------------------------
  // One row at 1/Period pulse per clock (Period a power of two: exact).
  task automatic run_move(input int pulses, input bit forward);
    int start_steps, waited;
    logic signed [sc_pkg::VelW-1:0] vel;
    vel = sc_pkg::VelW'(1) << (FracBits - $clog2(Period));
    @(negedge clk);
    row_flags  = sc_pkg::RowFlagW'((1 << sc_pkg::RowFlagMoveEnd) | (1 << sc_pkg::RowFlagStreamEnd));
    row_clocks = sc_pkg::SegClkW'(pulses * Period);
    row_vel0   = forward ? vel : -vel;
    if (fifo_full) $fatal(1, "row FIFO full before the move");
    row_push = 1'b1;
    @(negedge clk) row_push = 1'b0;
    start = 1'b1;
    @(negedge clk) start = 1'b0;
    start_steps = monitor_steps;
    waited = 0;
    do begin
      @(negedge clk);
      waited++;
      if (waited > pulses * Period + 1000) $fatal(1, "move of %0d pulses not done after %0d clocks", pulses, waited);
    end while (!done || busy);
    if (monitor_steps - start_steps != (forward ? pulses : -pulses))
      $fatal(1, "pin monitor saw %0d steps, want %0d", monitor_steps - start_steps, forward ? pulses : -pulses);
    if (pulse_count != (forward ? pulses : -pulses))
      $fatal(1, "pulse_count_o = %0d, want %0d", pulse_count, forward ? pulses : -pulses);
    $display("move of %0s%0d pulses: done after %0d clocks, %0d steps on the pins",
             forward ? "+" : "-", pulses, waited, monitor_steps - start_steps);
  endtask

  initial begin
    repeat (4) @(negedge clk);
    rst_n = 1'b1;
    repeat (4) @(negedge clk);
    if (!en) $fatal(1, "EN low with enable_i set");
    run_move(FwdPulses, 1'b1);
    if (ref_pos_int != FwdPulses || ref_pos_frac != '0)
      $fatal(1, "reference position %0d + frac %0h after the forward move, want %0d", ref_pos_int, ref_pos_frac, FwdPulses);
    run_move(RevPulses, 1'b0);
    if (monitor_steps != FwdPulses - RevPulses)
      $fatal(1, "net steps %0d, want %0d", monitor_steps, FwdPulses - RevPulses);
    $display("PASS: sc_axis_core smoke test, net %0d steps", monitor_steps);
    $finish;
  end
endmodule
