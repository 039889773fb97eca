// sc_quad_decoder: quadrature encoder interface.
//
//   enc_a_i/enc_b_i -> sc_sync (two flops) -> glitch filter -> 4x decoder
//
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
  input  logic [sc_pkg::EncFiltW-1:0]         cfg_filt_i,

  output logic signed [sc_pkg::EncCntW-1:0]   count_o,
  output logic [sc_pkg::EncIllW-1:0]          illegal_o,
  output logic                                a_o,      // filtered levels
  output logic                                b_o
);

  localparam int EncCntW  = sc_pkg::EncCntW;
  localparam int EncFiltW = sc_pkg::EncFiltW;
  localparam int EncIllW  = sc_pkg::EncIllW;

  logic                      a_s, b_s;   // synchronised levels
  logic                      a_f_q, a_f_d, b_f_q, b_f_d;
  logic [EncFiltW-1:0]       a_cnt_q, a_cnt_d, b_cnt_q, b_cnt_d;
  logic signed [EncCntW-1:0] count_q, count_d;
  logic [EncIllW-1:0]        ill_q, ill_d;
  logic [1:0]                ph_old, ph_new, ph_diff;

  // Gray pair -> quarter-cycle phase: 00->0, 10->1, 11->2, 01->3.
  function automatic logic [1:0] gray_phase(input logic a, input logic b);
    gray_phase = {b, a ^ b};
  endfunction

  sc_sync #(
    .Width    (2),
    .ResetVal (1'b0)
  ) u_sync_ab (
    .clk_i,
    .rst_ni,
    .d_i ({enc_b_i, enc_a_i}),
    .q_o ({b_s, a_s})
  );

  always_comb begin
    a_f_d   = a_f_q;
    b_f_d   = b_f_q;
    a_cnt_d = '0;
    b_cnt_d = '0;
    if (a_s != a_f_q) begin
      if (a_cnt_q >= cfg_filt_i) begin
        a_f_d = a_s;
      end else begin
        a_cnt_d = a_cnt_q + EncFiltW'(1);
      end
    end
    if (b_s != b_f_q) begin
      if (b_cnt_q >= cfg_filt_i) begin
        b_f_d = b_s;
      end else begin
        b_cnt_d = b_cnt_q + EncFiltW'(1);
      end
    end
  end

  assign ph_old  = gray_phase(a_f_q, b_f_q);
  assign ph_new  = gray_phase(a_f_d, b_f_d);
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
      a_f_q   <= 1'b0;
      b_f_q   <= 1'b0;
      a_cnt_q <= '0;
      b_cnt_q <= '0;
      count_q <= '0;
      ill_q   <= '0;
    end else begin
      a_f_q   <= a_f_d;
      b_f_q   <= b_f_d;
      a_cnt_q <= a_cnt_d;
      b_cnt_q <= b_cnt_d;
      count_q <= count_d;
      ill_q   <= ill_d;
    end
  end

  assign count_o   = count_q;
  assign illegal_o = ill_q;
  assign a_o       = a_f_q;
  assign b_o       = b_f_q;

endmodule
