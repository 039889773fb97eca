// sc_axi_regs: AXI4-Lite slave register file of one axis (map: sc_pkg
// "host register map", docs/regmap.md).
//
// Streams rows through a staging row (SEG_PHASE .. SEG_VEL0, appended to
// the core's row FIFO by ROW_PUSH, also while the axis runs), the pulse
// timing and POS_FRAC0; CMD starts, stops, e-stops and flushes the FIFO;
// STATUS/FIFO_STATUS/PULSE_COUNT/REF_POS/... read the core; IRQ_STATUS
// collects interrupt causes, irq_o = |(IRQ_STATUS & IRQ_ENABLE) (a flop).
// Every output to the core is a flop.
//
// AXI4-Lite: one write and one read in flight. AW and W are accepted in
// any order (each held until the write is done); the write takes effect
// the clock after both are held, together with BVALID. A read answers
// RVALID the clock after the AR handshake. Responses: OKAY; SLVERR for a
// write to a read-only register or a refused write (config/START/FLUSH
// while busy, START while e-stopped or disabled, ROW_PUSH to a full FIFO); DECERR for an address
// with no register (including unaligned ones). Refused and bad accesses
// change nothing but the sticky ERR flags. Reserved bits read 0. WSTRB
// selects bytes; CMD, ERR, IRQ_STATUS and ROW_PUSH act on byte 0 only. AWPROT/ARPROT
// are not used and not present.
//
// Servo = 1 (sc_axi_servo) adds the closed-loop words: ClCfgWords
// controller settings from RegClFirst on (each masked to its fields,
// locked while busy like the pulse timing, packed on cl_cfg_o, word i at bits
// 32i+31:32i) and ClStatWords read-only status words from RegClStat on
// (cl_stat_i). With Servo = 0 those addresses answer DECERR.
// CTRL.CLOSED_LOOP is a plain flop in both (closed_loop_o); a CTRL write
// that would change it while busy is refused.
//
// SW_CFG configures the switch filter (sw_invert_o, sw_debounce_o) and the
// limits: lim_fwd_o / lim_rev_o are the enabled limit switches or, with
// SW_CFG.SOFT_EN, REF_POS beyond SOFT_MAX / SOFT_MIN (the soft limits
// act as limit switches; lim_hard_o for both); STATUS.SW_LEVEL shows the filtered levels,
// an edge of one raises IRQ_STATUS.SWITCH, and the core's limit trips set
// ERR.LIMIT_NEG / LIMIT_POS (and ERR.SOFT_LIMIT when the window
// was the cause) and IRQ_STATUS.FAULT. The position latch
// captures PULSE_COUNT and ENC_POS in the clock the filtered home, probe or
// encoder index level (LATCH_CFG.SRC) changes (the edge LATCH_CFG selects),
// once until LATCH_CFG is written.
// GUARD_VEL / GUARD_ACC / GUARD_JERK are the executor's row limits
// (guard_*_o, locked while busy); the core's guard_i sets ERR.GUARD and
// IRQ_STATUS.FAULT when it rises.
// In a multi-axis map (sc_axi_multi_axis) group_i = 0 marks a write through
// one axis's own window: ROW_PUSH, SEG_CLOCKS, RETARGET_ROW and CMD.START /
// FLUSH act on every axis and are refused there (SLVERR, ERR.REJECT); a
// START is refused unless start_ok_i (every axis can take it).
module sc_axi_regs #(
  parameter bit Servo = 1'b0
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,

  // AXI4-Lite slave
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

  // side inputs (synchronous to clk_i)
  input  logic                                estop_i,     // level: abort, disable, latch ERR.ESTOP
  input  logic [1:0]                          enc_ab_i,    // synchronised encoder A (bit 0), B (bit 1)
  input  logic signed [sc_pkg::PosIntW-1:0]   enc_pos_i,
  input  logic                                enc_index_i, // encoder index (filtered Z), in step with enc_pos_i

  // to sc_axis_core
  output logic                                enable_o,
  output logic [sc_pkg::PulseTimeW-1:0]       cfg_high_o,
  output logic [sc_pkg::PulseTimeW-1:0]       cfg_low_o,
  output logic [sc_pkg::PulseTimeW-1:0]       cfg_setup_o,
  output logic [sc_pkg::PulseTimeW-1:0]       cfg_hold_o,
  output logic                                row_push_o,
  output logic                                row_replace_o,   // with row_push_o: a retarget
  output logic [sc_pkg::RowCountW-1:0]        retarget_row_o,
  output logic [sc_pkg::RowFlagW-1:0]         row_flags_o,
  output logic [sc_pkg::PhaseW-1:0]           row_phase_o,
  output logic [sc_pkg::SegClkW-1:0]          row_clocks_o,
  output logic signed [sc_pkg::JerkW-1:0]     row_jerk_o,
  output logic signed [sc_pkg::AccW-1:0]      row_acc0_o,
  output logic signed [sc_pkg::VelW-1:0]      row_vel0_o,
  output logic                                fifo_flush_o,
  output logic [sc_pkg::FracBits-1:0]         pos_frac0_o,
  output logic                                start_o,
  output logic                                abort_o,     // immediate stop (CMD.ESTOP, e-stop input)
  output logic                                stop_o,      // controlled stop (CMD.STOP)
  output logic [sc_pkg::JerkW-1:0]            stop_jerk_o, // STOP_JERK
  output logic [sc_pkg::AccW-1:0]             stop_acc_o,  // STOP_ACC
  output logic [sc_pkg::VelW-1:0]             guard_vel_o, // GUARD_VEL
  output logic [sc_pkg::AccW-1:0]             guard_acc_o, // GUARD_ACC
  output logic [sc_pkg::JerkW-1:0]            guard_jerk_o, // GUARD_JERK
  output logic                                closed_loop_o,
  output logic [sc_pkg::CtlCfgW-1:0]          ctl_cfg_o,   // controller configuration
  output logic [sc_pkg::SwW-1:0]              sw_invert_o, // SW_CFG
  output logic [sc_pkg::DebounceW-1:0]        sw_debounce_o,
  output logic                                lim_fwd_o,   // a limit (switch or soft) is active on the + side
  output logic                                soft_en_o,   // the soft-limit window, for the core's look-ahead
  output logic signed [sc_pkg::PosIntW-1:0]   soft_min_o,
  output logic signed [sc_pkg::PosIntW-1:0]   soft_max_o,
  output logic                                lim_rev_o,
  output logic                                lim_hard_o,

  // from sc_axis_core
  input  logic                                busy_i,
  input  logic                                done_i,
  input  logic [sc_pkg::PhaseW-1:0]           phase_i,
  input  logic                                en_i,
  input  logic                                fault_table_i,
  input  logic                                fault_overrun_i,
  input  logic signed [sc_pkg::PosIntW-1:0]   pulse_count_i,
  input  logic signed [sc_pkg::PosIntW-1:0]   ref_pos_i,
  input  logic [sc_pkg::SegIdxW-1:0]          seg_idx_i,
  input  logic                                underrun_i,
  input  logic                                discont_i,
  input  logic                                guard_i,
  input  logic                                reach_i,     // the soft-limit look-ahead refused a row
  input  logic                                stopping_i,
  input  logic                                overshoot_i,
  input  logic                                move_done_i,
  input  logic [sc_pkg::MoveIdxW-1:0]         move_idx_i,
  input  logic signed [sc_pkg::PosIntW-1:0]   boundary_pos_i,
  input  logic [sc_pkg::RowLevelW-1:0]        fifo_level_i,
  input  logic                                fifo_full_i,
  input  logic [sc_pkg::RowCountW-1:0]        row_count_i,
  input  logic                                retarget_refused_i,
  input  logic                                in_pos_i,
  input  logic                                fault_ferr_i,
  input  logic [sc_pkg::ClStatWords*32-1:0]   cl_stat_i,
  input  logic [sc_pkg::SwW-1:0]              sw_level_i,  // filtered switch levels
  input  logic [sc_pkg::SwW-1:0]              sw_edge_i,
  input  logic                                lim_trip_fwd_i,
  input  logic                                lim_trip_rev_i,

  // multi-axis register file (sc_axi_multi_axis); one axis: 1, 1, unused
  input  logic                                group_i,     // the write reaches every axis (held with it)
  input  logic                                start_ok_i,  // every axis can take a START
  output logic                                start_able_o, // this axis can take a START

  output logic                                busy_o,      // STATUS.BUSY
  output logic                                irq_o
);

  localparam int AW         = sc_pkg::RegAddrW;
  localparam int PulseTimeW = sc_pkg::PulseTimeW;
  localparam int PhaseW     = sc_pkg::PhaseW;
  localparam int SegIdxW    = sc_pkg::SegIdxW;
  localparam int RowLevelW  = sc_pkg::RowLevelW;
  localparam int IrqW       = sc_pkg::IrqW;
  localparam int SegClkW    = sc_pkg::SegClkW;
  localparam int FracBits   = sc_pkg::FracBits;
  localparam int JerkW      = sc_pkg::JerkW;
  localparam int AccW       = sc_pkg::AccW;
  localparam int VelW       = sc_pkg::VelW;
  localparam int NCfg       = sc_pkg::ClCfgWords;
  localparam int NStat      = sc_pkg::ClStatWords;

  localparam logic [1:0] RespOkay   = 2'b00;
  localparam logic [1:0] RespSlvErr = 2'b10;
  localparam logic [1:0] RespDecErr = 2'b11;

  localparam logic [AW-1:0] AId        = AW'(sc_pkg::RegId);
  localparam logic [AW-1:0] ACtrl      = AW'(sc_pkg::RegCtrl);
  localparam logic [AW-1:0] ACmd       = AW'(sc_pkg::RegCmd);
  localparam logic [AW-1:0] AStatus    = AW'(sc_pkg::RegStatus);
  localparam logic [AW-1:0] AErr       = AW'(sc_pkg::RegErr);
  localparam logic [AW-1:0] APulseCnt  = AW'(sc_pkg::RegPulseCount);
  localparam logic [AW-1:0] ARefPos    = AW'(sc_pkg::RegRefPos);
  localparam logic [AW-1:0] AEncPos    = AW'(sc_pkg::RegEncPos);
  localparam logic [AW-1:0] AFollowErr = AW'(sc_pkg::RegFollowErr);
  localparam logic [AW-1:0] AFifoStat  = AW'(sc_pkg::RegFifoStatus);
  localparam logic [AW-1:0] AFifoLow   = AW'(sc_pkg::RegFifoLow);
  localparam logic [AW-1:0] AMoveIdx   = AW'(sc_pkg::RegMoveIndex);
  localparam logic [AW-1:0] ABoundPos  = AW'(sc_pkg::RegBoundaryPos);
  localparam logic [AW-1:0] AIrqStat   = AW'(sc_pkg::RegIrqStatus);
  localparam logic [AW-1:0] AIrqEn     = AW'(sc_pkg::RegIrqEnable);
  localparam logic [AW-1:0] AStopJ0    = AW'(sc_pkg::RegStopJerk);
  localparam logic [AW-1:0] AStopJ1    = AW'(sc_pkg::RegStopJerk + 4);
  localparam logic [AW-1:0] AStopA0    = AW'(sc_pkg::RegStopAcc);
  localparam logic [AW-1:0] AStopA1    = AW'(sc_pkg::RegStopAcc + 4);
  localparam logic [AW-1:0] APulseTime = AW'(sc_pkg::RegPulseTime);
  localparam logic [AW-1:0] ADirTime   = AW'(sc_pkg::RegDirTime);
  localparam logic [AW-1:0] AFrac0     = AW'(sc_pkg::RegPosFrac0);
  localparam logic [AW-1:0] AFrac1     = AW'(sc_pkg::RegPosFrac0 + 4);
  localparam logic [AW-1:0] AFrac2     = AW'(sc_pkg::RegPosFrac0 + 8);
  localparam logic [AW-1:0] ASegPhase  = AW'(sc_pkg::RegSegPhase);
  localparam logic [AW-1:0] ASegClocks = AW'(sc_pkg::RegSegClocks);
  localparam logic [AW-1:0] AJerk0     = AW'(sc_pkg::RegSegJerk);
  localparam logic [AW-1:0] AJerk1     = AW'(sc_pkg::RegSegJerk + 4);
  localparam logic [AW-1:0] AAcc0      = AW'(sc_pkg::RegSegAcc0);
  localparam logic [AW-1:0] AAcc1      = AW'(sc_pkg::RegSegAcc0 + 4);
  localparam logic [AW-1:0] AVel0      = AW'(sc_pkg::RegSegVel0);
  localparam logic [AW-1:0] AVel1      = AW'(sc_pkg::RegSegVel0 + 4);
  localparam logic [AW-1:0] AVel2      = AW'(sc_pkg::RegSegVel0 + 8);
  localparam logic [AW-1:0] ARowPush   = AW'(sc_pkg::RegRowPush);
  localparam logic [AW-1:0] ASwCfg     = AW'(sc_pkg::RegSwCfg);
  localparam logic [AW-1:0] ALatchCfg  = AW'(sc_pkg::RegLatchCfg);
  localparam logic [AW-1:0] ALatchPul  = AW'(sc_pkg::RegLatchPulse);
  localparam logic [AW-1:0] ALatchEnc  = AW'(sc_pkg::RegLatchEnc);
  localparam logic [AW-1:0] AGuardV0   = AW'(sc_pkg::RegGuardVel);
  localparam logic [AW-1:0] AGuardV1   = AW'(sc_pkg::RegGuardVel + 4);
  localparam logic [AW-1:0] AGuardV2   = AW'(sc_pkg::RegGuardVel + 8);
  localparam logic [AW-1:0] AGuardA0   = AW'(sc_pkg::RegGuardAcc);
  localparam logic [AW-1:0] AGuardA1   = AW'(sc_pkg::RegGuardAcc + 4);
  localparam logic [AW-1:0] AGuardJ0   = AW'(sc_pkg::RegGuardJerk);
  localparam logic [AW-1:0] AGuardJ1   = AW'(sc_pkg::RegGuardJerk + 4);
  localparam logic [AW-1:0] ASoftMin   = AW'(sc_pkg::RegSoftMin);
  localparam logic [AW-1:0] ASoftMax   = AW'(sc_pkg::RegSoftMax);
  localparam logic [AW-1:0] ARowCount  = AW'(sc_pkg::RegRowCount);
  localparam logic [AW-1:0] ARetarget  = AW'(sc_pkg::RegRetargetRow);
  localparam int SwW       = sc_pkg::SwW;
  localparam int DebounceW = sc_pkg::DebounceW;

  localparam int CtrlEnableBit = sc_pkg::CtrlEnableBit;
  localparam int CtrlClosedBit = sc_pkg::CtrlClosedBit;
  localparam int CmdStartBit   = sc_pkg::CmdStartBit;
  localparam int CmdStopBit    = sc_pkg::CmdStopBit;
  localparam int CmdEstopBit   = sc_pkg::CmdEstopBit;
  localparam int CmdFlushBit   = sc_pkg::CmdFlushBit;
  localparam int ErrRejectBit  = sc_pkg::ErrRejectBit;
  localparam int ErrBadAddrBit = sc_pkg::ErrBadAddrBit;
  localparam int ErrEstopBit   = sc_pkg::ErrEstopBit;
  localparam int ErrFifoFullBit = sc_pkg::ErrFifoFullBit;
  localparam int ErrDiscontBit = sc_pkg::ErrDiscontBit;
  localparam int ErrUnderrunBit = sc_pkg::ErrUnderrunBit;
  localparam int ErrLimNegBit  = sc_pkg::ErrLimNegBit;
  localparam int ErrLimPosBit  = sc_pkg::ErrLimPosBit;
  localparam int ErrGuardBit   = sc_pkg::ErrGuardBit;

  // Closed-loop words: implemented bits and reset values (generated from the
  // register tags, word 0 lowest).
  localparam logic [NCfg*32-1:0] ClMask  = sc_pkg::ClCfgMask;
  localparam logic [NCfg*32-1:0] ClReset = sc_pkg::ClCfgReset;

  // byte-strobe merge of a 32-bit register word: one 2:1 choice per byte,
  // so that synthesis sees the register's own value fed back and makes the
  // strobe a flop enable (as AND-OR it took one LUT per register bit)
  function automatic logic [31:0] wmerge(input logic [31:0] old_v, input logic [31:0] new_v,
                                         input logic [31:0] mask);
    for (int b = 0; b < 4; b++) begin
      wmerge[8*b +: 8] = mask[8*b] ? new_v[8*b +: 8] : old_v[8*b +: 8];
    end
  endfunction

  // ---- state ---------------------------------------------------------------
  logic                      aw_full_q, aw_full_d;
  logic [AW-1:0]             awaddr_q, awaddr_d;
  logic                      w_full_q, w_full_d;
  logic [31:0]               wdata_q, wdata_d;
  logic [3:0]                wstrb_q, wstrb_d;
  logic                      bvalid_q, bvalid_d;
  logic [1:0]                bresp_q, bresp_d;
  logic                      rvalid_q, rvalid_d;
  logic [1:0]                rresp_q, rresp_d;
  logic [31:0]               rdata_q, rdata_d;

  logic                      en_q, en_d;
  logic                      closed_q, closed_d;
  logic [NCfg*32-1:0]        cl_q;                 // the closed-loop words, one register each
  logic                      cl_we;                // write the word at w_cfg_idx
  logic [RowLevelW-1:0]      low_water_q, low_water_d;
  logic [IrqW-1:0]           irq_st_q, irq_st_d, irq_en_q, irq_en_d;
  logic                      irq_q;
  logic                      below_q, busy_prev_q, underrun_prev_q, fault_prev_q, discont_prev_q,
                             guard_prev_q, reach_prev_q;
  logic                      below, fault_any;
  logic [PulseTimeW-1:0]     high_q, high_d, low_q, low_d, setup_q, setup_d, hold_q, hold_d;
  logic [FracBits-1:0]       frac0_q, frac0_d;
  logic [PhaseW-1:0]         st_phase_q, st_phase_d;
  logic [SegClkW-1:0]        st_clocks_q, st_clocks_d;
  logic [JerkW-1:0]          st_jerk_q, st_jerk_d;
  logic [AccW-1:0]           st_acc0_q, st_acc0_d;
  logic [VelW-1:0]           st_vel0_q, st_vel0_d;
  logic                      push_q, push_d;
  logic                      replace_q, replace_d;
  logic                      err_retarget_q, err_retarget_d;
  logic [sc_pkg::RowCountW-1:0] retarget_q, retarget_d;
  logic [sc_pkg::RowFlagW-1:0] push_flags_q, push_flags_d;
  logic                      flush_q, flush_d;
  logic                      start_q, start_d;
  logic                      start_d1_q;           // START accepted, core not busy yet
  logic                      abort_q, abort_d;
  logic                      stop_q, stop_d;
  logic [JerkW-1:0]          stop_jerk_q, stop_jerk_d;
  logic [AccW-1:0]           stop_acc_q, stop_acc_d;
  logic [VelW-1:0]           guard_vel_q, guard_vel_d;
  logic [AccW-1:0]           guard_acc_q, guard_acc_d;
  logic [JerkW-1:0]          guard_jerk_q, guard_jerk_d;
  logic                      err_reject_q, err_reject_d;
  logic                      err_bad_q, err_bad_d;
  logic                      err_estop_q, err_estop_d;
  logic                      err_full_q, err_full_d;
  logic                      err_disc_q, err_disc_d;
  logic                      err_under_q, err_under_d;
  logic                      err_lneg_q, err_lneg_d;
  logic                      err_lpos_q, err_lpos_d;
  logic                      err_guard_q, err_guard_d;
  logic [SwW-1:0]            sw_inv_q, sw_inv_d;
  logic                      lim_en_q, lim_en_d, lim_hard_q, lim_hard_d;
  logic                      soft_en_q, soft_en_d, err_soft_q, err_soft_d;
  logic signed [sc_pkg::PosIntW-1:0] soft_min_q, soft_min_d, soft_max_q, soft_max_d;
  logic                      soft_fwd, soft_rev;
  logic [DebounceW-1:0]      sw_deb_q, sw_deb_d;
  logic                      lim_trip;
  logic                      latch_rise_q, latch_rise_d, latch_fall_q, latch_fall_d;
  logic [sc_pkg::LatchSrcW-1:0] latch_src_q, latch_src_d;
  logic                      index_q;   // enc_index_i of the last clock: its edges
  logic                      latch_edge, latch_level;
  logic                      latched_q, latched_d, latch_cap;
  logic signed [sc_pkg::PosIntW-1:0] latch_pulse_q, latch_pulse_d, latch_enc_q, latch_enc_d;
  logic [31:0]               sw_cfg_word, sw_cfg_new;  // SW_CFG as read, and as a write would leave it
  logic [31:0]               pulse_new;  // PULSE_TIME as a write would leave it

  // ---- decode --------------------------------------------------------------
  logic        busy_eff;
  logic        do_write, do_read;
  logic [31:0] wmask, wd;
  logic        set_reject, set_bad;
  logic        w_locked;          // the written register is locked while busy
  logic        w_group_only;      // the written register acts on every axis: group window only
  logic [31:0] status_word, rd_word;
  logic [1:0]  rd_resp;
  // closed-loop window decode (write address held)
  logic [AW-1:0] w_cfg_off, w_st_off;
  logic          w_cfg_hit, w_st_hit;
  logic [AW-3:0] w_cfg_idx;

  assign w_cfg_off = awaddr_q - AW'(sc_pkg::RegClFirst);
  assign w_st_off  = awaddr_q - AW'(sc_pkg::RegClStat);
  assign w_cfg_hit = Servo && (w_cfg_off[1:0] == 2'b00) && (w_cfg_off[AW-1:2] < (AW-2)'(NCfg));
  assign w_st_hit  = Servo && (w_st_off[1:0] == 2'b00) && (w_st_off[AW-1:2] < (AW-2)'(NStat));
  assign w_cfg_idx = w_cfg_off[AW-1:2];

  assign busy_eff = busy_i || start_q || start_d1_q;
  assign do_write = aw_full_q && w_full_q && !bvalid_q;
  assign do_read  = s_axi_arvalid_i && !rvalid_q;
  assign wmask    = {{8{wstrb_q[3]}}, {8{wstrb_q[2]}}, {8{wstrb_q[1]}}, {8{wstrb_q[0]}}};
  assign wd       = wdata_q;

  always_comb begin
    unique case (awaddr_q)
      APulseTime, ADirTime, AFrac0, AFrac1, AFrac2,
      AStopJ0, AStopJ1, AStopA0, AStopA1, ASwCfg,
      AGuardV0, AGuardV1, AGuardV2, AGuardA0, AGuardA1, AGuardJ0, AGuardJ1,
      ASoftMin, ASoftMax:                           w_locked = 1'b1;
      default:                                      w_locked = w_cfg_hit;
    endcase
  end

  // The shared row clocks, row push, retarget and START / FLUSH act on
  // every axis: in one axis's window of a multi-axis map they are refused.
  assign w_group_only = awaddr_q == ARowPush || awaddr_q == ASegClocks || awaddr_q == ARetarget ||
                        (awaddr_q == ACmd && wstrb_q[0] && !wd[CmdEstopBit] && !wd[CmdStopBit] &&
                         (wd[CmdStartBit] || wd[CmdFlushBit]));
  assign start_able_o = !busy_eff && !err_estop_q && en_q;

  // STATUS and SW_CFG are packed in a block-local word and written once:
  // Icarus 11 counts a constant part-select write as a read of the whole
  // word, and the partial writes of a shared word woke the other blocks
  // without end at time 0.
  always_comb begin : pack_status_word
    logic [31:0] w;
    w = '0;
    w[sc_pkg::StatusPhaseLsb +: PhaseW]   = phase_i;
    w[sc_pkg::StatusBusyBit]              = busy_eff;
    w[sc_pkg::StatusDoneBit]              = done_i && !busy_eff;
    w[sc_pkg::StatusEnBit]                = en_i;
    w[sc_pkg::StatusFaultTableBit]        = fault_table_i;
    w[sc_pkg::StatusFaultOverrunBit]      = fault_overrun_i;
    w[sc_pkg::StatusEstopBit]             = err_estop_q;
    w[sc_pkg::StatusErrBit]               = err_reject_q || err_bad_q || err_estop_q ||
                                            err_lneg_q || err_lpos_q || err_guard_q || err_soft_q ||
                                            err_retarget_q;
    w[sc_pkg::StatusFaultFerrBit]         = fault_ferr_i;
    w[sc_pkg::StatusInPosBit]             = in_pos_i;
    w[sc_pkg::StatusEncALsb +: 2]         = enc_ab_i;
    w[sc_pkg::StatusSegIdxLsb +: SegIdxW] = seg_idx_i;
    w[sc_pkg::StatusUnderrunBit]          = underrun_i;
    w[sc_pkg::StatusDiscontBit]           = discont_i;
    w[sc_pkg::StatusStoppingBit]          = stopping_i;
    w[sc_pkg::StatusOvershootBit]         = overshoot_i;
    w[sc_pkg::StatusSwLevelLsb +: SwW]    = sw_level_i;
    w[sc_pkg::StatusLatchedBit]           = latched_q;
    w[sc_pkg::StatusGuardBit]             = guard_i;
    w[sc_pkg::StatusReachBit]             = reach_i;
    status_word = w;
  end

  always_comb begin : pack_sw_cfg_word
    logic [31:0] w;
    w = '0;
    w[sc_pkg::SwInvertLsb +: SwW]         = sw_inv_q;
    w[sc_pkg::SwLimEnBit]                 = lim_en_q;
    w[sc_pkg::SwLimHardBit]               = lim_hard_q;
    w[sc_pkg::SwSoftEnBit]                = soft_en_q;
    w[sc_pkg::SwDebounceLsb +: DebounceW] = sw_deb_q;
    sw_cfg_word = w;
  end
  assign sw_cfg_new = wmerge(sw_cfg_word, wd, wmask);
  assign pulse_new  = wmerge(32'(high_q) << sc_pkg::PulseHighLsb | 32'(low_q) << sc_pkg::PulseLowLsb, wd, wmask);

  // position latch: an edge of the filtered home, probe or index level, armed
  always_comb begin
    unique case (latch_src_q)
      sc_pkg::LatchSrcW'(sc_pkg::LatchSrcProbe): begin
        latch_edge  = sw_edge_i[sc_pkg::SwProbe];
        latch_level = sw_level_i[sc_pkg::SwProbe];
      end
      sc_pkg::LatchSrcW'(sc_pkg::LatchSrcIndex): begin
        latch_edge  = enc_index_i != index_q;
        latch_level = enc_index_i;
      end
      default: begin
        latch_edge  = sw_edge_i[sc_pkg::SwHome];
        latch_level = sw_level_i[sc_pkg::SwHome];
      end
    endcase
  end
  assign latch_cap = !latched_q && latch_edge && (latch_level ? latch_rise_q : latch_fall_q);

  // interrupt causes: events of the core's status (edges of its levels)
  assign below     = fifo_level_i < low_water_q;
  assign lim_trip  = lim_trip_fwd_i || lim_trip_rev_i;
  // soft limits: beyond the window's last positions REF_POS is on a limit
  // switch (a move planned to end on an edge does not trip)
  assign soft_fwd  = soft_en_q && ref_pos_i > soft_max_q;
  assign soft_rev  = soft_en_q && ref_pos_i < soft_min_q;
  assign fault_any = fault_table_i || fault_overrun_i || fault_ferr_i || err_estop_q || lim_trip;

  // Read mux. Every readable word is packed at its word index into one
  // vector, and a read selects its word by index: a LUT6/MUXF7/MUXF8 tree.
  // (A case over the byte address made one-hot decodes and an AND-OR per
  // bit, twice the LUTs.) The map ends below byte address 0x200: a register
  // placed higher would answer DECERR, which the board test of every
  // register's reset value and access type reports.
  localparam int RdWords = 2 ** (AW - 3);
  logic [RdWords*32-1:0] rd_words;
  logic [AW-4:0]         r_word;
  logic                  r_known;

  `define SC_RD(addr, lsb, width, value) w[32 * (32'(addr) >> 2) + (lsb) +: (width)] = (value)
  always_comb begin : pack_read_words
    logic [RdWords*32-1:0] w;
    w = '0;
    `SC_RD(AId, 0, 32, {16'(sc_pkg::RegIdMagic), 16'(sc_pkg::RegMapVersion)});
    `SC_RD(ACtrl, CtrlEnableBit, 1, en_q);
    `SC_RD(ACtrl, CtrlClosedBit, 1, closed_q);
    `SC_RD(AStatus, 0, 32, status_word);
    `SC_RD(AErr, ErrRejectBit, 1, err_reject_q);
    `SC_RD(AErr, ErrBadAddrBit, 1, err_bad_q);
    `SC_RD(AErr, ErrEstopBit, 1, err_estop_q);
    `SC_RD(AErr, ErrFifoFullBit, 1, err_full_q);
    `SC_RD(AErr, ErrDiscontBit, 1, err_disc_q);
    `SC_RD(AErr, ErrUnderrunBit, 1, err_under_q);
    `SC_RD(AErr, sc_pkg::ErrRetargetBit, 1, err_retarget_q);
    `SC_RD(AErr, ErrLimNegBit, 1, err_lneg_q);
    `SC_RD(AErr, ErrLimPosBit, 1, err_lpos_q);
    `SC_RD(AErr, ErrGuardBit, 1, err_guard_q);
    `SC_RD(AErr, sc_pkg::ErrSoftLimBit, 1, err_soft_q);
    `SC_RD(ASwCfg, 0, 32, sw_cfg_word);
    `SC_RD(ALatchCfg, sc_pkg::LatchRiseBit, 1, latch_rise_q);
    `SC_RD(ALatchCfg, sc_pkg::LatchFallBit, 1, latch_fall_q);
    `SC_RD(ALatchCfg, sc_pkg::LatchSrcLsb, sc_pkg::LatchSrcW, latch_src_q);
    `SC_RD(ALatchPul, 0, 32, 32'(latch_pulse_q));
    `SC_RD(ALatchEnc, 0, 32, 32'(latch_enc_q));
    `SC_RD(APulseCnt, 0, 32, 32'(pulse_count_i));
    `SC_RD(ARefPos, 0, 32, 32'(ref_pos_i));
    `SC_RD(AEncPos, 0, 32, 32'(enc_pos_i));
    `SC_RD(AFollowErr, 0, 32, 32'(ref_pos_i - enc_pos_i));
    `SC_RD(AFifoStat, sc_pkg::FifoLevelLsb, RowLevelW, fifo_level_i);
    `SC_RD(AFifoStat, sc_pkg::FifoFullBit, 1, fifo_full_i);
    `SC_RD(AFifoStat, sc_pkg::FifoLowBit, 1, below);
    `SC_RD(AFifoLow, sc_pkg::FifoLowLsb, RowLevelW, low_water_q);
    `SC_RD(AMoveIdx, 0, 32, 32'(move_idx_i));
    `SC_RD(ABoundPos, 0, 32, 32'(boundary_pos_i));
    `SC_RD(AIrqStat, 0, IrqW, irq_st_q);
    `SC_RD(AIrqEn, sc_pkg::IrqEnableLsb, IrqW, irq_en_q);
    `SC_RD(APulseTime, sc_pkg::PulseHighLsb, PulseTimeW, high_q);
    `SC_RD(APulseTime, sc_pkg::PulseLowLsb, PulseTimeW, low_q);
    `SC_RD(ADirTime, sc_pkg::DirSetupLsb, PulseTimeW, setup_q);
    `SC_RD(ADirTime, sc_pkg::DirHoldLsb, PulseTimeW, hold_q);
    `SC_RD(AFrac0, 0, 32, frac0_q[31:0]);
    `SC_RD(AFrac1, 0, 32, frac0_q[63:32]);
    `SC_RD(AFrac2, 0, FracBits - 64, frac0_q[FracBits-1:64]);
    `SC_RD(ASegPhase, sc_pkg::SegPhaseLsb, PhaseW, st_phase_q);
    `SC_RD(ASegClocks, 0, 32, st_clocks_q);
    `SC_RD(AJerk0, 0, 32, st_jerk_q[31:0]);
    `SC_RD(AJerk1, 0, JerkW - 32, st_jerk_q[JerkW-1:32]);
    `SC_RD(AStopJ0, 0, 32, stop_jerk_q[31:0]);
    `SC_RD(AStopJ1, 0, JerkW - 32, stop_jerk_q[JerkW-1:32]);
    `SC_RD(AStopA0, 0, 32, stop_acc_q[31:0]);
    `SC_RD(AStopA1, 0, 32, stop_acc_q[AccW-1:32]);
    `SC_RD(AGuardV0, 0, 32, guard_vel_q[31:0]);
    `SC_RD(AGuardV1, 0, 32, guard_vel_q[63:32]);
    `SC_RD(AGuardV2, 0, VelW - 64, guard_vel_q[VelW-1:64]);
    `SC_RD(AGuardA0, 0, 32, guard_acc_q[31:0]);
    `SC_RD(AGuardA1, 0, 32, guard_acc_q[AccW-1:32]);
    `SC_RD(AGuardJ0, 0, 32, guard_jerk_q[31:0]);
    `SC_RD(AGuardJ1, 0, JerkW - 32, guard_jerk_q[JerkW-1:32]);
    `SC_RD(ASoftMin, 0, 32, 32'(soft_min_q));
    `SC_RD(ASoftMax, 0, 32, 32'(soft_max_q));
    `SC_RD(ARowCount, 0, 32, 32'(row_count_i));
    `SC_RD(ARetarget, 0, 32, 32'(retarget_q));
    `SC_RD(AAcc0, 0, 32, st_acc0_q[31:0]);
    `SC_RD(AAcc1, 0, 32, st_acc0_q[63:32]);
    `SC_RD(AVel0, 0, 32, st_vel0_q[31:0]);
    `SC_RD(AVel1, 0, 32, st_vel0_q[63:32]);
    `SC_RD(AVel2, 0, VelW - 64, st_vel0_q[VelW-1:64]);
    if (Servo) begin
      for (int i = 0; i < NCfg; i++) `SC_RD(sc_pkg::RegClFirst + 4 * i, 0, 32, cl_q[32*i +: 32]);
      for (int i = 0; i < NStat; i++) `SC_RD(sc_pkg::RegClStat + 4 * i, 0, 32, cl_stat_i[32*i +: 32]);
    end
    rd_words = w;
  end
  `undef SC_RD

  // The words that answer a read (CMD and ROW_PUSH read 0); DECERR for the
  // rest, including unaligned addresses.
  assign r_word = s_axi_araddr_i[AW-2:2];
  always_comb begin
    unique case (s_axi_araddr_i)
      AId, ACtrl, ACmd, AStatus, AErr, ASwCfg, ALatchCfg, ALatchPul, ALatchEnc, APulseCnt, ARefPos,
      AEncPos, AFollowErr, AFifoStat, AFifoLow, AMoveIdx, ABoundPos, AIrqStat, AIrqEn, APulseTime,
      ADirTime, AFrac0, AFrac1, AFrac2, ASegPhase, ASegClocks, AJerk0, AJerk1, AStopJ0, AStopJ1,
      AStopA0, AStopA1, AGuardV0, AGuardV1, AGuardV2, AGuardA0, AGuardA1, AGuardJ0, AGuardJ1,
      ASoftMin, ASoftMax, ARowCount, ARetarget, AAcc0, AAcc1, AVel0, AVel1, AVel2,
      ARowPush: r_known = 1'b1;
      default: r_known = Servo && s_axi_araddr_i[1:0] == 2'b00 &&
                         ((s_axi_araddr_i >= AW'(sc_pkg::RegClFirst) &&
                           s_axi_araddr_i < AW'(sc_pkg::RegClFirst + 4 * NCfg)) ||
                          (s_axi_araddr_i >= AW'(sc_pkg::RegClStat) &&
                           s_axi_araddr_i < AW'(sc_pkg::RegClStat + 4 * NStat)));
    endcase
  end
  assign rd_word = r_known ? rd_words[32*r_word +: 32] : '0;
  assign rd_resp = r_known ? RespOkay : RespDecErr;

  // ---- next state ------------------------------------------------------------
  always_comb begin
    aw_full_d    = aw_full_q;
    awaddr_d     = awaddr_q;
    w_full_d     = w_full_q;
    wdata_d      = wdata_q;
    wstrb_d      = wstrb_q;
    bvalid_d     = bvalid_q;
    bresp_d      = bresp_q;
    rvalid_d     = rvalid_q;
    rresp_d      = rresp_q;
    rdata_d      = rdata_q;
    en_d         = en_q;
    closed_d     = closed_q;
    cl_we        = 1'b0;
    low_water_d  = low_water_q;
    irq_en_d     = irq_en_q;
    irq_st_d     = irq_st_q;
    high_d       = high_q;
    low_d        = low_q;
    setup_d      = setup_q;
    hold_d       = hold_q;
    frac0_d      = frac0_q;
    st_phase_d   = st_phase_q;
    st_clocks_d  = st_clocks_q;
    st_jerk_d    = st_jerk_q;
    st_acc0_d    = st_acc0_q;
    st_vel0_d    = st_vel0_q;
    push_d       = 1'b0;
    replace_d    = 1'b0;
    retarget_d   = retarget_q;
    err_retarget_d = err_retarget_q;
    push_flags_d = push_flags_q;
    flush_d      = 1'b0;
    start_d      = 1'b0;
    abort_d      = 1'b0;
    stop_d       = 1'b0;
    stop_jerk_d  = stop_jerk_q;
    stop_acc_d   = stop_acc_q;
    guard_vel_d  = guard_vel_q;
    guard_acc_d  = guard_acc_q;
    guard_jerk_d = guard_jerk_q;
    err_reject_d = err_reject_q;
    err_bad_d    = err_bad_q;
    err_estop_d  = err_estop_q;
    err_full_d   = err_full_q;
    err_disc_d   = err_disc_q;
    err_under_d  = err_under_q;
    err_lneg_d   = err_lneg_q;
    err_lpos_d   = err_lpos_q;
    err_guard_d  = err_guard_q;
    err_soft_d   = err_soft_q;
    soft_en_d    = soft_en_q;
    soft_min_d   = soft_min_q;
    soft_max_d   = soft_max_q;
    sw_inv_d     = sw_inv_q;
    lim_en_d     = lim_en_q;
    lim_hard_d   = lim_hard_q;
    sw_deb_d     = sw_deb_q;
    latch_rise_d = latch_rise_q;
    latch_src_d  = latch_src_q;
    latch_fall_d = latch_fall_q;
    latched_d    = latched_q;
    latch_pulse_d = latch_pulse_q;
    latch_enc_d  = latch_enc_q;
    set_reject   = 1'b0;
    set_bad      = 1'b0;

    // AXI handshakes
    if (s_axi_awvalid_i && !aw_full_q) begin
      aw_full_d = 1'b1;
      awaddr_d  = s_axi_awaddr_i;
    end
    if (s_axi_wvalid_i && !w_full_q) begin
      w_full_d = 1'b1;
      wdata_d  = s_axi_wdata_i;
      wstrb_d  = s_axi_wstrb_i;
    end
    if (bvalid_q && s_axi_bready_i) begin
      bvalid_d = 1'b0;
    end
    if (rvalid_q && s_axi_rready_i) begin
      rvalid_d = 1'b0;
    end

    // the write
    if (do_write) begin
      aw_full_d = 1'b0;
      w_full_d  = 1'b0;
      bvalid_d  = 1'b1;
      bresp_d   = RespOkay;
      if ((busy_eff && (w_locked || (awaddr_q == ACtrl && wstrb_q[0] &&
                                     wd[CtrlClosedBit] != closed_q))) ||
          (!group_i && w_group_only)) begin
        bresp_d    = RespSlvErr;
        set_reject = 1'b1;
      end else begin
        unique case (awaddr_q)
          AId, AStatus, APulseCnt, ARefPos, AEncPos, AFollowErr, AFifoStat, AMoveIdx, ABoundPos,
          ALatchPul, ALatchEnc, ARowCount: begin
            bresp_d = RespSlvErr;
            set_bad = 1'b1;
          end
          ACtrl: begin
            if (wstrb_q[0]) begin
              en_d     = wd[CtrlEnableBit];
              closed_d = wd[CtrlClosedBit];
            end
          end
          ACmd: begin
            if (wstrb_q[0]) begin
              if (wd[CmdEstopBit]) begin
                abort_d     = 1'b1;
                en_d        = 1'b0;
                err_estop_d = 1'b1;
              end else if (wd[CmdStopBit]) begin
                stop_d = 1'b1;
              end else if (wd[CmdStartBit]) begin
                if (busy_eff || err_estop_q || !en_q || !start_ok_i) begin
                  bresp_d    = RespSlvErr;
                  set_reject = 1'b1;
                end else begin
                  start_d = 1'b1;
                end
              end else if (wd[CmdFlushBit]) begin
                if (busy_eff) begin
                  bresp_d    = RespSlvErr;
                  set_reject = 1'b1;
                end else begin
                  flush_d = 1'b1;
                end
              end
            end
          end
          AErr: begin
            if (wstrb_q[0]) begin
              if (wd[ErrRejectBit])  err_reject_d = 1'b0;
              if (wd[ErrBadAddrBit]) err_bad_d    = 1'b0;
              if (wd[ErrEstopBit])   err_estop_d  = 1'b0;
              if (wd[ErrFifoFullBit]) err_full_d  = 1'b0;
              if (wd[ErrDiscontBit])  err_disc_d  = 1'b0;
              if (wd[ErrUnderrunBit]) err_under_d = 1'b0;
              if (wd[ErrLimNegBit])   err_lneg_d  = 1'b0;
              if (wd[ErrLimPosBit])   err_lpos_d  = 1'b0;
              if (wd[ErrGuardBit])    err_guard_d = 1'b0;
              if (wd[sc_pkg::ErrSoftLimBit]) err_soft_d = 1'b0;
              if (wd[sc_pkg::ErrRetargetBit]) err_retarget_d = 1'b0;
            end
          end
          AIrqStat: begin
            if (wstrb_q[0]) irq_st_d = irq_st_q & ~wd[IrqW-1:0];
          end
          AIrqEn:   irq_en_d = IrqW'(wmerge(32'(irq_en_q) << sc_pkg::IrqEnableLsb, wd, wmask)
                                     >> sc_pkg::IrqEnableLsb);
          ASwCfg: begin
            sw_inv_d   = sw_cfg_new[sc_pkg::SwInvertLsb +: SwW];
            lim_en_d   = sw_cfg_new[sc_pkg::SwLimEnBit];
            lim_hard_d = sw_cfg_new[sc_pkg::SwLimHardBit];
            soft_en_d  = sw_cfg_new[sc_pkg::SwSoftEnBit];
            sw_deb_d   = sw_cfg_new[sc_pkg::SwDebounceLsb +: DebounceW];
          end
          ALatchCfg: begin
            if (wstrb_q[0]) begin
              if (wd[sc_pkg::LatchSrcLsb +: sc_pkg::LatchSrcW] > sc_pkg::LatchSrcW'(sc_pkg::LatchSrcIndex)) begin
                bresp_d    = RespSlvErr;  // no such input: nothing changes
                set_reject = 1'b1;
              end else begin
                latch_rise_d = wd[sc_pkg::LatchRiseBit];
                latch_src_d  = wd[sc_pkg::LatchSrcLsb +: sc_pkg::LatchSrcW];
                latch_fall_d = wd[sc_pkg::LatchFallBit];
                latched_d    = 1'b0;
              end
            end
          end
          AFifoLow: low_water_d = RowLevelW'(wmerge(32'(low_water_q) << sc_pkg::FifoLowLsb, wd, wmask)
                                             >> sc_pkg::FifoLowLsb);
          APulseTime: begin
            if (pulse_new[sc_pkg::PulseHighLsb +: PulseTimeW] == '0 ||
                pulse_new[sc_pkg::PulseLowLsb +: PulseTimeW] == '0) begin
              bresp_d    = RespSlvErr;  // a pulse time of 0 clocks: nothing changes
              set_reject = 1'b1;
            end else begin
              high_d = pulse_new[sc_pkg::PulseHighLsb +: PulseTimeW];
              low_d  = pulse_new[sc_pkg::PulseLowLsb +: PulseTimeW];
            end
          end
          ADirTime: begin
            setup_d = PulseTimeW'(wmerge(32'(setup_q) << sc_pkg::DirSetupLsb, wd, wmask)
                                  >> sc_pkg::DirSetupLsb);
            hold_d  = PulseTimeW'(wmerge(32'(hold_q) << sc_pkg::DirHoldLsb, wd, wmask)
                                  >> sc_pkg::DirHoldLsb);
          end
          AFrac0:     frac0_d[31:0]  = wmerge(frac0_q[31:0], wd, wmask);
          AFrac1:     frac0_d[63:32] = wmerge(frac0_q[63:32], wd, wmask);
          AFrac2:     frac0_d[FracBits-1:64] =
                          (FracBits-64)'(wmerge(32'(frac0_q[FracBits-1:64]), wd, wmask));
          ASegPhase:  st_phase_d = PhaseW'(wmerge(32'(st_phase_q) << sc_pkg::SegPhaseLsb, wd, wmask)
                                           >> sc_pkg::SegPhaseLsb);
          ASegClocks: st_clocks_d = wmerge(st_clocks_q, wd, wmask);
          AJerk0:     st_jerk_d[31:0] = wmerge(st_jerk_q[31:0], wd, wmask);
          AJerk1:     st_jerk_d[JerkW-1:32] = (JerkW-32)'(wmerge(32'(st_jerk_q[JerkW-1:32]), wd, wmask));
          AStopJ0:    stop_jerk_d[31:0] = wmerge(stop_jerk_q[31:0], wd, wmask);
          AStopJ1:    stop_jerk_d[JerkW-1:32] = (JerkW-32)'(wmerge(32'(stop_jerk_q[JerkW-1:32]), wd, wmask));
          AStopA0:    stop_acc_d[31:0] = wmerge(stop_acc_q[31:0], wd, wmask);
          AStopA1:    stop_acc_d[AccW-1:32] = wmerge(stop_acc_q[AccW-1:32], wd, wmask);
          AGuardV0:   guard_vel_d[31:0]  = wmerge(guard_vel_q[31:0], wd, wmask);
          AGuardV1:   guard_vel_d[63:32] = wmerge(guard_vel_q[63:32], wd, wmask);
          AGuardV2:   guard_vel_d[VelW-1:64] =
                          (VelW-64)'(wmerge(32'(guard_vel_q[VelW-1:64]), wd, wmask));
          AGuardA0:   guard_acc_d[31:0] = wmerge(guard_acc_q[31:0], wd, wmask);
          AGuardA1:   guard_acc_d[AccW-1:32] = wmerge(guard_acc_q[AccW-1:32], wd, wmask);
          AGuardJ0:   guard_jerk_d[31:0] = wmerge(guard_jerk_q[31:0], wd, wmask);
          AGuardJ1:   guard_jerk_d[JerkW-1:32] =
                          (JerkW-32)'(wmerge(32'(guard_jerk_q[JerkW-1:32]), wd, wmask));
          ASoftMin:   soft_min_d = wmerge(soft_min_q, wd, wmask);
          ASoftMax:   soft_max_d = wmerge(soft_max_q, wd, wmask);
          ARetarget:  retarget_d = wmerge(retarget_q, wd, wmask);
          AAcc0:      st_acc0_d[31:0]  = wmerge(st_acc0_q[31:0], wd, wmask);
          AAcc1:      st_acc0_d[63:32] = wmerge(st_acc0_q[63:32], wd, wmask);
          AVel0:      st_vel0_d[31:0]  = wmerge(st_vel0_q[31:0], wd, wmask);
          AVel1:      st_vel0_d[63:32] = wmerge(st_vel0_q[63:32], wd, wmask);
          AVel2:      st_vel0_d[VelW-1:64] = (VelW-64)'(wmerge(32'(st_vel0_q[VelW-1:64]), wd, wmask));
          ARowPush: begin
            if (wstrb_q[0]) begin
              // A replace drops queued rows: the executor decides, not the level.
              if (fifo_full_i && !wd[sc_pkg::RowPushReplaceBit]) begin
                bresp_d    = RespSlvErr;
                err_full_d = 1'b1;
              end else begin
                push_d       = 1'b1;
                replace_d    = wd[sc_pkg::RowPushReplaceBit];
                push_flags_d[sc_pkg::RowFlagMoveEnd]   = wd[sc_pkg::RowPushMoveEndBit];
                push_flags_d[sc_pkg::RowFlagStreamEnd] = wd[sc_pkg::RowPushStreamEndBit];
                push_flags_d[sc_pkg::RowFlagAccStep]   = wd[sc_pkg::RowPushAccStepBit];
                push_flags_d[sc_pkg::RowFlagHold]      = wd[sc_pkg::RowPushHoldBit];
              end
            end
          end
          default: begin
            if (w_cfg_hit) begin
              cl_we = 1'b1;
            end else if (w_st_hit) begin
              bresp_d = RespSlvErr;
              set_bad = 1'b1;
            end else begin
              bresp_d = RespDecErr;
              set_bad = 1'b1;
            end
          end
        endcase
      end
    end

    // the read
    if (do_read) begin
      rvalid_d = 1'b1;
      rdata_d  = rd_word;
      rresp_d  = rd_resp;
      if (rd_resp != RespOkay) set_bad = 1'b1;
    end

    // e-stop input: overrides everything
    if (estop_i) begin
      abort_d     = 1'b1;
      en_d        = 1'b0;
      start_d     = 1'b0;
      err_estop_d = 1'b1;
    end

    // sticky flags: setting wins over a clear in the same clock
    if (set_reject) err_reject_d = 1'b1;
    if (set_bad)    err_bad_d    = 1'b1;
    if (discont_i && !discont_prev_q)   err_disc_d  = 1'b1;
    if (underrun_i && !underrun_prev_q) err_under_d = 1'b1;
    if (lim_trip_rev_i)                 err_lneg_d  = 1'b1;
    if (lim_trip_fwd_i)                 err_lpos_d  = 1'b1;
    if (guard_i && !guard_prev_q)       err_guard_d = 1'b1;
    if (retarget_refused_i)             err_retarget_d = 1'b1;
    if ((lim_trip_fwd_i && soft_fwd) || (lim_trip_rev_i && soft_rev)) err_soft_d = 1'b1;
    if (reach_i && !reach_prev_q)       err_soft_d  = 1'b1;
    if (sw_edge_i != '0)                irq_st_d[sc_pkg::IrqSwitchBit]   = 1'b1;
    // a capture wins over a re-arm in the same clock (the edge is not lost)
    if (latch_cap) begin
      latched_d     = 1'b1;
      latch_pulse_d = pulse_count_i;
      latch_enc_d   = enc_pos_i;
      irq_st_d[sc_pkg::IrqLatchBit] = 1'b1;
    end
    if (below && !below_q)              irq_st_d[sc_pkg::IrqLowWaterBit] = 1'b1;
    if (move_done_i)                    irq_st_d[sc_pkg::IrqMoveDoneBit] = 1'b1;
    if (busy_prev_q && !busy_eff)       irq_st_d[sc_pkg::IrqIdleBit]     = 1'b1;
    if (underrun_i && !underrun_prev_q) irq_st_d[sc_pkg::IrqUnderrunBit] = 1'b1;
    if ((fault_any && !fault_prev_q) || (discont_i && !discont_prev_q) ||
        (guard_i && !guard_prev_q) || (reach_i && !reach_prev_q))
                                        irq_st_d[sc_pkg::IrqFaultBit]    = 1'b1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      aw_full_q    <= 1'b0;
      awaddr_q     <= '0;
      w_full_q     <= 1'b0;
      wdata_q      <= '0;
      wstrb_q      <= '0;
      bvalid_q     <= 1'b0;
      bresp_q      <= RespOkay;
      rvalid_q     <= 1'b0;
      rresp_q      <= RespOkay;
      rdata_q      <= '0;
      en_q         <= 1'b0;
      closed_q     <= 1'b0;
      low_water_q  <= RowLevelW'(sc_pkg::RstFifoLow);
      irq_en_q     <= '0;
      irq_st_q     <= '0;
      irq_q        <= 1'b0;
      below_q      <= 1'b0;
      busy_prev_q  <= 1'b0;
      underrun_prev_q <= 1'b0;
      fault_prev_q <= 1'b0;
      discont_prev_q <= 1'b0;
      guard_prev_q <= 1'b0;
      reach_prev_q <= 1'b0;
      high_q       <= PulseTimeW'(sc_pkg::RstPulseHigh);
      low_q        <= PulseTimeW'(sc_pkg::RstPulseLow);
      setup_q      <= PulseTimeW'(sc_pkg::RstDirSetup);
      hold_q       <= PulseTimeW'(sc_pkg::RstDirHold);
      frac0_q      <= '0;
      st_phase_q   <= '0;
      st_clocks_q  <= '0;
      st_jerk_q    <= '0;
      st_acc0_q    <= '0;
      st_vel0_q    <= '0;
      push_q       <= 1'b0;
      replace_q    <= 1'b0;
      retarget_q   <= '0;
      err_retarget_q <= 1'b0;
      push_flags_q <= '0;
      flush_q      <= 1'b0;
      start_q      <= 1'b0;
      start_d1_q   <= 1'b0;
      abort_q      <= 1'b0;
      stop_q       <= 1'b0;
      stop_jerk_q  <= sc_pkg::StopJerkReset;
      stop_acc_q   <= sc_pkg::StopAccReset;
      guard_vel_q  <= '0;
      guard_acc_q  <= '0;
      guard_jerk_q <= '0;
      err_reject_q <= 1'b0;
      err_bad_q    <= 1'b0;
      err_estop_q  <= 1'b0;
      err_full_q   <= 1'b0;
      err_disc_q   <= 1'b0;
      err_under_q  <= 1'b0;
      err_lneg_q   <= 1'b0;
      err_lpos_q   <= 1'b0;
      err_guard_q  <= 1'b0;
      err_soft_q   <= 1'b0;
      soft_en_q    <= 1'b0;
      soft_min_q   <= '0;
      soft_max_q   <= '0;
      sw_inv_q     <= '0;
      lim_en_q     <= 1'b1;
      lim_hard_q   <= 1'b0;
      sw_deb_q     <= DebounceW'(sc_pkg::RstDebounce);
      latch_rise_q <= 1'b0;
      latch_src_q  <= '0;
      index_q      <= 1'b0;
      latch_fall_q <= 1'b0;
      latched_q    <= 1'b0;
      latch_pulse_q <= '0;
      latch_enc_q  <= '0;
    end else begin
      aw_full_q    <= aw_full_d;
      awaddr_q     <= awaddr_d;
      w_full_q     <= w_full_d;
      wdata_q      <= wdata_d;
      wstrb_q      <= wstrb_d;
      bvalid_q     <= bvalid_d;
      bresp_q      <= bresp_d;
      rvalid_q     <= rvalid_d;
      rresp_q      <= rresp_d;
      rdata_q      <= rdata_d;
      en_q         <= en_d;
      closed_q     <= closed_d;
      low_water_q  <= low_water_d;
      irq_en_q     <= irq_en_d;
      irq_st_q     <= irq_st_d;
      irq_q        <= |(irq_st_d & irq_en_d);
      below_q      <= below;
      busy_prev_q  <= busy_eff;
      underrun_prev_q <= underrun_i;
      fault_prev_q <= fault_any;
      discont_prev_q <= discont_i;
      guard_prev_q <= guard_i;
      reach_prev_q <= reach_i;
      high_q       <= high_d;
      low_q        <= low_d;
      setup_q      <= setup_d;
      hold_q       <= hold_d;
      frac0_q      <= frac0_d;
      st_phase_q   <= st_phase_d;
      st_clocks_q  <= st_clocks_d;
      st_jerk_q    <= st_jerk_d;
      st_acc0_q    <= st_acc0_d;
      st_vel0_q    <= st_vel0_d;
      push_q       <= push_d;
      replace_q    <= replace_d;
      retarget_q   <= retarget_d;
      err_retarget_q <= err_retarget_d;
      push_flags_q <= push_flags_d;
      flush_q      <= flush_d;
      start_q      <= start_d;
      start_d1_q   <= start_q;
      abort_q      <= abort_d;
      stop_q       <= stop_d;
      stop_jerk_q  <= stop_jerk_d;
      stop_acc_q   <= stop_acc_d;
      guard_vel_q  <= guard_vel_d;
      guard_acc_q  <= guard_acc_d;
      guard_jerk_q <= guard_jerk_d;
      err_reject_q <= err_reject_d;
      err_bad_q    <= err_bad_d;
      err_estop_q  <= err_estop_d;
      err_full_q   <= err_full_d;
      err_disc_q   <= err_disc_d;
      err_under_q  <= err_under_d;
      err_lneg_q   <= err_lneg_d;
      err_lpos_q   <= err_lpos_d;
      err_guard_q  <= err_guard_d;
      err_soft_q   <= err_soft_d;
      soft_en_q    <= soft_en_d;
      soft_min_q   <= soft_min_d;
      soft_max_q   <= soft_max_d;
      sw_inv_q     <= sw_inv_d;
      lim_en_q     <= lim_en_d;
      lim_hard_q   <= lim_hard_d;
      sw_deb_q     <= sw_deb_d;
      latch_rise_q <= latch_rise_d;
      latch_src_q  <= latch_src_d;
      index_q      <= enc_index_i;
      latch_fall_q <= latch_fall_d;
      latched_q    <= latched_d;
      latch_pulse_q <= latch_pulse_d;
      latch_enc_q  <= latch_enc_d;
    end
  end

  assign s_axi_awready_o = !aw_full_q;
  assign s_axi_wready_o  = !w_full_q;
  assign s_axi_bvalid_o  = bvalid_q;
  assign s_axi_bresp_o   = bresp_q;
  assign s_axi_arready_o = !rvalid_q;
  assign s_axi_rvalid_o  = rvalid_q;
  assign s_axi_rresp_o   = rresp_q;
  assign s_axi_rdata_o   = rdata_q;

  // One register per closed-loop word, written through its own enable: a
  // single wide vector written by a part-select loop made Verilator emit a
  // 44,000-line update function for the servo top.
  for (genvar i = 0; i < NCfg; i++) begin : g_cl_word
    logic [31:0] word_q;
    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        word_q <= ClReset[32*i +: 32];
      end else if (cl_we && w_cfg_idx == (AW-2)'(i)) begin
        word_q <= wmerge(word_q, wd, wmask) & ClMask[32*i +: 32];
      end
    end
    assign cl_q[32*i +: 32] = word_q;
  end

  assign enable_o    = en_q;
  assign cfg_high_o  = high_q;
  assign cfg_low_o   = low_q;
  assign cfg_setup_o = setup_q;
  assign cfg_hold_o  = hold_q;
  assign row_push_o  = push_q;
  assign row_replace_o = replace_q;
  assign retarget_row_o = retarget_q;
  assign row_flags_o = push_flags_q;
  assign row_phase_o = st_phase_q;
  assign row_clocks_o = st_clocks_q;
  assign row_jerk_o  = st_jerk_q;
  assign row_acc0_o  = st_acc0_q;
  assign row_vel0_o  = st_vel0_q;
  assign fifo_flush_o = flush_q;
  assign pos_frac0_o = frac0_q;
  assign start_o     = start_q;
  assign abort_o     = abort_q;
  assign stop_o      = stop_q;
  assign stop_jerk_o = stop_jerk_q;
  assign stop_acc_o  = stop_acc_q;
  assign guard_vel_o  = guard_vel_q;
  assign guard_acc_o  = guard_acc_q;
  assign guard_jerk_o = guard_jerk_q;
  assign soft_en_o    = soft_en_q;
  assign soft_min_o   = soft_min_q;
  assign soft_max_o   = soft_max_q;
  assign closed_loop_o = closed_q;
  assign ctl_cfg_o   = sc_pkg::ctl_cfg_from_words(cl_q);
  assign sw_invert_o = sw_inv_q;
  assign sw_debounce_o = sw_deb_q;
  assign lim_fwd_o   = (lim_en_q && sw_level_i[sc_pkg::SwLimPos]) || soft_fwd;
  assign lim_rev_o   = (lim_en_q && sw_level_i[sc_pkg::SwLimNeg]) || soft_rev;
  assign lim_hard_o  = lim_hard_q;
  assign busy_o      = busy_eff;
  assign irq_o       = irq_q;

`ifdef FORMAL
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // Slave side of AXI4-Lite, proven on this module alone: reset in the first
  // clock only; every other input (the bus master, the core) is free, so the
  // properties hold whatever the master does. The register map below is
  // written out again from docs/regmap.md (word addresses, bytes 0x000-0x3FF),
  // independent of the decode above.
  localparam logic [1:0] FUnmapped = 2'd0, FReadOnly = 2'd1, FWritable = 2'd2;

  function automatic logic [1:0] f_kind(input logic [AW-1:0] a);
    logic [AW-1:0] w;
    w = {a[AW-1:2], 2'b00};
    f_kind = FUnmapped;
    if (a[1:0] == 2'b00) begin
      unique case (w)
        10'h000, 10'h00C, 10'h014, 10'h018, 10'h01C, 10'h020, 10'h024, 10'h0CC, 10'h0F4,
        10'h118, 10'h11C, 10'h148: f_kind = FReadOnly;
        10'h004, 10'h008, 10'h010, 10'h028, 10'h02C, 10'h0F8, 10'h0FC: f_kind = FWritable;
        default: begin
          if ((w >= 10'h030 && w <= 10'h064) || (w >= 10'h100 && w <= 10'h128) ||
              (w >= 10'h130 && w <= 10'h144) || w == 10'h14C) begin
            f_kind = FWritable;
          end else if (Servo && w >= 10'h068 && w <= 10'h0C8) begin
            f_kind = FWritable;   // closed-loop settings
          end else if (Servo && w >= 10'h0D0 && w <= 10'h0F0) begin
            f_kind = FReadOnly;   // closed-loop status
          end
        end
      endcase
    end
  endfunction

  logic          f_init_q = 1'b1;   // the first clock of every trace
  logic [1:0]    f_aw_n_q, f_w_n_q; // AW / W accepted and not yet answered by a B handshake
  logic          f_ar_n_q;          // AR accepted, R handshake not yet done
  logic [AW-1:0] f_wr_addr_q, f_rd_addr_q;  // address of the last AW / AR accepted
  logic          f_bvalid_prev_q, f_bready_prev_q, f_rvalid_prev_q, f_rready_prev_q, f_ar_hs_prev_q;
  logic          f_both_prev_q;     // last clock: a whole write held, no response out
  logic [1:0]    f_bresp_prev_q, f_rresp_prev_q;
  logic [31:0]   f_rdata_prev_q;
  logic          f_aw_hs, f_w_hs, f_b_hs, f_ar_hs, f_r_hs, f_b_new, f_r_new;

  assign f_aw_hs = s_axi_awvalid_i && s_axi_awready_o;
  assign f_w_hs  = s_axi_wvalid_i && s_axi_wready_o;
  assign f_b_hs  = s_axi_bvalid_o && s_axi_bready_i;
  assign f_ar_hs = s_axi_arvalid_i && s_axi_arready_o;
  assign f_r_hs  = s_axi_rvalid_o && s_axi_rready_i;
  // the first clock of a response (not one still waiting for READY)
  assign f_b_new = s_axi_bvalid_o && !(f_bvalid_prev_q && !f_bready_prev_q);
  assign f_r_new = s_axi_rvalid_o && !(f_rvalid_prev_q && !f_rready_prev_q);

  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
    end
  end

  always_ff @(posedge clk_i) begin
    f_init_q <= 1'b0;
    if (!rst_ni) begin
      f_aw_n_q        <= '0;
      f_w_n_q         <= '0;
      f_ar_n_q        <= 1'b0;
      f_wr_addr_q     <= '0;
      f_rd_addr_q     <= '0;
      f_bvalid_prev_q <= 1'b0;
      f_bready_prev_q <= 1'b0;
      f_rvalid_prev_q <= 1'b0;
      f_rready_prev_q <= 1'b0;
      f_ar_hs_prev_q  <= 1'b0;
      f_both_prev_q   <= 1'b0;
      f_bresp_prev_q  <= '0;
      f_rresp_prev_q  <= '0;
      f_rdata_prev_q  <= '0;
    end else begin
      f_aw_n_q        <= f_aw_n_q + 2'(f_aw_hs) - 2'(f_b_hs);
      f_w_n_q         <= f_w_n_q + 2'(f_w_hs) - 2'(f_b_hs);
      f_ar_n_q        <= f_ar_hs ? 1'b1 : (f_r_hs ? 1'b0 : f_ar_n_q);
      if (f_aw_hs) f_wr_addr_q <= s_axi_awaddr_i;
      if (f_ar_hs) f_rd_addr_q <= s_axi_araddr_i;
      f_bvalid_prev_q <= s_axi_bvalid_o;
      f_bready_prev_q <= s_axi_bready_i;
      f_rvalid_prev_q <= s_axi_rvalid_o;
      f_rready_prev_q <= s_axi_rready_i;
      f_ar_hs_prev_q  <= f_ar_hs;
      f_both_prev_q   <= aw_full_q && w_full_q && !s_axi_bvalid_o;
      f_bresp_prev_q  <= s_axi_bresp_o;
      f_rresp_prev_q  <= s_axi_rresp_o;
      f_rdata_prev_q  <= s_axi_rdata_o;
    end
  end

  always_comb begin
    if (!f_init_q) begin
      // -- group handshake: a VALID waits for its READY with its payload held
      p_b_hold: assert (!(f_bvalid_prev_q && !f_bready_prev_q) ||
                        (s_axi_bvalid_o && s_axi_bresp_o == f_bresp_prev_q));
      p_r_hold: assert (!(f_rvalid_prev_q && !f_rready_prev_q) ||
                        (s_axi_rvalid_o && s_axi_rresp_o == f_rresp_prev_q &&
                         s_axi_rdata_o == f_rdata_prev_q));
      // -- group response: no response without a request, one per request,
      // and it comes: B the clock after AW and W are both held (no B pending),
      // R the clock after the AR handshake
      p_b_needs_req: assert (!s_axi_bvalid_o || (f_aw_n_q != '0 && f_w_n_q != '0));
      p_b_prompt: assert (!f_both_prev_q || s_axi_bvalid_o);
      p_r_needs_req: assert (!s_axi_rvalid_o || f_ar_n_q);
      p_r_prompt: assert (!f_ar_hs_prev_q || f_r_new);
      // helper invariants: at most one write held and one answered
      inv_aw_n: assert (f_aw_n_q == 2'(aw_full_q) + 2'(s_axi_bvalid_o));
      inv_w_n: assert (f_w_n_q == 2'(w_full_q) + 2'(s_axi_bvalid_o));
      inv_ar_n: assert (f_ar_n_q == s_axi_rvalid_o);
      inv_wr_addr: assert (!aw_full_q || f_wr_addr_q == awaddr_q);
      // -- group decode: the response code of a new response from the address
      p_b_slverr_ro: assert (!f_b_new || f_kind(f_wr_addr_q) != FReadOnly ||
                             s_axi_bresp_o == RespSlvErr);
      p_b_decerr: assert (!f_b_new || ((f_kind(f_wr_addr_q) == FUnmapped) ==
                                       (s_axi_bresp_o == RespDecErr)));
      p_b_no_exokay: assert (!s_axi_bvalid_o || s_axi_bresp_o != 2'b01);
      p_r_resp: assert (!f_r_new || s_axi_rresp_o ==
                        (f_kind(f_rd_addr_q) == FUnmapped ? RespDecErr : RespOkay));
      // -- group pulse_time: the step generator's input contract (sc_step_gen's
      // a_cfg_min) holds whatever the master writes
      p_pulse_nonzero: assert (cfg_high_o != '0 && cfg_low_o != '0);
    end
  end
`endif

endmodule
