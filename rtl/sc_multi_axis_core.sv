// sc_multi_axis_core: Axes open-loop axes (sc_axis_core) that execute one
// shared row sequence in lockstep with each other.
//
// One row push writes a multi-axis row: the shared clocks, retarget and
// push strobes, and per axis its jerk, start acceleration, start velocity,
// phase and flags. Every axis's FIFO takes it in the same clock, so the
// FIFOs hold the same rows, level and move index at all times: logically one
// FIFO of multi-axis rows (each axis keeps its copy of the clocks field).
//
// One start: a START is taken by every axis or by none (sync_start_ok: each
// axis idle, enabled and not heading into an active limit), every axis arms
// its DIR, and all executors start on the clock the last axis has its DIR
// set up (sync_go); an axis that drops its arming (STOP, abort, a limit)
// drops it on every axis. Because the rows of all axes last the same clocks,
// every axis then starts and ends every row on the same clock.
//
// One stop: a controlled stop of any axis (CMD.STOP, a limit, a
// discontinuity, a guard, an underrun) is a controlled stop of all (the
// OR of stopping_o feeds every axis's stop input, one register later on
// the others); an immediate stop of any axis (a hard limit, the step-rate
// guard) is an immediate stop of all. With each axis's STOP_JERK / STOP_ACC
// set to its share of the path's (scurve::line_stop_limits), the axes brake
// along the line they were on. Per-axis ports are flat vectors, axis a in
// bits [a*W +: W] of a W-bit field (one-dimensional: yosys 0.23 reads no
// packed arrays of vectors in ports).
//
// One row reach evaluator (sc_row_reach) serves the soft-limit look-ahead
// of every axis: the axes' requests are taken in turn (round robin from the
// axis after the last one served), so each axis's queued rows are checked
// one after the other, interleaved with the other axes' rows; a row that
// one axis refuses is loaded by none (the OR of reach_bad_o vetoes it on
// every axis). Lookahead = 0 leaves the look-ahead out (an area option).
//
// Servo = 1: every axis is a closed-loop capable sc_servo_axis (its own
// encoder, neuron-PI cascade and step NCO; closed_loop_i per axis selects
// the loop or the open-loop path through the same pins). The start, row
// and stop synchronisation is the same; a following-error fault of one axis
// stops all: under control with CL_CFG.FERR_STOP (its stopping_o), else
// at once (its fault_abort_o). Servo = 0: the loop ports are unused and
// their outputs 0.
module sc_multi_axis_core #(
  parameter int Axes  = 2,
  parameter bit Servo = 1'b0,
  // 0: no soft-limit look-ahead (an area option, sc_profile_exec): no
  // evaluator, the soft-limit window only the register tops' reactive limit
  parameter bit Lookahead = 1'b1
) (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,

  input  logic                                   enable_i,
  input  logic [Axes*sc_pkg::PulseTimeW-1:0] cfg_high_i,
  input  logic [Axes*sc_pkg::PulseTimeW-1:0] cfg_low_i,
  input  logic [Axes*sc_pkg::PulseTimeW-1:0] cfg_setup_i,
  input  logic [Axes*sc_pkg::PulseTimeW-1:0] cfg_hold_i,

  input  logic                                   row_push_i,
  input  logic                                   row_replace_i,
  input  logic [sc_pkg::RowCountW-1:0]           retarget_row_i,
  input  logic [sc_pkg::SegClkW-1:0]             row_clocks_i,
  input  logic [Axes*sc_pkg::RowFlagW-1:0] row_flags_i,
  input  logic [Axes*sc_pkg::PhaseW-1:0] row_phase_i,
  input  logic [Axes*sc_pkg::JerkW-1:0] row_jerk_i,
  input  logic [Axes*sc_pkg::AccW-1:0] row_acc0_i,
  input  logic [Axes*sc_pkg::VelW-1:0] row_vel0_i,
  input  logic                                   fifo_flush_i,
  input  logic [Axes*sc_pkg::FracBits-1:0] pos_frac0_i,
  input  logic                                   start_i,
  input  logic                                   abort_i,
  input  logic                                   stop_i,
  input  logic [Axes*sc_pkg::JerkW-1:0] stop_jerk_i,
  input  logic [Axes*sc_pkg::AccW-1:0] stop_acc_i,
  input  logic [Axes*sc_pkg::VelW-1:0] guard_vel_i,
  input  logic [Axes*sc_pkg::AccW-1:0] guard_acc_i,
  input  logic [Axes*sc_pkg::JerkW-1:0] guard_jerk_i,
  input  logic [Axes-1:0]                        soft_en_i,
  input  logic [Axes*sc_pkg::PosIntW-1:0] soft_min_i,
  input  logic [Axes*sc_pkg::PosIntW-1:0] soft_max_i,
  input  logic [Axes-1:0]                        lim_fwd_i,
  input  logic [Axes-1:0]                        lim_rev_i,
  input  logic [Axes-1:0]                        lim_hard_i,

  output logic [Axes-1:0]                        step_o,
  output logic [Axes-1:0]                        dir_o,
  output logic [Axes-1:0]                        en_o,
  output logic [Axes-1:0]                        busy_o,
  output logic [Axes-1:0]                        done_o,
  output logic [Axes*sc_pkg::PhaseW-1:0] phase_o,
  output logic [Axes-1:0]                        fault_table_o,
  output logic [Axes-1:0]                        fault_overrun_o,
  output logic [Axes-1:0]                        underrun_o,
  output logic [Axes-1:0]                        discont_o,
  output logic [Axes-1:0]                        guard_o,
  output logic [Axes-1:0]                        reach_o,
  output logic [Axes-1:0]                        stopping_o,
  output logic [Axes-1:0]                        overshoot_o,
  output logic [Axes-1:0]                        move_done_o,
  output logic [Axes*sc_pkg::MoveIdxW-1:0] move_idx_o,
  output logic [Axes*sc_pkg::PosIntW-1:0] boundary_pos_o,
  output logic [Axes*sc_pkg::RowLevelW-1:0] fifo_level_o,
  output logic [Axes*sc_pkg::RowCountW-1:0] row_count_o,
  output logic [Axes-1:0]                        retarget_refused_o,
  output logic [Axes-1:0]                        fifo_full_o,
  output logic [Axes*sc_pkg::PosIntW-1:0] pulse_count_o,
  output logic [Axes-1:0]                        lim_trip_fwd_o,
  output logic [Axes-1:0]                        lim_trip_rev_o,
  output logic [Axes*sc_pkg::PosIntW-1:0] ref_pos_int_o,
  output logic [Axes*sc_pkg::FracBits-1:0] ref_pos_frac_o,
  output logic [Axes*sc_pkg::VelW-1:0] ref_vel_o,
  output logic [Axes*sc_pkg::AccW-1:0] ref_acc_o,
  output logic [Axes*sc_pkg::JerkW-1:0] ref_jerk_o,
  output logic [Axes*sc_pkg::SegIdxW-1:0] seg_idx_o,
  output logic [Axes*sc_pkg::PendW-1:0] step_pending_o,

  // closed loop per axis (Servo = 1)
  input  logic [Axes-1:0]                        closed_loop_i,
  input  logic [Axes*sc_pkg::CtlCfgW-1:0]        ctl_cfg_i,
  input  logic [Axes-1:0]                        enc_a_i,
  input  logic [Axes-1:0]                        enc_b_i,
  input  logic [Axes-1:0]                        enc_z_i,
  output logic [Axes-1:0]                        fault_ferr_o,
  output logic [Axes-1:0]                        in_pos_o,
  output logic [Axes*sc_pkg::EncCntW-1:0]        enc_pos_o,
  output logic [Axes*sc_pkg::EncIllW-1:0]        enc_illegal_o,
  output logic [Axes-1:0]                        enc_index_o,
  output logic [Axes-1:0]                        ctl_active_o,
  output logic [Axes*sc_pkg::CtlStW-1:0]         ctl_state_o,
  output logic [Axes*sc_pkg::CtlW-1:0]           u_o,
  output logic [Axes*sc_pkg::CtlW-1:0]           v_cmd_o,
  output logic [Axes*sc_pkg::CtlW-1:0]           e_p_o,
  output logic [Axes*sc_pkg::CtlW-1:0]           e_v_o,
  output logic [Axes*sc_pkg::WgtW-1:0]           w_p1_o,
  output logic [Axes*sc_pkg::WgtW-1:0]           w_p2_o,
  output logic [Axes*sc_pkg::WgtW-1:0]           w_v1_o,
  output logic [Axes*sc_pkg::WgtW-1:0]           w_v2_o,
  output logic [Axes*sc_pkg::NcoW-1:0]           nco_phase_o
);

