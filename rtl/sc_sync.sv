// sc_sync: the two-flop synchroniser for every asynchronous level input
// (encoder A/B in sc_quad_decoder and sc_axi_servo, e-stop button, UART RX;
// the reset has its own, sc_rst_sync). Each bit is synchronised on its own:
// use it only for signals whose bits may be seen a clock apart (Gray-like or
// single). Model: cmodel/sync.h.
module sc_sync #(
  parameter int          Width    = 1,
  parameter logic [0:0]  ResetVal = 1'b0   // value held in reset (idle level)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic [Width-1:0] d_i,
  output logic [Width-1:0] q_o
);

  (* ASYNC_REG = "TRUE" *) logic [Width-1:0] meta_q;
  (* ASYNC_REG = "TRUE" *) logic [Width-1:0] sync_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      meta_q <= {Width{ResetVal}};
      sync_q <= {Width{ResetVal}};
    end else begin
      meta_q <= d_i;
      sync_q <= meta_q;
    end
  end

  assign q_o = sync_q;

endmodule
