// sc_clkgen: the board's 100 MHz oscillator to the 20 MHz system clock.
// For synthesis (`SYNTHESIS, defined by Vivado and yosys): an MMCME2_BASE,
// VCO = 100 MHz * 10 = 1000 MHz (600..1200 MHz for -1L), CLKOUT0 = VCO / 50
// = 20 MHz, feedback through a BUFG, output through a BUFG. Vivado derives
// the generated clock from the create_clock on the input pin.
// For simulation (Verilator, Icarus): a behavioural stand-in that divides
// by 5 (2 high / 3 low input periods) and raises locked_o after 16 input
// clocks, so the same top builds everywhere.
module sc_clkgen (
  input  logic clk100_i,
  output logic clk_o,      // 20 MHz
  output logic locked_o
);

`ifdef SYNTHESIS
  logic clkfb, clkfb_buf, clk_unbuf;

  MMCME2_BASE #(
    .BANDWIDTH          ("OPTIMIZED"),
    .CLKIN1_PERIOD      (10.0),
    .DIVCLK_DIVIDE      (1),
    .CLKFBOUT_MULT_F    (10.0),
    .CLKFBOUT_PHASE     (0.0),
    .CLKOUT0_DIVIDE_F   (50.0),
    .CLKOUT0_DUTY_CYCLE (0.5),
    .CLKOUT0_PHASE      (0.0),
    .STARTUP_WAIT       ("FALSE")
  ) u_mmcm (
    .CLKIN1   (clk100_i),
    .CLKFBIN  (clkfb_buf),
    .CLKFBOUT (clkfb),
    .CLKFBOUTB(),
    .CLKOUT0  (clk_unbuf),
    .CLKOUT0B (),
    .CLKOUT1  (),
    .CLKOUT1B (),
    .CLKOUT2  (),
    .CLKOUT2B (),
    .CLKOUT3  (),
    .CLKOUT3B (),
    .CLKOUT4  (),
    .CLKOUT5  (),
    .CLKOUT6  (),
    .LOCKED   (locked_o),
    .PWRDWN   (1'b0),
    .RST      (1'b0)
  );

  BUFG u_bufg_fb  (.I(clkfb),     .O(clkfb_buf));
  BUFG u_bufg_out (.I(clk_unbuf), .O(clk_o));
`else
  // Simulation stand-in (never synthesized).
  logic [2:0] div_q = 3'd0;
  logic [4:0] lock_q = 5'd0;
  logic       clk_q = 1'b0;

  always_ff @(posedge clk100_i) begin
    div_q  <= (div_q == 3'd4) ? 3'd0 : div_q + 3'd1;
    clk_q  <= (div_q == 3'd4) || (div_q == 3'd0);
    lock_q <= lock_q[4] ? lock_q : lock_q + 5'd1;
  end

  assign clk_o    = clk_q;
  assign locked_o = lock_q[4];
`endif

endmodule
