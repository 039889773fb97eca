// sc_neuron_pi: the cascade of two single-neuron adaptive PI controllers
// (outer: position, inner: speed) on ONE microcoded datapath: a register
// file (LUT RAM, two read ports), one 34-bit adder/subtractor (saturating,
// compare flags), one signed MulAW x MulBW multiplier and one restoring
// divider (one quotient bit per clock) for the weight normalisation,
// sequenced once per control period (div clocks, e.g. 2000 = 10 kHz)
// by a micro-program of one operation per clock: 141 clocks of work per
// period (12 more after start_i to initialise), so div must be >= 256.
// Every word the datapath computes goes through the adder, the multiplier
// or the divider, so the LUTs are operand selection and one of each unit,
// not one unit per equation.
//
// Per period, for loop L = position then speed (docs/closed_loop.md):
//   wn_i   = w_i / (|w_1| + |w_2|)                     (divider, Q1.16)
//   e      = r - y ;  x1 = e ;  x2 = e - e_prev
//   du     = K * (wn_1 x1 + wn_2 x2)                   (incremental PI)
//   acc    = sat(acc + du - Kb * es_prev)              (back-calculation)
//   tot    = acc + b ;  out = clamp(tot, +-lim) ;  es = tot - out
//   w_i    = clamp(w_i + eta_i * e * x_i / 2^ls, wmin, wmax)   (Hebb;
//            no update while |e| <= learn_dz: dead-zone modification)
// position: r = P* - 1/2 (counts), y = P (encoder), b = 0, lim = v_lim;
// speed:    r = out_p + FF*V*, y = P - P_prev, b = FF*V*, lim = u_lim;
// u = out_speed drives the step NCO. Every product is rounded half up
// ((p + 2^(s-1)) >>> s) and saturated to the CtlW word.
// CL_CFG.PID: paper 003's fixed-gain PID with back-calculation instead, on
// the same steps: the position loop alone, learning off (fixed weights: P
// gain K wn_2, I gain K wn_1), the D term d = K_V x2 formed in the Learn
// step, tot = acc + d, limited to u_lim, out drives u; no speed loop.
// Following-error fault: |e_p| > ferr_lim latches; it stops the loop (u = 0)
// unless CL_CFG.FERR_STOP asks for a controlled stop of the reference, which
// the loop then keeps tracking to rest.
// Settling (after the reference is done): the PI accumulators are held at 0
// and u = 0 until, for `hold` consecutive periods, no step has been commanded
// (cmd_busy_i low) and the encoder has not moved (the rotor has stopped
// ringing). Then either |e_p| <=
// win (or e_p rounds to 0 whole steps) latches in_pos_o and stops the loop,
// or e_p, rounded to whole steps, is issued as corrective steps at
// +-settle_rate (counted on nco_req_i) and the wait starts again. A stepper
// at rest sits on its commanded step, so this ends without hunting on rotor
// ringing, where a PI on a quantised encoder would limit-cycle.
module sc_neuron_pi (
  input  logic                                clk_i,
  input  logic                                rst_ni,

  // controller configuration (fields: sc_pkg::CtlCfg*, docs/regmap.md)
  input  logic [sc_pkg::CtlCfgW-1:0]          ctl_cfg_i,

  input  logic                                start_i,
  input  logic                                stop_i,

  input  logic signed [sc_pkg::PosIntW-1:0]   ref_int_i,    // P* integer pulses
  input  logic [sc_pkg::CtlFrac-1:0]          ref_frac_i,   // P* fraction, top bits
  input  logic signed [sc_pkg::MulAW-1:0]     ref_vel_i,    // V*, Q.VffFrac pulses/clock
  input  logic                                ref_done_i,
  input  logic signed [sc_pkg::EncCntW-1:0]   enc_pos_i,
  input  logic                                cmd_busy_i,   // a step is requested/owed/on the pin
  input  logic                                nco_req_i,    // the NCO requests a step this clock

  output logic                                active_o,
  output logic                                in_pos_o,
  output logic                                fault_ferr_o,
  output logic signed [sc_pkg::CtlW-1:0]      u_o,
  output logic signed [sc_pkg::CtlW-1:0]      v_cmd_o,      // position-loop output
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
  output logic [sc_pkg::CtlStW-1:0]           state_o,
  // div << shift (clocks per period x counts per pulse), for the
  // step NCO's modulus: one shifter for both
  output logic [sc_pkg::CtlDivW+(1<<sc_pkg::EncShiftW)-2:0] div_sh_o
);

  localparam int CtlDivW  = sc_pkg::CtlDivW;
  localparam int CtlW     = sc_pkg::CtlW;
  localparam int CtlFrac  = sc_pkg::CtlFrac;
  localparam int WgtW     = sc_pkg::WgtW;
  localparam int NWgtW    = sc_pkg::NWgtW;
  localparam int NWgtFrac = sc_pkg::NWgtFrac;
  localparam int CoefFrac = sc_pkg::CoefFrac;
  localparam int MulAW    = sc_pkg::MulAW;
  localparam int MulBW    = sc_pkg::MulBW;
  localparam int VffFrac  = sc_pkg::VffFrac;
  localparam int HoldW    = sc_pkg::HoldW;
  localparam int CtlStW   = sc_pkg::CtlStW;
  localparam int LearnShW = sc_pkg::LearnShW;
  localparam int CorrW    = sc_pkg::CorrW;
  localparam int ProdW    = MulAW + MulBW;
  localparam int QuoW     = NWgtFrac + 1;   // |wn| <= 1.0
  localparam int RemW     = WgtW + 2;
  localparam int SumW     = WgtW + 1;
  localparam int DbitW    = 5;
  localparam int AluW     = CtlW + 2;       // exact sum/difference of two CtlW+1-bit words
  localparam int UpcW     = sc_pkg::UpcW;

  // state_o codes (sc_pkg::CtlSt*) and micro-program steps (sc_pkg::Upc*,
  // cmodel/neuron_pi.cpp runs the same list) come from sc_pkg.
  localparam int NInit = 32'(sc_pkg::UpcVff) - 32'(sc_pkg::UpcInit);  // Init steps

  // register file words; per-loop pairs at even addresses, + sel
  localparam logic [4:0] RfEp   = 5'd0;
  localparam logic [4:0] RfAcc  = 5'd2;
  localparam logic [4:0] RfEs   = 5'd4;
  localparam logic [4:0] RfW1   = 5'd6;
  localparam logic [4:0] RfW2   = 5'd8;
  localparam logic [4:0] RfN1   = 5'd10;
  localparam logic [4:0] RfN2   = 5'd12;
  localparam logic [4:0] RfOutP = 5'd14;
  localparam logic [4:0] RfVff  = 5'd15;
  localparam logic [4:0] RfE    = 5'd16;
  localparam logic [4:0] RfX2   = 5'd17;
  localparam logic [4:0] RfT1   = 5'd18;
  localparam logic [4:0] RfSum  = 5'd19;
  localparam logic [4:0] RfDu   = 5'd20;
  localparam logic [4:0] RfBc   = 5'd21;
  localparam logic [4:0] RfH    = 5'd22;
  localparam logic [4:0] RfDw   = 5'd23;
  localparam logic [4:0] RfEraw = 5'd24;
  localparam logic [4:0] RfT2   = 5'd25;
  localparam logic [4:0] RfTot  = 5'd26;

  // ---- configuration fields --------------------------------------------------------
  logic [sc_pkg::CtlCfgDivW-1:0] cfg_div;
  logic [sc_pkg::CtlCfgShiftW-1:0] cfg_shift;
  logic cfg_ff_en;
  logic cfg_ferr_stop;
  logic cfg_pid;
  logic [sc_pkg::CtlCfgLearnShiftW-1:0] cfg_learn_shift;
  logic [sc_pkg::CtlCfgLearnDzPW-1:0] cfg_learn_dz_p;
  logic [sc_pkg::CtlCfgLearnDzVW-1:0] cfg_learn_dz_v;
  logic [sc_pkg::CtlCfgKPW-1:0] cfg_k_p;
  logic [sc_pkg::CtlCfgKVW-1:0] cfg_k_v;
  logic [sc_pkg::CtlCfgKbW-1:0] cfg_kb;
  logic [sc_pkg::CtlCfgEtaP1W-1:0] cfg_eta_p1;
  logic [sc_pkg::CtlCfgEtaP2W-1:0] cfg_eta_p2;
  logic [sc_pkg::CtlCfgEtaV1W-1:0] cfg_eta_v1;
  logic [sc_pkg::CtlCfgEtaV2W-1:0] cfg_eta_v2;
  logic signed [sc_pkg::CtlCfgWP1W-1:0] cfg_w_p1;
  logic signed [sc_pkg::CtlCfgWP2W-1:0] cfg_w_p2;
  logic signed [sc_pkg::CtlCfgWV1W-1:0] cfg_w_v1;
  logic signed [sc_pkg::CtlCfgWV2W-1:0] cfg_w_v2;
  logic signed [sc_pkg::CtlCfgWMinW-1:0] cfg_w_min;
  logic signed [sc_pkg::CtlCfgWP1MaxW-1:0] cfg_w_p1_max;
  logic signed [sc_pkg::CtlCfgWP2MaxW-1:0] cfg_w_p2_max;
  logic signed [sc_pkg::CtlCfgWV1MaxW-1:0] cfg_w_v1_max;
  logic signed [sc_pkg::CtlCfgWV2MaxW-1:0] cfg_w_v2_max;
  logic [sc_pkg::CtlCfgVLimW-1:0] cfg_v_lim;
  logic [sc_pkg::CtlCfgULimW-1:0] cfg_u_lim;
  logic [sc_pkg::CtlCfgFerrLimW-1:0] cfg_ferr_lim;
  logic [sc_pkg::CtlCfgInposWinW-1:0] cfg_inpos_win;
  logic [sc_pkg::CtlCfgInposHoldW-1:0] cfg_inpos_hold;
  logic [sc_pkg::CtlCfgSettleRateW-1:0] cfg_settle_rate;
  assign cfg_div = ctl_cfg_i[sc_pkg::CtlCfgDivLsb +: sc_pkg::CtlCfgDivW];
  assign cfg_shift = ctl_cfg_i[sc_pkg::CtlCfgShiftLsb +: sc_pkg::CtlCfgShiftW];
  assign cfg_ff_en = ctl_cfg_i[sc_pkg::CtlCfgFfEnLsb];
  assign cfg_ferr_stop = ctl_cfg_i[sc_pkg::CtlCfgFerrStopLsb];
  assign cfg_pid = ctl_cfg_i[sc_pkg::CtlCfgPidLsb];
  assign cfg_learn_shift = ctl_cfg_i[sc_pkg::CtlCfgLearnShiftLsb +: sc_pkg::CtlCfgLearnShiftW];
  assign cfg_learn_dz_p = ctl_cfg_i[sc_pkg::CtlCfgLearnDzPLsb +: sc_pkg::CtlCfgLearnDzPW];
  assign cfg_learn_dz_v = ctl_cfg_i[sc_pkg::CtlCfgLearnDzVLsb +: sc_pkg::CtlCfgLearnDzVW];
  assign cfg_k_p = ctl_cfg_i[sc_pkg::CtlCfgKPLsb +: sc_pkg::CtlCfgKPW];
  assign cfg_k_v = ctl_cfg_i[sc_pkg::CtlCfgKVLsb +: sc_pkg::CtlCfgKVW];
  assign cfg_kb = ctl_cfg_i[sc_pkg::CtlCfgKbLsb +: sc_pkg::CtlCfgKbW];
  assign cfg_eta_p1 = ctl_cfg_i[sc_pkg::CtlCfgEtaP1Lsb +: sc_pkg::CtlCfgEtaP1W];
  assign cfg_eta_p2 = ctl_cfg_i[sc_pkg::CtlCfgEtaP2Lsb +: sc_pkg::CtlCfgEtaP2W];
  assign cfg_eta_v1 = ctl_cfg_i[sc_pkg::CtlCfgEtaV1Lsb +: sc_pkg::CtlCfgEtaV1W];
  assign cfg_eta_v2 = ctl_cfg_i[sc_pkg::CtlCfgEtaV2Lsb +: sc_pkg::CtlCfgEtaV2W];
  assign cfg_w_p1 = ctl_cfg_i[sc_pkg::CtlCfgWP1Lsb +: sc_pkg::CtlCfgWP1W];
  assign cfg_w_p2 = ctl_cfg_i[sc_pkg::CtlCfgWP2Lsb +: sc_pkg::CtlCfgWP2W];
  assign cfg_w_v1 = ctl_cfg_i[sc_pkg::CtlCfgWV1Lsb +: sc_pkg::CtlCfgWV1W];
  assign cfg_w_v2 = ctl_cfg_i[sc_pkg::CtlCfgWV2Lsb +: sc_pkg::CtlCfgWV2W];
  assign cfg_w_min = ctl_cfg_i[sc_pkg::CtlCfgWMinLsb +: sc_pkg::CtlCfgWMinW];
  assign cfg_w_p1_max = ctl_cfg_i[sc_pkg::CtlCfgWP1MaxLsb +: sc_pkg::CtlCfgWP1MaxW];
  assign cfg_w_p2_max = ctl_cfg_i[sc_pkg::CtlCfgWP2MaxLsb +: sc_pkg::CtlCfgWP2MaxW];
  assign cfg_w_v1_max = ctl_cfg_i[sc_pkg::CtlCfgWV1MaxLsb +: sc_pkg::CtlCfgWV1MaxW];
  assign cfg_w_v2_max = ctl_cfg_i[sc_pkg::CtlCfgWV2MaxLsb +: sc_pkg::CtlCfgWV2MaxW];
  assign cfg_v_lim = ctl_cfg_i[sc_pkg::CtlCfgVLimLsb +: sc_pkg::CtlCfgVLimW];
  assign cfg_u_lim = ctl_cfg_i[sc_pkg::CtlCfgULimLsb +: sc_pkg::CtlCfgULimW];
  assign cfg_ferr_lim = ctl_cfg_i[sc_pkg::CtlCfgFerrLimLsb +: sc_pkg::CtlCfgFerrLimW];
  assign cfg_inpos_win = ctl_cfg_i[sc_pkg::CtlCfgInposWinLsb +: sc_pkg::CtlCfgInposWinW];
  assign cfg_inpos_hold = ctl_cfg_i[sc_pkg::CtlCfgInposHoldLsb +: sc_pkg::CtlCfgInposHoldW];
  assign cfg_settle_rate = ctl_cfg_i[sc_pkg::CtlCfgSettleRateLsb +: sc_pkg::CtlCfgSettleRateW];
  logic [sc_pkg::CtlCfgEncFiltW-1:0] unused_enc_filt;  // the decoder's field
  assign unused_enc_filt = ctl_cfg_i[sc_pkg::CtlCfgEncFiltLsb +: sc_pkg::CtlCfgEncFiltW];

  // operand sources
  localparam logic [1:0] ARf = 2'd0, AT = 2'd1, ARef = 2'd2, AZero = 2'd3;
  localparam logic [2:0] BRf = 3'd0, BCfg = 3'd1, BPfb = 3'd2, BVmeas = 3'd3, BZero = 3'd4;
  // configuration words on the B port (and the multiplier's B operand)
  localparam logic [4:0] CfDzP = 5'd0, CfDzV = 5'd1, CfFerr = 5'd2, CfWin = 5'd3, CfVLim = 5'd4,
                         CfULim = 5'd5, CfWMin = 5'd6, CfWP1Max = 5'd7, CfWV1Max = 5'd8,
                         CfWP2Max = 5'd9, CfWV2Max = 5'd10, CfWP1 = 5'd11, CfWV1 = 5'd12,
                         CfWP2 = 5'd13, CfWV2 = 5'd14, CfKP = 5'd15, CfKV = 5'd16, CfKb = 5'd17,
                         CfEtaP1 = 5'd18, CfEtaV1 = 5'd19, CfEtaP2 = 5'd20, CfEtaV2 = 5'd21;
  // register-file write data
  localparam logic [2:0] WWrap = 3'd0, WSat = 3'd1, WMul = 3'd2, WDiv = 3'd3, WZero = 3'd4;
  // multiplier operands
  localparam logic [1:0] MbRf = 2'd0, MbCfg = 2'd1, MbEb = 2'd2, MbDivSh = 2'd3;

  localparam logic signed [CtlW-1:0]  CtlMax = {1'b0, {(CtlW-1){1'b1}}};
  localparam logic signed [CtlW-1:0]  CtlMin = {1'b1, {(CtlW-1){1'b0}}};
  localparam logic signed [MulBW-1:0] BMax   = {1'b0, {(MulBW-1){1'b1}}};

  // ---- state ---------------------------------------------------------------------
  logic                      active_q, active_d;
  logic                      in_pos_q, in_pos_d;
  logic                      ferr_q, ferr_d;
  logic [CtlDivW-1:0]        cnt_q, cnt_d;
  logic [UpcW-1:0]           upc_q, upc_d;
  logic                      sel_q, sel_d;      // 0 = position loop, 1 = speed loop
  logic [DbitW-1:0]          dbit_q, dbit_d;
  logic [RemW-1:0]           drem_q, drem_d;
  logic [QuoW-1:0]           dquo_q, dquo_d;
  logic [SumW-1:0]           dsum_q, dsum_d;
  logic [HoldW-1:0]          hold_q, hold_d;
  logic                      hush_q, hush_d;    // settling: accumulators held at 0
  logic signed [CorrW-1:0]   corr_q, corr_d;    // corrective steps still to issue
  logic                      learn_q, learn_d;  // |e| > learning dead zone
  logic                      eq_q, eq_d;        // e_p unchanged since the last period
  logic                      over_q, over_d;    // weight sum above its upper bound
  logic                      under_q, under_d;  // ... below the lower bound
  logic signed [AluW-1:0]    t_q, t_d;          // exact intermediate
  logic signed [CtlW-1:0]    eraw_q, eraw_d;    // e_p for the corrective steps
  // control-period snapshot
  logic signed [CtlW-1:0]    ref_q, ref_d;      // P* - 1/2, counts Q.CtlFrac
  logic signed [CtlW-1:0]    pfb_q, pfb_d;      // P
  logic signed [CtlW-1:0]    vmeas_q, vmeas_d;  // P - P_prev
  logic signed [MulAW-1:0]   vq_q, vq_d;        // V*, Q.VffFrac pulses/clock
  logic                      fin_q, fin_d;
  logic                      mv_q, mv_d;        // cmd_busy_i seen since the last snapshot
  logic                      mvs_q, mvs_d;      // ... in the period before the snapshot
  // outputs (copies of register-file words, written with them)
  logic signed [CtlW-1:0]    u_q, u_d, vcmd_q, vcmd_d, ep_p_q, ep_p_d, ep_v_q, ep_v_d;
  logic signed [WgtW-1:0]    w_p1_q, w_p1_d, w_p2_q, w_p2_d, w_v1_q, w_v1_d, w_v2_q, w_v2_d;
  logic signed [NWgtW-1:0]   n_p1_q, n_p1_d, n_p2_q, n_p2_d, n_v1_q, n_v1_d, n_v2_q, n_v2_d;

  // register file: LUT RAM, written once per clock, read combinationally.
  // No reset: every word is written (by the initialisation steps after
  // start_i, or earlier in the period) before a step reads it.
  logic [CtlW-1:0] rf_q [32];
  logic [4:0]      ra, rb, rf_wa;
  logic            rf_we;
  logic [CtlW-1:0] rf_a, rf_b, rf_wd;
  assign rf_a = rf_q[ra];
  assign rf_b = rf_q[rb];

  always_ff @(posedge clk_i) begin
    if (rf_we) rf_q[rf_wa] <= rf_wd;
  end

  // ---- configuration word for the B port --------------------------------------------
  logic [4:0]             cfg_sel;
  logic signed [AluW-1:0] cfg_val;   // unsigned words zero-, weights sign-extended
  always_comb begin
    unique case (cfg_sel)
      CfDzP:    cfg_val = AluW'({2'b00, cfg_learn_dz_p});
      CfDzV:    cfg_val = AluW'({2'b00, cfg_learn_dz_v});
      CfFerr:   cfg_val = AluW'({2'b00, cfg_ferr_lim});
      CfWin:    cfg_val = AluW'({2'b00, cfg_inpos_win});
      CfVLim:   cfg_val = AluW'({2'b00, cfg_v_lim});
      CfULim:   cfg_val = AluW'({2'b00, cfg_u_lim});
      CfWMin:   cfg_val = AluW'(cfg_w_min);
      CfWP1Max: cfg_val = AluW'(cfg_w_p1_max);
      CfWV1Max: cfg_val = AluW'(cfg_w_v1_max);
      CfWP2Max: cfg_val = AluW'(cfg_w_p2_max);
      CfWV2Max: cfg_val = AluW'(cfg_w_v2_max);
      CfWP1:    cfg_val = AluW'(cfg_w_p1);
      CfWV1:    cfg_val = AluW'(cfg_w_v1);
      CfWP2:    cfg_val = AluW'(cfg_w_p2);
      CfWV2:    cfg_val = AluW'(cfg_w_v2);
      CfKP:     cfg_val = AluW'({1'b0, cfg_k_p});
      CfKV:     cfg_val = AluW'({1'b0, cfg_k_v});
      CfKb:     cfg_val = AluW'({1'b0, cfg_kb});
      CfEtaP1:  cfg_val = AluW'({1'b0, cfg_eta_p1});
      CfEtaV1:  cfg_val = AluW'({1'b0, cfg_eta_v1});
      CfEtaP2:  cfg_val = AluW'({1'b0, cfg_eta_p2});
      CfEtaV2:  cfg_val = AluW'({1'b0, cfg_eta_v2});
      default:  cfg_val = '0;
    endcase
  end

  // ---- the adder ---------------------------------------------------------------------
  logic [1:0]             a_src;
  logic [2:0]             b_src;
  logic                   alu_sub;   // a - b (else a + b)
  logic                   alu_abs;   // a + |b|
  logic signed [AluW-1:0] alu_a, alu_b, alu_r;
  logic                   alu_n, alu_z, alu_sub_eff;
  logic signed [CtlW-1:0] alu_sat;

  always_comb begin
    unique case (a_src)
      ARf:     alu_a = AluW'($signed(rf_a));
      AT:      alu_a = t_q;
      ARef:    alu_a = AluW'(ref_q);
      default: alu_a = '0;
    endcase
    unique case (b_src)
      BRf:     alu_b = AluW'($signed(rf_b));
      BCfg:    alu_b = cfg_val;
      BPfb:    alu_b = AluW'(pfb_q);
      BVmeas:  alu_b = AluW'(vmeas_q);
      default: alu_b = '0;
    endcase
  end
  assign alu_sub_eff = alu_abs ? alu_b[AluW-1] : alu_sub;
  assign alu_r       = alu_sub_eff ? alu_a - alu_b : alu_a + alu_b;
  assign alu_n       = alu_r[AluW-1];
  assign alu_z       = (alu_r == '0);
  assign alu_sat     = (alu_r[AluW-1:CtlW-1] != '0 && alu_r[AluW-1:CtlW-1] != '1) ?
                       (alu_r[AluW-1] ? CtlMin : CtlMax) : alu_r[CtlW-1:0];

  // ---- the multiplier ----------------------------------------------------------------
  // Every product is rounded half up and shifted by s = 16 (Vff, T1, T2, H1,
  // H2), 20 (Du, Bc) or 20 + learn_shift (Dw1, Dw2). Vff's shift
  // (VffFrac - CtlFrac - shift = 15 - shift) is brought to 16 by scaling the
  // B operand by 2^(shift+1) (exact). (p + 2^(s-1)) >>> s is computed as
  // ((p >>> (s-1)) + 1) >>> 1 = (v >>> 1) + v[0].
  localparam int DivShW = CtlDivW + (1 << sc_pkg::EncShiftW) - 1;
  logic [DivShW-1:0]       div_sh;
  assign div_sh   = DivShW'(cfg_div) << cfg_shift;
  assign div_sh_o = div_sh;

  logic                    mul_a_vq;  // A operand: V* (else register-file port A)
  logic [1:0]              mb_src;
  logic                    mul_s20;   // base shift 20 (else 16)
  logic                    mul_ls;    // plus learn_shift
  logic signed [MulAW-1:0] mul_a;
  logic signed [MulBW-1:0] mul_b, e_b;
  logic signed [ProdW-1:0] mul_p, mul_r;
  logic signed [CtlW-1:0]  mul_y;

  // e (register-file port B) saturated to the B port, 0 while not learning;
  // |e| <= BMax iff bits CtlW-1..MulBW-1 are all equal and e != -2^(MulBW-1)
  logic                    e_in_b;
  assign e_in_b = ((rf_b[CtlW-1:MulBW-1] == '0) || (rf_b[CtlW-1:MulBW-1] == '1))
                  && (rf_b[MulBW-2:0] != '0 || !rf_b[CtlW-1]);
  assign e_b    = !learn_q ? '0 : !e_in_b ? (rf_b[CtlW-1] ? -BMax : BMax) : rf_b[MulBW-1:0];

  assign mul_a = mul_a_vq ? vq_q : $signed(rf_a);
  always_comb begin
    unique case (mb_src)
      MbRf:    mul_b = rf_b[MulBW-1:0];
      MbCfg:   mul_b = cfg_val[MulBW-1:0];
      MbEb:    mul_b = e_b;
      default: mul_b = MulBW'(div_sh) << (NWgtFrac - (VffFrac - CtlFrac));
    endcase
  end

  localparam int ShLo = NWgtFrac;
  localparam int ShHi = CoefFrac;
  localparam int TW   = ProdW - (ShLo - 1);   // p >>> (ShLo - 1)
  logic signed [TW-1:0]    mul_t, mul_v;
  logic signed [TW-2:0]    mul_h;
  assign mul_p   = ProdW'(mul_a) * ProdW'(mul_b);
  assign mul_t   = mul_s20 ? TW'(mul_p >>> (ShHi - 1)) : TW'(mul_p >>> (ShLo - 1));
  // learn shift: log shifter in explicit 4:1 stages (one LUT6 per bit and
  // stage; yosys's generic >>> maps to twice as many LUTs here)
  logic [LearnShW-1:0]  mul_sa;
  logic signed [TW-1:0] mul_s1, mul_s2;
  assign mul_sa = mul_ls ? cfg_learn_shift : LearnShW'(0);
  always_comb begin
    unique case (mul_sa[1:0])
      2'd0: mul_s1 = mul_t;
      2'd1: mul_s1 = mul_t >>> 1;
      2'd2: mul_s1 = mul_t >>> 2;
      default: mul_s1 = mul_t >>> 3;
    endcase
    unique case (mul_sa[3:2])
      2'd0: mul_s2 = mul_s1;
      2'd1: mul_s2 = mul_s1 >>> 4;
      2'd2: mul_s2 = mul_s1 >>> 8;
      default: mul_s2 = mul_s1 >>> 12;
    endcase
    mul_v = mul_sa[4] ? mul_s2 >>> 16 : mul_s2;
  end
  // floor((v + 1) / 2) = (v >>> 1) + v[0]
  assign mul_h   = mul_v[TW-1:1];
  logic signed [TW-2:0]    mul_rn;    // cannot overflow: |p| < 2^(ProdW-2)
  assign mul_rn  = mul_h + (TW-1)'({1'b0, mul_v[0]});
  assign mul_r   = ProdW'(mul_rn);
  assign mul_y   = (mul_r[ProdW-1:CtlW-1] != '0 && mul_r[ProdW-1:CtlW-1] != '1) ?
                   (mul_r[ProdW-1] ? CtlMin : CtlMax) : mul_r[CtlW-1:0];

  // ---- divider step ------------------------------------------------------------------
  // restoring division: the borrow of one subtraction decides the quotient
  // bit; bits enter at the LSB, MSB first (NWgtFrac+1 steps fill dquo). The
  // sign is the weight's (register-file port B during the division).
  logic [RemW:0]           div_diff;
  logic                    div_ge;
  logic [RemW-1:0]         div_rem_sub;
  logic [QuoW-1:0]         div_quo, div_res;
  logic signed [NWgtW-1:0] div_pos, div_wn;
  assign div_diff    = {1'b0, drem_q} - {1'b0, RemW'(dsum_q)};
  assign div_ge      = !div_diff[RemW];
  assign div_rem_sub = div_ge ? div_diff[RemW-1:0] : drem_q;
  assign div_quo     = {dquo_q[QuoW-2:0], div_ge};
  assign div_res     = (dsum_q == '0) ? '0 : div_quo;
  assign div_pos     = NWgtW'(div_res);
  assign div_wn      = rf_b[CtlW-1] ? -div_pos : div_pos;

  // ---- e_p rounded to whole steps (2^(CtlFrac+shift) per step), saturated -----------
  logic signed [CtlW-1:0]  corr_full;
  logic signed [CorrW-1:0] corr_steps, corr_step_dir;
  // (e + 2^(sh-1)) >>> sh, sh = CtlFrac + shift: v = (e >>> (CtlFrac-1)) >>> shift,
  // then floor((v + 1) / 2) = (v >>> 1) + v[0]
  localparam int CvW = CtlW - CtlFrac + 1;
  logic signed [CvW-1:0]   corr_v;
  logic signed [CvW-2:0]   corr_h;
  assign corr_v     = CvW'(eraw_q >>> (CtlFrac - 1)) >>> cfg_shift;
  assign corr_h     = corr_v[CvW-1:1];
  assign corr_full  = CtlW'(corr_h) + CtlW'({1'b0, corr_v[0]});
  logic                    corr_in;   // |corr_full| <= 2^(CorrW-1) - 1
  assign corr_in    = ((corr_full[CtlW-1:CorrW-1] == '0) || (corr_full[CtlW-1:CorrW-1] == '1))
                      && (corr_full[CorrW-2:0] != '0 || !corr_full[CtlW-1]);
  assign corr_steps = !corr_in ? (corr_full[CtlW-1] ? -CorrW'(2**(CorrW-1) - 1) : CorrW'(2**(CorrW-1) - 1)) :
                      corr_full[CorrW-1:0];
  assign corr_step_dir = corr_q[CorrW-1] ? CorrW'(1) : -CorrW'(1);

  logic hush_now;   // settling: position error held at 0 for the PI
  assign hush_now = !sel_q && fin_q;

  // ---- micro-program -------------------------------------------------------------------
  logic [4:0]        pair;      // the weight this update writes (w1 or w2 of the loop)
  logic [2:0]        w_src;
  logic              t_we;      // T := alu_r
  logic [UpcW-1:0]   u2;        // step within the weight update (w1: sc_pkg::UpcW1.., w2: sc_pkg::UpcW5..)
  logic              w2nd;      // the weight update is for w2
  logic [CtlStW-1:0] st;        // state_o

  assign w2nd = (upc_q >= sc_pkg::UpcH2);
  assign u2   = w2nd ? upc_q - (sc_pkg::UpcH2 - sc_pkg::UpcH1) : upc_q;

  always_comb begin
    ra      = '0;
    rb      = '0;
    a_src   = AZero;
    b_src   = BZero;
    cfg_sel = CfWMin;
    alu_sub = 1'b0;
    alu_abs = 1'b0;
    mul_a_vq = 1'b0;
    mb_src  = MbRf;
    mul_s20 = 1'b0;
    mul_ls  = 1'b0;
    rf_we   = 1'b0;
    rf_wa   = '0;
    w_src   = WWrap;
    t_we    = 1'b0;
    pair    = '0;
    st      = sc_pkg::CtlStIdle;
    unique case (upc_q)
      sc_pkg::UpcIdle: st = sc_pkg::CtlStIdle;
      sc_pkg::UpcVff: begin
        st       = sc_pkg::CtlStVff;
        mul_a_vq = 1'b1;
        mb_src   = MbDivSh;
        rf_we    = 1'b1;
        rf_wa    = RfVff;
        w_src    = WMul;
      end
      sc_pkg::UpcSet1, sc_pkg::UpcSet2, sc_pkg::UpcSet3, sc_pkg::UpcDiv1, sc_pkg::UpcDiv2: begin
        st      = sc_pkg::CtlStDiv;
        rb      = ((upc_q == sc_pkg::UpcSet1 || upc_q == sc_pkg::UpcDiv1) ? RfW1 : RfW2) | {4'd0, sel_q};
        a_src   = (upc_q == sc_pkg::UpcSet2) ? AT : AZero;
        b_src   = BRf;
        alu_abs = 1'b1;
        t_we    = (upc_q == sc_pkg::UpcSet1);
        rf_we   = (upc_q == sc_pkg::UpcDiv1 || upc_q == sc_pkg::UpcDiv2) && dbit_q == '0;
        rf_wa   = ((upc_q == sc_pkg::UpcDiv1) ? RfN1 : RfN2) | {4'd0, sel_q};
        w_src   = WDiv;
      end
      sc_pkg::UpcRef: begin
        st    = sc_pkg::CtlStErr;
        a_src = sel_q ? ARf : ARef;
        ra    = RfOutP;
        rb    = RfVff;
        b_src = (sel_q && cfg_ff_en) ? BRf : BZero;
        t_we  = 1'b1;
      end
      sc_pkg::UpcErr: begin
        st      = sc_pkg::CtlStErr;
        a_src   = AT;
        b_src   = sel_q ? BVmeas : BPfb;
        alu_sub = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = RfEraw;
      end
      sc_pkg::UpcAbs: begin
        st      = sc_pkg::CtlStErr;
        rb      = RfEraw;
        b_src   = BRf;
        alu_abs = 1'b1;
        t_we    = 1'b1;
      end
      sc_pkg::UpcEq, sc_pkg::UpcX2: begin
        st      = sc_pkg::CtlStErr;
        ra      = RfEraw;
        rb      = RfEp | {4'd0, sel_q};
        a_src   = (upc_q == sc_pkg::UpcX2 && hush_now) ? AZero : ARf;
        b_src   = BRf;
        alu_sub = 1'b1;
        rf_we   = (upc_q == sc_pkg::UpcX2);
        rf_wa   = RfX2;
      end
      sc_pkg::UpcE, sc_pkg::UpcEp: begin
        st      = sc_pkg::CtlStErr;
        ra      = RfEraw;
        a_src   = (upc_q == sc_pkg::UpcE && hush_now) ? AZero : ARf;
        rf_we   = 1'b1;
        rf_wa   = (upc_q == sc_pkg::UpcE) ? RfE : (RfEp | {4'd0, sel_q});
      end
      sc_pkg::UpcLearn, sc_pkg::UpcFerr, sc_pkg::UpcWin: begin
        st      = sc_pkg::CtlStErr;
        a_src   = AT;
        b_src   = BCfg;
        cfg_sel = (upc_q == sc_pkg::UpcLearn) ? (sel_q ? CfDzV : CfDzP) : (upc_q == sc_pkg::UpcFerr) ? CfFerr : CfWin;
        alu_sub = 1'b1;
        if (upc_q == sc_pkg::UpcLearn && cfg_pid) begin
          // PID: no learning; the multiplier forms the D term d = K_V x2
          ra      = RfX2;
          mb_src  = MbCfg;
          cfg_sel = CfKV;
          mul_s20 = 1'b1;
          rf_we   = 1'b1;
          rf_wa   = RfH;
          w_src   = WMul;
        end
      end
      sc_pkg::UpcT1: begin
        st    = sc_pkg::CtlStT1;
        ra    = RfE;
        rb    = RfN1 | {4'd0, sel_q};
        rf_we = 1'b1;
        rf_wa = RfT1;
        w_src = WMul;
      end
      sc_pkg::UpcT2: begin
        st    = sc_pkg::CtlStT2;
        ra    = RfX2;
        rb    = RfN2 | {4'd0, sel_q};
        rf_we = 1'b1;
        rf_wa = RfT2;
        w_src = WMul;
      end
      sc_pkg::UpcSum: begin
        st    = sc_pkg::CtlStT2;
        ra    = RfT1;
        rb    = RfT2;
        a_src = ARf;
        b_src = BRf;
        rf_we = 1'b1;
        rf_wa = RfSum;
        w_src = WSat;
      end
      sc_pkg::UpcDu, sc_pkg::UpcBc: begin
        st      = (upc_q == sc_pkg::UpcDu) ? sc_pkg::CtlStDu : sc_pkg::CtlStBc;
        ra      = (upc_q == sc_pkg::UpcDu) ? RfSum : (RfEs | {4'd0, sel_q});
        mb_src  = MbCfg;
        cfg_sel = (upc_q == sc_pkg::UpcBc) ? CfKb : sel_q ? CfKV : CfKP;
        mul_s20 = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = (upc_q == sc_pkg::UpcDu) ? RfDu : RfBc;
        w_src   = WMul;
      end
      sc_pkg::UpcAcc1: begin
        st    = sc_pkg::CtlStBc;
        ra    = RfAcc | {4'd0, sel_q};
        rb    = RfDu;
        a_src = ARf;
        b_src = BRf;
        t_we  = 1'b1;
      end
      sc_pkg::UpcAcc2: begin
        st      = sc_pkg::CtlStBc;
        rb      = RfBc;
        a_src   = AT;
        b_src   = BRf;
        alu_sub = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = RfAcc | {4'd0, sel_q};
        w_src   = hush_q ? WZero : WSat;
      end
      sc_pkg::UpcTot: begin
        st    = sc_pkg::CtlStBc;
        ra    = RfAcc | {4'd0, sel_q};
        rb    = cfg_pid ? RfH : RfVff;
        a_src = ARf;
        b_src = ((sel_q && cfg_ff_en) || (cfg_pid && !hush_q)) ? BRf : BZero;
        rf_we = 1'b1;
        rf_wa = RfTot;
        w_src = WSat;
      end
      sc_pkg::UpcHi, sc_pkg::UpcLo: begin
        st      = sc_pkg::CtlStBc;
        ra      = RfTot;
        a_src   = ARf;
        b_src   = BCfg;
        cfg_sel = (sel_q || cfg_pid) ? CfULim : CfVLim;
        alu_sub = (upc_q == sc_pkg::UpcHi);
        // es = tot - lim when tot > lim (else 0), then tot + lim when < -lim
        rf_we   = (upc_q == sc_pkg::UpcHi) || alu_n;
        rf_wa   = RfEs | {4'd0, sel_q};
        w_src   = (upc_q == sc_pkg::UpcHi && (alu_n || alu_z)) ? WZero : WWrap;
      end
      sc_pkg::UpcOut: begin
        st      = sc_pkg::CtlStBc;
        ra      = RfTot;
        rb      = RfEs | {4'd0, sel_q};
        a_src   = ARf;
        b_src   = BRf;
        alu_sub = 1'b1;
        rf_we   = !sel_q;
        rf_wa   = RfOutP;
      end
      sc_pkg::UpcH1, sc_pkg::UpcH2: begin
        st     = (upc_q == sc_pkg::UpcH1) ? sc_pkg::CtlStH1 : sc_pkg::CtlStH2;
        ra     = (upc_q == sc_pkg::UpcH1) ? RfE : RfX2;
        rb     = RfE;
        mb_src = MbEb;
        rf_we  = 1'b1;
        rf_wa  = RfH;
        w_src  = WMul;
      end
      sc_pkg::UpcDw1, sc_pkg::UpcDw2: begin
        st      = (upc_q == sc_pkg::UpcDw1) ? sc_pkg::CtlStDw1 : sc_pkg::CtlStDw2;
        ra      = RfH;
        mb_src  = MbCfg;
        cfg_sel = (upc_q == sc_pkg::UpcDw1) ? (sel_q ? CfEtaV1 : CfEtaP1) : (sel_q ? CfEtaV2 : CfEtaP2);
        mul_s20 = 1'b1;
        mul_ls  = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = RfDw;
        w_src   = WMul;
      end
      default: begin
        // sc_pkg::UpcW1..sc_pkg::UpcW4 (w1), sc_pkg::UpcW5..sc_pkg::UpcW8 (w2)
        if (upc_q >= sc_pkg::UpcW1 && upc_q <= sc_pkg::UpcW8 && upc_q != sc_pkg::UpcH2 && upc_q != sc_pkg::UpcDw2) begin
          st      = w2nd ? sc_pkg::CtlStDw2 : sc_pkg::CtlStDw1;
          pair    = (w2nd ? RfW2 : RfW1) | {4'd0, sel_q};
          cfg_sel = (u2 == sc_pkg::UpcW3) ? CfWMin :
                    (u2 == sc_pkg::UpcW4) ? (over_q ? (w2nd ? (sel_q ? CfWV2Max : CfWP2Max)
                                                  : (sel_q ? CfWV1Max : CfWP1Max)) : CfWMin) :
                    w2nd ? (sel_q ? CfWV2Max : CfWP2Max) : (sel_q ? CfWV1Max : CfWP1Max);
          unique case (u2)
            sc_pkg::UpcW1: begin                      // T = w + dw
              ra    = pair;
              rb    = RfDw;
              a_src = ARf;
              b_src = BRf;
              t_we  = 1'b1;
            end
            sc_pkg::UpcW2, sc_pkg::UpcW3: begin                 // T - w_max > 0 ?  T - w_min < 0 ?
              a_src   = AT;
              b_src   = BCfg;
              alu_sub = 1'b1;
            end
            default: begin                  // w = w_max, w_min or T (then within both)
              a_src = (over_q || under_q) ? AZero : AT;
              b_src = (over_q || under_q) ? BCfg : BZero;
              rf_we = 1'b1;
              rf_wa = pair;
            end
          endcase
        end else if (upc_q >= sc_pkg::UpcInit && upc_q < sc_pkg::UpcInit + 6'(NInit)) begin
          // start: e_prev, acc, es, out_p, vff = 0; weights = their initial values
          st    = sc_pkg::CtlStInit;
          rf_we = 1'b1;
          b_src = BCfg;
          unique case (upc_q - sc_pkg::UpcInit)
            6'd0: rf_wa = RfEp;
            6'd1: rf_wa = RfEp + 5'd1;
            6'd2: rf_wa = RfAcc;
            6'd3: rf_wa = RfAcc + 5'd1;
            6'd4: rf_wa = RfEs;
            6'd5: rf_wa = RfEs + 5'd1;
            6'd6: rf_wa = RfOutP;
            6'd7: rf_wa = RfVff;
            6'd8: begin rf_wa = RfW1;        cfg_sel = CfWP1; end
            6'd9: begin rf_wa = RfW1 + 5'd1; cfg_sel = CfWV1; end
            6'd10: begin rf_wa = RfW2;        cfg_sel = CfWP2; end
            default: begin rf_wa = RfW2 + 5'd1; cfg_sel = CfWV2; end
          endcase
          if (upc_q - sc_pkg::UpcInit < 6'd8) b_src = BZero;
        end
      end
    endcase
  end

  always_comb begin
    unique case (w_src)
      WSat:    rf_wd = alu_sat;
      WMul:    rf_wd = mul_y;
      WDiv:    rf_wd = CtlW'(div_wn);
      WZero:   rf_wd = '0;
      default: rf_wd = alu_r[CtlW-1:0];
    endcase
  end

  // ---- sequencing, flags, snapshot, settling --------------------------------------------
  always_comb begin
    active_d = active_q;
    in_pos_d = in_pos_q;
    ferr_d   = ferr_q;
    cnt_d    = cnt_q;
    upc_d    = upc_q;
    sel_d    = sel_q;
    dbit_d   = dbit_q;
    drem_d   = drem_q;
    dquo_d   = dquo_q;
    dsum_d   = dsum_q;
    hold_d   = hold_q;
    hush_d   = hush_q;
    corr_d   = corr_q;
    if (corr_q != '0 && nco_req_i) corr_d = corr_q + corr_step_dir;
    learn_d  = learn_q;
    eq_d     = eq_q;
    over_d   = over_q;
    under_d  = under_q;
    t_d      = t_q;
    eraw_d   = eraw_q;
    ref_d    = ref_q;
    pfb_d    = pfb_q;
    vmeas_d  = vmeas_q;
    vq_d     = vq_q;
    fin_d    = fin_q;
    mv_d     = mv_q | cmd_busy_i;
    mvs_d    = mvs_q;
    u_d      = u_q;
    if (t_we) t_d = alu_r;

    if (active_q) begin
      if (cnt_q == '0) begin
        cnt_d = cfg_div - CtlDivW'(1);
        if (upc_q == sc_pkg::UpcIdle) begin
          // snapshot: P* - 1/2 (the integer target L once the reference is done), P, V
          ref_d   = (ref_done_i ? CtlW'(ref_int_i) << CtlFrac
                                    : CtlW'({ref_int_i, ref_frac_i}) - (CtlW'(1) << (CtlFrac - 1)))
                    <<< cfg_shift;
          pfb_d   = CtlW'(enc_pos_i) <<< CtlFrac;
          vmeas_d = (CtlW'(enc_pos_i) <<< CtlFrac) - pfb_q;
          vq_d    = ref_vel_i;
          fin_d   = ref_done_i;
          mvs_d   = mv_q | cmd_busy_i;
          mv_d    = 1'b0;
          sel_d   = 1'b0;
          upc_d   = sc_pkg::UpcVff;
        end
      end else begin
        cnt_d = cnt_q - CtlDivW'(1);
      end
    end

    if (upc_q != sc_pkg::UpcIdle) upc_d = upc_q + 6'd1;
    if (upc_q == sc_pkg::UpcInit + 6'(NInit - 1)) upc_d = sc_pkg::UpcIdle;   // wait for the first snapshot
    unique case (upc_q)
      sc_pkg::UpcIdle: ;
      sc_pkg::UpcSet1: drem_d = RemW'(alu_r);
      sc_pkg::UpcSet2: begin
        dsum_d = SumW'(alu_r);
        dbit_d = DbitW'(NWgtFrac);
        dquo_d = '0;
      end
      sc_pkg::UpcSet3: begin
        drem_d = RemW'(alu_r);
        dbit_d = DbitW'(NWgtFrac);
        dquo_d = '0;
      end
      sc_pkg::UpcDiv1, sc_pkg::UpcDiv2: begin
        drem_d = div_rem_sub << 1;
        dquo_d = div_quo;
        dbit_d = dbit_q - DbitW'(1);
        if (dbit_q != '0) upc_d = upc_q;
      end
      sc_pkg::UpcErr: eraw_d = alu_r[CtlW-1:0];
      sc_pkg::UpcEq: eq_d = alu_z;
      sc_pkg::UpcEp: if (!sel_q) hush_d = hush_now;
      sc_pkg::UpcLearn: learn_d = !cfg_pid && !hush_now && !alu_n && !alu_z;
      sc_pkg::UpcFerr: begin
        if (!sel_q && !alu_n && !alu_z) begin
          ferr_d = 1'b1;
          // Immediate: the loop stops here. Controlled: the axis stops the
          // reference (sc_servo_axis) and the loop keeps tracking it.
          if (!cfg_ferr_stop) begin
            active_d = 1'b0;
            u_d      = '0;
            upc_d    = sc_pkg::UpcIdle;
          end
        end
      end
      sc_pkg::UpcWin: begin
        if (!sel_q) begin
          if (fin_q && !mvs_q && corr_q == '0 && eq_q) begin
            hold_d = hold_q + HoldW'(1);
            if (hold_d >= cfg_inpos_hold) begin
              hold_d = '0;
              if (alu_n || alu_z || corr_steps == '0) begin   // |e_p| <= win
                in_pos_d = 1'b1;
                active_d = 1'b0;
                u_d      = '0;
                upc_d    = sc_pkg::UpcIdle;
              end else begin
                corr_d = corr_steps;
              end
            end
          end else begin
            hold_d = '0;
          end
        end
      end
      sc_pkg::UpcOut: begin
        if (sel_q || cfg_pid) u_d = alu_r[CtlW-1:0];
        if (cfg_pid) upc_d = sc_pkg::UpcIdle;   // PID: no weight updates, no speed loop
      end
      default: ;
    endcase
    if (u2 == sc_pkg::UpcW2 && upc_q != sc_pkg::UpcH2 && upc_q != sc_pkg::UpcDw2) over_d = !alu_n && !alu_z;
    if (u2 == sc_pkg::UpcW3 && upc_q != sc_pkg::UpcH2 && upc_q != sc_pkg::UpcDw2) under_d = alu_n;
    if (upc_q == sc_pkg::UpcW8) begin
      if (sel_q) begin
        upc_d = sc_pkg::UpcIdle;
      end else begin
        sel_d = 1'b1;
        upc_d = sc_pkg::UpcSet1;
      end
    end

    // settling: the rate command is the corrective stepping only
    if (fin_q && active_d) begin
      u_d = (corr_d == '0) ? '0 : corr_d[CorrW-1] ? -$signed(cfg_settle_rate) : $signed(cfg_settle_rate);
    end

    if (start_i) begin
      active_d = 1'b1;
      in_pos_d = 1'b0;
      ferr_d   = 1'b0;
      cnt_d    = CtlDivW'(NInit);   // the first snapshot follows the initialisation
      upc_d    = sc_pkg::UpcInit;
      sel_d    = 1'b0;
      hold_d   = '0;
      hush_d   = 1'b0;
      corr_d   = '0;
      fin_d    = 1'b0;
      pfb_d    = CtlW'(enc_pos_i) <<< CtlFrac;
      vmeas_d  = '0;
      u_d      = '0;
    end else if (stop_i) begin
      active_d = 1'b0;
      upc_d    = sc_pkg::UpcIdle;
      u_d      = '0;
    end
  end

  // output copies follow their register-file words
  always_comb begin
    vcmd_d = vcmd_q;
    ep_p_d = ep_p_q;
    ep_v_d = ep_v_q;
    w_p1_d = w_p1_q;
    w_v1_d = w_v1_q;
    w_p2_d = w_p2_q;
    w_v2_d = w_v2_q;
    n_p1_d = n_p1_q;
    n_v1_d = n_v1_q;
    n_p2_d = n_p2_q;
    n_v2_d = n_v2_q;
    if (rf_we) begin
      unique case (rf_wa)
        RfOutP:          vcmd_d = rf_wd;
        RfEp:            ep_p_d = rf_wd;
        RfEp + 5'd1:     ep_v_d = rf_wd;
        RfW1:            w_p1_d = rf_wd[WgtW-1:0];
        RfW1 + 5'd1:     w_v1_d = rf_wd[WgtW-1:0];
        RfW2:            w_p2_d = rf_wd[WgtW-1:0];
        RfW2 + 5'd1:     w_v2_d = rf_wd[WgtW-1:0];
        RfN1:            n_p1_d = rf_wd[NWgtW-1:0];
        RfN1 + 5'd1:     n_v1_d = rf_wd[NWgtW-1:0];
        RfN2:            n_p2_d = rf_wd[NWgtW-1:0];
        RfN2 + 5'd1:     n_v2_d = rf_wd[NWgtW-1:0];
        default: ;
      endcase
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      active_q <= 1'b0;
      in_pos_q <= 1'b0;
      ferr_q   <= 1'b0;
      cnt_q    <= '0;
      upc_q    <= sc_pkg::UpcIdle;
      sel_q    <= 1'b0;
      dbit_q   <= '0;
      drem_q   <= '0;
      dquo_q   <= '0;
      dsum_q   <= '0;
      hold_q   <= '0;
      hush_q   <= 1'b0;
      corr_q   <= '0;
      learn_q  <= 1'b0;
      eq_q     <= 1'b0;
      over_q   <= 1'b0;
      under_q  <= 1'b0;
      t_q      <= '0;
      eraw_q   <= '0;
      ref_q    <= '0;
      pfb_q    <= '0;
      vmeas_q  <= '0;
      vq_q     <= '0;
      fin_q    <= 1'b0;
      mv_q     <= 1'b0;
      mvs_q    <= 1'b0;
      u_q      <= '0;
      vcmd_q   <= '0;
      ep_p_q   <= '0;
      ep_v_q   <= '0;
      w_p1_q   <= '0;
      w_v1_q   <= '0;
      w_p2_q   <= '0;
      w_v2_q   <= '0;
      n_p1_q   <= '0;
      n_v1_q   <= '0;
      n_p2_q   <= '0;
      n_v2_q   <= '0;
    end else begin
      active_q <= active_d;
      in_pos_q <= in_pos_d;
      ferr_q   <= ferr_d;
      cnt_q    <= cnt_d;
      upc_q    <= upc_d;
      sel_q    <= sel_d;
      dbit_q   <= dbit_d;
      drem_q   <= drem_d;
      dquo_q   <= dquo_d;
      dsum_q   <= dsum_d;
      hold_q   <= hold_d;
      hush_q   <= hush_d;
      corr_q   <= corr_d;
      learn_q  <= learn_d;
      eq_q     <= eq_d;
      over_q   <= over_d;
      under_q  <= under_d;
      t_q      <= t_d;
      eraw_q   <= eraw_d;
      ref_q    <= ref_d;
      pfb_q    <= pfb_d;
      vmeas_q  <= vmeas_d;
      vq_q     <= vq_d;
      fin_q    <= fin_d;
      mv_q     <= mv_d;
      mvs_q    <= mvs_d;
      u_q      <= u_d;
      vcmd_q   <= vcmd_d;
      ep_p_q   <= ep_p_d;
      ep_v_q   <= ep_v_d;
      w_p1_q   <= w_p1_d;
      w_v1_q   <= w_v1_d;
      w_p2_q   <= w_p2_d;
      w_v2_q   <= w_v2_d;
      n_p1_q   <= n_p1_d;
      n_v1_q   <= n_v1_d;
      n_p2_q   <= n_p2_d;
      n_v2_q   <= n_v2_d;
    end
  end

  assign active_o     = active_q;
  assign in_pos_o     = in_pos_q;
  assign fault_ferr_o = ferr_q;
  assign u_o          = u_q;
  assign v_cmd_o      = vcmd_q;
  assign e_p_o        = ep_p_q;
  assign e_v_o        = ep_v_q;
  assign w_p1_o       = w_p1_q;
  assign w_p2_o       = w_p2_q;
  assign w_v1_o       = w_v1_q;
  assign w_v2_o       = w_v2_q;
  assign wn_p1_o      = n_p1_q;
  assign wn_p2_o      = n_p2_q;
  assign wn_v1_o      = n_v1_q;
  assign wn_v2_o      = n_v2_q;
  assign state_o      = st;

`ifdef SC_COVER
  // Cover points (the coverage build, scripts/coverage.py): every micro-step in
  // each loop (pairs no program reaches are excluded in
  // scripts/coverage_exclusions.json, with the reason), the output clamp on
  // both sides and each weight's clamp to its bounds, in each loop.
  for (genvar u = 0; u <= int'(sc_pkg::UpcW8); u++) begin : g_cov_upc
    for (genvar l = 0; l < 2; l++) begin : g_loop
      c_step: cover property (@(posedge clk_i) rst_ni && upc_q == UpcW'(u) && sel_q == 1'(l));
    end
  end
  for (genvar l = 0; l < 2; l++) begin : g_cov_loop
    c_out_clamp_hi: cover property (@(posedge clk_i) rst_ni && sel_q == 1'(l) && upc_q == sc_pkg::UpcHi &&
                                    !alu_n && !alu_z);
    c_out_clamp_lo: cover property (@(posedge clk_i) rst_ni && sel_q == 1'(l) && upc_q == sc_pkg::UpcLo && alu_n);
    c_w1_max: cover property (@(posedge clk_i) rst_ni && sel_q == 1'(l) && upc_q == sc_pkg::UpcW4 && over_q);
    c_w1_min: cover property (@(posedge clk_i) rst_ni && sel_q == 1'(l) && upc_q == sc_pkg::UpcW4 && under_q);
    c_w2_max: cover property (@(posedge clk_i) rst_ni && sel_q == 1'(l) && upc_q == sc_pkg::UpcW8 && over_q);
    c_w2_min: cover property (@(posedge clk_i) rst_ni && sel_q == 1'(l) && upc_q == sc_pkg::UpcW8 && under_q);
  end
  // the PID: its period ends at Out, its output clamp on both sides
  c_pid_out: cover property (@(posedge clk_i) rst_ni && cfg_pid && upc_q == sc_pkg::UpcOut);
  c_pid_clamp_hi: cover property (@(posedge clk_i) rst_ni && cfg_pid && upc_q == sc_pkg::UpcHi && !alu_n && !alu_z);
  c_pid_clamp_lo: cover property (@(posedge clk_i) rst_ni && cfg_pid && upc_q == sc_pkg::UpcLo && alu_n);
`endif

endmodule
