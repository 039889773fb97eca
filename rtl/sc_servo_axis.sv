// sc_servo_axis: one closed-loop axis.
//
//   sc_profile_exec --P*,V*--> sc_neuron_pi --u--> sc_step_nco --> sc_step_gen --> STEP/DIR
//   encoder A/B --> sc_quad_decoder --P--^
//
// closed_loop_i = 0 runs the open-loop path of sc_axis_core (executor carry
// -> step generator) through the same pins, for comparison.
// Closed loop: done_o = in position (|P - L| <= window for the hold time)
// and no pulse owed. A following-error fault stops the controller (u = 0),
// aborts the reference, latches fault_ferr_o and keeps every count.
// All control and configuration inputs are registered first (one clock of
// latency); the encoder inputs go through the decoder's synchronisers.
module sc_servo_axis (
  input  logic                                clk_i,
  input  logic                                rst_ni,

  input  logic                                enable_i,
  input  logic                                closed_loop_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_high_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_low_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_setup_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_hold_i,

  input  logic                                seg_we_i,
  input  logic [sc_pkg::SegIdxW-1:0]          seg_waddr_i,
  input  logic [sc_pkg::PhaseW-1:0]           seg_phase_i,
  input  logic [sc_pkg::SegClkW-1:0]          seg_clocks_i,
  input  logic signed [sc_pkg::JerkW-1:0]     seg_jerk_i,
  input  logic signed [sc_pkg::AccW-1:0]      seg_acc0_i,
  input  logic signed [sc_pkg::VelW-1:0]      seg_vel0_i,
  input  logic [sc_pkg::SegCntW-1:0]          seg_count_i,
  input  logic [sc_pkg::FracBits-1:0]         pos_frac0_i,
  input  logic                                start_i,
  input  logic                                abort_i,

  input  logic                                enc_a_i,
  input  logic                                enc_b_i,

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
  output logic                                fault_ferr_o,
  output logic                                in_pos_o,
  output logic signed [sc_pkg::PosIntW-1:0]   pulse_count_o,
  output logic signed [sc_pkg::EncCntW-1:0]   enc_pos_o,
  output logic [sc_pkg::EncIllW-1:0]          enc_illegal_o,

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
  output logic signed [sc_pkg::PendW-1:0]     step_pending_o
);

  localparam int PulseTimeW = sc_pkg::PulseTimeW;
  localparam int SegCntW    = sc_pkg::SegCntW;
  localparam int FracBits   = sc_pkg::FracBits;
  localparam int PhaseW     = sc_pkg::PhaseW;
  localparam int VelW       = sc_pkg::VelW;
  localparam int MulAW      = sc_pkg::MulAW;
  localparam int CtlFrac    = sc_pkg::CtlFrac;
  localparam int CtlW       = sc_pkg::CtlW;

  // ---- registered inputs ---------------------------------------------------
  logic                   en_q, closed_q, start_q, abort_q;
  logic [PulseTimeW-1:0]  cfg_high_q, cfg_low_q, cfg_setup_q, cfg_hold_q;
  logic [SegCntW-1:0]     seg_count_q;
  logic [FracBits-1:0]    pos_frac0_q;
  logic [sc_pkg::CtlCfgW-1:0] ctl_cfg_q;

  // ---- internal ------------------------------------------------------------
  logic                   exec_running, exec_finished, exec_fault;
  logic                   exec_step_req, exec_step_fwd;
  logic [PhaseW-1:0]      exec_phase;
  logic [FracBits-1:0]    exec_frac;
  logic signed [VelW-1:0] exec_vel;
  logic                   sg_busy, start_ok, exec_abort;
  logic                   ctl_active, ctl_in_pos, ctl_ferr;
  logic signed [CtlW-1:0] ctl_u;
  logic                   nco_req, nco_fwd;
  logic                   sg_req, sg_fwd;
  logic signed [MulAW-1:0] ref_vel_q31;
  logic                   sg_hint_valid, sg_hint;
  logic signed [sc_pkg::AccW-1:0]  unused_acc;
  logic signed [sc_pkg::JerkW-1:0] unused_jerk;
  logic [sc_pkg::SegIdxW-1:0]      unused_seg_idx;
  logic                   unused_enc_a, unused_enc_b;
  logic [FracBits-MulAW-1:0] unused_frac_lo;

  assign busy_o      = exec_running || exec_step_req || sg_busy || ctl_active || nco_req;
  assign start_ok    = start_q && !busy_o && en_q;
  assign exec_abort  = abort_q || ctl_ferr;
  assign ref_vel_q31 = exec_vel[VelW-1 -: MulAW];
  assign sg_req      = closed_q ? nco_req : exec_step_req;
  assign sg_fwd      = closed_q ? nco_fwd : exec_step_fwd;
  // DIR is pre-positioned to the commanded direction while no step is owed.
  assign sg_hint_valid = closed_q ? (ctl_active && ctl_u != '0) : (exec_running && exec_vel != '0);
  assign sg_hint       = closed_q ? !ctl_u[CtlW-1] : !exec_vel[VelW-1];
  assign unused_frac_lo = exec_frac[FracBits-MulAW-1:0];

  sc_profile_exec u_exec (
    .clk_i,
    .rst_ni,
    .seg_we_i,
    .seg_waddr_i,
    .seg_phase_i,
    .seg_clocks_i,
    .seg_jerk_i,
    .seg_acc0_i,
    .seg_vel0_i,
    .seg_count_i (seg_count_q),
    .pos_frac0_i (pos_frac0_q),
    .start_i     (start_ok),
    .abort_i     (exec_abort),
    .running_o   (exec_running),
    .finished_o  (exec_finished),
    .fault_o     (exec_fault),
    .step_req_o  (exec_step_req),
    .step_fwd_o  (exec_step_fwd),
    .pos_int_o   (ref_pos_int_o),
    .pos_frac_o  (exec_frac),
    .vel_o       (exec_vel),
    .acc_o       (unused_acc),
    .jerk_o      (unused_jerk),
    .phase_o     (exec_phase),
    .seg_idx_o   (unused_seg_idx)
  );

  sc_quad_decoder u_dec (
    .clk_i,
    .rst_ni,
    .enc_a_i,
    .enc_b_i,
    .cfg_filt_i (ctl_cfg_q[sc_pkg::CtlCfgEncFiltLsb +: sc_pkg::CtlCfgEncFiltW]),
    .count_o    (enc_pos_o),
    .illegal_o  (enc_illegal_o),
    .a_o        (unused_enc_a),
    .b_o        (unused_enc_b)
  );

  logic [sc_pkg::CtlDivW+(1<<sc_pkg::EncShiftW)-2:0] div_sh;  // div << shift

  sc_neuron_pi u_ctl (
    .clk_i,
    .rst_ni,
    .ctl_cfg_i         (ctl_cfg_q),
    .start_i           (start_ok && closed_q),
    .stop_i            (abort_q),
    .ref_int_i         (ref_pos_int_o),
    .ref_frac_i        (exec_frac[FracBits-1 -: CtlFrac]),
    .ref_vel_i         (ref_vel_q31),
    .ref_done_i        (exec_finished),
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
    .load_i      (start_ok),
    .run_i       (ctl_active),
    .u_i         (ctl_u),
    .step_req_o  (nco_req),
    .step_fwd_o  (nco_fwd),
    .phase_o     (nco_phase_o)
  );

  sc_step_gen u_step_gen (
    .clk_i,
    .rst_ni,
    .cfg_high_i  (cfg_high_q),
    .cfg_low_i   (cfg_low_q),
    .cfg_setup_i (cfg_setup_q),
    .cfg_hold_i  (cfg_hold_q),
    .clear_i     (start_ok),
    .step_req_i  (sg_req),
    .step_fwd_i  (sg_fwd),
    .dir_hint_valid_i (sg_hint_valid),
    .dir_hint_i  (sg_hint),
    .step_o,
    .dir_o,
    .busy_o      (sg_busy),
    .overrun_o   (fault_overrun_o),
    .pending_o   (step_pending_o),
    .count_o     (pulse_count_o)
  );

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      en_q          <= 1'b0;
      closed_q      <= 1'b0;
      start_q       <= 1'b0;
      abort_q       <= 1'b0;
      cfg_high_q    <= '0;
      cfg_low_q     <= '0;
      cfg_setup_q   <= '0;
      cfg_hold_q    <= '0;
      seg_count_q   <= '0;
      pos_frac0_q   <= '0;
      ctl_cfg_q     <= '0;
    end else begin
      en_q          <= enable_i;
      closed_q      <= closed_loop_i;
      start_q       <= start_i;
      abort_q       <= abort_i;
      cfg_high_q    <= cfg_high_i;
      cfg_low_q     <= cfg_low_i;
      cfg_setup_q   <= cfg_setup_i;
      cfg_hold_q    <= cfg_hold_i;
      seg_count_q   <= seg_count_i;
      pos_frac0_q   <= pos_frac0_i;
      ctl_cfg_q     <= ctl_cfg_i;
    end
  end

  assign en_o          = en_q;
  assign done_o        = closed_q ? (ctl_in_pos && !busy_o) : (exec_finished && !busy_o);
  assign phase_o       = ctl_ferr ? sc_pkg::PhFault : done_o ? sc_pkg::PhDone : exec_phase;
  assign fault_table_o = exec_fault;
  assign fault_ferr_o  = ctl_ferr;
  assign in_pos_o      = ctl_in_pos;
  assign ref_frac_hi_o = exec_frac[FracBits-1 -: MulAW];
  assign ref_vel_o     = ref_vel_q31;
  assign ref_done_o    = exec_finished;
  assign ctl_active_o  = ctl_active;
  assign u_o           = ctl_u;

endmodule
