// sc_axi_multi_axis: Axes coordinated axes behind one AXI4-Lite slave
// (sc_axi_window_demux + one sc_axi_regs per axis + sc_multi_axis_core).
//
// Map (sc_pkg::MultiRegAddrW-bit byte addresses): window 1 + a (byte
// address (1 + a) << RegAddrW) is axis a's register file, the one-axis map
// of docs/regmap.md; window 0 is the group window, whose writes reach every
// axis's register file in the same clock and whose reads answer axis 0's.
// What belongs to all axes is written through the group window only:
// SEG_CLOCKS (the shared row clocks), ROW_PUSH (one multi-axis row: every
// axis's staged row, the flags of the write), RETARGET_ROW and CMD.START /
// FLUSH; an axis's window refuses them (SLVERR, that axis's ERR.REJECT).
// A START is taken by every register file or by none (start_ok: every
// axis enabled, idle and not e-stopped), so all STATUS.BUSY rise together.
// Per axis: the staged row's jerk, acc0, vel0 and phase, POS_FRAC0, the
// pulse timing, the stop and guard limits, switches and soft limits, the
// closed-loop settings (Servo = 1) and CTRL.CLOSED_LOOP.
// CMD.STOP or CMD.ESTOP in any window stops every axis (controlled or at
// once: the core's one stop); CTRL.ENABLE of every axis enables the core.
// irq_o is the OR of the axes' interrupts.
module sc_axi_multi_axis #(
  parameter int Axes      = 2,
  parameter bit Servo     = 1'b1,
  parameter bit Lookahead = 1'b1   // 0: no soft-limit look-ahead (sc_multi_axis_core)
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,

  input  logic [sc_pkg::MultiRegAddrW-1:0]   s_axi_awaddr_i,
  input  logic                               s_axi_awvalid_i,
  output logic                               s_axi_awready_o,
  input  logic [31:0]                        s_axi_wdata_i,
  input  logic [3:0]                         s_axi_wstrb_i,
  input  logic                               s_axi_wvalid_i,
  output logic                               s_axi_wready_o,
  output logic [1:0]                         s_axi_bresp_o,
  output logic                               s_axi_bvalid_o,
  input  logic                               s_axi_bready_i,
  input  logic [sc_pkg::MultiRegAddrW-1:0]   s_axi_araddr_i,
  input  logic                               s_axi_arvalid_i,
  output logic                               s_axi_arready_o,
  output logic [31:0]                        s_axi_rdata_o,
  output logic [1:0]                         s_axi_rresp_o,
  output logic                               s_axi_rvalid_o,
  input  logic                               s_axi_rready_i,

  input  logic                               estop_i,
  input  logic [Axes-1:0]                    enc_a_i,
  input  logic [Axes-1:0]                    enc_b_i,
  input  logic [Axes-1:0]                    enc_z_i,
  input  logic [Axes*sc_pkg::SwW-1:0]        sw_i,      // per axis: limit -, limit +, home, probe

  output logic [Axes-1:0]                    step_o,
  output logic [Axes-1:0]                    dir_o,
  output logic [Axes-1:0]                    en_o,

  // status for LEDs and the lockstep checker, per axis
  output logic [Axes-1:0]                    busy_o,
  output logic [Axes-1:0]                    done_o,
  output logic [Axes-1:0]                    fault_o,
  output logic [Axes*sc_pkg::PhaseW-1:0]     phase_o,
  output logic [Axes*sc_pkg::PosIntW-1:0]    pulse_count_o,
  output logic [Axes*sc_pkg::PosIntW-1:0]    ref_pos_o,
  output logic [Axes*sc_pkg::EncCntW-1:0]    enc_pos_o,
  output logic [Axes-1:0]                    in_pos_o,
  output logic [Axes-1:0]                    fault_ferr_o,
  output logic                               irq_o
);

  localparam int AW         = sc_pkg::RegAddrW;
  localparam int PulseTimeW = sc_pkg::PulseTimeW;
  localparam int PhaseW     = sc_pkg::PhaseW;
  localparam int SegClkW    = sc_pkg::SegClkW;
  localparam int JerkW      = sc_pkg::JerkW;
  localparam int AccW       = sc_pkg::AccW;
  localparam int VelW       = sc_pkg::VelW;
  localparam int FracBits   = sc_pkg::FracBits;
  localparam int PosIntW    = sc_pkg::PosIntW;
  localparam int EncCntW    = sc_pkg::EncCntW;
  localparam int SwW        = sc_pkg::SwW;
  localparam int RowFlagW   = sc_pkg::RowFlagW;
  localparam int RowCountW  = sc_pkg::RowCountW;
  localparam int RowLevelW  = sc_pkg::RowLevelW;
  localparam int MoveIdxW   = sc_pkg::MoveIdxW;
  localparam int SegIdxW    = sc_pkg::SegIdxW;
  localparam int CtlCfgW    = sc_pkg::CtlCfgW;
  localparam int CtlW       = sc_pkg::CtlW;
  localparam int WgtW       = sc_pkg::WgtW;
  localparam int CtlStW     = sc_pkg::CtlStW;
  localparam int EncIllW    = sc_pkg::EncIllW;
  localparam int NStat      = sc_pkg::ClStatWords;

  // ---- bus: the group window and one window per axis ----------------------
  logic [AW-1:0]      m_awaddr, m_araddr;
  logic [31:0]        m_wdata;
  logic [3:0]         m_wstrb;
  logic [Axes-1:0]    m_awvalid, m_awready, m_wvalid, m_wready, m_bvalid, m_bready;
  logic [Axes-1:0]    m_arvalid, m_arready, m_rvalid, m_rready;
  logic [Axes*2-1:0]  m_bresp, m_rresp;
  logic [Axes*32-1:0] m_rdata;
  logic               group;
  logic               unused_ready;

  sc_axi_window_demux #(.Slaves(Axes)) u_demux (
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
    .m_axi_awaddr_o  (m_awaddr),
    .m_axi_awvalid_o (m_awvalid),
    .m_axi_wdata_o   (m_wdata),
    .m_axi_wstrb_o   (m_wstrb),
    .m_axi_wvalid_o  (m_wvalid),
    .m_axi_bresp_i   (m_bresp),
    .m_axi_bvalid_i  (m_bvalid),
    .m_axi_bready_o  (m_bready),
    .m_axi_araddr_o  (m_araddr),
    .m_axi_arvalid_o (m_arvalid),
    .m_axi_rdata_i   (m_rdata),
    .m_axi_rresp_i   (m_rresp),
    .m_axi_rvalid_i  (m_rvalid),
    .m_axi_rready_o  (m_rready),
    .group_o         (group)
  );
  // the register files are idle whenever the demux issues: always ready then
  assign unused_ready = ^{m_awready, m_wready, m_arready};

  // ---- per-axis register files (flat vectors, axis a at [a*W +: W]) -------
  logic [Axes-1:0]             enable, closed_loop, row_push, row_replace, fifo_flush, start, abort, stop;
  logic [Axes-1:0]             start_able, lim_fwd, lim_rev, lim_hard, regs_busy, irq;
  logic [Axes*PulseTimeW-1:0]  cfg_high, cfg_low, cfg_setup, cfg_hold;
  logic [Axes*RowCountW-1:0]   retarget_row;
  logic [Axes*RowFlagW-1:0]    row_flags;
  logic [Axes*PhaseW-1:0]      row_phase;
  logic [Axes*SegClkW-1:0]     row_clocks;
  logic [Axes*JerkW-1:0]       row_jerk, stop_jerk, guard_jerk;
  logic [Axes-1:0]             soft_en, reach;
  logic [Axes*PosIntW-1:0]     soft_min, soft_max;
  logic [Axes*AccW-1:0]        row_acc0, stop_acc, guard_acc;
  logic [Axes*VelW-1:0]        row_vel0, guard_vel;
  logic [Axes*FracBits-1:0]    pos_frac0;
  logic [Axes*CtlCfgW-1:0]     ctl_cfg;
  logic [Axes*SwW-1:0]         sw_invert, sw_level, sw_edge;
  logic [Axes*sc_pkg::DebounceW-1:0] sw_debounce;

  // core outputs
  logic [Axes-1:0]             core_busy, core_done, fault_table, fault_overrun, underrun, discont, guard;
  logic [Axes-1:0]             stopping, overshoot, move_done, retarget_refused, fifo_full;
  logic [Axes-1:0]             lim_trip_fwd, lim_trip_rev, enc_index, ctl_active;
  logic [Axes*MoveIdxW-1:0]    move_idx;
  logic [Axes*PosIntW-1:0]     boundary_pos;
  logic [Axes*RowLevelW-1:0]   fifo_level;
  logic [Axes*RowCountW-1:0]   row_count;
  logic [Axes*SegIdxW-1:0]     seg_idx;
  logic [Axes*EncIllW-1:0]     enc_illegal;
  logic [Axes*CtlStW-1:0]      ctl_state;
  logic [Axes*CtlW-1:0]        ctl_u, ctl_v_cmd, ctl_e_p, ctl_e_v;
  logic [Axes*WgtW-1:0]        w_p1, w_p2, w_v1, w_v2;
  logic [Axes*FracBits-1:0]    unused_ref_frac;
  logic [Axes*VelW-1:0]        unused_ref_vel;
  logic [Axes*AccW-1:0]        unused_ref_acc;
  logic [Axes*JerkW-1:0]       unused_ref_jerk;
  logic [Axes*sc_pkg::PendW-1:0] unused_pending;
  logic [Axes*sc_pkg::NcoW-1:0]  unused_nco_phase;
  logic                        start_ok;

  assign start_ok = &start_able;

  for (genvar a = 0; a < Axes; a++) begin : g_axis
    logic [1:0]         enc_ab_sync;
    logic [NStat*32-1:0] cl_stat;

    sc_sync #(
      .Width    (2),
      .ResetVal (1'b0)
    ) u_sync_enc (
      .clk_i,
      .rst_ni,
      .d_i ({enc_b_i[a], enc_a_i[a]}),
      .q_o (enc_ab_sync)
    );

    sc_cl_stat_pack u_cl_stat (
      .in_pos_i      (in_pos_o[a]),
      .fault_ferr_i  (fault_ferr_o[a]),
      .ctl_active_i  (ctl_active[a]),
      .ctl_state_i   (ctl_state[a*CtlStW +: CtlStW]),
      .enc_illegal_i (enc_illegal[a*EncIllW +: EncIllW]),
      .u_i           (ctl_u[a*CtlW +: CtlW]),
      .v_cmd_i       (ctl_v_cmd[a*CtlW +: CtlW]),
      .e_p_i         (ctl_e_p[a*CtlW +: CtlW]),
      .e_v_i         (ctl_e_v[a*CtlW +: CtlW]),
      .w_p1_i        (w_p1[a*WgtW +: WgtW]),
      .w_p2_i        (w_p2[a*WgtW +: WgtW]),
      .w_v1_i        (w_v1[a*WgtW +: WgtW]),
      .w_v2_i        (w_v2[a*WgtW +: WgtW]),
      .cl_stat_o     (cl_stat)
    );

    sc_axi_regs #(.Servo(Servo)) u_regs (
      .clk_i,
      .rst_ni,
      .s_axi_awaddr_i    (m_awaddr),
      .s_axi_awvalid_i   (m_awvalid[a]),
      .s_axi_awready_o   (m_awready[a]),
      .s_axi_wdata_i     (m_wdata),
      .s_axi_wstrb_i     (m_wstrb),
      .s_axi_wvalid_i    (m_wvalid[a]),
      .s_axi_wready_o    (m_wready[a]),
      .s_axi_bresp_o     (m_bresp[2*a +: 2]),
      .s_axi_bvalid_o    (m_bvalid[a]),
      .s_axi_bready_i    (m_bready[a]),
      .s_axi_araddr_i    (m_araddr),
      .s_axi_arvalid_i   (m_arvalid[a]),
      .s_axi_arready_o   (m_arready[a]),
      .s_axi_rdata_o     (m_rdata[32*a +: 32]),
      .s_axi_rresp_o     (m_rresp[2*a +: 2]),
      .s_axi_rvalid_o    (m_rvalid[a]),
      .s_axi_rready_i    (m_rready[a]),
      .estop_i,
      .enc_ab_i          (enc_ab_sync),
      .enc_pos_i         (enc_pos_o[a*EncCntW +: EncCntW]),
      .enc_index_i       (enc_index[a]),
      .enable_o          (enable[a]),
      .cfg_high_o        (cfg_high[a*PulseTimeW +: PulseTimeW]),
      .cfg_low_o         (cfg_low[a*PulseTimeW +: PulseTimeW]),
      .cfg_setup_o       (cfg_setup[a*PulseTimeW +: PulseTimeW]),
      .cfg_hold_o        (cfg_hold[a*PulseTimeW +: PulseTimeW]),
      .row_push_o        (row_push[a]),
      .row_replace_o     (row_replace[a]),
      .retarget_row_o    (retarget_row[a*RowCountW +: RowCountW]),
      .row_flags_o       (row_flags[a*RowFlagW +: RowFlagW]),
      .row_phase_o       (row_phase[a*PhaseW +: PhaseW]),
      .row_clocks_o      (row_clocks[a*SegClkW +: SegClkW]),
      .row_jerk_o        (row_jerk[a*JerkW +: JerkW]),
      .row_acc0_o        (row_acc0[a*AccW +: AccW]),
      .row_vel0_o        (row_vel0[a*VelW +: VelW]),
      .fifo_flush_o      (fifo_flush[a]),
      .pos_frac0_o       (pos_frac0[a*FracBits +: FracBits]),
      .start_o           (start[a]),
      .abort_o           (abort[a]),
      .stop_o            (stop[a]),
      .stop_jerk_o       (stop_jerk[a*JerkW +: JerkW]),
      .stop_acc_o        (stop_acc[a*AccW +: AccW]),
      .guard_vel_o       (guard_vel[a*VelW +: VelW]),
      .guard_acc_o       (guard_acc[a*AccW +: AccW]),
      .guard_jerk_o      (guard_jerk[a*JerkW +: JerkW]),
      .soft_en_o         (soft_en[a]),
      .soft_min_o        (soft_min[a*PosIntW +: PosIntW]),
      .soft_max_o        (soft_max[a*PosIntW +: PosIntW]),
      .closed_loop_o     (closed_loop[a]),
      .ctl_cfg_o         (ctl_cfg[a*CtlCfgW +: CtlCfgW]),
      .sw_invert_o       (sw_invert[a*SwW +: SwW]),
      .sw_debounce_o     (sw_debounce[a*sc_pkg::DebounceW +: sc_pkg::DebounceW]),
      .lim_fwd_o         (lim_fwd[a]),
      .lim_rev_o         (lim_rev[a]),
      .lim_hard_o        (lim_hard[a]),
      .busy_i            (core_busy[a]),
      .done_i            (core_done[a]),
      .phase_i           (phase_o[a*PhaseW +: PhaseW]),
      .en_i              (en_o[a]),
      .fault_table_i     (fault_table[a]),
      .fault_overrun_i   (fault_overrun[a]),
      .pulse_count_i     (pulse_count_o[a*PosIntW +: PosIntW]),
      .ref_pos_i         (ref_pos_o[a*PosIntW +: PosIntW]),
      .seg_idx_i         (seg_idx[a*SegIdxW +: SegIdxW]),
      .underrun_i        (underrun[a]),
      .discont_i         (discont[a]),
      .guard_i           (guard[a]),
      .reach_i           (reach[a]),
      .stopping_i        (stopping[a]),
      .overshoot_i       (overshoot[a]),
      .move_done_i       (move_done[a]),
      .move_idx_i        (move_idx[a*MoveIdxW +: MoveIdxW]),
      .boundary_pos_i    (boundary_pos[a*PosIntW +: PosIntW]),
      .fifo_level_i      (fifo_level[a*RowLevelW +: RowLevelW]),
      .fifo_full_i       (fifo_full[a]),
      .row_count_i       (row_count[a*RowCountW +: RowCountW]),
      .retarget_refused_i(retarget_refused[a]),
      .in_pos_i          (in_pos_o[a]),
      .fault_ferr_i      (fault_ferr_o[a]),
      .cl_stat_i         (cl_stat),
      .sw_level_i        (sw_level[a*SwW +: SwW]),
      .sw_edge_i         (sw_edge[a*SwW +: SwW]),
      .lim_trip_fwd_i    (lim_trip_fwd[a]),
      .lim_trip_rev_i    (lim_trip_rev[a]),
      .group_i           (group),
      .start_ok_i        (start_ok),
      .start_able_o      (start_able[a]),
      .busy_o            (regs_busy[a]),
      .irq_o             (irq[a])
    );

    sc_switch_filter #(.Width(SwW)) u_sw (
      .clk_i,
      .rst_ni,
      .sw_i       (sw_i[a*SwW +: SwW]),
      .invert_i   (sw_invert[a*SwW +: SwW]),
      .debounce_i (sw_debounce[a*sc_pkg::DebounceW +: sc_pkg::DebounceW]),
      .level_o    (sw_level[a*SwW +: SwW]),
      .edge_o     (sw_edge[a*SwW +: SwW])
    );
  end

  // ---- the coordinated axes ---------------------------------------------------
  // The shared row fields and commands come from axis 0's register file:
  // they are written through the group window only, so every file holds
  // the same (the others' copies are unused).
  logic unused_shared;
  assign unused_shared = ^{row_push, row_replace, retarget_row, row_clocks, fifo_flush, start};

  sc_multi_axis_core #(.Axes(Axes), .Servo(Servo), .Lookahead(Lookahead)) u_core (
    .clk_i,
    .rst_ni,
    .enable_i           (&enable),
    .cfg_high_i         (cfg_high),
    .cfg_low_i          (cfg_low),
    .cfg_setup_i        (cfg_setup),
    .cfg_hold_i         (cfg_hold),
    .row_push_i         (row_push[0]),
    .row_replace_i      (row_replace[0]),
    .retarget_row_i     (retarget_row[0 +: RowCountW]),
    .row_clocks_i       (row_clocks[0 +: SegClkW]),
    .row_flags_i        (row_flags),
    .row_phase_i        (row_phase),
    .row_jerk_i         (row_jerk),
    .row_acc0_i         (row_acc0),
    .row_vel0_i         (row_vel0),
    .fifo_flush_i       (fifo_flush[0]),
    .pos_frac0_i        (pos_frac0),
    .start_i            (start[0]),
    .abort_i            (|abort),
    .stop_i             (|stop),
    .stop_jerk_i        (stop_jerk),
    .stop_acc_i         (stop_acc),
    .guard_vel_i        (guard_vel),
    .guard_acc_i        (guard_acc),
    .guard_jerk_i       (guard_jerk),
    .soft_en_i          (soft_en),
    .soft_min_i         (soft_min),
    .soft_max_i         (soft_max),
    .lim_fwd_i          (lim_fwd),
    .lim_rev_i          (lim_rev),
    .lim_hard_i         (lim_hard),
    .step_o,
    .dir_o,
    .en_o,
    .busy_o             (core_busy),
    .done_o             (core_done),
    .phase_o,
    .fault_table_o      (fault_table),
    .fault_overrun_o    (fault_overrun),
    .underrun_o         (underrun),
    .discont_o          (discont),
    .guard_o            (guard),
    .reach_o            (reach),
    .stopping_o         (stopping),
    .overshoot_o        (overshoot),
    .move_done_o        (move_done),
    .move_idx_o         (move_idx),
    .boundary_pos_o     (boundary_pos),
    .fifo_level_o       (fifo_level),
    .row_count_o        (row_count),
    .retarget_refused_o (retarget_refused),
    .fifo_full_o        (fifo_full),
    .pulse_count_o,
    .lim_trip_fwd_o     (lim_trip_fwd),
    .lim_trip_rev_o     (lim_trip_rev),
    .ref_pos_int_o      (ref_pos_o),
    .ref_pos_frac_o     (unused_ref_frac),
    .ref_vel_o          (unused_ref_vel),
    .ref_acc_o          (unused_ref_acc),
    .ref_jerk_o         (unused_ref_jerk),
    .seg_idx_o          (seg_idx),
    .step_pending_o     (unused_pending),
    .closed_loop_i      (closed_loop),
    .ctl_cfg_i          (ctl_cfg),
    .enc_a_i,
    .enc_b_i,
    .enc_z_i,
    .fault_ferr_o,
    .in_pos_o,
    .enc_pos_o,
    .enc_illegal_o      (enc_illegal),
    .enc_index_o        (enc_index),
    .ctl_active_o       (ctl_active),
    .ctl_state_o        (ctl_state),
    .u_o                (ctl_u),
    .v_cmd_o            (ctl_v_cmd),
    .e_p_o              (ctl_e_p),
    .e_v_o              (ctl_e_v),
    .w_p1_o             (w_p1),
    .w_p2_o             (w_p2),
    .w_v1_o             (w_v1),
    .w_v2_o             (w_v2),
    .nco_phase_o        (unused_nco_phase)
  );

  assign busy_o  = regs_busy;
  assign done_o  = core_done & ~regs_busy;
  assign fault_o = fault_table | fault_overrun | fault_ferr_o;
  assign irq_o   = |irq;

endmodule