`ifndef SYNTHESIS
  initial begin
    if (Axes < 1 || Axes > sc_pkg::MaxAxes) $fatal(1, "sc_multi_axis_core: Axes=%0d is not 1 .. MaxAxes", Axes);
  end
`endif

  logic [Axes-1:0] start_able, arm_ready, arm_drop, fault_abort, arming, exec_start, reach_bad;
  logic            sync_start_ok, sync_go, sync_drop, reach_veto, stop_all, abort_all;

  // ---- the shared row reach evaluator --------------------------------------
  localparam int OwnerW = Axes > 1 ? $clog2(Axes) : 1;
  logic [Axes-1:0]                    rc_start, rc_abort, rc_done_to;
  logic [Axes*sc_pkg::SegClkW-1:0]    rc_clocks;
  logic [Axes*sc_pkg::JerkW-1:0]      rc_jerk;
  logic [Axes*sc_pkg::AccW-1:0]       rc_acc0;
  logic [Axes*sc_pkg::VelW-1:0]       rc_vel0;
  logic [OwnerW-1:0]                  owner_q, owner_d, grant;
  logic                               granted, ev_busy, ev_done;
  logic signed [sc_pkg::ReachW-1:0]   ev_fwd, ev_rev;

  if (Lookahead) begin : g_reach
    // While idle: the first requesting axis after the last one served.
    logic [OwnerW-1:0] cand;
    always_comb begin
      grant   = owner_q;
      granted = 1'b0;
      cand    = '0;
      for (int unsigned i = 1; i <= Axes; i++) begin
        cand = OwnerW'((32'(owner_q) + i) % Axes);
        if (!granted && rc_start[cand]) begin
          grant   = cand;
          granted = 1'b1;
        end
      end
      owner_d = (!ev_busy && granted) ? grant : owner_q;
    end

    sc_row_reach u_reach (
      .clk_i,
      .rst_ni,
      .start_i     (!ev_busy && granted),
      .abort_i     (ev_busy && rc_abort[owner_q]),
      .clocks_i    (rc_clocks[grant*sc_pkg::SegClkW +: sc_pkg::SegClkW]),
      .jerk_i      (rc_jerk[grant*sc_pkg::JerkW +: sc_pkg::JerkW]),
      .acc0_i      (rc_acc0[grant*sc_pkg::AccW +: sc_pkg::AccW]),
      .vel0_i      (rc_vel0[grant*sc_pkg::VelW +: sc_pkg::VelW]),
      .busy_o      (ev_busy),
      .done_o      (ev_done),
      .reach_fwd_o (ev_fwd),
      .reach_rev_o (ev_rev)
    );

    for (genvar a = 0; a < Axes; a++) begin : g_rc_done
      assign rc_done_to[a] = ev_done && owner_q == OwnerW'(a);
    end

    always_ff @(posedge clk_i) begin
      if (!rst_ni) owner_q <= OwnerW'(Axes - 1);  // axis 0 first
      else         owner_q <= owner_d;
    end
  end else begin : g_no_reach
    assign ev_busy = 1'b0;
    assign ev_done = 1'b0;
    assign ev_fwd  = '0;
    assign ev_rev  = '0;
    assign owner_q = '0;
    assign owner_d = '0;
    assign grant   = '0;
    assign granted = 1'b0;
    assign rc_done_to = '0;
    logic unused_rc;
    assign unused_rc = ^{rc_start, rc_abort, rc_clocks, rc_jerk, rc_acc0, rc_vel0, owner_q, owner_d, grant, granted,
                         ev_done};
  end

  assign sync_start_ok = &start_able;
  assign sync_go       = &arm_ready;
  assign sync_drop     = |arm_drop;
  // a row that one axis's look-ahead refuses is loaded by none: every axis
  // stops at that boundary (reach_bad_o does not depend on the veto)
  assign reach_veto    = |reach_bad;
  // stopping_o and fault_abort are register outputs: no loop through the axes
  assign stop_all      = stop_i || (|stopping_o);
  assign abort_all     = abort_i || (|fault_abort);

  for (genvar a = 0; a < Axes; a++) begin : g_axis
    if (Servo) begin : g_servo
      logic [sc_pkg::MulAW-1:0] unused_ref_frac_hi;
      logic [sc_pkg::MulAW-1:0] unused_ref_vel;
      logic                     unused_ref_done;
      logic [sc_pkg::NWgtW-1:0] unused_wn_p1, unused_wn_p2, unused_wn_v1, unused_wn_v2;

      sc_servo_axis #(
        .SyncStart (1'b1),
        .OwnReach  (1'b0),
        .Lookahead (Lookahead)
      ) u_servo (
        .clk_i,
        .rst_ni,
        .enable_i,
        .closed_loop_i    (closed_loop_i[a]),
        .cfg_high_i       (cfg_high_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .cfg_low_i        (cfg_low_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .cfg_setup_i      (cfg_setup_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .cfg_hold_i       (cfg_hold_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .row_push_i,
        .row_replace_i,
        .retarget_row_i,
        .row_flags_i      (row_flags_i[a*sc_pkg::RowFlagW +: sc_pkg::RowFlagW]),
        .row_phase_i      (row_phase_i[a*sc_pkg::PhaseW +: sc_pkg::PhaseW]),
        .row_clocks_i,
        .row_jerk_i       (row_jerk_i[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .row_acc0_i       (row_acc0_i[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .row_vel0_i       (row_vel0_i[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .fifo_flush_i,
        .pos_frac0_i      (pos_frac0_i[a*sc_pkg::FracBits +: sc_pkg::FracBits]),
        .start_i,
        .abort_i          (abort_all),
        .stop_i           (stop_all),
        .stop_jerk_i      (stop_jerk_i[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .stop_acc_i       (stop_acc_i[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .guard_vel_i      (guard_vel_i[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .guard_acc_i      (guard_acc_i[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .guard_jerk_i     (guard_jerk_i[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .soft_en_i        (soft_en_i[a]),
        .soft_min_i       (soft_min_i[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .soft_max_i       (soft_max_i[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .lim_fwd_i        (lim_fwd_i[a]),
        .lim_rev_i        (lim_rev_i[a]),
        .lim_hard_i       (lim_hard_i[a]),
        .enc_a_i          (enc_a_i[a]),
        .enc_b_i          (enc_b_i[a]),
        .enc_z_i          (enc_z_i[a]),
        .ctl_cfg_i        (ctl_cfg_i[a*sc_pkg::CtlCfgW +: sc_pkg::CtlCfgW]),
        .step_o           (step_o[a]),
        .dir_o            (dir_o[a]),
        .en_o             (en_o[a]),
        .busy_o           (busy_o[a]),
        .done_o           (done_o[a]),
        .phase_o          (phase_o[a*sc_pkg::PhaseW +: sc_pkg::PhaseW]),
        .fault_table_o    (fault_table_o[a]),
        .fault_overrun_o  (fault_overrun_o[a]),
        .underrun_o       (underrun_o[a]),
        .discont_o        (discont_o[a]),
        .guard_o          (guard_o[a]),
        .reach_o          (reach_o[a]),
        .stopping_o       (stopping_o[a]),
        .overshoot_o      (overshoot_o[a]),
        .move_done_o      (move_done_o[a]),
        .move_idx_o       (move_idx_o[a*sc_pkg::MoveIdxW +: sc_pkg::MoveIdxW]),
        .boundary_pos_o   (boundary_pos_o[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .fifo_level_o     (fifo_level_o[a*sc_pkg::RowLevelW +: sc_pkg::RowLevelW]),
        .row_count_o      (row_count_o[a*sc_pkg::RowCountW +: sc_pkg::RowCountW]),
        .retarget_refused_o (retarget_refused_o[a]),
        .fifo_full_o      (fifo_full_o[a]),
        .lim_trip_fwd_o   (lim_trip_fwd_o[a]),
        .lim_trip_rev_o   (lim_trip_rev_o[a]),
        .fault_ferr_o     (fault_ferr_o[a]),
        .in_pos_o         (in_pos_o[a]),
        .pulse_count_o    (pulse_count_o[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .enc_pos_o        (enc_pos_o[a*sc_pkg::EncCntW +: sc_pkg::EncCntW]),
        .enc_illegal_o    (enc_illegal_o[a*sc_pkg::EncIllW +: sc_pkg::EncIllW]),
        .enc_index_o      (enc_index_o[a]),
        .ref_pos_int_o    (ref_pos_int_o[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .ref_frac_hi_o    (unused_ref_frac_hi),
        .ref_vel_o        (unused_ref_vel),
        .ref_done_o       (unused_ref_done),
        .ctl_active_o     (ctl_active_o[a]),
        .ctl_state_o      (ctl_state_o[a*sc_pkg::CtlStW +: sc_pkg::CtlStW]),
        .u_o              (u_o[a*sc_pkg::CtlW +: sc_pkg::CtlW]),
        .v_cmd_o          (v_cmd_o[a*sc_pkg::CtlW +: sc_pkg::CtlW]),
        .e_p_o            (e_p_o[a*sc_pkg::CtlW +: sc_pkg::CtlW]),
        .e_v_o            (e_v_o[a*sc_pkg::CtlW +: sc_pkg::CtlW]),
        .w_p1_o           (w_p1_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]),
        .w_p2_o           (w_p2_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]),
        .w_v1_o           (w_v1_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]),
        .w_v2_o           (w_v2_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]),
        .wn_p1_o          (unused_wn_p1),
        .wn_p2_o          (unused_wn_p2),
        .wn_v1_o          (unused_wn_v1),
        .wn_v2_o          (unused_wn_v2),
        .nco_phase_o      (nco_phase_o[a*sc_pkg::NcoW +: sc_pkg::NcoW]),
        .step_pending_o   (step_pending_o[a*sc_pkg::PendW +: sc_pkg::PendW]),
        .ref_pos_frac_o   (ref_pos_frac_o[a*sc_pkg::FracBits +: sc_pkg::FracBits]),
        .ref_vel_full_o   (ref_vel_o[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .ref_acc_o        (ref_acc_o[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .ref_jerk_o       (ref_jerk_o[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .seg_idx_o        (seg_idx_o[a*sc_pkg::SegIdxW +: sc_pkg::SegIdxW]),
        .sync_start_ok_i  (sync_start_ok),
        .sync_go_i        (sync_go),
        .sync_drop_i      (sync_drop),
        .sync_reach_veto_i (reach_veto),
        .reach_bad_o      (reach_bad[a]),
        .start_able_o     (start_able[a]),
        .arm_ready_o      (arm_ready[a]),
        .arm_drop_o       (arm_drop[a]),
        .fault_abort_o    (fault_abort[a]),
        .arming_o         (arming[a]),
        .exec_start_o     (exec_start[a]),
        .rc_start_o       (rc_start[a]),
        .rc_abort_o       (rc_abort[a]),
        .rc_clocks_o      (rc_clocks[a*sc_pkg::SegClkW +: sc_pkg::SegClkW]),
        .rc_jerk_o        (rc_jerk[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .rc_acc0_o        (rc_acc0[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .rc_vel0_o        (rc_vel0[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .rc_busy_i        (ev_busy),
        .rc_done_i        (rc_done_to[a]),
        .rc_fwd_i         (ev_fwd),
        .rc_rev_i         (ev_rev)
      );
    end else begin : g_open
      logic unused_abort, unused_ref_done, unused_ref_running, unused_step_busy;

      sc_axis_core #(
        .ExtStep   (1'b0),
        .SyncStart (1'b1),
        .OwnReach  (1'b0),
        .Lookahead (Lookahead)
      ) u_core (
        .clk_i,
        .rst_ni,
        .enable_i,
        .cfg_high_i       (cfg_high_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .cfg_low_i        (cfg_low_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .cfg_setup_i      (cfg_setup_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .cfg_hold_i       (cfg_hold_i[a*sc_pkg::PulseTimeW +: sc_pkg::PulseTimeW]),
        .row_push_i,
        .row_replace_i,
        .retarget_row_i,
        .row_flags_i      (row_flags_i[a*sc_pkg::RowFlagW +: sc_pkg::RowFlagW]),
        .row_phase_i      (row_phase_i[a*sc_pkg::PhaseW +: sc_pkg::PhaseW]),
        .row_clocks_i,
        .row_jerk_i       (row_jerk_i[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .row_acc0_i       (row_acc0_i[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .row_vel0_i       (row_vel0_i[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .fifo_flush_i,
        .pos_frac0_i      (pos_frac0_i[a*sc_pkg::FracBits +: sc_pkg::FracBits]),
        .start_i,
        .abort_i          (abort_all),
        .stop_i           (stop_all),
        .stop_jerk_i      (stop_jerk_i[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .stop_acc_i       (stop_acc_i[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .guard_vel_i      (guard_vel_i[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .guard_acc_i      (guard_acc_i[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .guard_jerk_i     (guard_jerk_i[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .soft_en_i        (soft_en_i[a]),
        .soft_min_i       (soft_min_i[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .soft_max_i       (soft_max_i[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .lim_fwd_i        (lim_fwd_i[a]),
        .lim_rev_i        (lim_rev_i[a]),
        .lim_hard_i       (lim_hard_i[a]),
        .ext_sel_i        (1'b0),
        .ext_req_i        (1'b0),
        .ext_fwd_i        (1'b0),
        .ext_hint_valid_i (1'b0),
        .ext_hint_i       (1'b0),
        .ext_busy_i       (1'b0),
        .ext_abort_i      (1'b0),
        .ext_done_i       (1'b0),
        .sync_start_ok_i  (sync_start_ok),
        .sync_go_i        (sync_go),
        .sync_drop_i      (sync_drop),
        .sync_reach_veto_i (reach_veto),
        .reach_bad_o      (reach_bad[a]),
        .start_able_o     (start_able[a]),
        .arm_ready_o      (arm_ready[a]),
        .arm_drop_o       (arm_drop[a]),
        .fault_abort_o    (fault_abort[a]),
        .arming_o         (arming[a]),
        .exec_start_o     (exec_start[a]),
        .abort_o          (unused_abort),
        .ref_done_o       (unused_ref_done),
        .ref_running_o    (unused_ref_running),
        .step_busy_o      (unused_step_busy),
        .lim_trip_fwd_o   (lim_trip_fwd_o[a]),
        .lim_trip_rev_o   (lim_trip_rev_o[a]),
        .step_o           (step_o[a]),
        .dir_o            (dir_o[a]),
        .en_o             (en_o[a]),
        .busy_o           (busy_o[a]),
        .done_o           (done_o[a]),
        .phase_o          (phase_o[a*sc_pkg::PhaseW +: sc_pkg::PhaseW]),
        .fault_table_o    (fault_table_o[a]),
        .fault_overrun_o  (fault_overrun_o[a]),
        .underrun_o       (underrun_o[a]),
        .discont_o        (discont_o[a]),
        .guard_o          (guard_o[a]),
        .reach_o          (reach_o[a]),
        .stopping_o       (stopping_o[a]),
        .overshoot_o      (overshoot_o[a]),
        .move_done_o      (move_done_o[a]),
        .move_idx_o       (move_idx_o[a*sc_pkg::MoveIdxW +: sc_pkg::MoveIdxW]),
        .boundary_pos_o   (boundary_pos_o[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .fifo_level_o     (fifo_level_o[a*sc_pkg::RowLevelW +: sc_pkg::RowLevelW]),
        .row_count_o      (row_count_o[a*sc_pkg::RowCountW +: sc_pkg::RowCountW]),
        .retarget_refused_o (retarget_refused_o[a]),
        .fifo_full_o      (fifo_full_o[a]),
        .pulse_count_o    (pulse_count_o[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .ref_pos_int_o    (ref_pos_int_o[a*sc_pkg::PosIntW +: sc_pkg::PosIntW]),
        .ref_pos_frac_o   (ref_pos_frac_o[a*sc_pkg::FracBits +: sc_pkg::FracBits]),
        .ref_vel_o        (ref_vel_o[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .ref_acc_o        (ref_acc_o[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .ref_jerk_o       (ref_jerk_o[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .seg_idx_o        (seg_idx_o[a*sc_pkg::SegIdxW +: sc_pkg::SegIdxW]),
        .step_pending_o   (step_pending_o[a*sc_pkg::PendW +: sc_pkg::PendW]),
        .rc_start_o       (rc_start[a]),
        .rc_abort_o       (rc_abort[a]),
        .rc_clocks_o      (rc_clocks[a*sc_pkg::SegClkW +: sc_pkg::SegClkW]),
        .rc_jerk_o        (rc_jerk[a*sc_pkg::JerkW +: sc_pkg::JerkW]),
        .rc_acc0_o        (rc_acc0[a*sc_pkg::AccW +: sc_pkg::AccW]),
        .rc_vel0_o        (rc_vel0[a*sc_pkg::VelW +: sc_pkg::VelW]),
        .rc_busy_i        (ev_busy),
        .rc_done_i        (rc_done_to[a]),
        .rc_fwd_i         (ev_fwd),
        .rc_rev_i         (ev_rev)
      );

      // no loop: its ports unused, its outputs 0
      logic unused_loop_in;
      assign unused_loop_in = ^{closed_loop_i[a], ctl_cfg_i[a*sc_pkg::CtlCfgW +: sc_pkg::CtlCfgW],
                                enc_a_i[a], enc_b_i[a], enc_z_i[a]};
      assign fault_ferr_o[a]  = 1'b0;
      assign in_pos_o[a]      = 1'b0;
      assign enc_pos_o[a*sc_pkg::EncCntW +: sc_pkg::EncCntW]   = '0;
      assign enc_illegal_o[a*sc_pkg::EncIllW +: sc_pkg::EncIllW] = '0;
      assign enc_index_o[a]   = 1'b0;
      assign ctl_active_o[a]  = 1'b0;
      assign ctl_state_o[a*sc_pkg::CtlStW +: sc_pkg::CtlStW] = '0;
      assign u_o[a*sc_pkg::CtlW +: sc_pkg::CtlW]     = '0;
      assign v_cmd_o[a*sc_pkg::CtlW +: sc_pkg::CtlW] = '0;
      assign e_p_o[a*sc_pkg::CtlW +: sc_pkg::CtlW]   = '0;
      assign e_v_o[a*sc_pkg::CtlW +: sc_pkg::CtlW]   = '0;
      assign w_p1_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]  = '0;
      assign w_p2_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]  = '0;
      assign w_v1_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]  = '0;
      assign w_v2_o[a*sc_pkg::WgtW +: sc_pkg::WgtW]  = '0;
      assign nco_phase_o[a*sc_pkg::NcoW +: sc_pkg::NcoW] = '0;
    end
  end

`ifndef FORMAL
  logic unused_sync_state;
  assign unused_sync_state = ^{arming, exec_start};
`else
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // Proven with the axes' modules read without FORMAL. Input contract:
  // reset in the first clock only; every other input free in every clock
  // (rows per axis, START, STOP, abort, limits per axis, pulse timing per
  // axis). The start is one for all axes: every axis arms on the same
  // clock, drops its arming on the same clock and starts its executor on the
  // same clock, whatever the axes' DIR, setup times, limits and rows.
  logic f_init_q = 1'b1;

  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
    end
  end

  always_ff @(posedge clk_i) f_init_q <= 1'b0;

  always_comb begin
    if (!f_init_q) begin
      // -- group multi_sync_start
      p_arm_together:   assert (arming == '0 || arming == '1);
      p_start_together: assert (exec_start == '0 || exec_start == '1);
    end
  end
`endif

endmodule
