// sc_quad_decoder: quadrature encoder interface.
//
//   enc_a_i/enc_b_i/enc_z_i -> sc_sync (two flops) -> glitch filter -> 4x decoder
//
// The index Z goes through the same synchroniser and filter as A and B, so
// a Z edge that came with an A/B edge shows in the same clock as that
// count (z_o and count_o change together): a latch of the count on z_o's
// edge holds the quadrature state Z is tied to, exactly.
// Glitch filter (per channel): a synchronised level that differs from the
// filtered one is accepted on the (cfg_filt_i+1)-th consecutive clock it is
// seen, so any pulse of <= cfg_filt_i clocks is ignored (0 = no filter).
// 4x decoding: the filtered (A,B) pair walks the Gray sequence
// 00 -> 10 -> 11 -> 01 -> 00 forward (A leads B) and backward the other
// way; each legal step is +-1 count. A change of both channels in one clock
// is illegal: the count keeps its value and illegal_o (saturating) counts it.
module sc_quad_decoder (
  input  logic                                clk_i,
  input  logic                                rst_ni,

  input  logic                                enc_a_i,
  input  logic                                enc_b_i,
  input  logic                                enc_z_i,  // index, once per revolution
  input  logic [sc_pkg::EncFiltW-1:0]         cfg_filt_i,

  output logic signed [sc_pkg::EncCntW-1:0]   count_o,
  output logic [sc_pkg::EncIllW-1:0]          illegal_o,
  output logic                                a_o,      // filtered levels
  output logic                                b_o,
  output logic                                z_o
);

  localparam int EncCntW  = sc_pkg::EncCntW;
  localparam int EncFiltW = sc_pkg::EncFiltW;
  localparam int EncIllW  = sc_pkg::EncIllW;
  localparam int ChA = 0, ChB = 1, ChZ = 2, Channels = 3;

  logic [Channels-1:0]                s_ch;        // synchronised levels
  logic [Channels-1:0]                f_q, f_d;    // filtered levels
  logic [Channels*EncFiltW-1:0]       cnt_q, cnt_d;  // channel c: [c*EncFiltW +: EncFiltW]
  logic signed [EncCntW-1:0] count_q, count_d;
  logic [EncIllW-1:0]        ill_q, ill_d;
  logic [1:0]                ph_old, ph_new, ph_diff;

  // Gray pair -> quarter-cycle phase: 00->0, 10->1, 11->2, 01->3.
  function automatic logic [1:0] gray_phase(input logic a, input logic b);
    gray_phase = {b, a ^ b};
  endfunction

  sc_sync #(
    .Width    (Channels),
    .ResetVal (1'b0)
  ) u_sync_abz (
    .clk_i,
    .rst_ni,
    .d_i ({enc_z_i, enc_b_i, enc_a_i}),
    .q_o (s_ch)
  );

  // the same filter on every channel
  always_comb begin
    f_d   = f_q;
    cnt_d = '0;
    for (int c = 0; c < Channels; c++) begin
      if (s_ch[c] != f_q[c]) begin
        if (cnt_q[c*EncFiltW +: EncFiltW] >= cfg_filt_i) begin
          f_d[c] = s_ch[c];
        end else begin
          cnt_d[c*EncFiltW +: EncFiltW] = cnt_q[c*EncFiltW +: EncFiltW] + EncFiltW'(1);
        end
      end
    end
  end

  assign ph_old  = gray_phase(f_q[ChA], f_q[ChB]);
  assign ph_new  = gray_phase(f_d[ChA], f_d[ChB]);
  assign ph_diff = ph_new - ph_old;

  always_comb begin
    count_d = count_q;
    ill_d   = ill_q;
    unique case (ph_diff)
      2'd1:    count_d = count_q + EncCntW'(1);
      2'd3:    count_d = count_q - EncCntW'(1);
      2'd2:    if (ill_q != '1) ill_d = ill_q + EncIllW'(1);
      default: ;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      f_q     <= '0;
      cnt_q   <= '0;
      count_q <= '0;
      ill_q   <= '0;
    end else begin
      f_q     <= f_d;
      cnt_q   <= cnt_d;
      count_q <= count_d;
      ill_q   <= ill_d;
    end
  end

  assign count_o   = count_q;
  assign illegal_o = ill_q;
  assign a_o       = f_q[ChA];
  assign b_o       = f_q[ChB];
  assign z_o       = f_q[ChZ];

