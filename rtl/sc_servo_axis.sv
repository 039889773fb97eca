// sc_servo_axis: one closed-loop axis.
//
//   sc_axis_core (sc_profile_exec --P*,V*--> ... sc_step_gen --> STEP/DIR)
//                  |                            ^
//                  +--> sc_neuron_pi --u--> sc_step_nco (external step source)
//   encoder A/B --> sc_quad_decoder --P--^
//
// sc_axis_core does the start arming (DIR turned to the move's direction and
// held for the setup time), the step generator and done/abort, in both
// modes. closed_loop_i = 0 runs its open-loop path (executor carry -> step
// generator) through the same pins, for comparison; closed_loop_i = 1
// selects the NCO as the step source. The controller and the NCO start on
// the core's exec_start_o, i.e. together with the reference, after arming.
// Closed loop: done_o = in position (|P - L| <= window for the hold time)
// and no pulse owed. A following-error fault stops the controller (u = 0),
// aborts the reference, latches fault_ferr_o and keeps every count; the
// next closed-loop start clears it when the move begins.
// All control and configuration inputs are registered first (one clock of
// latency; the core registers its own); the encoder inputs go through the
// decoder's synchroniser.
// SyncStart = 1 makes it one axis of sc_multi_axis_core #(.Servo(1)): the
// core's start synchronisation ports (sc_axis_core) pass through.
module sc_servo_axis #(
  parameter bit SyncStart = 1'b0,
  parameter bit OwnReach  = 1'b1,  // 0: the row reach evaluator is outside (rc_*), shared
  parameter bit Lookahead = 1'b1   // 0: no soft-limit look-ahead (sc_profile_exec)
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,

  input  logic                                enable_i,
  input  logic                                closed_loop_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_high_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_low_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_setup_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_hold_i,

  input  logic                                row_push_i,
  input  logic                                row_replace_i,  // with row_push_i: replace from retarget_row_i on
  input  logic [sc_pkg::RowCountW-1:0]        retarget_row_i,
  input  logic [sc_pkg::RowFlagW-1:0]         row_flags_i,
  input  logic [sc_pkg::PhaseW-1:0]           row_phase_i,
  input  logic [sc_pkg::SegClkW-1:0]          row_clocks_i,
  input  logic signed [sc_pkg::JerkW-1:0]     row_jerk_i,
  input  logic signed [sc_pkg::AccW-1:0]      row_acc0_i,
  input  logic signed [sc_pkg::VelW-1:0]      row_vel0_i,
  input  logic                                fifo_flush_i,
  input  logic [sc_pkg::FracBits-1:0]         pos_frac0_i,
  input  logic                                start_i,
  input  logic                                abort_i,
  input  logic                                stop_i,
  input  logic [sc_pkg::JerkW-1:0]            stop_jerk_i,
  input  logic [sc_pkg::AccW-1:0]             stop_acc_i,
  input  logic [sc_pkg::VelW-1:0]             guard_vel_i, // row guard limits: sc_axis_core
  input  logic [sc_pkg::AccW-1:0]             guard_acc_i,
  input  logic [sc_pkg::JerkW-1:0]            guard_jerk_i,
  input  logic                                soft_en_i,   // soft-limit look-ahead: sc_axis_core
  input  logic signed [sc_pkg::PosIntW-1:0]   soft_min_i,
  input  logic signed [sc_pkg::PosIntW-1:0]   soft_max_i,
  input  logic                                lim_fwd_i,   // limits: sc_axis_core
  input  logic                                lim_rev_i,
  input  logic                                lim_hard_i,

  input  logic                                enc_a_i,
  input  logic                                enc_b_i,
  input  logic                                enc_z_i,     // index: to the decoder with A/B

  // controller configuration (fields: sc_pkg::CtlCfg*, docs/regmap.md)
  input  logic [sc_pkg::CtlCfgW-1:0]          ctl_cfg_i,

  output logic                                step_o,
  output logic                                dir_o,
  output logic                                en_o,

  output logic                                busy_o,
  output logic                                done_o,
  output logic [sc_pkg::PhaseW-1:0]           phase_o,
  output logic                                fault_table_o,
  output logic                                fault_overrun_o,
  output logic                                underrun_o,
  output logic                                discont_o,
  output logic                                guard_o,
  output logic                                reach_o,
  output logic                                stopping_o,
  output logic                                overshoot_o,
  output logic                                move_done_o,
  output logic [sc_pkg::MoveIdxW-1:0]         move_idx_o,
  output logic signed [sc_pkg::PosIntW-1:0]   boundary_pos_o,
  output logic [sc_pkg::RowLevelW-1:0]        fifo_level_o,
  output logic [sc_pkg::RowCountW-1:0]        row_count_o,         // rows loaded since START
  output logic                                retarget_refused_o,  // a replace was refused (one clock)
  output logic                                fifo_full_o,
  output logic                                lim_trip_fwd_o,
  output logic                                lim_trip_rev_o,
  output logic                                fault_ferr_o,
  output logic                                in_pos_o,
  output logic signed [sc_pkg::PosIntW-1:0]   pulse_count_o,
  output logic signed [sc_pkg::EncCntW-1:0]   enc_pos_o,
  output logic [sc_pkg::EncIllW-1:0]          enc_illegal_o,
  output logic                                enc_index_o, // filtered Z, in step with enc_pos_o

  output logic signed [sc_pkg::PosIntW-1:0]   ref_pos_int_o,
  output logic [sc_pkg::MulAW-1:0]            ref_frac_hi_o,  // top MulAW bits of the fraction
  output logic signed [sc_pkg::MulAW-1:0]     ref_vel_o,      // V*, Q.VffFrac pulses/clock
  output logic                                ref_done_o,

  output logic                                ctl_active_o,
  output logic [sc_pkg::CtlStW-1:0]           ctl_state_o,
  output logic signed [sc_pkg::CtlW-1:0]      u_o,
  output logic signed [sc_pkg::CtlW-1:0]      v_cmd_o,
  output logic signed [sc_pkg::CtlW-1:0]      e_p_o,
  output logic signed [sc_pkg::CtlW-1:0]      e_v_o,
  output logic signed [sc_pkg::WgtW-1:0]      w_p1_o,
  output logic signed [sc_pkg::WgtW-1:0]      w_p2_o,
  output logic signed [sc_pkg::WgtW-1:0]      w_v1_o,
  output logic signed [sc_pkg::WgtW-1:0]      w_v2_o,
  output logic signed [sc_pkg::NWgtW-1:0]     wn_p1_o,
  output logic signed [sc_pkg::NWgtW-1:0]     wn_p2_o,
  output logic signed [sc_pkg::NWgtW-1:0]     wn_v1_o,
  output logic signed [sc_pkg::NWgtW-1:0]     wn_v2_o,
  output logic signed [sc_pkg::NcoW-1:0]      nco_phase_o,
  output logic signed [sc_pkg::PendW-1:0]     step_pending_o,

  // the executor's whole state (the multi-axis core's lockstep compares it)
  output logic [sc_pkg::FracBits-1:0]         ref_pos_frac_o,
  output logic signed [sc_pkg::VelW-1:0]      ref_vel_full_o,
  output logic signed [sc_pkg::AccW-1:0]      ref_acc_o,
  output logic signed [sc_pkg::JerkW-1:0]     ref_jerk_o,
  output logic [sc_pkg::SegIdxW-1:0]          seg_idx_o,

  // start synchronisation across axes (SyncStart = 1 only; sc_axis_core)
  input  logic                                sync_start_ok_i,
  input  logic                                sync_go_i,
  input  logic                                sync_drop_i,
  input  logic                                sync_reach_veto_i,
  output logic                                reach_bad_o,
  output logic                                start_able_o,
  output logic                                arm_ready_o,
  output logic                                arm_drop_o,
  output logic                                fault_abort_o,
  output logic                                arming_o,
  output logic                                exec_start_o,

  // the row reach evaluator outside (OwnReach = 0; sc_profile_exec)
  output logic                                rc_start_o,
  output logic                                rc_abort_o,
  output logic [sc_pkg::SegClkW-1:0]          rc_clocks_o,
  output logic signed [sc_pkg::JerkW-1:0]     rc_jerk_o,
  output logic signed [sc_pkg::AccW-1:0]      rc_acc0_o,
  output logic signed [sc_pkg::VelW-1:0]      rc_vel0_o,
  input  logic                                rc_busy_i,
  input  logic                                rc_done_i,
  input  logic signed [sc_pkg::ReachW-1:0]    rc_fwd_i,
  input  logic signed [sc_pkg::ReachW-1:0]    rc_rev_i
);

  localparam int FracBits   = sc_pkg::FracBits;
  localparam int VelW       = sc_pkg::VelW;
  localparam int MulAW      = sc_pkg::MulAW;
  localparam int CtlFrac    = sc_pkg::CtlFrac;
  localparam int CtlW       = sc_pkg::CtlW;
  localparam logic signed [sc_pkg::PendW-1:0] PendMax = {1'b0, {(sc_pkg::PendW-1){1'b1}}};
  localparam logic signed [sc_pkg::PendW-1:0] PendMin = {1'b1, {(sc_pkg::PendW-1){1'b0}}};

  // ---- registered inputs ---------------------------------------------------
  logic                   closed_q;
  logic [sc_pkg::CtlCfgW-1:0] ctl_cfg_q;

  // ---- internal ------------------------------------------------------------
  logic                   exec_start, exec_finished, exec_running, core_abort, sg_busy;
  logic [sc_pkg::PhaseW-1:0] core_phase;
  logic [FracBits-1:0]    exec_frac;
  logic signed [VelW-1:0] exec_vel;
  logic                   ctl_active, ctl_in_pos, ctl_ferr;
  // A following-error fault with CL_CFG.FERR_STOP: a controlled stop of the
  // reference, held while the loop runs (the executor takes it once; gone
  // once in position, so the next START is not dropped), else an abort.
  logic                   cfg_ferr_stop, ferr_stop;
  logic signed [CtlW-1:0] ctl_u;
  logic                   nco_req, nco_fwd, nco_run, queue_near_full;
  logic signed [MulAW-1:0] ref_vel_q31;
  logic                   unused_enc_a, unused_enc_b;

  // Backpressure: the NCO holds its phase while the step queue is within one
  // step of either end (one request may still be in flight), so it never
  // requests a step the step generator cannot queue, e.g. while DIR waits
  // out the setup time after a reversal. The loop sees the delay on P.
  assign queue_near_full = step_pending_o >= (PendMax - sc_pkg::PendW'(1)) ||
                           step_pending_o <= (PendMin + sc_pkg::PendW'(1));
  assign nco_run         = ctl_active && !queue_near_full;
  assign ref_vel_q31    = exec_vel[VelW-1 -: MulAW];
  assign cfg_ferr_stop  = ctl_cfg_q[sc_pkg::CtlCfgFerrStopLsb];
  assign ferr_stop      = ctl_ferr && cfg_ferr_stop && ctl_active;

  sc_axis_core #(
    .ExtStep   (1'b1),
    .SyncStart (SyncStart),
    .OwnReach  (OwnReach),
    .Lookahead (Lookahead)
  ) u_core (
    .clk_i,
    .rst_ni,
    .enable_i,
    .cfg_high_i,
    .cfg_low_i,
    .cfg_setup_i,
    .cfg_hold_i,
    .row_push_i,
    .row_replace_i,
    .retarget_row_i,
    .row_flags_i,
    .row_phase_i,
    .row_clocks_i,
    .row_jerk_i,
    .row_acc0_i,
    .row_vel0_i,
    .fifo_flush_i,
    .pos_frac0_i,
    .start_i,
    .abort_i,
    .stop_i           (stop_i || ferr_stop),
    .stop_jerk_i,
    .stop_acc_i,
    .guard_vel_i,
    .guard_acc_i,
    .guard_jerk_i,
    .soft_en_i,
    .soft_min_i,
    .soft_max_i,
    .lim_fwd_i,
    .lim_rev_i,
    .lim_hard_i,
    .ext_sel_i        (closed_q),
    .ext_req_i        (nco_req),
    .ext_fwd_i        (nco_fwd),
    // DIR hint once the reference has stopped: the sign of the rate command
    .ext_hint_valid_i (ctl_active && ctl_u != '0),
    .ext_hint_i       (!ctl_u[CtlW-1]),
    .ext_busy_i       (ctl_active || nco_req),
    .ext_abort_i      (ctl_ferr && !cfg_ferr_stop),
    // A stream that ended in a controlled stop (STOP, underrun,
    // discontinuity, guard) is not done, as on the open-loop core: in position,
    // the axis is idle with its stop flags.
    .ext_done_i       (ctl_in_pos && exec_finished),
    .sync_start_ok_i,
    .sync_go_i,
    .sync_drop_i,
    .sync_reach_veto_i,
    .reach_bad_o,
    .start_able_o,
    .arm_ready_o,
    .arm_drop_o,
    .fault_abort_o,
    .arming_o,
    .exec_start_o     (exec_start),
    .abort_o          (core_abort),
    .ref_done_o       (exec_finished),
    .ref_running_o    (exec_running),
    .step_busy_o      (sg_busy),
    .lim_trip_fwd_o,
    .lim_trip_rev_o,
    .step_o,
    .dir_o,
    .en_o,
    .busy_o,
    .done_o,
    .phase_o          (core_phase),
    .fault_table_o,
    .fault_overrun_o,
    .underrun_o,
    .discont_o,
    .guard_o,
    .reach_o,
    .stopping_o,
    .overshoot_o,
    .move_done_o,
    .move_idx_o,
    .boundary_pos_o,
    .fifo_level_o,
    .row_count_o,
    .retarget_refused_o,
    .fifo_full_o,
    .pulse_count_o,
    .ref_pos_int_o,
    .ref_pos_frac_o   (exec_frac),
    .ref_vel_o        (exec_vel),
    .ref_acc_o,
    .ref_jerk_o,
    .seg_idx_o,
    .step_pending_o,
    .rc_start_o,
    .rc_abort_o,
    .rc_clocks_o,
    .rc_jerk_o,
    .rc_acc0_o,
    .rc_vel0_o,
    .rc_busy_i,
    .rc_done_i,
    .rc_fwd_i,
    .rc_rev_i
  );

  sc_quad_decoder u_dec (
    .clk_i,
    .rst_ni,
    .enc_a_i,
    .enc_b_i,
    .enc_z_i,
    .cfg_filt_i (ctl_cfg_q[sc_pkg::CtlCfgEncFiltLsb +: sc_pkg::CtlCfgEncFiltW]),
    .count_o    (enc_pos_o),
    .illegal_o  (enc_illegal_o),
    .a_o        (unused_enc_a),
    .b_o        (unused_enc_b),
    .z_o        (enc_index_o)
  );

  logic [sc_pkg::CtlDivW+(1<<sc_pkg::EncShiftW)-2:0] div_sh;  // div << shift

  sc_neuron_pi u_ctl (
    .clk_i,
    .rst_ni,
    .ctl_cfg_i         (ctl_cfg_q),
    .start_i           (exec_start && closed_q),
    .stop_i            (core_abort),
    .ref_int_i         (ref_pos_int_o),
    .ref_frac_i        (exec_frac[FracBits-1 -: CtlFrac]),
    .ref_vel_i         (ref_vel_q31),
    // The reference moves no more once the executor stops running: the
    // stream finished, or a controlled stop brought it to rest. Either way
    // the controller settles on the integer reference position.
    .ref_done_i        (!exec_running),
    .enc_pos_i         (enc_pos_o),
    .cmd_busy_i        (nco_req || sg_busy),
    .nco_req_i         (nco_req),
    .active_o          (ctl_active),
    .in_pos_o          (ctl_in_pos),
    .fault_ferr_o      (ctl_ferr),
    .u_o               (ctl_u),
    .v_cmd_o,
    .e_p_o,
    .e_v_o,
    .w_p1_o,
    .w_p2_o,
    .w_v1_o,
    .w_v2_o,
    .wn_p1_o,
    .wn_p2_o,
    .wn_v1_o,
    .wn_v2_o,
    .state_o           (ctl_state_o),
    .div_sh_o          (div_sh)
  );

  sc_step_nco u_nco (
    .clk_i,
    .rst_ni,
    .div_sh_i    (div_sh),
    .load_i      (exec_start),
    .run_i       (nco_run),
    .u_i         (ctl_u),
    .step_req_o  (nco_req),
    .step_fwd_o  (nco_fwd),
    .phase_o     (nco_phase_o)
  );

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      closed_q      <= 1'b0;
      ctl_cfg_q     <= '0;
    end else begin
      closed_q      <= closed_loop_i;
      ctl_cfg_q     <= ctl_cfg_i;
    end
  end

  assign phase_o       = ctl_ferr ? sc_pkg::PhFault : core_phase;
  assign fault_ferr_o  = ctl_ferr;
  assign in_pos_o      = ctl_in_pos;
  assign ref_frac_hi_o = exec_frac[FracBits-1 -: MulAW];
  assign ref_vel_o     = ref_vel_q31;
  assign ref_done_o    = exec_finished;
  assign ctl_active_o  = ctl_active;
  assign u_o           = ctl_u;
  assign ref_pos_frac_o = exec_frac;
  assign ref_vel_full_o = exec_vel;
  assign exec_start_o   = exec_start;

endmodule
