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

endmodule