`ifdef FORMAL
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // Input contract: reset in the first clock only; cfg_filt_i constant. The
  // encoder pins are free (any glitches, any two-channel jumps).
  localparam int FRunW = EncFiltW + 1;  // holds cfg_filt + 1

  logic                      f_init_q = 1'b1;  // the first clock of every trace
  logic [EncFiltW-1:0]       f_filt_q;
  logic                      f_a_prev_q, f_b_prev_q;
  logic signed [EncCntW-1:0] f_count_prev_q;
  logic [EncIllW-1:0]        f_ill_prev_q;
  logic [Channels-1:0]       f_s_prev_q;       // synchronised levels of the last clock
  logic [Channels*FRunW-1:0] f_run_q;          // clocks they had held that level (saturating)
  logic                      f_a_chg, f_b_chg, f_fwd, f_rev;
  logic signed [EncCntW-1:0] f_count_exp;

  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
      a_filt_stable: assume (cfg_filt_i == f_filt_q);
    end
  end

  always_ff @(posedge clk_i) begin
    f_init_q <= 1'b0;
    f_filt_q <= cfg_filt_i;
    if (!rst_ni) begin
      f_a_prev_q     <= 1'b0;
      f_b_prev_q     <= 1'b0;
      f_count_prev_q <= '0;
      f_ill_prev_q   <= '0;
      f_s_prev_q     <= '0;
      f_run_q        <= '0;   // no history is claimed at reset
    end else begin
      f_a_prev_q     <= a_o;
      f_b_prev_q     <= b_o;
      f_count_prev_q <= count_o;
      f_ill_prev_q   <= illegal_o;
      f_s_prev_q     <= s_ch;
      for (int c = 0; c < Channels; c++) begin
        if (s_ch[c] != f_s_prev_q[c]) begin
          f_run_q[c*FRunW +: FRunW] <= FRunW'(1);
        end else if (f_run_q[c*FRunW +: FRunW] != '1) begin
          f_run_q[c*FRunW +: FRunW] <= f_run_q[c*FRunW +: FRunW] + FRunW'(1);
        end
      end
    end
  end

  // the Gray walk (A,B): 00 -> 10 -> 11 -> 01 -> 00 forward, reversed backward
  assign f_a_chg = a_o != f_a_prev_q;
  assign f_b_chg = b_o != f_b_prev_q;
  assign f_fwd   = (f_a_chg && !f_b_chg && a_o == !f_b_prev_q) ||
                   (f_b_chg && !f_a_chg && b_o == f_a_prev_q);
  assign f_rev   = (f_a_chg && !f_b_chg && a_o == f_b_prev_q) ||
                   (f_b_chg && !f_a_chg && b_o == !f_a_prev_q);
  always_comb begin
    f_count_exp = f_count_prev_q;
    if (f_fwd) f_count_exp = f_count_prev_q + EncCntW'(1);
    if (f_rev) f_count_exp = f_count_prev_q - EncCntW'(1);
  end

  always_comb begin
    if (!f_init_q) begin
      // -- group count: at most one count per clock, +1 / -1 for a forward /
      // backward Gray step of the filtered levels, none otherwise; a jump of
      // both channels never moves the count and is counted (saturating)
      p_count_one: assert (count_o == f_count_prev_q || count_o == f_count_prev_q + EncCntW'(1) ||
                           count_o == f_count_prev_q - EncCntW'(1));
      p_count_decode: assert (count_o == f_count_exp);
      p_illegal_count: assert (illegal_o == ((f_a_chg && f_b_chg && f_ill_prev_q != '1) ?
                                             f_ill_prev_q + EncIllW'(1) : f_ill_prev_q));
      p_illegal_still: assert (!(f_a_chg && f_b_chg) || count_o == f_count_prev_q);
    end
  end

  // per channel (yosys names an assertion once, so the channels are AND-ed)
  logic [Channels-1:0] f_prev_q, f_sound, f_complete, f_cnt_ok;
  always_ff @(posedge clk_i) f_prev_q <= rst_ni ? f_q : '0;
  always_comb begin
    for (int c = 0; c < Channels; c++) begin
      f_sound[c]    = f_q[c] == f_prev_q[c] ||
                      (f_q[c] == f_s_prev_q[c] && f_run_q[c*FRunW +: FRunW] > FRunW'(cfg_filt_i));
      f_complete[c] = f_run_q[c*FRunW +: FRunW] <= FRunW'(cfg_filt_i) || f_q[c] == f_s_prev_q[c];
      f_cnt_ok[c]   = f_s_prev_q[c] != f_q[c] ?
                      (FRunW'(cnt_q[c*EncFiltW +: EncFiltW]) == f_run_q[c*FRunW +: FRunW] &&
                       f_run_q[c*FRunW +: FRunW] <= FRunW'(cfg_filt_i))
                      : cnt_q[c*EncFiltW +: EncFiltW] == '0;
    end
    if (!f_init_q) begin
      // -- group filter: a filtered level changes only to a synchronised
      // level held for cfg_filt + 1 clocks, and always after that long
      p_filt_sound: assert (&f_sound);
      p_filt_complete: assert (&f_complete);
      // helper: a filter counter is the run of the mismatching level
      inv_filt_cnt: assert (&f_cnt_ok);
    end
  end
`endif

endmodule
