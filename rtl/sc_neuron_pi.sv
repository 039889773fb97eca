// sc_neuron_pi: the cascade of two single-neuron adaptive PI controllers
// (outer: position, inner: speed) on ONE microcoded datapath: a register
// file (LUT RAM, two read ports), one 34-bit adder/subtractor (saturating,
// compare flags), one signed MulAW x MulBW multiplier and one restoring
// divider (one quotient bit per clock) for the weight normalisation,
// sequenced once per control period (cfg_div_i clocks, e.g. 2000 = 10 kHz)
// by a micro-program of one operation per clock: 141 clocks of work per
// period (12 more after start_i to initialise), so cfg_div_i must be >= 256.
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
// Following-error fault: |e_p| > ferr_lim stops (u = 0) and latches.
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

  input  logic [sc_pkg::CtlDivW-1:0]          cfg_div_i,
  input  logic [sc_pkg::EncShiftW-1:0]        cfg_shift_i,
  input  logic                                cfg_ff_en_i,
  input  logic [sc_pkg::LearnShW-1:0]         cfg_learn_shift_i,
  input  logic [sc_pkg::CtlW-1:0]             cfg_learn_dz_p_i,  // no learning while |e| <= dz
  input  logic [sc_pkg::CtlW-1:0]             cfg_learn_dz_v_i,
  input  logic [sc_pkg::CoefW-1:0]            cfg_k_p_i,
  input  logic [sc_pkg::CoefW-1:0]            cfg_k_v_i,
  input  logic [sc_pkg::CoefW-1:0]            cfg_kb_i,
  input  logic [sc_pkg::CoefW-1:0]            cfg_eta_p1_i,
  input  logic [sc_pkg::CoefW-1:0]            cfg_eta_p2_i,
  input  logic [sc_pkg::CoefW-1:0]            cfg_eta_v1_i,
  input  logic [sc_pkg::CoefW-1:0]            cfg_eta_v2_i,
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_p1_i,     // initial weights
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_p2_i,
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_v1_i,
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_v2_i,
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_min_i,    // lower bound, all weights
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_p1_max_i, // upper bounds, per weight
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_p2_max_i,
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_v1_max_i,
  input  logic signed [sc_pkg::WgtW-1:0]      cfg_w_v2_max_i,
  input  logic [sc_pkg::CtlW-1:0]             cfg_v_lim_i,    // unsigned, < 2^31
  input  logic [sc_pkg::CtlW-1:0]             cfg_u_lim_i,
  input  logic [sc_pkg::CtlW-1:0]             cfg_ferr_lim_i,
  input  logic [sc_pkg::CtlW-1:0]             cfg_inpos_win_i,
  input  logic [sc_pkg::HoldW-1:0]            cfg_inpos_hold_i,
  input  logic [sc_pkg::CtlW-1:0]             cfg_settle_rate_i, // corrective step rate, counts/period

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
  // cfg_div_i << cfg_shift_i (clocks per period x counts per pulse), for the
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
  localparam int UpcW     = 6;

  // state_o: the phase of the period (as the equations above)
  localparam logic [CtlStW-1:0] StIdle = 4'd0;
  localparam logic [CtlStW-1:0] StVff  = 4'd1;
  localparam logic [CtlStW-1:0] StDiv  = 4'd2;
  localparam logic [CtlStW-1:0] StErr  = 4'd3;
  localparam logic [CtlStW-1:0] StT1   = 4'd4;
  localparam logic [CtlStW-1:0] StT2   = 4'd5;
  localparam logic [CtlStW-1:0] StDu   = 4'd6;
  localparam logic [CtlStW-1:0] StBc   = 4'd7;
  localparam logic [CtlStW-1:0] StH1   = 4'd8;
  localparam logic [CtlStW-1:0] StDw1  = 4'd9;
  localparam logic [CtlStW-1:0] StH2   = 4'd10;
  localparam logic [CtlStW-1:0] StDw2  = 4'd11;
  localparam logic [CtlStW-1:0] StInit = 4'd12;

  // micro-program steps (cmodel/neuron_pi.cpp runs the same list)
  localparam logic [UpcW-1:0] UIdle  = 6'd0;
  localparam logic [UpcW-1:0] UInit  = 6'd1;   // 1..12: clear/load the loop registers
  localparam int              NInit  = 12;
  localparam logic [UpcW-1:0] UVff   = 6'd13;
  localparam logic [UpcW-1:0] USet1  = 6'd14;  // |w1| -> drem, T
  localparam logic [UpcW-1:0] USet2  = 6'd15;  // T + |w2| -> dsum
  localparam logic [UpcW-1:0] UDiv1  = 6'd16;  // w1 / dsum, NWgtFrac+1 clocks
  localparam logic [UpcW-1:0] USet3  = 6'd17;  // |w2| -> drem
  localparam logic [UpcW-1:0] UDiv2  = 6'd18;  // w2 / dsum
  localparam logic [UpcW-1:0] URef   = 6'd19;  // T = r
  localparam logic [UpcW-1:0] UErr   = 6'd20;  // eraw = T - y
  localparam logic [UpcW-1:0] UAbs   = 6'd21;  // T = |eraw|
  localparam logic [UpcW-1:0] UEq    = 6'd22;  // eraw == e_prev ?
  localparam logic [UpcW-1:0] UX2    = 6'd23;  // x2 = e - e_prev
  localparam logic [UpcW-1:0] UE     = 6'd24;  // e
  localparam logic [UpcW-1:0] UEp    = 6'd25;  // e_prev = eraw
  localparam logic [UpcW-1:0] ULearn = 6'd26;  // |e| > dead zone ?
  localparam logic [UpcW-1:0] UFerr  = 6'd27;  // |e_p| > ferr_lim ? (position loop)
  localparam logic [UpcW-1:0] UWin   = 6'd28;  // in position ? (position loop)
  localparam logic [UpcW-1:0] UT1    = 6'd29;  // t1 = wn1 e
  localparam logic [UpcW-1:0] UT2    = 6'd30;  // t2 = wn2 x2
  localparam logic [UpcW-1:0] USum   = 6'd31;  // sum = sat(t1 + t2)
  localparam logic [UpcW-1:0] UDu    = 6'd32;  // du = K sum
  localparam logic [UpcW-1:0] UBc    = 6'd33;  // bc = Kb es
  localparam logic [UpcW-1:0] UAcc1  = 6'd34;  // T = acc + du
  localparam logic [UpcW-1:0] UAcc2  = 6'd35;  // acc = sat(T - bc)
  localparam logic [UpcW-1:0] UTot   = 6'd36;  // tot = sat(acc + b)
  localparam logic [UpcW-1:0] UHi    = 6'd37;  // es = tot - lim if > 0
  localparam logic [UpcW-1:0] ULo    = 6'd38;  // es = tot + lim if < 0
  localparam logic [UpcW-1:0] UOut   = 6'd39;  // out = tot - es
  localparam logic [UpcW-1:0] UH1    = 6'd40;  // h = e e_b
  localparam logic [UpcW-1:0] UDw1   = 6'd41;  // dw = eta1 h / 2^ls
  localparam logic [UpcW-1:0] UW1    = 6'd42;  // T = w1 + dw
  localparam logic [UpcW-1:0] UW2    = 6'd43;  // T > w1_max ?
  localparam logic [UpcW-1:0] UW3    = 6'd44;  // T < w_min ?
  localparam logic [UpcW-1:0] UW4    = 6'd45;  // w1 = clamp
  localparam logic [UpcW-1:0] UH2    = 6'd46;
  localparam logic [UpcW-1:0] UDw2   = 6'd47;
  // 6'd48..6'd51: UW1..UW4 for w2
  localparam logic [UpcW-1:0] UW8    = 6'd51;

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
      CfDzP:    cfg_val = AluW'({2'b00, cfg_learn_dz_p_i});
      CfDzV:    cfg_val = AluW'({2'b00, cfg_learn_dz_v_i});
      CfFerr:   cfg_val = AluW'({2'b00, cfg_ferr_lim_i});
      CfWin:    cfg_val = AluW'({2'b00, cfg_inpos_win_i});
      CfVLim:   cfg_val = AluW'({2'b00, cfg_v_lim_i});
      CfULim:   cfg_val = AluW'({2'b00, cfg_u_lim_i});
      CfWMin:   cfg_val = AluW'(cfg_w_min_i);
      CfWP1Max: cfg_val = AluW'(cfg_w_p1_max_i);
      CfWV1Max: cfg_val = AluW'(cfg_w_v1_max_i);
      CfWP2Max: cfg_val = AluW'(cfg_w_p2_max_i);
      CfWV2Max: cfg_val = AluW'(cfg_w_v2_max_i);
      CfWP1:    cfg_val = AluW'(cfg_w_p1_i);
      CfWV1:    cfg_val = AluW'(cfg_w_v1_i);
      CfWP2:    cfg_val = AluW'(cfg_w_p2_i);
      CfWV2:    cfg_val = AluW'(cfg_w_v2_i);
      CfKP:     cfg_val = AluW'({1'b0, cfg_k_p_i});
      CfKV:     cfg_val = AluW'({1'b0, cfg_k_v_i});
      CfKb:     cfg_val = AluW'({1'b0, cfg_kb_i});
      CfEtaP1:  cfg_val = AluW'({1'b0, cfg_eta_p1_i});
      CfEtaV1:  cfg_val = AluW'({1'b0, cfg_eta_v1_i});
      CfEtaP2:  cfg_val = AluW'({1'b0, cfg_eta_p2_i});
      CfEtaV2:  cfg_val = AluW'({1'b0, cfg_eta_v2_i});
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
  assign div_sh   = DivShW'(cfg_div_i) << cfg_shift_i;
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
  assign mul_sa = mul_ls ? cfg_learn_shift_i : LearnShW'(0);
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
  assign corr_v     = CvW'(eraw_q >>> (CtlFrac - 1)) >>> cfg_shift_i;
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
  logic [UpcW-1:0]   u2;        // step within the weight update (w1: UW1.., w2: UW5..)
  logic              w2nd;      // the weight update is for w2
  logic [CtlStW-1:0] st;        // state_o

  assign w2nd = (upc_q >= UH2);
  assign u2   = w2nd ? upc_q - (UH2 - UH1) : upc_q;

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
    st      = StIdle;
    unique case (upc_q)
      UIdle: st = StIdle;
      UVff: begin
        st       = StVff;
        mul_a_vq = 1'b1;
        mb_src   = MbDivSh;
        rf_we    = 1'b1;
        rf_wa    = RfVff;
        w_src    = WMul;
      end
      USet1, USet2, USet3, UDiv1, UDiv2: begin
        st      = StDiv;
        rb      = ((upc_q == USet1 || upc_q == UDiv1) ? RfW1 : RfW2) | {4'd0, sel_q};
        a_src   = (upc_q == USet2) ? AT : AZero;
        b_src   = BRf;
        alu_abs = 1'b1;
        t_we    = (upc_q == USet1);
        rf_we   = (upc_q == UDiv1 || upc_q == UDiv2) && dbit_q == '0;
        rf_wa   = ((upc_q == UDiv1) ? RfN1 : RfN2) | {4'd0, sel_q};
        w_src   = WDiv;
      end
      URef: begin
        st    = StErr;
        a_src = sel_q ? ARf : ARef;
        ra    = RfOutP;
        rb    = RfVff;
        b_src = (sel_q && cfg_ff_en_i) ? BRf : BZero;
        t_we  = 1'b1;
      end
      UErr: begin
        st      = StErr;
        a_src   = AT;
        b_src   = sel_q ? BVmeas : BPfb;
        alu_sub = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = RfEraw;
      end
      UAbs: begin
        st      = StErr;
        rb      = RfEraw;
        b_src   = BRf;
        alu_abs = 1'b1;
        t_we    = 1'b1;
      end
      UEq, UX2: begin
        st      = StErr;
        ra      = RfEraw;
        rb      = RfEp | {4'd0, sel_q};
        a_src   = (upc_q == UX2 && hush_now) ? AZero : ARf;
        b_src   = BRf;
        alu_sub = 1'b1;
        rf_we   = (upc_q == UX2);
        rf_wa   = RfX2;
      end
      UE, UEp: begin
        st      = StErr;
        ra      = RfEraw;
        a_src   = (upc_q == UE && hush_now) ? AZero : ARf;
        rf_we   = 1'b1;
        rf_wa   = (upc_q == UE) ? RfE : (RfEp | {4'd0, sel_q});
      end
      ULearn, UFerr, UWin: begin
        st      = StErr;
        a_src   = AT;
        b_src   = BCfg;
        cfg_sel = (upc_q == ULearn) ? (sel_q ? CfDzV : CfDzP) : (upc_q == UFerr) ? CfFerr : CfWin;
        alu_sub = 1'b1;
      end
      UT1: begin
        st    = StT1;
        ra    = RfE;
        rb    = RfN1 | {4'd0, sel_q};
        rf_we = 1'b1;
        rf_wa = RfT1;
        w_src = WMul;
      end
      UT2: begin
        st    = StT2;
        ra    = RfX2;
        rb    = RfN2 | {4'd0, sel_q};
        rf_we = 1'b1;
        rf_wa = RfT2;
        w_src = WMul;
      end
      USum: begin
        st    = StT2;
        ra    = RfT1;
        rb    = RfT2;
        a_src = ARf;
        b_src = BRf;
        rf_we = 1'b1;
        rf_wa = RfSum;
        w_src = WSat;
      end
      UDu, UBc: begin
        st      = (upc_q == UDu) ? StDu : StBc;
        ra      = (upc_q == UDu) ? RfSum : (RfEs | {4'd0, sel_q});
        mb_src  = MbCfg;
        cfg_sel = (upc_q == UBc) ? CfKb : sel_q ? CfKV : CfKP;
        mul_s20 = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = (upc_q == UDu) ? RfDu : RfBc;
        w_src   = WMul;
      end
      UAcc1: begin
        st    = StBc;
        ra    = RfAcc | {4'd0, sel_q};
        rb    = RfDu;
        a_src = ARf;
        b_src = BRf;
        t_we  = 1'b1;
      end
      UAcc2: begin
        st      = StBc;
        rb      = RfBc;
        a_src   = AT;
        b_src   = BRf;
        alu_sub = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = RfAcc | {4'd0, sel_q};
        w_src   = hush_q ? WZero : WSat;
      end
      UTot: begin
        st    = StBc;
        ra    = RfAcc | {4'd0, sel_q};
        rb    = RfVff;
        a_src = ARf;
        b_src = (sel_q && cfg_ff_en_i) ? BRf : BZero;
        rf_we = 1'b1;
        rf_wa = RfTot;
        w_src = WSat;
      end
      UHi, ULo: begin
        st      = StBc;
        ra      = RfTot;
        a_src   = ARf;
        b_src   = BCfg;
        cfg_sel = sel_q ? CfULim : CfVLim;
        alu_sub = (upc_q == UHi);
        // es = tot - lim when tot > lim (else 0), then tot + lim when < -lim
        rf_we   = (upc_q == UHi) || alu_n;
        rf_wa   = RfEs | {4'd0, sel_q};
        w_src   = (upc_q == UHi && (alu_n || alu_z)) ? WZero : WWrap;
      end
      UOut: begin
        st      = StBc;
        ra      = RfTot;
        rb      = RfEs | {4'd0, sel_q};
        a_src   = ARf;
        b_src   = BRf;
        alu_sub = 1'b1;
        rf_we   = !sel_q;
        rf_wa   = RfOutP;
      end
      UH1, UH2: begin
        st     = (upc_q == UH1) ? StH1 : StH2;
        ra     = (upc_q == UH1) ? RfE : RfX2;
        rb     = RfE;
        mb_src = MbEb;
        rf_we  = 1'b1;
        rf_wa  = RfH;
        w_src  = WMul;
      end
      UDw1, UDw2: begin
        st      = (upc_q == UDw1) ? StDw1 : StDw2;
        ra      = RfH;
        mb_src  = MbCfg;
        cfg_sel = (upc_q == UDw1) ? (sel_q ? CfEtaV1 : CfEtaP1) : (sel_q ? CfEtaV2 : CfEtaP2);
        mul_s20 = 1'b1;
        mul_ls  = 1'b1;
        rf_we   = 1'b1;
        rf_wa   = RfDw;
        w_src   = WMul;
      end
      default: begin
        // UW1..UW4 (w1), UW5..UW8 (w2)
        if (upc_q >= UW1 && upc_q <= UW8 && upc_q != UH2 && upc_q != UDw2) begin
          st      = w2nd ? StDw2 : StDw1;
          pair    = (w2nd ? RfW2 : RfW1) | {4'd0, sel_q};
          cfg_sel = (u2 == UW3) ? CfWMin :
                    (u2 == UW4) ? (over_q ? (w2nd ? (sel_q ? CfWV2Max : CfWP2Max)
                                                  : (sel_q ? CfWV1Max : CfWP1Max)) : CfWMin) :
                    w2nd ? (sel_q ? CfWV2Max : CfWP2Max) : (sel_q ? CfWV1Max : CfWP1Max);
          unique case (u2)
            UW1: begin                      // T = w + dw
              ra    = pair;
              rb    = RfDw;
              a_src = ARf;
              b_src = BRf;
              t_we  = 1'b1;
            end
            UW2, UW3: begin                 // T - w_max > 0 ?  T - w_min < 0 ?
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
        end else if (upc_q >= UInit && upc_q < UInit + 6'(NInit)) begin
          // start: e_prev, acc, es, out_p, vff = 0; weights = their initial values
          st    = StInit;
          rf_we = 1'b1;
          b_src = BCfg;
          unique case (upc_q - UInit)
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
          if (upc_q - UInit < 6'd8) b_src = BZero;
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
        cnt_d = cfg_div_i - CtlDivW'(1);
        if (upc_q == UIdle) begin
          // snapshot: P* - 1/2 (the integer target L once the reference is done), P, V
          ref_d   = (ref_done_i ? CtlW'(ref_int_i) << CtlFrac
                                    : CtlW'({ref_int_i, ref_frac_i}) - (CtlW'(1) << (CtlFrac - 1)))
                    <<< cfg_shift_i;
          pfb_d   = CtlW'(enc_pos_i) <<< CtlFrac;
          vmeas_d = (CtlW'(enc_pos_i) <<< CtlFrac) - pfb_q;
          vq_d    = ref_vel_i;
          fin_d   = ref_done_i;
          mvs_d   = mv_q | cmd_busy_i;
          mv_d    = 1'b0;
          sel_d   = 1'b0;
          upc_d   = UVff;
        end
      end else begin
        cnt_d = cnt_q - CtlDivW'(1);
      end
    end

    if (upc_q != UIdle) upc_d = upc_q + 6'd1;
    if (upc_q == UInit + 6'(NInit - 1)) upc_d = UIdle;   // wait for the first snapshot
    unique case (upc_q)
      UIdle: ;
      USet1: drem_d = RemW'(alu_r);
      USet2: begin
        dsum_d = SumW'(alu_r);
        dbit_d = DbitW'(NWgtFrac);
        dquo_d = '0;
      end
      USet3: begin
        drem_d = RemW'(alu_r);
        dbit_d = DbitW'(NWgtFrac);
        dquo_d = '0;
      end
      UDiv1, UDiv2: begin
        drem_d = div_rem_sub << 1;
        dquo_d = div_quo;
        dbit_d = dbit_q - DbitW'(1);
        if (dbit_q != '0) upc_d = upc_q;
      end
      UErr: eraw_d = alu_r[CtlW-1:0];
      UEq: eq_d = alu_z;
      UEp: if (!sel_q) hush_d = hush_now;
      ULearn: learn_d = !hush_now && !alu_n && !alu_z;
      UFerr: begin
        if (!sel_q && !alu_n && !alu_z) begin
          ferr_d   = 1'b1;
          active_d = 1'b0;
          u_d      = '0;
          upc_d    = UIdle;
        end
      end
      UWin: begin
        if (!sel_q) begin
          if (fin_q && !mvs_q && corr_q == '0 && eq_q) begin
            hold_d = hold_q + HoldW'(1);
            if (hold_d >= cfg_inpos_hold_i) begin
              hold_d = '0;
              if (alu_n || alu_z || corr_steps == '0) begin   // |e_p| <= win
                in_pos_d = 1'b1;
                active_d = 1'b0;
                u_d      = '0;
                upc_d    = UIdle;
              end else begin
                corr_d = corr_steps;
              end
            end
          end else begin
            hold_d = '0;
          end
        end
      end
      UOut: if (sel_q) u_d = alu_r[CtlW-1:0];
      default: ;
    endcase
    if (u2 == UW2 && upc_q != UH2 && upc_q != UDw2) over_d = !alu_n && !alu_z;
    if (u2 == UW3 && upc_q != UH2 && upc_q != UDw2) under_d = alu_n;
    if (upc_q == UW8) begin
      if (sel_q) begin
        upc_d = UIdle;
      end else begin
        sel_d = 1'b1;
        upc_d = USet1;
      end
    end

    // settling: the rate command is the corrective stepping only
    if (fin_q && active_d) begin
      u_d = (corr_d == '0) ? '0 : corr_d[CorrW-1] ? -$signed(cfg_settle_rate_i) : $signed(cfg_settle_rate_i);
    end

    if (start_i) begin
      active_d = 1'b1;
      in_pos_d = 1'b0;
      ferr_d   = 1'b0;
      cnt_d    = CtlDivW'(NInit);   // the first snapshot follows the initialisation
      upc_d    = UInit;
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
      upc_d    = UIdle;
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
      upc_q    <= UIdle;
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

endmodule
