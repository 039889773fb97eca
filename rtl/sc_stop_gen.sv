// sc_stop_gen: jerk-limited controlled stop from any (v, a) to rest.
//
// The executor integrates pos += v; v += a; a += jerk_o every clock while
// active_o is high. The generator keeps its own copy of the state, mirrored
// so that the motion is forward (v >= 0): level b = -a (braking acceleration
// > 0). Each clock it picks the largest next level b' (the most braking) among
//   up   b + J (clamped at D)     if the stop stays possible from (v', b')
//   land b' = v' (<= J)           ends the stop exactly at the next clock
//   hold b                        if the stop stays possible
//   down b - J (to 0 at the end)  always possible while the start was
// where v' = v - b and "possible" is v' >= u(b'): u is an upper bound of
// the velocity the ramp-down path from b' consumes (exact sum of its levels,
// tracked with adders as b' moves by J). A braking start level b0 > J needs
// R(b0) = sum of b0, b0 - J, ..., b0 mod J: a restoring division of b0 by J,
// one quotient bit per clock (set up by one shifter over the first clocks),
// tightens u from a safe bound to the exact sum while the stop already runs. Algorithm, proofs, latency: docs/stop.md.
//
// Timing: in the clock with start_i = 1, vel_i/acc_i are the values the
// executor's v and a registers take at that clock edge; from the next clock
// on (active_o = 1) the executor applies jerk_o. done_o rises with the clock
// edge after which v = a = 0; active_o falls at the same edge.
module sc_stop_gen (
  input  logic                               clk_i,
  input  logic                               rst_ni,

  input  logic                               start_i,
  input  logic signed [sc_pkg::VelW-1:0]     vel_i,
  input  logic signed [sc_pkg::AccW-1:0]     acc_i,
  input  logic        [sc_pkg::JerkW-1:0]    stop_jerk_i,  // J > 0 (0 -> 1, >= 2^(JerkW-1) clamped)
  input  logic        [sc_pkg::AccW-1:0]     stop_acc_i,   // D > 0 (0 -> 1, >= 2^(AccW-1) clamped)

  output logic                               active_o,
  output logic                               done_o,
  output logic                               overshoot_o,  // sticky: start state not stoppable within J
  output logic signed [sc_pkg::JerkW-1:0]    jerk_o
);

  localparam int VelW  = sc_pkg::VelW;
  localparam int AccW  = sc_pkg::AccW;
  localparam int JerkW = sc_pkg::JerkW;
  localparam int VW    = VelW + 1;  // mirrored velocity
  localparam int BW    = AccW + 1;  // mirrored level
  localparam int UW    = 88;        // bound u
  // Division registers: b0 << k0, J << 2k0 < 2^(2 msb(b0) - msb(J) + 1) <= 2^84 (else uinf);
  // J << k0 < 2^(msb(b0) + 1) <= 2^64; all only shift down from there.
  localparam int DW    = 84;        // remk, j2k
  localparam int JKW   = 64;        // jk
  localparam int CW    = 90;        // compare width
  localparam int KW    = 7;         // division bit index
  localparam int RW    = 64;        // division remainder: a dividing b0 is at most 2^63
  localparam int JW    = JerkW - 1; // latched J (positive)
  localparam int AW    = AccW - 1;  // latched D (positive)
  localparam int InfExp = 84;

  logic                  active_q, active_d;
  logic                  done_q, done_d;
  logic                  neg_q, neg_d;
  logic                  over_q, over_d;
  logic                  div_q, div_d;
  logic                  uinf_q, uinf_d;
  logic                  clamp_q, clamp_d;
  logic signed [VW-1:0]  v_q, v_d;
  logic signed [BW-1:0]  b_q, b_d;
  logic signed [UW-1:0]  u_q, u_d;
  logic signed [BW-1:0]  g_q, g_d;
  logic                  gz_q, gz_d;  // g == 0
  logic [JW-1:0]         j_q, j_d;
  logic [AW-1:0]         dlim_q, dlim_d;
  logic [KW-1:0]         k_q, k_d;
  logic [1:0]            prep_q, prep_d;  // division set-up: 1 = J << k next, 2 = J << 2k next
  logic [RW-1:0]         rem_q, rem_d;
  logic [JKW-1:0]        jk_q, jk_d;
  logic [DW-1:0]         j2k_q, j2k_d;
  logic [DW-1:0]         remk_q, remk_d;

  // ---- load: mirror the start state, latch the limits, set up the division
  logic [JW-1:0]        j_ld;
  logic [AW-1:0]        d_ld;
  logic                 neg_ld;
  logic signed [VW-1:0] vel_x;
  logic signed [BW-1:0] acc_x;
  logic signed [VW-1:0] v_ld;
  logic signed [BW-1:0] b_ld;
  logic [5:0]           eb, ej;
  logic [KW-1:0]        k_ld;
  logic [KW:0]          inf_exp;
  logic                 b_ld_le_j;

  // Start-clock logic. The defaults are don't-cares ('x): synthesis drops
  // the gating (no AND per bit), and the simulator skips the wide terms in
  // every other clock; nothing reads them outside the start clock.
  always_comb begin
    vel_x     = 'x;
    acc_x     = 'x;
    neg_ld    = 1'bx;
    v_ld      = 'x;
    b_ld      = 'x;
    j_ld      = 'x;
    d_ld      = 'x;
    b_ld_le_j = 1'bx;
    if (start_i) begin
      vel_x  = VW'(vel_i);
      acc_x  = BW'(acc_i);
      neg_ld = vel_i[VelW-1] || (vel_i == '0 && acc_i[AccW-1]);
      // conditional negation as XOR and carry in: one adder, no mux
      v_ld   = (vel_x ^ {VW{neg_ld}}) + VW'(neg_ld);
      b_ld   = (acc_x ^ {BW{!neg_ld}}) + BW'(!neg_ld);
      j_ld   = stop_jerk_i == '0 ? JW'(1) : stop_jerk_i[JerkW-1] ? '1 : stop_jerk_i[JW-1:0];
      d_ld   = stop_acc_i == '0 ? AW'(1) : stop_acc_i[AccW-1] ? '1 : stop_acc_i[AW-1:0];
      b_ld_le_j = b_ld <= $signed(BW'({1'b0, j_ld}));
    end
  end

  // Highest set bits of b (a braking start: 0 < J < b <= 2^63) and J.
  always_comb begin
    eb = 'x;
    ej = 'x;
    if (start_i) begin
      eb = '0;
      ej = '0;
      for (int i = 0; i < 64; i++) begin
        if (b_ld[i]) eb = 6'(i);
      end
      for (int i = 0; i < JW; i++) begin
        if (j_ld[i]) ej = 6'(i);
      end
    end
  end
  assign k_ld    = KW'(eb) - KW'(ej);

  // One shifter sets the division up over three clocks: b0 << k0 in the start
  // clock (the first bound), then J << k0, then (J << k0) << k0 = J << 2k0
  // (jk holds J from the start clock, so the shifter has two sources).
  // Inputs below 2^64: b0 <= 2^63, J << k0 < 2^(msb(b0)+1); k0 <= 63.
  logic [JKW-1:0]  sh_in;
  logic [5:0]      sh_amt;
  logic [DW-1:0]   sh_out;
  logic [JKW+2:0]  sh_1;
  logic [JKW+14:0] sh_2;
  always_comb begin
    sh_in  = start_i ? JKW'(b_ld) : jk_q;
    sh_amt = start_i ? k_ld[5:0] : k_q[5:0];
    // three stages of 4:1, each only as wide as it can fill
    sh_1   = (JKW+3)'(sh_in) << sh_amt[1:0];
    sh_2   = (JKW+15)'(sh_1) << {sh_amt[3:2], 2'b00};
    sh_out = DW'(sh_2) << {sh_amt[5:4], 4'b0000};
  end
  assign inf_exp = {1'b0, eb, 1'b0} - (KW+1)'(ej);

  // ---- one clock of the stop (mirrored): pick the next level ---------------
  // Levels (b, J, D) in LW bits, velocities and bounds in CW bits.
  localparam int LW = BW + 2;
  logic signed [CW-1:0] v1, u, uu;
  logic signed [LW-1:0] b, j, dl, bsum, bu, bdn, b1;
  logic signed [LW-1:0] v1_lo;     // v1 when 0 <= v1 < 2^JW (landing range)
  logic signed [UW-1:0] u1;
  logic                 clamp_up, up_ok, land_ok, hold_ok, v1_small;
  logic                 b1_zero, bdn_zero;
  logic                 take;
  logic [DW:0]          dec;

  // Evaluated while the stop runs; otherwise don't-cares ('x, as above): no
  // gating in synthesis, and the clocks of normal motion cost the simulator
  // nothing here.
  always_comb begin
    v1       = 'x;
    v1_small = 'x;
    v1_lo    = 'x;
    u        = 'x;
    b        = 'x;
    j        = 'x;
    dl       = 'x;
    bsum     = 'x;
    clamp_up = 'x;
    bu       = 'x;
    uu       = 'x;
    up_ok    = 'x;
    land_ok  = 'x;
    hold_ok  = 'x;
    bdn      = 'x;
    bdn_zero = 'x;
    b1       = 'x;
    u1       = 'x;
    b1_zero  = 'x;
    if (active_q) begin
      v1       = CW'(v_q) - CW'(b_q);
      v1_small = v1[CW-1:JW] == '0;
      v1_lo    = LW'({1'b0, v1[JW-1:0]});
      u        = CW'(u_q);
      b        = LW'(b_q);
      j        = LW'({1'b0, j_q});
      dl       = LW'({1'b0, dlim_q});
      // the level of a move up: b + J, clamped at D
      bsum     = b + j;
      clamp_up = bsum > dl;
      bu       = clamp_up ? dl : bsum;
      if (b_q[BW-1] || b_q == '0) begin  // b <= 0: max(bu, 0)
        uu = bu[LW-1] ? '0 : CW'(bu);
      end else begin
        uu = u + CW'(bu);
      end
      up_ok   = b < dl && !uinf_q && v1 >= uu;
      land_ok = v1_small && v1_lo <= j && v1_lo <= dl && v1_lo <= bsum && v1_lo >= b - j;
      hold_ok = b <= dl && !uinf_q && v1 >= u;
      // b1 == 0 per move, beside the level mux (b - J > 0 here; D >= 1)
      if (b > j) begin
        bdn      = clamp_q ? LW'(g_q) : b - j;
        bdn_zero = clamp_q && gz_q;
      end else begin
        bdn      = b_q[BW-1] ? b : '0;
        bdn_zero = !b_q[BW-1];
      end
      if (up_ok) begin
        b1      = bu;
        u1      = UW'(uu);
        b1_zero = !clamp_up && bsum == '0;
      end else if (land_ok) begin
        b1      = v1_lo;
        u1      = UW'(v1_lo);
        b1_zero = v1[JW-1:0] == '0;
      end else if (hold_ok) begin
        b1      = b;
        u1      = u_q;
        b1_zero = b_q == '0;
      end else begin
        b1      = bdn;
        b1_zero = bdn_zero;
        if (bdn <= j) begin
          u1 = bdn[LW-1] ? '0 : UW'(bdn);
        end else begin
          u1 = UW'(u - CW'(b));
        end
      end
    end
  end

  // ---- next state ------------------------------------------------------------
  always_comb begin
    active_d = active_q;
    done_d   = done_q;
    neg_d    = neg_q;
    over_d   = over_q;
    div_d    = div_q;
    uinf_d   = uinf_q;
    clamp_d  = clamp_q;
    v_d      = v_q;
    b_d      = b_q;
    u_d      = u_q;
    g_d      = g_q;
    gz_d     = gz_q;
    j_d      = j_q;
    dlim_d   = dlim_q;
    k_d      = k_q;
    prep_d   = prep_q;
    rem_d    = rem_q;
    jk_d     = jk_q;
    j2k_d    = j2k_q;
    remk_d   = remk_q;
    take     = 1'b0;
    dec      = '0;

    if (start_i) begin
      active_d = 1'b0;
      done_d   = 1'b0;
      neg_d    = neg_ld;
      over_d   = 1'b0;
      div_d    = 1'b0;
      uinf_d   = 1'b0;
      clamp_d  = 1'b0;
      v_d      = v_ld;
      b_d      = b_ld;
      j_d      = j_ld;
      dlim_d   = d_ld;
      // The division state (k, prep, rem, remk; jk, j2k follow in the set-up)
      // is read only while div_q, g only while clamp_q, u only while active
      // and not uinf: load them without the cases that leave them unused.
      k_d      = k_ld;
      jk_d     = JKW'(j_ld);
      prep_d   = 2'd1;
      rem_d    = RW'(b_ld);
      remk_d   = sh_out;
      u_d      = b_ld_le_j ? (b_ld[BW-1] ? '0 : UW'(b_ld)) : UW'({sh_out, 1'b0});
      if (v_ld == '0 && b_ld == '0) begin
        done_d = 1'b1;
      end else begin
        active_d = 1'b1;
        if (!b_ld_le_j) begin
          uinf_d = inf_exp >= (KW+1)'(InfExp);
          div_d  = inf_exp < (KW+1)'(InfExp);
        end
      end
    end else if (active_q) begin
      v_d     = VW'(v1);
      b_d     = BW'(b1);
      u_d     = u1;
      clamp_d = up_ok ? clamp_up : (!land_ok && hold_ok && clamp_q);
      if (up_ok) begin
        g_d  = b_q;
        gz_d = b_q == '0;
      end
      if (b1 <= j) begin
        // at or below one jerk step the bound is exact (R(b) = b)
        div_d  = 1'b0;
        uinf_d = 1'b0;
      end else if (div_q && prep_q == 2'd1) begin
        jk_d   = JKW'(sh_out);
        prep_d = 2'd2;
      end else if (div_q && prep_q == 2'd2) begin
        j2k_d  = sh_out;
        prep_d = 2'd0;
      end else if (div_q) begin
        take = rem_q >= RW'(jk_q);
        // 3 j2k - jk < 2^(DW+2): j2k = J << 2k >= jk = J << k
        dec  = take ? (DW+1)'(((DW+2)'(j2k_q) + (DW+2)'({j2k_q, 1'b0}) - (DW+2)'(jk_q)) >> 1)
                    : (DW+1)'(remk_q);
        u_d  = u1 - UW'(dec);
        if (take) begin
          rem_d  = rem_q - RW'(jk_q);
        end
        // after the last bit (k = 0) the division state is no longer read
        div_d  = k_q != '0;
        k_d    = k_q - KW'(1);
        jk_d   = jk_q >> 1;
        j2k_d  = j2k_q >> 2;
        remk_d = (take ? remk_q - j2k_q : remk_q) >> 1;
      end
      if (v1[CW-1]) begin
        over_d = 1'b1;
        if (b1_zero) begin
          neg_d = !neg_q;
          v_d   = VW'(-v1);
        end
      end
      if (v1 == '0 && b1_zero) begin
        active_d = 1'b0;
        done_d   = 1'b1;
        div_d    = 1'b0;
        clamp_d  = 1'b0;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      active_q <= 1'b0;
      done_q   <= 1'b0;
      neg_q    <= 1'b0;
      over_q   <= 1'b0;
      div_q    <= 1'b0;
      uinf_q   <= 1'b0;
      clamp_q  <= 1'b0;
      v_q      <= '0;
      b_q      <= '0;
      u_q      <= '0;
      g_q      <= '0;
      gz_q     <= 1'b1;
      j_q      <= JW'(1);
      dlim_q   <= AW'(1);
      k_q      <= '0;
      prep_q   <= '0;
      rem_q    <= '0;
      jk_q     <= '0;
      j2k_q    <= '0;
      remk_q   <= '0;
    end else begin
      active_q <= active_d;
      done_q   <= done_d;
      neg_q    <= neg_d;
      over_q   <= over_d;
      div_q    <= div_d;
      uinf_q   <= uinf_d;
      clamp_q  <= clamp_d;
      v_q      <= v_d;
      b_q      <= b_d;
      u_q      <= u_d;
      g_q      <= g_d;
      gz_q     <= gz_d;
      j_q      <= j_d;
      dlim_q   <= dlim_d;
      k_q      <= k_d;
      prep_q   <= prep_d;
      rem_q    <= rem_d;
      jk_q     <= jk_d;
      j2k_q    <= j2k_d;
      remk_q   <= remk_d;
    end
  end

  // jerk applied this clock: a' - a with a = neg ? b : -b
  // (only the low JerkW bits of the difference matter: |b1 - b| <= J)
  logic [JerkW-1:0] lev_new, lev_old;
  assign lev_new     = neg_q ? JerkW'(b1) : JerkW'(b_q);
  assign lev_old     = neg_q ? JerkW'(b_q) : JerkW'(b1);
  assign jerk_o      = !active_q ? '0 : $signed(lev_new - lev_old);
  assign active_o    = active_q;
  assign done_o      = done_q;
  assign overshoot_o = over_q;

`ifdef SC_COVER
  // Cover points (the coverage build, scripts/coverage.py): each choice of the
  // next level, a start in each direction, the start-level division, the
  // clamp at D and an overshoot.
  c_start_fwd:  cover property (@(posedge clk_i) rst_ni && start_i && !vel_i[VelW-1]);
  c_start_rev:  cover property (@(posedge clk_i) rst_ni && start_i && vel_i[VelW-1]);
  c_up:         cover property (@(posedge clk_i) rst_ni && active_q && up_ok);
  c_land:       cover property (@(posedge clk_i) rst_ni && active_q && !up_ok && land_ok);
  c_hold:       cover property (@(posedge clk_i) rst_ni && active_q && !up_ok && !land_ok && hold_ok);
  c_down:       cover property (@(posedge clk_i) rst_ni && active_q && !up_ok && !land_ok && !hold_ok);
  c_division:   cover property (@(posedge clk_i) rst_ni && active_q && div_q);
  c_clamp:      cover property (@(posedge clk_i) rst_ni && active_q && clamp_q);
  c_done:       cover property (@(posedge clk_i) rst_ni && done_d && !done_q);
  c_overshoot:  cover property (@(posedge clk_i) rst_ni && over_d && !over_q);
`endif

`ifdef FORMAL
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // The decision of one clock of the stop, on the generator's mirrored level
  // b (a = -b, or b after a mirror): the next level b1 is within J of b, at
  // most D once b is, and nearer to 0 while b is beyond D. Input contract:
  // reset in the first clock only; start_i, vel_i, acc_i and the limits free.
  // Checked to a bounded depth from reset (docs/formal.md: z3 does not finish
  // an induction step, or a bounded check past the first active clock, on
  // these widths).
  logic                 f_init_q = 1'b1;  // the first clock of every trace
  logic signed [LW-1:0] f_babs, f_b1abs;

  assign f_babs  = b < 0 ? -b : b;
  assign f_b1abs = b1 < 0 ? -b1 : b1;

  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
    end
  end

  always_ff @(posedge clk_i) begin
    f_init_q <= 1'b0;
  end

  always_comb begin
    if (!f_init_q) begin
      // -- group stop_gen_limits
      p_level_step: assert (!active_q || (b1 <= b + j && b1 >= b - j));
      p_acc_stay: assert (!(active_q && f_babs <= dl) || f_b1abs <= dl);
      p_acc_down: assert (!(active_q && f_babs > dl) || f_b1abs < f_babs);
    end
  end
`endif

endmodule
