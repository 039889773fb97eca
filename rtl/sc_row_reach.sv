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
// k the first clock where the acceleration a + n j has the jerk's sign (a
// division), so each piece has at most one sign change, found by a binary
// search on v. A row whose velocity or acceleration leaves its register's
// range inside the row (the executor would wrap) cannot be bounded: its
// reach is the largest the outputs hold, so any window refuses it.
//
// One 120-bit adder does all of it, one operation after another, each a
// shift-add multiplication by a 32-bit count (32 clocks), a restoring
// division (one quotient bit per clock) or a single add/subtract, with one
// decision clock between operations:
//   6 S(n) = n (6v + (n-1) (3a + (n-2) j)),   2 v_m = 2v + m (2a + (m-1) j).
// A row without a sign change takes about 450 clocks, one with two about
// 4,800 at most. abort_i drops the evaluation; start_i is taken while idle.
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

  localparam int W      = sc_pkg::ReachAccW;
  localparam int NW     = sc_pkg::SegClkW;
  localparam int RW     = sc_pkg::ReachW;
  localparam int OpW    = sc_pkg::ReachOpW;
  localparam int VelW   = sc_pkg::VelW;
  localparam int AccW   = sc_pkg::AccW;
  localparam int JerkW  = sc_pkg::JerkW;
  // |6 S| is divided by 6 * 2^(FracBits - ReachFrac): QuoW quotient bits
  localparam int QuoW   = RW;
  localparam int DivSh  = sc_pkg::FracBits - sc_pkg::ReachFrac;
  localparam logic signed [W-1:0] SixUnit = W'(6) <<< (DivSh + QuoW - 1);

  // state
  localparam logic [1:0] StIdle = 2'd0, StOp = 2'd1, StDec = 2'd2, StDone = 2'd3;
  // the operation that just ended (in StDec)
  localparam logic [3:0] PhStart = 4'd0, PhAccEnd = 4'd1, PhNegK = 4'd2, PhDivK = 4'd3,
                         PhV1 = 4'd4, PhV2 = 4'd5, PhS0 = 4'd6, PhS1 = 4'd7, PhS2 = 4'd8,
                         PhS2b = 4'd9, PhS3 = 4'd10, PhNegS = 4'd11, PhDivS = 4'd12;
  // what a v or S evaluation is for
  localparam logic [2:0] GoVk = 3'd0, GoVn = 3'd1, GoSearch = 3'd2, GoSn = 3'd3, GoSt1 = 3'd4,
                         GoSt2 = 3'd5;
  // operations of the adder
  localparam logic [1:0] OpMul = 2'd0, OpDiv = 2'd1, OpSub = 2'd2;

  logic [1:0]             st_q, st_d;
  logic [3:0]             ph_q, ph_d;
  logic [2:0]             goal_q, goal_d;
  logic [1:0]             op_q, op_d;
  logic [OpW-1:0]         cnt_q, cnt_d, len_q, len_d;
  logic [NW-1:0]          n_q, n_d, k_q, k_d, m_q, m_d, lo_q, lo_d, hi_q, hi_d;
  logic signed [JerkW-1:0] j_q, j_d;
  logic signed [AccW-1:0] a_q, a_d;
  logic signed [VelW-1:0] v_q, v_d;
  logic signed [W-1:0]    acc_q, acc_d, mcd_q, mcd_d;
  logic [63:0]            mlr_q, mlr_d;
  logic                   bad_q, bad_d, neg_q, neg_d, srch2_q, srch2_d;
  logic                   clsk_q, clsk_d, clsn_q, clsn_d, cls_ref_q, cls_ref_d;
  logic signed [RW-1:0]   fwd_q, fwd_d, rev_q, rev_d;

  logic signed [W-1:0]  opnd, sum;
  logic signed [W-1:0]  a_x, j_x, v_x;
  logic                 cls0, v_in_range, a_in_range;
  logic [QuoW-1:0]      quo;
  logic                 rem_nz;
  logic signed [RW-1:0] cand_up, cand_dn;
  logic                 after_acc_end, after_k, after_vk, after_vn, after_sn, after_st1, after_search;
  logic                 go_v, go_s, go_sat;
  logic [NW-1:0]        go_m;
  logic [2:0]           go_goal;
  // the next operation (launch)
  logic                 op_go;
  logic [1:0]           op_kind;
  logic [OpW-1:0]       op_len;
  logic signed [W-1:0]  op_acc, op_mcd;
  logic [63:0]          op_mlr;
  logic [3:0]           op_ph;
  logic [NW-1:0]        n_m1, n_m2, m_m1, m_m2;

  // counts one and two below n and m (wrapping: a product by them is then
  // multiplied by zero, see the formulas above)
  assign n_m1    = n_q - NW'(1);
  assign n_m2    = n_q - NW'(2);
  assign m_m1    = m_q - NW'(1);
  assign m_m2    = m_q - NW'(2);

  assign a_x = W'(a_q);
  assign j_x = W'(j_q);
  assign v_x = W'(v_q);

  // The one adder: acc + mcd (MUL), acc - mcd (DIV, SUB).
  assign opnd = op_q == OpMul ? mcd_q : ~mcd_q;
  assign sum  = acc_q + opnd + W'(op_q != OpMul);

  assign cls0 = v_q[VelW-1];  // class of v_0: 1 = negative
  // 2 v_m in acc: v_m within the velocity register's range
  assign v_in_range = acc_q[W-1:VelW] == {(W-VelW){acc_q[VelW]}};
  // a_(N-2) in acc: within the acceleration register's range
  assign a_in_range = acc_q[W-1:AccW-1] == {(W-AccW+1){acc_q[AccW-1]}};
  // |6 S| / (6 * 2^DivSh): quotient and remainder, rounded outward with the sign
  assign quo     = mlr_q[QuoW-1:0];
  assign rem_nz  = acc_q != '0;
  assign cand_up = neg_q ? -$signed(quo) : $signed(quo) + RW'(rem_nz);
  assign cand_dn = neg_q ? -$signed(quo) - RW'(rem_nz) : $signed(quo);

  always_comb begin
    st_d      = st_q;
    ph_d      = ph_q;
    goal_d    = goal_q;
    op_d      = op_q;
    cnt_d     = cnt_q;
    len_d     = len_q;
    n_d       = n_q;
    k_d       = k_q;
    m_d       = m_q;
    lo_d      = lo_q;
    hi_d      = hi_q;
    j_d       = j_q;
    a_d       = a_q;
    v_d       = v_q;
    acc_d     = acc_q;
    mcd_d     = mcd_q;
    mlr_d     = mlr_q;
    bad_d     = bad_q;
    neg_d     = neg_q;
    srch2_d   = srch2_q;
    clsk_d    = clsk_q;
    clsn_d    = clsn_q;
    cls_ref_d = cls_ref_q;
    fwd_d     = fwd_q;
    rev_d     = rev_q;
    after_acc_end = 1'b0;
    after_k       = 1'b0;
    after_vk      = 1'b0;
    after_vn      = 1'b0;
    after_sn      = 1'b0;
    after_st1     = 1'b0;
    after_search  = 1'b0;
    go_v    = 1'b0;
    go_s    = 1'b0;
    go_sat  = 1'b0;
    go_m    = '0;
    go_goal = GoVk;
    op_go   = 1'b0;
    op_kind = OpMul;
    op_len  = OpW'(32);
    op_acc  = '0;
    op_mcd  = '0;
    op_mlr  = '0;
    op_ph   = PhStart;

    unique case (st_q)
      StIdle: begin
        if (start_i) begin
          st_d  = StDec;
          ph_d  = PhStart;
          n_d   = clocks_i;
          j_d   = jerk_i;
          a_d   = acc0_i;
          v_d   = vel0_i;
          bad_d = 1'b0;
          fwd_d = '0;  // S(0) = 0
          rev_d = '0;
        end
      end

      StOp: begin
        cnt_d = cnt_q + OpW'(1);
        unique case (op_q)
          OpMul: begin
            if (mlr_q[0]) acc_d = sum;
            mcd_d = mcd_q <<< 1;
            mlr_d = mlr_q >> 1;
          end
          OpDiv: begin
            if (!sum[W-1]) acc_d = sum;
            mcd_d = mcd_q >>> 1;
            mlr_d = {mlr_q[62:0], !sum[W-1]};
          end
          default: acc_d = sum;  // OpSub
        endcase
        if (cnt_q == len_q - OpW'(1)) st_d = StDec;
      end

      StDec: begin
        // The operation that ended; where the sequence continues.
        unique case (ph_q)
          PhStart: begin
            if (n_q == '0) begin
              st_d = StDone;
            end else if (n_q >= NW'(2) && j_q != '0) begin
              // a_(N-2) = a + (N-2) j: the last acceleration the row integrates
              op_go  = 1'b1;
              op_acc = a_x;
              op_mcd = j_x;
              op_mlr = {32'b0, n_m2};
              op_ph  = PhAccEnd;
            end else begin
              after_acc_end = 1'b1;
            end
          end
          PhAccEnd: begin
            if (!a_in_range) bad_d = 1'b1;
            after_acc_end = 1'b1;
          end
          PhNegK: begin
            // |a| or |j| << 63 in acc: the other operand into place
            op_go   = 1'b1;
            op_kind = OpDiv;
            op_len  = OpW'(64);
            op_acc  = a_q[AccW-1] ? acc_q : a_x;
            op_mcd  = a_q[AccW-1] ? j_x <<< 63 : acc_q;
            op_ph   = PhDivK;
          end
          PhDivK: begin
            // k = min(ceil(|a| / |j|), N - 1)
            if (mlr_q >= {32'b0, n_m1}) k_d = n_m1;
            else                            k_d = NW'(mlr_q) + NW'(rem_nz);
            after_k = 1'b1;
          end
          PhV1: begin
            op_go  = 1'b1;
            op_acc = v_x <<< 1;
            op_mcd = acc_q;
            op_mlr = {32'b0, m_q};
            op_ph  = PhV2;
          end
          PhV2: begin
            if (!v_in_range) bad_d = 1'b1;
            unique case (goal_q)
              GoVk: begin
                clsk_d   = acc_q[W-1];
                after_vk = 1'b1;
              end
              GoVn: begin
                clsn_d   = acc_q[W-1];
                after_vn = 1'b1;
              end
              default: begin  // GoSearch
                if (acc_q[W-1] == cls_ref_q) lo_d = m_q;
                else                         hi_d = m_q;
                after_search = 1'b1;
              end
            endcase
          end
          PhS0: begin
            op_go  = 1'b1;
            op_acc = acc_q;
            op_mcd = j_x;
            op_mlr = {32'b0, m_m2};
            op_ph  = PhS1;
          end
          PhS1: begin
            op_go  = 1'b1;
            op_acc = v_x <<< 1;
            op_mcd = acc_q;
            op_mlr = {32'b0, m_m1};
            op_ph  = PhS2;
          end
          PhS2: begin
            op_go  = 1'b1;
            op_len = OpW'(1);
            op_acc = acc_q;
            op_mcd = v_x <<< 2;
            op_mlr = 64'd1;
            op_ph  = PhS2b;
          end
          PhS2b: begin
            op_go  = 1'b1;
            op_acc = '0;
            op_mcd = acc_q;
            op_mlr = {32'b0, m_q};
            op_ph  = PhS3;
          end
          PhS3, PhNegS: begin
            // 6 S(m) in acc: its magnitude (one subtraction), then the division
            op_go = 1'b1;
            if (ph_q == PhS3 && acc_q[W-1]) begin
              neg_d   = 1'b1;
              op_kind = OpSub;
              op_len  = OpW'(1);
              op_acc  = '0;
              op_mcd  = acc_q;
              op_ph   = PhNegS;
            end else begin
              if (ph_q == PhS3) neg_d = 1'b0;
              op_kind = OpDiv;
              op_len  = OpW'(QuoW);
              op_acc  = acc_q;
              op_mcd  = SixUnit;
              op_ph   = PhDivS;
            end
          end
          default: begin  // PhDivS
            if (cand_up > fwd_q) fwd_d = cand_up;
            if (cand_dn < rev_q) rev_d = cand_dn;
            unique case (goal_q)
              GoSn:    after_sn  = 1'b1;
              GoSt1:   after_st1 = 1'b1;
              default: st_d      = StDone;  // GoSt2
            endcase
          end
        endcase

        // The sequence, in order; each step may fall through to the next.
        if (after_acc_end) begin
          if (bad_d) begin
            go_sat = 1'b1;
          end else if (j_q != '0 && a_q != '0 && a_q[AccW-1] != j_q[JerkW-1]) begin
            // the vertex: the first clock whose acceleration has the jerk's sign
            op_go   = 1'b1;
            op_kind = OpSub;
            op_len  = OpW'(1);
            op_acc  = '0;
            op_mcd  = a_q[AccW-1] ? a_x : j_x <<< 63;
            op_ph   = PhNegK;
          end else begin
            k_d     = '0;
            after_k = 1'b1;
          end
        end
        if (after_k) begin
          if (k_d != '0) begin
            go_v    = 1'b1;
            go_m    = k_d;
            go_goal = GoVk;
          end else begin
            clsk_d   = cls0;
            after_vk = 1'b1;
          end
        end
        if (after_vk) begin
          if (n_m1 > k_d) begin
            go_v    = 1'b1;
            go_m    = n_m1;
            go_goal = GoVn;
          end else begin
            clsn_d   = clsk_d;
            after_vn = 1'b1;
          end
        end
        if (after_vn) begin
          if (bad_d) begin
            go_sat = 1'b1;
          end else begin
            go_s    = 1'b1;
            go_m    = n_q;
            go_goal = GoSn;
          end
        end
        if (after_sn) begin
          if (clsk_d != cls0) begin
            lo_d         = '0;
            hi_d         = k_d;
            cls_ref_d    = cls0;
            srch2_d      = 1'b0;
            after_search = 1'b1;
          end else begin
            after_st1 = 1'b1;
          end
        end
        if (after_st1) begin
          if (clsn_d != clsk_d) begin
            lo_d         = k_d;
            hi_d         = n_m1;
            cls_ref_d    = clsk_d;
            srch2_d      = 1'b1;
            after_search = 1'b1;
          end else begin
            st_d = StDone;
          end
        end
        if (after_search) begin
          // v changes class once in (lo, hi]: halve it, or evaluate S there
          if (hi_d - lo_d > NW'(1)) begin
            go_v    = 1'b1;
            go_m    = lo_d + ((hi_d - lo_d) >> 1);
            go_goal = GoSearch;
          end else begin
            go_s    = 1'b1;
            go_m    = hi_d;
            go_goal = srch2_d ? GoSt2 : GoSt1;
          end
        end

        // 2 v_m: 2a + (m-1) j first; 6 S(m): 3a = a + 2a first
        if (go_v || go_s) begin
          m_d     = go_m;
          goal_d  = go_goal;
          op_go   = 1'b1;
          op_kind = OpMul;
          op_mlr = go_v ? {32'b0, go_m - NW'(1)} : 64'd1;
          op_len = go_v ? OpW'(32) : OpW'(1);
          op_acc = go_v ? a_x <<< 1 : a_x;
          op_mcd = go_v ? j_x : a_x <<< 1;
          op_ph  = go_v ? PhV1 : PhS0;
        end
        if (go_sat) begin
          // the velocity or acceleration leaves its range: unbounded reach
          fwd_d = {1'b0, {(RW-1){1'b1}}};
          rev_d = {1'b1, {(RW-1){1'b0}}};
          st_d  = StDone;
        end
        if (op_go) begin
          st_d  = StOp;
          op_d  = op_kind;
          len_d = op_len;
          cnt_d = '0;
          acc_d = op_acc;
          mcd_d = op_mcd;
          mlr_d = op_mlr;
          ph_d  = op_ph;
        end
      end

      default: st_d = StIdle;  // StDone
    endcase

    if (abort_i) st_d = StIdle;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      st_q      <= StIdle;
      ph_q      <= PhStart;
      goal_q    <= GoVk;
      op_q      <= OpMul;
      cnt_q     <= '0;
      len_q     <= '0;
      n_q       <= '0;
      k_q       <= '0;
      m_q       <= '0;
      lo_q      <= '0;
      hi_q      <= '0;
      j_q       <= '0;
      a_q       <= '0;
      v_q       <= '0;
      acc_q     <= '0;
      mcd_q     <= '0;
      mlr_q     <= '0;
      bad_q     <= 1'b0;
      neg_q     <= 1'b0;
      srch2_q   <= 1'b0;
      clsk_q    <= 1'b0;
      clsn_q    <= 1'b0;
      cls_ref_q <= 1'b0;
      fwd_q     <= '0;
      rev_q     <= '0;
    end else begin
      st_q      <= st_d;
      ph_q      <= ph_d;
      goal_q    <= goal_d;
      op_q      <= op_d;
      cnt_q     <= cnt_d;
      len_q     <= len_d;
      n_q       <= n_d;
      k_q       <= k_d;
      m_q       <= m_d;
      lo_q      <= lo_d;
      hi_q      <= hi_d;
      j_q       <= j_d;
      a_q       <= a_d;
      v_q       <= v_d;
      acc_q     <= acc_d;
      mcd_q     <= mcd_d;
      mlr_q     <= mlr_d;
      bad_q     <= bad_d;
      neg_q     <= neg_d;
      srch2_q   <= srch2_d;
      clsk_q    <= clsk_d;
      clsn_q    <= clsn_d;
      cls_ref_q <= cls_ref_d;
      fwd_q     <= fwd_d;
      rev_q     <= rev_d;
    end
  end

  assign busy_o      = st_q != StIdle;
  assign done_o      = st_q == StDone;
  assign reach_fwd_o = fwd_q;
  assign reach_rev_o = rev_q;

endmodule
