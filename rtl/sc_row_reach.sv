// sc_row_reach: how far a row moves the position, forward and backward,
// for the soft-limit look-ahead.
//
// A row (N clocks, jerk j, start acceleration a, start velocity v) moves the
// executor's position by S(n) = n v + C(n,2) a + C(n,3) j after n of its
// clocks (v_n = v + n a + C(n,2) j is the velocity added in clock n). The
// evaluator finds the largest and smallest S(n) over n = 0 .. N exactly and
// reports them with ReachFrac fraction bits, rounded outward (reach_fwd_o up,
// reach_rev_o down): the window check on them is exact to 2^-ReachFrac pulse
// and errs on the safe side.
//
// The extremes of S are at n = 0, n = N and where v changes sign (v >= 0 to
// v < 0 or back). v is quadratic in n: monotone on [0, k] and on [k, N-1],
// k the first clock whose acceleration a_k = a + k j has not the sign of a
// (a division; k = N-1 if a_(N-2) still has it), so each piece has at most
// one sign change, found by a binary search on v. A row whose velocity or
// acceleration leaves its register's range inside the row (the executor
// would wrap) cannot be bounded: its reach is the largest the outputs hold,
// so any window refuses it.
//
// One W-bit adder (acc +/- mcd) does all of it under a micro-program: each
// micro-operation loads its operand (one clock) and then runs a shift-add
// multiplication by a 32-bit count (32 clocks) or a small constant, a
// restoring division (one quotient bit per clock), or the exact division of
// 6 S by 6 2^64 (one bit per clock, mod-3 remainder); one decision clock
// ends each program. In M = m (or N-1 for the row's end):
//   2 v_M = M (M j + 2a - j) + 2v,
//   6 S(M) = M (M (M j + 3a - 3j) + 6v - 3a + 2j),
//   6 S(M+1) = M (M (M j + 3a) + 6v + 3a - j) + 6v.
// A row without a sign change takes 282 clocks (425 with a vertex inside),
// one with two about 5,700 at most. abort_i drops the evaluation; start_i is taken while idle.
module sc_row_reach (
  input  logic                              clk_i,
  input  logic                              rst_ni,

  input  logic                              start_i,
  input  logic                              abort_i,
  input  logic [sc_pkg::SegClkW-1:0]        clocks_i,
  input  logic signed [sc_pkg::JerkW-1:0]   jerk_i,
  input  logic signed [sc_pkg::AccW-1:0]    acc0_i,
  input  logic signed [sc_pkg::VelW-1:0]    vel0_i,

  output logic                              busy_o,
  output logic                              done_o,       // one clock: the reach outputs hold this row's
  output logic signed [sc_pkg::ReachW-1:0]  reach_fwd_o,  // max S(n), 2^-ReachFrac pulses, rounded up
  output logic signed [sc_pkg::ReachW-1:0]  reach_rev_o   // min S(n), rounded down
);

  // |6 S| <= 6 (2^32 - 1) 2^80 < 2^115 for a row in range and |2 v_m| < 2^112
  // for any: 116 bits hold every result exactly (modulo 2^W in between).
  localparam int W      = sc_pkg::ReachAccW;
  localparam int NW     = sc_pkg::SegClkW;
  localparam int RW     = sc_pkg::ReachW;
  localparam int VelW   = sc_pkg::VelW;
  localparam int AccW   = sc_pkg::AccW;
  localparam int JerkW  = sc_pkg::JerkW;
  // 6 S is divided by 6 * 2^DivSh: its bits from DivSh+1 up, one a clock
  localparam int DivSh  = sc_pkg::FracBits - sc_pkg::ReachFrac;

  localparam logic [2:0] StIdle = 3'd0, StLd = 3'd1, StRun = 3'd2, StDec = 3'd3, StDone = 3'd4;
  // the program that just ended (in StDec)
  localparam logic [3:0] PhStart = 4'd0, PhA = 4'd1, PhK = 4'd2, PhVk = 4'd3, PhVn = 4'd4,
                         PhSn = 4'd5, PhSrch = 4'd6, PhStep = 4'd7, PhSt = 4'd8;
  // micro-programs: first address
  localparam logic [4:0] PcA = 5'd0, PcK = 5'd3, PcV = 5'd6, PcSn = 5'd11, PcS = 5'd20;
  // the count M of a program
  localparam logic [1:0] MNm1 = 2'd0, MK = 2'd1, MMid = 2'd2, MHi = 2'd3;
  // micro-operation kinds and operands
  localparam logic [1:0] KMul = 2'd0, KDivK = 2'd1, KDiv3 = 2'd2;
  localparam logic [1:0] SrcA = 2'd0, SrcJ = 2'd1, SrcV = 2'd2, SrcAcc = 2'd3;

  logic [2:0]              st_q, st_d;
  logic [3:0]              ph_q, ph_d;
  logic [4:0]              pc_q, pc_d;
  logic [5:0]              cnt_q, cnt_d;
  logic [1:0]              msel_q, msel_d;
  logic [NW-1:0]           nm1_q, nm1_d, k_q, k_d, lo_q, lo_d, hi_q, hi_d;
  logic signed [JerkW-1:0] j_q, j_d;
  logic signed [AccW-1:0]  a_q, a_d;
  logic signed [VelW-1:0]  v_q, v_d;
  logic signed [W-1:0]     acc_q, acc_d, mcd_q, mcd_d;
  logic [RW-1:0]           mlr_q, mlr_d;
  logic [1:0]              r3_q, r3_d;
  logic                    one_q, one_d, kc_q, kc_d, clsk_q, clsk_d, clsn_q, clsn_d;
  logic                    ref_q, ref_d, srch2_q, srch2_d;
  logic signed [RW-1:0]    fwd_q, fwd_d, rev_q, rev_d;

  // the micro-operation at pc
  logic [1:0]  u_kind, u_src;
  logic        u_clr, u_usem, u_sub, u_last;
  logic [2:0]  u_c;
  logic [5:0]  u_len;   // iterations - 1

  logic signed [W-1:0] opnd, sum, bus;
  logic [NW-1:0]       m_val;
  logic [NW-1:0]       mid;
  logic [2:0]          t3;
  logic                cls0, v_in_range, a_in_range, rem_nz;
  logic signed [RW-1:0] cand_up;
  logic                search, srch_init2, go_sat;

  always_comb begin
    u_kind = KMul;
    u_src  = SrcJ;
    u_clr  = 1'b0;
    u_usem = 1'b0;
    u_sub  = 1'b0;
    u_last = 1'b0;
    u_c    = 3'd1;
    u_len  = 6'd0;
    unique case (pc_q)
      // a_(N-2) = (N-1) j + a - j
      5'd0:  begin u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd1:  u_src = SrcA;
      5'd2:  begin u_sub = 1'b1; u_last = 1'b1; end
      // k: (a - j) / (j 2^31 .. j), counting the steps that keep the sign of a
      5'd3:  begin u_src = SrcA; u_clr = 1'b1; end
      5'd4:  begin u_sub = 1'b1; u_len = 6'd30; end
      5'd5:  begin u_kind = KDivK; u_c = 3'd0; u_len = 6'd31; u_last = 1'b1; end
      // 2 v_M
      5'd6:  begin u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd7:  begin u_src = SrcA; u_c = 3'd2; u_len = 6'd1; end
      5'd8:  u_sub = 1'b1;
      5'd9:  begin u_src = SrcAcc; u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd10: begin u_src = SrcV; u_c = 3'd2; u_len = 6'd1; u_last = 1'b1; end
      // 6 S(M+1)
      5'd11: begin u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd12: begin u_src = SrcA; u_c = 3'd3; u_len = 6'd1; end
      5'd13: begin u_src = SrcAcc; u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd14: begin u_src = SrcV; u_c = 3'd6; u_len = 6'd2; end
      5'd15: begin u_src = SrcA; u_c = 3'd3; u_len = 6'd1; end
      5'd16: u_sub = 1'b1;
      5'd17: begin u_src = SrcAcc; u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd18: begin u_src = SrcV; u_c = 3'd6; u_len = 6'd2; end
      5'd19: begin u_kind = KDiv3; u_src = SrcAcc; u_len = 6'(W - DivSh - 3); u_last = 1'b1; end
      // 6 S(M)
      5'd20: begin u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd21: begin u_src = SrcA; u_c = 3'd3; u_len = 6'd1; end
      5'd22: begin u_sub = 1'b1; u_c = 3'd3; u_len = 6'd1; end
      5'd23: begin u_src = SrcAcc; u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      5'd24: begin u_src = SrcV; u_c = 3'd6; u_len = 6'd2; end
      5'd25: begin u_src = SrcA; u_sub = 1'b1; u_c = 3'd3; u_len = 6'd1; end
      5'd26: begin u_c = 3'd2; u_len = 6'd1; end
      5'd27: begin u_src = SrcAcc; u_clr = 1'b1; u_usem = 1'b1; u_len = 6'd31; end
      default: begin u_kind = KDiv3; u_src = SrcAcc; u_len = 6'(W - DivSh - 3); u_last = 1'b1; end
    endcase
  end

  // The one adder: acc + mcd, or acc - mcd.
  assign opnd = u_sub ? ~mcd_q : mcd_q;
  assign sum  = acc_q + opnd + W'(u_sub);

  // operand of a load
  always_comb begin
    unique case (u_src)
      SrcA:    bus = W'(a_q);
      SrcJ:    bus = W'(j_q);
      SrcV:    bus = W'(v_q);
      default: bus = acc_q;
    endcase
  end

  assign mid = NW'(({1'b0, lo_q} + {1'b0, hi_q}) >> 1);
  always_comb begin
    unique case (msel_q)
      MNm1:    m_val = nm1_q;
      MK:      m_val = k_q;
      MMid:    m_val = mid;
      default: m_val = hi_q;
    endcase
  end

  // 6 S >> DivSh+1 divided by 3, MSB first: twice the remainder plus the next bit
  assign t3 = {r3_q, mcd_q[W-2]};

  assign cls0 = v_q[VelW-1];  // class of v_0: 1 = negative
  // 2 v_m in acc: v_m within the velocity register's range
  assign v_in_range = acc_q[W-1:VelW] == {(W-VelW){acc_q[VelW]}};
  // a_(N-2) in acc: within the acceleration register's range
  assign a_in_range = acc_q[W-1:AccW-1] == {(W-AccW+1){acc_q[AccW-1]}};
  // S = 6 S / 6 is a multiple of 2^DivSh iff 6 S is of 2^(DivSh+1) and the quotient of 3
  assign rem_nz  = acc_q[DivSh:0] != '0 || r3_q != 2'd0;
  assign cand_up = $signed(mlr_q) + RW'(rem_nz);

  always_comb begin
    st_d    = st_q;
    ph_d    = ph_q;
    pc_d    = pc_q;
    cnt_d   = cnt_q;
    msel_d  = msel_q;
    nm1_d   = nm1_q;
    k_d     = k_q;
    lo_d    = lo_q;
    hi_d    = hi_q;
    j_d     = j_q;
    a_d     = a_q;
    v_d     = v_q;
    acc_d   = acc_q;
    mcd_d   = mcd_q;
    mlr_d   = mlr_q;
    r3_d    = r3_q;
    one_d   = one_q;
    kc_d    = kc_q;
    clsk_d  = clsk_q;
    clsn_d  = clsn_q;
    ref_d   = ref_q;
    srch2_d = srch2_q;
    fwd_d   = fwd_q;
    rev_d   = rev_q;
    search     = 1'b0;
    srch_init2 = 1'b0;
    go_sat     = 1'b0;

    unique case (st_q)
      StIdle: begin
        if (start_i) begin
          st_d  = clocks_i == '0 ? StDone : StDec;  // no clocks: nothing moves
          ph_d  = PhStart;
          nm1_d = clocks_i - NW'(1);
          one_d = clocks_i == NW'(1);
          j_d   = jerk_i;
          a_d   = acc0_i;
          v_d   = vel0_i;
          fwd_d = '0;  // S(0) = 0
          rev_d = '0;
        end
      end

      StLd: begin
        st_d  = StRun;
        cnt_d = u_len;
        if (u_clr) acc_d = '0;
        if (u_kind != KDivK) mcd_d = bus;
        if (u_kind == KDiv3) begin
          mlr_d = {RW{acc_q[W-1]}};  // floor(-1 / 3) = -1 rem 2
          r3_d  = {acc_q[W-1], 1'b0};
        end else if (u_usem) begin
          mlr_d = RW'(m_val);
        end else begin
          mlr_d = RW'(u_c);
        end
      end

      StRun: begin
        cnt_d = cnt_q - 6'd1;
        unique case (u_kind)
          KMul: begin
            if (mlr_q[0]) acc_d = sum;
            mcd_d = mcd_q <<< 1;
            mlr_d = mlr_q >> 1;
          end
          KDivK: begin
            if (sum[W-1] == a_q[AccW-1]) acc_d = sum;
            mcd_d = mcd_q >>> 1;
            mlr_d = {mlr_q[RW-2:0], sum[W-1] == a_q[AccW-1]};
          end
          default: begin  // KDiv3
            mcd_d = mcd_q <<< 1;
            mlr_d = {mlr_q[RW-2:0], t3 >= 3'd3};
            r3_d  = t3 >= 3'd3 ? 2'(t3 - 3'd3) : t3[1:0];
          end
        endcase
        if (cnt_q == '0) begin
          st_d = u_last ? StDec : StLd;
          pc_d = pc_q + 5'd1;
        end
      end

      StDec: begin
        st_d = StLd;
        unique case (ph_q)
          PhStart: begin
            if (one_q) begin
              // one clock: v_0 only, no acceleration to check
              k_d    = nm1_q;
              kc_d   = 1'b1;
              pc_d   = PcV;
              msel_d = MK;
              ph_d   = PhVk;
            end else begin
              pc_d   = PcA;
              msel_d = MNm1;
              ph_d   = PhA;
            end
          end
          PhA: begin
            if (!a_in_range) begin
              go_sat = 1'b1;
            end else if (acc_q[W-1] != a_q[AccW-1]) begin
              kc_d = 1'b0;
              pc_d = PcK;
              ph_d = PhK;
            end else begin
              k_d    = nm1_q;
              kc_d   = 1'b1;
              pc_d   = PcV;
              msel_d = MK;
              ph_d   = PhVk;
            end
          end
          PhK: begin
            k_d    = mlr_q[NW-1:0];
            pc_d   = PcV;
            msel_d = MK;
            ph_d   = PhVk;
          end
          PhVk, PhVn: begin
            if (!v_in_range) begin
              go_sat = 1'b1;
            end else if (ph_q == PhVk && !kc_q) begin
              clsk_d = acc_q[W-1];
              pc_d   = PcV;
              msel_d = MNm1;
              ph_d   = PhVn;
            end else begin
              // v_(N-1): evaluated, or the same clock as v_k
              if (ph_q == PhVk) clsk_d = acc_q[W-1];
              clsn_d = acc_q[W-1];
              pc_d   = PcSn;
              msel_d = MNm1;
              ph_d   = PhSn;
            end
          end
          PhSrch: begin
            if (acc_q[W-1] == ref_q) lo_d = mid;
            else                     hi_d = mid;
            st_d = StDec;
            ph_d = PhStep;
          end
          PhStep: begin
            // v changes class once in (lo, hi]: halve it, or evaluate S at hi
            if (mid == lo_q) begin
              pc_d   = PcS;
              msel_d = MHi;
              ph_d   = PhSt;
            end else begin
              pc_d   = PcV;
              msel_d = MMid;
              ph_d   = PhSrch;
            end
          end
          default: begin  // PhSn, PhSt: 6 S in acc, S / 2^DivSh in mlr
            if (cand_up > fwd_q)          fwd_d = cand_up;
            if ($signed(mlr_q) < rev_q)   rev_d = $signed(mlr_q);
            if (ph_q == PhSn && clsk_q != cls0) begin
              lo_d    = '0;
              hi_d    = k_q;
              ref_d   = cls0;
              srch2_d = 1'b0;
              search  = 1'b1;
            end else if (!(ph_q == PhSt && srch2_q) && clsn_q != clsk_q) begin
              srch_init2 = 1'b1;
            end else begin
              st_d = StDone;
            end
          end
        endcase
        if (srch_init2) begin
          lo_d    = k_q;
          hi_d    = nm1_q;
          ref_d   = clsk_q;
          srch2_d = 1'b1;
          search  = 1'b1;
        end
        if (search) begin
          st_d = StDec;
          ph_d = PhStep;
        end
        if (go_sat) begin
          // the velocity or acceleration leaves its range: unbounded reach
          fwd_d = {1'b0, {(RW-1){1'b1}}};
          rev_d = {1'b1, {(RW-1){1'b0}}};
          st_d  = StDone;
        end
      end

      default: st_d = StIdle;  // StDone
    endcase

    if (abort_i) st_d = StIdle;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      st_q    <= StIdle;
      ph_q    <= PhStart;
      pc_q    <= '0;
      cnt_q   <= '0;
      msel_q  <= MNm1;
      nm1_q   <= '0;
      k_q     <= '0;
      lo_q    <= '0;
      hi_q    <= '0;
      j_q     <= '0;
      a_q     <= '0;
      v_q     <= '0;
      acc_q   <= '0;
      mcd_q   <= '0;
      mlr_q   <= '0;
      r3_q    <= '0;
      one_q   <= 1'b0;
      kc_q    <= 1'b0;
      clsk_q  <= 1'b0;
      clsn_q  <= 1'b0;
      ref_q   <= 1'b0;
      srch2_q <= 1'b0;
      fwd_q   <= '0;
      rev_q   <= '0;
    end else begin
      st_q    <= st_d;
      ph_q    <= ph_d;
      pc_q    <= pc_d;
      cnt_q   <= cnt_d;
      msel_q  <= msel_d;
      nm1_q   <= nm1_d;
      k_q     <= k_d;
      lo_q    <= lo_d;
      hi_q    <= hi_d;
      j_q     <= j_d;
      a_q     <= a_d;
      v_q     <= v_d;
      acc_q   <= acc_d;
      mcd_q   <= mcd_d;
      mlr_q   <= mlr_d;
      r3_q    <= r3_d;
      one_q   <= one_d;
      kc_q    <= kc_d;
      clsk_q  <= clsk_d;
      clsn_q  <= clsn_d;
      ref_q   <= ref_d;
      srch2_q <= srch2_d;
      fwd_q   <= fwd_d;
      rev_q   <= rev_d;
    end
  end

  assign busy_o      = st_q != StIdle;
  assign done_o      = st_q == StDone;
  assign reach_fwd_o = fwd_q;
  assign reach_rev_o = rev_q;

endmodule
