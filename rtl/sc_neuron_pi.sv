// sc_neuron_pi: the cascade of two single-neuron adaptive PI controllers
// (outer: position, inner: speed) on ONE time-multiplexed datapath: one
// signed MulAW x MulBW multiplier, one restoring divider (one quotient bit
// per clock) for the weight normalisation, sequenced by an FSM once per
// control period (cfg_div_i clocks, e.g. 2000 = 10 kHz). About 100 clocks
// of work per period; cfg_div_i must be >= 128.
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
  localparam int CoefW    = sc_pkg::CoefW;
  localparam int CoefFrac = sc_pkg::CoefFrac;
  localparam int MulAW    = sc_pkg::MulAW;
  localparam int MulBW    = sc_pkg::MulBW;
  localparam int VffFrac  = sc_pkg::VffFrac;
  localparam int HoldW    = sc_pkg::HoldW;
  localparam int CtlStW   = sc_pkg::CtlStW;
  localparam int LearnShW = sc_pkg::LearnShW;
  localparam int ProdW    = MulAW + MulBW;
  localparam int QuoW     = NWgtFrac + 1;   // |wn| <= 1.0
  localparam int RemW     = WgtW + 2;
  localparam int SumW     = WgtW + 1;
  localparam int DbitW    = 5;

  // FSM states (state_o)
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

  localparam logic signed [CtlW-1:0]  CtlMax = {1'b0, {(CtlW-1){1'b1}}};
  localparam logic signed [CtlW-1:0]  CtlMin = {1'b1, {(CtlW-1){1'b0}}};
  localparam logic signed [MulBW-1:0] BMax   = {1'b0, {(MulBW-1){1'b1}}};

  // ---- state ---------------------------------------------------------------
  logic                      active_q, active_d;
  logic                      in_pos_q, in_pos_d;
  logic                      ferr_q, ferr_d;
  logic [CtlDivW-1:0]        cnt_q, cnt_d;
  logic [CtlStW-1:0]         st_q, st_d;
  logic                      sel_q, sel_d;      // 0 = position loop, 1 = speed loop
  logic                      dsel_q, dsel_d;    // divider: 0 = w1, 1 = w2
  logic [DbitW-1:0]          dbit_q, dbit_d;
  logic [RemW-1:0]           drem_q, drem_d;
  logic [QuoW-1:0]           dquo_q, dquo_d;
  logic [SumW-1:0]           dsum_q, dsum_d;
  logic [HoldW-1:0]          hold_q, hold_d;
  logic                      hush_q, hush_d;    // settling: accumulators held at 0
  logic signed [sc_pkg::CorrW-1:0] corr_q, corr_d;  // corrective steps still to issue
  // control-period snapshot
  logic signed [CtlW-1:0]    ref_q, ref_d;      // P* - 1/2, counts Q.8
  logic signed [CtlW-1:0]    pfb_q, pfb_d;      // P, counts Q.8
  logic signed [CtlW-1:0]    vmeas_q, vmeas_d;  // P - P_prev, counts/period Q.8
  logic signed [MulAW-1:0]   vq_q, vq_d;        // V*, Q.31 pulses/clock
  logic                      fin_q, fin_d;
  logic                      mv_q, mv_d;        // cmd_busy_i seen since the last snapshot
  logic                      mvs_q, mvs_d;      // ... in the period before the snapshot
  logic signed [CtlW-1:0]    vff_q, vff_d;      // V*, counts/period Q.8
  // per-loop state: index 0 position, 1 speed
  logic signed [WgtW-1:0]    w1_p_q, w1_p_d, w2_p_q, w2_p_d, w1_v_q, w1_v_d, w2_v_q, w2_v_d;
  logic signed [NWgtW-1:0]   n1_p_q, n1_p_d, n2_p_q, n2_p_d, n1_v_q, n1_v_d, n2_v_q, n2_v_d;
  logic signed [CtlW-1:0]    ep_p_q, ep_p_d, ep_v_q, ep_v_d;     // e(k-1)
  logic signed [CtlW-1:0]    acc_p_q, acc_p_d, acc_v_q, acc_v_d;
  logic signed [CtlW-1:0]    es_p_q, es_p_d, es_v_q, es_v_d;     // tot - sat(tot)
  logic signed [CtlW-1:0]    out_p_q, out_p_d;                  // v_cmd
  logic signed [CtlW-1:0]    u_q, u_d;                          // speed-loop output
  // datapath temporaries
  logic signed [CtlW-1:0]    e_q, e_d, x2_q, x2_d, t1_q, t1_d, t2_q, t2_d, du_q, du_d, h_q, h_d;

  // ---- helpers ---------------------------------------------------------------
  // Saturation as sign-bit checks (no magnitude comparators): a value is in
  // the CtlW range iff its bits above CtlW-2 are all equal.
  function automatic logic signed [CtlW-1:0] sat_c33(input logic signed [CtlW:0] v);
    if (v[CtlW] != v[CtlW-1]) begin
      sat_c33 = v[CtlW] ? CtlMin : CtlMax;
    end else begin
      sat_c33 = v[CtlW-1:0];
    end
  endfunction

  function automatic logic signed [CtlW-1:0] sat_prod(input logic signed [ProdW-1:0] v);
    if (v[ProdW-1:CtlW-1] != '0 && v[ProdW-1:CtlW-1] != '1) begin
      sat_prod = v[ProdW-1] ? CtlMin : CtlMax;
    end else begin
      sat_prod = v[CtlW-1:0];
    end
  endfunction

  function automatic logic [WgtW-1:0] abs_w(input logic signed [WgtW-1:0] v);
    abs_w = v[WgtW-1] ? WgtW'(-v) : WgtW'(v);
  endfunction

  // ---- per-loop views (selected by sel_q) ---------------------------------------
  logic signed [WgtW-1:0]  cur_w1, cur_w2;
  logic signed [NWgtW-1:0] cur_n1, cur_n2;
  logic signed [CtlW-1:0]  cur_ep, cur_acc, cur_es, cur_bias, cur_ref, cur_fb;
  logic [CtlW-1:0]         cur_lim;
  logic [CoefW-1:0]        cur_k, cur_eta1, cur_eta2;

  assign cur_w1   = sel_q ? w1_v_q : w1_p_q;
  assign cur_w2   = sel_q ? w2_v_q : w2_p_q;
  assign cur_n1   = sel_q ? n1_v_q : n1_p_q;
  assign cur_n2   = sel_q ? n2_v_q : n2_p_q;
  assign cur_ep   = sel_q ? ep_v_q : ep_p_q;
  assign cur_acc  = sel_q ? acc_v_q : acc_p_q;
  assign cur_es   = sel_q ? es_v_q : es_p_q;
  assign cur_bias = (sel_q && cfg_ff_en_i) ? vff_q : '0;
  assign cur_ref  = sel_q ? out_p_q + cur_bias : ref_q;
  assign cur_fb   = sel_q ? vmeas_q : pfb_q;
  assign cur_lim  = sel_q ? cfg_u_lim_i : cfg_v_lim_i;
  assign cur_k    = sel_q ? cfg_k_v_i : cfg_k_p_i;
  assign cur_eta1 = sel_q ? cfg_eta_v1_i : cfg_eta_p1_i;
  assign cur_eta2 = sel_q ? cfg_eta_v2_i : cfg_eta_p2_i;

  // ---- cfg_div_i << cfg_shift_i ---------------------------------------------------
  localparam int DivShW = CtlDivW + (1 << sc_pkg::EncShiftW) - 1;
  logic [DivShW-1:0] div_sh;
  assign div_sh   = DivShW'(cfg_div_i) << cfg_shift_i;
  assign div_sh_o = div_sh;

  // ---- the one multiplier ---------------------------------------------------------
  logic signed [MulAW-1:0] mul_a;
  logic signed [MulBW-1:0] mul_b;
  logic signed [ProdW-1:0] mul_p, mul_r;
  logic signed [CtlW-1:0]  mul_y;     // rounded, shifted, saturated
  logic signed [MulBW-1:0] e_b;       // e saturated to the B port

  // learn = |e| > dead zone, registered in StErr (from |e_now|, which is
  // |e_q| from then on, or e_q = 0 while settling)
  logic                    learn_q, learn_d;
  logic                    learn;
  assign learn  = learn_q;
  // |e| <= BMax iff bits CtlW-1..MulBW-1 are all equal and e != -2^(MulBW-1)
  logic                    e_in_b;
  assign e_in_b = ((e_q[CtlW-1:MulBW-1] == '0) || (e_q[CtlW-1:MulBW-1] == '1))
                  && (e_q[MulBW-2:0] != '0 || !e_q[CtlW-1]);
  assign e_b    = !learn ? '0 : !e_in_b ? (e_q[CtlW-1] ? -BMax : BMax) : e_q[MulBW-1:0];

  // Every product is rounded half up and shifted by s = 16 (Vff, T1, T2, H1,
  // H2), 20 (Du, Bc) or 20 + learn_shift (Dw1, Dw2). Vff's shift
  // (VffFrac - CtlFrac - shift = 15 - shift) is brought to 16 by scaling the
  // B operand by 2^(shift+1) (exact: floor((p 2^k + 2^15) / 2^16) =
  // floor((p + 2^(15-k)) / 2^(16-k))). (p + 2^(s-1)) >>> s is computed as
  // ((p >>> (s-1)) + 1) >>> 1 = (v >>> 1) + v[0], with v = p >>> (s-1) = (p >>> (b-1)) >>> ls.
  logic                    mul_s20;   // base shift 20 (else 16)
  logic                    mul_ls;    // plus learn_shift
  always_comb begin
    mul_a   = '0;
    mul_b   = '0;
    mul_s20 = 1'b0;
    mul_ls  = 1'b0;
    unique case (st_q)
      StVff: begin
        mul_a  = vq_q;
        mul_b  = MulBW'(div_sh) << (ShLo - (VffFrac - CtlFrac));
      end
      StT1: begin
        mul_a  = e_q;
        mul_b  = MulBW'(cur_n1);
      end
      StT2: begin
        mul_a  = x2_q;
        mul_b  = MulBW'(cur_n2);
      end
      StDu: begin
        mul_a   = sat_c33((CtlW+1)'(t1_q) + (CtlW+1)'(t2_q));
        mul_b   = MulBW'({1'b0, cur_k});
        mul_s20 = 1'b1;
      end
      StBc: begin
        mul_a   = cur_es;
        mul_b   = MulBW'({1'b0, cfg_kb_i});
        mul_s20 = 1'b1;
      end
      StH1: begin
        mul_a  = e_q;
        mul_b  = e_b;
      end
      StDw1: begin
        mul_a   = h_q;
        mul_b   = MulBW'({1'b0, cur_eta1});
        mul_s20 = 1'b1;
        mul_ls  = 1'b1;
      end
      StH2: begin
        mul_a  = x2_q;
        mul_b  = e_b;
      end
      StDw2: begin
        mul_a   = h_q;
        mul_b   = MulBW'({1'b0, cur_eta2});
        mul_s20 = 1'b1;
        mul_ls  = 1'b1;
      end
      default: ;
    endcase
  end

  // ShLo = NWgtFrac = CtlFrac, ShHi = CoefFrac = CoefFrac + CtlFrac - WgtFrac
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
  assign mul_y   = sat_prod(mul_r);

  // ---- divider step -------------------------------------------------------------------
  logic             div_ge;
  logic [RemW-1:0]  div_rem_sub;
  logic [QuoW-1:0]  div_quo;
  logic [QuoW-1:0]  div_res;
  logic signed [NWgtW-1:0] div_wn;
  logic             div_neg;
  logic signed [NWgtW-1:0] div_pos;

  // restoring division: the borrow of one subtraction decides the quotient
  // bit; bits enter at the LSB, MSB first (NWgtFrac+1 steps fill dquo)
  logic [RemW:0]    div_diff;
  assign div_diff    = {1'b0, drem_q} - {1'b0, RemW'(dsum_q)};
  assign div_ge      = !div_diff[RemW];
  assign div_rem_sub = div_ge ? div_diff[RemW-1:0] : drem_q;
  assign div_quo     = {dquo_q[QuoW-2:0], div_ge};
  assign div_neg     = dsel_q ? cur_w2[WgtW-1] : cur_w1[WgtW-1];
  assign div_res     = (dsum_q == '0) ? '0 : div_quo;
  assign div_pos     = NWgtW'(div_res);
  assign div_wn      = div_neg ? -div_pos : div_pos;

  // ---- position error (checked in StErr) ----------------------------------------------
  logic signed [CtlW-1:0] e_now, ae_now;
  logic [CtlW-1:0]        abs_e;
  assign e_now  = cur_ref - cur_fb;
  assign ae_now = e_now[CtlW-1] ? -e_now : e_now;
  assign abs_e  = ae_now;
  logic signed [CtlW-1:0] e_db;
  logic                   hush_now;
  assign hush_now = !sel_q && fin_q;
  assign e_db     = hush_now ? '0 : e_now;

  // e_p rounded to whole steps (2^(CtlFrac+shift) per step), saturated
  localparam int CorrW = sc_pkg::CorrW;
  logic signed [CtlW-1:0]  corr_full;
  logic signed [CorrW-1:0] corr_steps, corr_step_dir;
  // (e + 2^(sh-1)) >>> sh, sh = CtlFrac + shift: v = (e >>> (CtlFrac-1)) >>> shift,
  // then floor((v + 1) / 2) = (v >>> 1) + v[0]
  localparam int CvW = CtlW - CtlFrac + 1;
  logic signed [CvW-1:0]   corr_v;
  logic signed [CvW-2:0]   corr_h;
  assign corr_v     = CvW'(e_now >>> (CtlFrac - 1)) >>> cfg_shift_i;
  assign corr_h     = corr_v[CvW-1:1];
  assign corr_full  = CtlW'(corr_h) + CtlW'({1'b0, corr_v[0]});
  logic                    corr_in;   // |corr_full| <= 2^(CorrW-1) - 1
  assign corr_in    = ((corr_full[CtlW-1:CorrW-1] == '0) || (corr_full[CtlW-1:CorrW-1] == '1))
                      && (corr_full[CorrW-2:0] != '0 || !corr_full[CtlW-1]);
  assign corr_steps = !corr_in ? (corr_full[CtlW-1] ? -CorrW'(2**(CorrW-1) - 1) : CorrW'(2**(CorrW-1) - 1)) :
                      corr_full[CorrW-1:0];
  assign corr_step_dir = corr_q[CorrW-1] ? CorrW'(1) : -CorrW'(1);

  // ---- accumulate and saturate (StBc) -------------------------------------------------
  // out = clamp(tot, +-lim), es = tot - out: with o_hi = tot - lim and
  // o_lo = tot + lim (CtlW+2 bits, exact), tot > lim iff o_hi > 0 and then
  // es = o_hi (in range: 0 < o_hi < 2^(CtlW-1)), tot < -lim iff o_lo < 0 and
  // es = o_lo; a lim >= 2^(CtlW-1) never limits. No comparator, no saturation.
  localparam int LimW = CtlW + 2;
  logic signed [CtlW-1:0] acc_new, tot, out_sat, es_new;
  logic signed [CtlW+1:0] acc3;      // acc + du - bc, exact; saturated once
  logic signed [LimW-1:0] lim_s, o_hi, o_lo;
  logic                   lim_hi, lim_lo;
  assign acc3    = (CtlW+2)'(cur_acc) + (CtlW+2)'(du_q) - (CtlW+2)'(mul_y);
  assign acc_new = hush_q ? '0 :
                   (acc3[CtlW+1:CtlW-1] != '0 && acc3[CtlW+1:CtlW-1] != '1) ?
                   (acc3[CtlW+1] ? CtlMin : CtlMax) : acc3[CtlW-1:0];
  assign tot     = sat_c33((CtlW+1)'(acc_new) + (CtlW+1)'(cur_bias));
  assign lim_s   = $signed({2'b00, cur_lim});
  assign o_hi    = LimW'(tot) - lim_s;
  assign o_lo    = LimW'(tot) + lim_s;
  assign lim_hi  = !o_hi[LimW-1] && (o_hi != '0);
  assign lim_lo  = o_lo[LimW-1];
  assign out_sat = lim_hi ? CtlW'(cur_lim) : lim_lo ? CtlW'(-lim_s) : tot;
  assign es_new  = lim_hi ? o_hi[CtlW-1:0] : lim_lo ? o_lo[CtlW-1:0] : '0;

  // ---- weight update (StDw1/StDw2) ----------------------------------------------------
  logic signed [CtlW:0]   w_sum;
  logic signed [WgtW-1:0] w_new, w_old;
  assign w_old = (st_q == StDw1) ? cur_w1 : cur_w2;
  assign w_sum = (CtlW+1)'(w_old) + (CtlW+1)'(mul_y);
  logic signed [WgtW-1:0] w_hi;
  assign w_hi  = (st_q == StDw1) ? (sel_q ? cfg_w_v1_max_i : cfg_w_p1_max_i)
                                 : (sel_q ? cfg_w_v2_max_i : cfg_w_p2_max_i);
  assign w_new = (w_sum > (CtlW+1)'(w_hi)) ? w_hi :
                 (w_sum < (CtlW+1)'(cfg_w_min_i)) ? cfg_w_min_i : w_sum[WgtW-1:0];

  // divider set-up (StVff: position weights; StDw2: speed weights; StDiv:
  // |w2| of the current loop) on one pair of |.| and one adder
  logic signed [WgtW-1:0] ws1, ws2;
  logic [WgtW-1:0]        aws1, aws2;
  logic [SumW-1:0]        aws_sum;
  assign ws1     = (st_q == StVff) ? w1_p_q : w1_v_q;
  assign ws2     = (st_q == StVff || (st_q == StDiv && !sel_q)) ? w2_p_q : w2_v_q;
  assign aws1    = abs_w(ws1);
  assign aws2    = abs_w(ws2);
  assign aws_sum = SumW'(aws1) + SumW'(aws2);

  // ---- FSM and datapath ---------------------------------------------------------------
  always_comb begin
    active_d = active_q;
    in_pos_d = in_pos_q;
    ferr_d   = ferr_q;
    cnt_d    = cnt_q;
    st_d     = st_q;
    sel_d    = sel_q;
    dsel_d   = dsel_q;
    dbit_d   = dbit_q;
    drem_d   = drem_q;
    dquo_d   = dquo_q;
    dsum_d   = dsum_q;
    hold_d   = hold_q;
    hush_d   = hush_q;
    corr_d   = corr_q;
    if (corr_q != '0 && nco_req_i) corr_d = corr_q + corr_step_dir;
    ref_d    = ref_q;
    pfb_d    = pfb_q;
    vmeas_d  = vmeas_q;
    vq_d     = vq_q;
    fin_d    = fin_q;
    mv_d     = mv_q | cmd_busy_i;
    mvs_d    = mvs_q;
    vff_d    = vff_q;
    w1_p_d   = w1_p_q;
    w2_p_d   = w2_p_q;
    w1_v_d   = w1_v_q;
    w2_v_d   = w2_v_q;
    n1_p_d   = n1_p_q;
    n2_p_d   = n2_p_q;
    n1_v_d   = n1_v_q;
    n2_v_d   = n2_v_q;
    ep_p_d   = ep_p_q;
    ep_v_d   = ep_v_q;
    acc_p_d  = acc_p_q;
    acc_v_d  = acc_v_q;
    es_p_d   = es_p_q;
    es_v_d   = es_v_q;
    out_p_d  = out_p_q;
    u_d      = u_q;
    e_d      = e_q;
    x2_d     = x2_q;
    t1_d     = t1_q;
    t2_d     = t2_q;
    du_d     = du_q;
    h_d      = h_q;
    learn_d  = learn_q;

    if (active_q) begin
      if (cnt_q == '0) begin
        cnt_d = cfg_div_i - CtlDivW'(1);
        if (st_q == StIdle) begin
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
          st_d    = StVff;
        end
      end else begin
        cnt_d = cnt_q - CtlDivW'(1);
      end
    end

    unique case (st_q)
      StIdle: ;
      StVff: begin
        vff_d  = mul_y;
        sel_d  = 1'b0;
        dsel_d = 1'b0;
        dbit_d = DbitW'(NWgtFrac);
        dquo_d = '0;
        drem_d = RemW'(aws1);
        dsum_d = aws_sum;
        st_d   = StDiv;
      end
      StDiv: begin
        drem_d = div_rem_sub << 1;
        dquo_d = div_quo;
        dbit_d = dbit_q - DbitW'(1);
        if (dbit_q == '0) begin
          if (!dsel_q) begin
            if (sel_q) n1_v_d = div_wn; else n1_p_d = div_wn;
            dsel_d = 1'b1;
            dbit_d = DbitW'(NWgtFrac);
            dquo_d = '0;
            drem_d = RemW'(aws2);
          end else begin
            if (sel_q) n2_v_d = div_wn; else n2_p_d = div_wn;
            st_d = StErr;
          end
        end
      end
      StErr: begin
        e_d  = e_db;
        learn_d = !hush_now && (abs_e > (sel_q ? cfg_learn_dz_v_i : cfg_learn_dz_p_i));
        x2_d = e_db - cur_ep;
        // e_p_o keeps the raw position error (also while settling)
        if (sel_q) ep_v_d = e_db; else ep_p_d = e_now;
        if (!sel_q) hush_d = hush_now;
        st_d = StT1;
        if (!sel_q) begin
          if (abs_e > cfg_ferr_lim_i) begin
            ferr_d   = 1'b1;
            active_d = 1'b0;
            u_d      = '0;
            st_d     = StIdle;
          end else if (fin_q && !mvs_q && corr_q == '0 && e_now == ep_p_q) begin
            hold_d = hold_q + HoldW'(1);
            if (hold_d >= cfg_inpos_hold_i) begin
              hold_d = '0;
              if (abs_e <= cfg_inpos_win_i || corr_steps == '0) begin
                in_pos_d = 1'b1;
                active_d = 1'b0;
                u_d      = '0;
                st_d     = StIdle;
              end else begin
                corr_d = corr_steps;
              end
            end
          end else begin
            hold_d = '0;
          end
        end
      end
      StT1: begin
        t1_d = mul_y;
        st_d = StT2;
      end
      StT2: begin
        t2_d = mul_y;
        st_d = StDu;
      end
      StDu: begin
        du_d = mul_y;
        st_d = StBc;
      end
      StBc: begin
        if (sel_q) begin
          acc_v_d = acc_new;
          es_v_d  = es_new;
          u_d     = out_sat;
        end else begin
          acc_p_d = acc_new;
          es_p_d  = es_new;
          out_p_d = out_sat;
        end
        st_d = StH1;
      end
      StH1: begin
        h_d  = mul_y;
        st_d = StDw1;
      end
      StDw1: begin
        if (sel_q) w1_v_d = w_new; else w1_p_d = w_new;
        st_d = StH2;
      end
      StH2: begin
        h_d  = mul_y;
        st_d = StDw2;
      end
      StDw2: begin
        if (sel_q) begin
          w2_v_d = w_new;
          st_d   = StIdle;
        end else begin
          w2_p_d = w_new;
          sel_d  = 1'b1;
          dsel_d = 1'b0;
          dbit_d = DbitW'(NWgtFrac);
          dquo_d = '0;
          drem_d = RemW'(aws1);
          dsum_d = aws_sum;
          st_d   = StDiv;
        end
      end
      default: st_d = StIdle;
    endcase

    // settling: the rate command is the corrective stepping only
    if (fin_q && active_d) begin
      u_d = (corr_d == '0) ? '0 : corr_d[CorrW-1] ? -$signed(cfg_settle_rate_i) : $signed(cfg_settle_rate_i);
    end

    if (start_i) begin
      active_d = 1'b1;
      in_pos_d = 1'b0;
      ferr_d   = 1'b0;
      cnt_d    = '0;
      st_d     = StIdle;
      sel_d    = 1'b0;
      hold_d   = '0;
      hush_d   = 1'b0;
      corr_d   = '0;
      fin_d    = 1'b0;
      pfb_d    = CtlW'(enc_pos_i) <<< CtlFrac;
      vmeas_d  = '0;
      vff_d    = '0;
      w1_p_d   = cfg_w_p1_i;
      w2_p_d   = cfg_w_p2_i;
      w1_v_d   = cfg_w_v1_i;
      w2_v_d   = cfg_w_v2_i;
      ep_p_d   = '0;
      ep_v_d   = '0;
      acc_p_d  = '0;
      acc_v_d  = '0;
      es_p_d   = '0;
      es_v_d   = '0;
      out_p_d  = '0;
      u_d      = '0;
    end else if (stop_i) begin
      active_d = 1'b0;
      st_d     = StIdle;
      u_d      = '0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      active_q <= 1'b0;
      in_pos_q <= 1'b0;
      ferr_q   <= 1'b0;
      cnt_q    <= '0;
      st_q     <= StIdle;
      sel_q    <= 1'b0;
      dsel_q   <= 1'b0;
      dbit_q   <= '0;
      drem_q   <= '0;
      dquo_q   <= '0;
      dsum_q   <= '0;
      hold_q   <= '0;
      hush_q   <= 1'b0;
      corr_q   <= '0;
      ref_q    <= '0;
      pfb_q    <= '0;
      vmeas_q  <= '0;
      vq_q     <= '0;
      fin_q    <= 1'b0;
      mv_q     <= 1'b0;
      mvs_q    <= 1'b0;
      vff_q    <= '0;
      w1_p_q   <= '0;
      w2_p_q   <= '0;
      w1_v_q   <= '0;
      w2_v_q   <= '0;
      n1_p_q   <= '0;
      n2_p_q   <= '0;
      n1_v_q   <= '0;
      n2_v_q   <= '0;
      ep_p_q   <= '0;
      ep_v_q   <= '0;
      acc_p_q  <= '0;
      acc_v_q  <= '0;
      es_p_q   <= '0;
      es_v_q   <= '0;
      out_p_q  <= '0;
      u_q      <= '0;
      e_q      <= '0;
      x2_q     <= '0;
      t1_q     <= '0;
      t2_q     <= '0;
      du_q     <= '0;
      h_q      <= '0;
      learn_q  <= 1'b0;
    end else begin
      active_q <= active_d;
      in_pos_q <= in_pos_d;
      ferr_q   <= ferr_d;
      cnt_q    <= cnt_d;
      st_q     <= st_d;
      sel_q    <= sel_d;
      dsel_q   <= dsel_d;
      dbit_q   <= dbit_d;
      drem_q   <= drem_d;
      dquo_q   <= dquo_d;
      dsum_q   <= dsum_d;
      hold_q   <= hold_d;
      hush_q   <= hush_d;
      corr_q   <= corr_d;
      ref_q    <= ref_d;
      pfb_q    <= pfb_d;
      vmeas_q  <= vmeas_d;
      vq_q     <= vq_d;
      fin_q    <= fin_d;
      mv_q     <= mv_d;
      mvs_q    <= mvs_d;
      vff_q    <= vff_d;
      w1_p_q   <= w1_p_d;
      w2_p_q   <= w2_p_d;
      w1_v_q   <= w1_v_d;
      w2_v_q   <= w2_v_d;
      n1_p_q   <= n1_p_d;
      n2_p_q   <= n2_p_d;
      n1_v_q   <= n1_v_d;
      n2_v_q   <= n2_v_d;
      ep_p_q   <= ep_p_d;
      ep_v_q   <= ep_v_d;
      acc_p_q  <= acc_p_d;
      acc_v_q  <= acc_v_d;
      es_p_q   <= es_p_d;
      es_v_q   <= es_v_d;
      out_p_q  <= out_p_d;
      u_q      <= u_d;
      e_q      <= e_d;
      x2_q     <= x2_d;
      t1_q     <= t1_d;
      t2_q     <= t2_d;
      du_q     <= du_d;
      h_q      <= h_d;
      learn_q  <= learn_d;
    end
  end

  assign active_o     = active_q;
  assign in_pos_o     = in_pos_q;
  assign fault_ferr_o = ferr_q;
  assign u_o          = u_q;
  assign v_cmd_o      = out_p_q;
  assign e_p_o        = ep_p_q;
  assign e_v_o        = ep_v_q;
  assign w_p1_o       = w1_p_q;
  assign w_p2_o       = w2_p_q;
  assign w_v1_o       = w1_v_q;
  assign w_v2_o       = w2_v_q;
  assign wn_p1_o      = n1_p_q;
  assign wn_p2_o      = n2_p_q;
  assign wn_v1_o      = n1_v_q;
  assign wn_v2_o      = n2_v_q;
  assign state_o      = st_q;

endmodule
