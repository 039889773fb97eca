// sc_axi_axis: one open-loop axis behind an AXI4-Lite slave
// (sc_axi_regs + sc_axis_core). This is the block a MicroBlaze/Zynq design
// or the UART bridge (sc_board_top) connects to; the testbench drives it in
// lockstep with the model (cmodel/axi_axis.h).
module sc_axi_axis (
  input  logic                                clk_i,
  input  logic                                rst_ni,

  input  logic [sc_pkg::RegAddrW-1:0]         s_axi_awaddr_i,
  input  logic                                s_axi_awvalid_i,
  output logic                                s_axi_awready_o,
  input  logic [31:0]                         s_axi_wdata_i,
  input  logic [3:0]                          s_axi_wstrb_i,
  input  logic                                s_axi_wvalid_i,
  output logic                                s_axi_wready_o,
  output logic [1:0]                          s_axi_bresp_o,
  output logic                                s_axi_bvalid_o,
  input  logic                                s_axi_bready_i,
  input  logic [sc_pkg::RegAddrW-1:0]         s_axi_araddr_i,
  input  logic                                s_axi_arvalid_i,
  output logic                                s_axi_arready_o,
  output logic [31:0]                         s_axi_rdata_o,
  output logic [1:0]                          s_axi_rresp_o,
  output logic                                s_axi_rvalid_o,
  input  logic                                s_axi_rready_i,

  input  logic                                estop_i,
  input  logic [1:0]                          enc_ab_i,
  input  logic signed [sc_pkg::PosIntW-1:0]   enc_pos_i,
  input  logic                                enc_index_i, // encoder index level, in step with enc_pos_i
  input  logic [sc_pkg::SwW-1:0]              sw_i,        // switch pins: limit -, limit +, home, probe

  output logic                                step_o,
  output logic                                dir_o,
  output logic                                en_o,

  // status for LEDs and the lockstep checker
  output logic                                busy_o,
  output logic                                done_o,
  output logic                                fault_o,
  output logic [sc_pkg::PhaseW-1:0]           phase_o,
  output logic signed [sc_pkg::PosIntW-1:0]   pulse_count_o,
  output logic signed [sc_pkg::PosIntW-1:0]   ref_pos_o,
  output logic                                irq_o        // IRQ_STATUS & IRQ_ENABLE
);

  localparam int PulseTimeW = sc_pkg::PulseTimeW;
  localparam int SegIdxW    = sc_pkg::SegIdxW;
  localparam int PhaseW     = sc_pkg::PhaseW;
  localparam int SegClkW    = sc_pkg::SegClkW;
  localparam int JerkW      = sc_pkg::JerkW;
  localparam int AccW       = sc_pkg::AccW;
  localparam int VelW       = sc_pkg::VelW;
  localparam int RowLevelW  = sc_pkg::RowLevelW;
  localparam int FracBits   = sc_pkg::FracBits;
  localparam int PendW      = sc_pkg::PendW;

  logic                        unused_regs_start_able;
  logic                        enable, row_push, fifo_flush, start, abort;
  logic [PulseTimeW-1:0]       cfg_high, cfg_low, cfg_setup, cfg_hold;
  logic [SegIdxW-1:0]          seg_idx;
  logic [PhaseW-1:0]           seg_phase;
  logic [SegClkW-1:0]          seg_clocks;
  logic signed [JerkW-1:0]     seg_jerk;
  logic signed [AccW-1:0]      seg_acc0;
  logic signed [VelW-1:0]      seg_vel0;
  logic [sc_pkg::RowFlagW-1:0] row_flags;
  logic                        underrun, discont, guard, move_done, fifo_full;
  logic [sc_pkg::VelW-1:0]     guard_vel;
  logic [sc_pkg::AccW-1:0]     guard_acc;
  logic [sc_pkg::JerkW-1:0]    guard_jerk;
  logic                        soft_en, reach;
  logic signed [sc_pkg::PosIntW-1:0] soft_min, soft_max;
  logic [sc_pkg::MoveIdxW-1:0] move_idx;
  logic signed [sc_pkg::PosIntW-1:0] boundary_pos;
  logic [RowLevelW-1:0]        fifo_level;
  logic                        row_replace, retarget_refused;
  logic [sc_pkg::RowCountW-1:0] retarget_row, row_count;
  logic [FracBits-1:0]         pos_frac0;
  logic                        core_busy, core_done, fault_table, fault_overrun;

  // reference kinematics not used here (the closed loop will take them)
  logic [FracBits-1:0]         unused_ref_frac;
  logic signed [VelW-1:0]      unused_ref_vel;
  logic signed [AccW-1:0]      unused_ref_acc;
  logic signed [JerkW-1:0]     unused_ref_jerk;
  logic signed [PendW-1:0]     unused_pending;
  // the core's own row reach evaluator: its outside ports unused
  logic                               unused_rc_start, unused_rc_abort;
  logic [sc_pkg::SegClkW-1:0]         unused_rc_clocks;
  logic signed [sc_pkg::JerkW-1:0]    unused_rc_jerk;
  logic signed [sc_pkg::AccW-1:0]     unused_rc_acc0;
  logic signed [sc_pkg::VelW-1:0]     unused_rc_vel0;
  logic                        unused_exec_start, unused_abort, unused_ref_done, unused_ref_running,
                               unused_step_busy;
  logic                        stop, stopping, overshoot;
  logic [sc_pkg::JerkW-1:0]    stop_jerk;
  logic [sc_pkg::AccW-1:0]     stop_acc;
  logic [sc_pkg::SwW-1:0]      sw_invert, sw_level, sw_edge;
  logic [sc_pkg::DebounceW-1:0] sw_debounce;
  logic                        lim_fwd, lim_rev, lim_hard, lim_trip_fwd, lim_trip_rev;
  logic                        unused_closed;
  logic [sc_pkg::CtlCfgW-1:0]  unused_ctl_cfg;

  sc_axi_regs u_regs (
    .clk_i,
    .rst_ni,
    .s_axi_awaddr_i,
    .s_axi_awvalid_i,
    .s_axi_awready_o,
    .s_axi_wdata_i,
    .s_axi_wstrb_i,
    .s_axi_wvalid_i,
    .s_axi_wready_o,
    .s_axi_bresp_o,
    .s_axi_bvalid_o,
    .s_axi_bready_i,
    .s_axi_araddr_i,
    .s_axi_arvalid_i,
    .s_axi_arready_o,
    .s_axi_rdata_o,
    .s_axi_rresp_o,
    .s_axi_rvalid_o,
    .s_axi_rready_i,
    .estop_i,
    .enc_ab_i,
    .enc_pos_i,
    .enc_index_i,
    .enable_o        (enable),
    .cfg_high_o      (cfg_high),
    .cfg_low_o       (cfg_low),
    .cfg_setup_o     (cfg_setup),
    .cfg_hold_o      (cfg_hold),
    .row_push_o      (row_push),
    .row_replace_o   (row_replace),
    .retarget_row_o  (retarget_row),
    .row_flags_o     (row_flags),
    .row_phase_o     (seg_phase),
    .row_clocks_o    (seg_clocks),
    .row_jerk_o      (seg_jerk),
    .row_acc0_o      (seg_acc0),
    .row_vel0_o      (seg_vel0),
    .fifo_flush_o    (fifo_flush),
    .pos_frac0_o     (pos_frac0),
    .start_o         (start),
    .abort_o         (abort),
    .stop_o          (stop),
    .stop_jerk_o     (stop_jerk),
    .stop_acc_o      (stop_acc),
    .guard_vel_o     (guard_vel),
    .guard_acc_o     (guard_acc),
    .guard_jerk_o    (guard_jerk),
    .soft_en_o       (soft_en),
    .soft_min_o      (soft_min),
    .soft_max_o      (soft_max),
    .closed_loop_o   (unused_closed),
    .ctl_cfg_o       (unused_ctl_cfg),
    .busy_i          (core_busy),
    .done_i          (core_done),
    .phase_i         (phase_o),
    .en_i            (en_o),
    .fault_table_i   (fault_table),
    .fault_overrun_i (fault_overrun),
    .pulse_count_i   (pulse_count_o),
    .ref_pos_i       (ref_pos_o),
    .seg_idx_i       (seg_idx),
    .in_pos_i        (1'b0),
    .fault_ferr_i    (1'b0),
    .cl_stat_i       ({(sc_pkg::ClStatWords*32){1'b0}}),
    .sw_invert_o     (sw_invert),
    .sw_debounce_o   (sw_debounce),
    .lim_fwd_o       (lim_fwd),
    .lim_rev_o       (lim_rev),
    .lim_hard_o      (lim_hard),
    .sw_level_i      (sw_level),
    .sw_edge_i       (sw_edge),
    .lim_trip_fwd_i  (lim_trip_fwd),
    .lim_trip_rev_i  (lim_trip_rev),
    .underrun_i      (underrun),
    .discont_i       (discont),
    .guard_i         (guard),
    .reach_i         (reach),
    .stopping_i      (stopping),
    .overshoot_i     (overshoot),
    .move_done_i     (move_done),
    .move_idx_i      (move_idx),
    .boundary_pos_i  (boundary_pos),
    .fifo_level_i    (fifo_level),
    .fifo_full_i     (fifo_full),
    .row_count_i     (row_count),
    .retarget_refused_i(retarget_refused),
    .group_i         (1'b1),  // one axis: every write is the group's
    .start_ok_i      (1'b1),
    .start_able_o    (unused_regs_start_able),
    .busy_o,
    .irq_o
  );

  sc_switch_filter #(.Width(sc_pkg::SwW)) u_sw (
    .clk_i,
    .rst_ni,
    .sw_i,
    .invert_i   (sw_invert),
    .debounce_i (sw_debounce),
    .level_o    (sw_level),
    .edge_o     (sw_edge)
  );

  logic unused_start_able, unused_arm_ready, unused_arm_drop, unused_fault_abort, unused_reach_bad,
        unused_arming;

  sc_axis_core u_core (
    .clk_i,
    .rst_ni,
    .enable_i        (enable),
    .cfg_high_i      (cfg_high),
    .cfg_low_i       (cfg_low),
    .cfg_setup_i     (cfg_setup),
    .cfg_hold_i      (cfg_hold),
    .row_push_i      (row_push),
    .row_replace_i   (row_replace),
    .retarget_row_i  (retarget_row),
    .row_flags_i     (row_flags),
    .row_phase_i     (seg_phase),
    .row_clocks_i    (seg_clocks),
    .row_jerk_i      (seg_jerk),
    .row_acc0_i      (seg_acc0),
    .row_vel0_i      (seg_vel0),
    .fifo_flush_i    (fifo_flush),
    .pos_frac0_i     (pos_frac0),
    .start_i         (start),
    .abort_i         (abort),
    .stop_i          (stop),
    .stop_jerk_i     (stop_jerk),
    .stop_acc_i      (stop_acc),
    .guard_vel_i     (guard_vel),
    .guard_acc_i     (guard_acc),
    .guard_jerk_i    (guard_jerk),
    .soft_en_i       (soft_en),
    .soft_min_i      (soft_min),
    .soft_max_i      (soft_max),
    .lim_fwd_i       (lim_fwd),
    .lim_rev_i       (lim_rev),
    .lim_hard_i      (lim_hard),
    .ext_sel_i        (1'b0),
    .ext_req_i        (1'b0),
    .ext_fwd_i        (1'b0),
    .ext_hint_valid_i (1'b0),
    .ext_hint_i       (1'b0),
    .ext_busy_i       (1'b0),
    .ext_abort_i      (1'b0),
    .ext_done_i       (1'b0),
    .sync_start_ok_i  (1'b0),   // one axis: no start synchronisation
    .sync_go_i        (1'b0),
    .sync_drop_i      (1'b0),
    .sync_reach_veto_i (1'b0),
    .reach_bad_o      (unused_reach_bad),
    .start_able_o     (unused_start_able),
    .arm_ready_o      (unused_arm_ready),
    .arm_drop_o       (unused_arm_drop),
    .fault_abort_o    (unused_fault_abort),
    .arming_o         (unused_arming),
    .exec_start_o     (unused_exec_start),
    .abort_o          (unused_abort),
    .ref_done_o       (unused_ref_done),
    .ref_running_o    (unused_ref_running),
    .step_busy_o      (unused_step_busy),
    .lim_trip_fwd_o   (lim_trip_fwd),
    .lim_trip_rev_o   (lim_trip_rev),
    .step_o,
    .dir_o,
    .en_o,
    .busy_o          (core_busy),
    .done_o          (core_done),
    .phase_o,
    .fault_table_o   (fault_table),
    .fault_overrun_o (fault_overrun),
    .underrun_o      (underrun),
    .discont_o       (discont),
    .guard_o         (guard),
    .reach_o         (reach),
    .stopping_o      (stopping),
    .overshoot_o     (overshoot),
    .move_done_o     (move_done),
    .move_idx_o      (move_idx),
    .boundary_pos_o  (boundary_pos),
    .fifo_level_o    (fifo_level),
    .fifo_full_o     (fifo_full),
    .row_count_o     (row_count),
    .retarget_refused_o(retarget_refused),
    .pulse_count_o,
    .ref_pos_int_o   (ref_pos_o),
    .ref_pos_frac_o  (unused_ref_frac),
    .ref_vel_o       (unused_ref_vel),
    .ref_acc_o       (unused_ref_acc),
    .ref_jerk_o      (unused_ref_jerk),
    .seg_idx_o       (seg_idx),
    .step_pending_o  (unused_pending),
    .rc_start_o      (unused_rc_start),
    .rc_abort_o      (unused_rc_abort),
    .rc_clocks_o     (unused_rc_clocks),
    .rc_jerk_o       (unused_rc_jerk),
    .rc_acc0_o       (unused_rc_acc0),
    .rc_vel0_o       (unused_rc_vel0),
    .rc_busy_i       (1'b0),
    .rc_done_i       (1'b0),
    .rc_fwd_i        ('0),
    .rc_rev_i        ('0)
  );

  assign done_o  = core_done && !busy_o;
  assign fault_o = fault_table || fault_overrun;

endmodule
