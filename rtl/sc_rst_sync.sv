// sc_rst_sync: reset synchroniser. rst_no is low while arst_ni is low (or
// the clock was just locked) and for Stages clocks after it rises; it falls
// and rises only on clk_i edges. arst_ni is sampled as a synchronous reset
// of the chain: only the first flop (D = 1) can go metastable on release,
// the others hold 0 until it has settled. The flops start at 0 (FPGA INIT),
// so the design is in reset straight after configuration.
module sc_rst_sync #(
  parameter int Stages = 4
) (
  input  logic clk_i,
  input  logic arst_ni,   // asynchronous, active low (button AND clock locked)
  output logic rst_no
);

  (* ASYNC_REG = "TRUE" *) logic [Stages-1:0] chain_q = '0;

  always_ff @(posedge clk_i) begin
    if (!arst_ni) begin
      chain_q <= '0;
    end else begin
      chain_q <= {chain_q[Stages-2:0], 1'b1};
    end
  end

  assign rst_no = chain_q[Stages-1];

endmodule
