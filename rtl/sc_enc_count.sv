// sc_enc_count: placeholder encoder input stage for the board top: counts
// the synchronised quadrature A/B inputs 4x (+1 / -1 per valid transition,
// A leading B = forward) and counts illegal (double) transitions. No glitch
// filter: the closed-loop quadrature decoder (separate issue) replaces this
// module behind the same enc_pos_o port.
module sc_enc_count (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic [1:0]                         ab_i,        // synchronised {B, A}
  output logic signed [sc_pkg::PosIntW-1:0]  pos_o,
  output logic [7:0]                         illegal_o    // saturating
);

  localparam int PosIntW = sc_pkg::PosIntW;

  logic [1:0]                prev_q;
  logic signed [PosIntW-1:0] pos_q, pos_d;
  logic [7:0]                ill_q, ill_d;
  logic [3:0]                tr;

  assign tr = {prev_q, ab_i};   // {B', A', B, A}

  always_comb begin
    pos_d = pos_q;
    ill_d = ill_q;
    unique case (tr)
      // forward: 00 -> 01 -> 11 -> 10 -> 00 (written {B, A})
      4'b0001, 4'b0111, 4'b1110, 4'b1000: pos_d = pos_q + PosIntW'(1);
      4'b0010, 4'b1011, 4'b1101, 4'b0100: pos_d = pos_q - PosIntW'(1);
      4'b0011, 4'b1100, 4'b0110, 4'b1001: ill_d = (ill_q == 8'hFF) ? ill_q : ill_q + 8'd1;
      default: ;                 // no change
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      prev_q <= '0;
      pos_q  <= '0;
      ill_q  <= '0;
    end else begin
      prev_q <= ab_i;
      pos_q  <= pos_d;
      ill_q  <= ill_d;
    end
  end

  assign pos_o     = pos_q;
  assign illegal_o = ill_q;

endmodule
