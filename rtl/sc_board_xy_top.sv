// sc_board_xy_top: Digilent Arty A7-35T (xc7a35ticsg324-1L) top level with
// two coordinated, closed-loop capable axes X and Y (the X-Y table).
// Pins: constraints/arty_a7_35t_xy.xdc.
//
//   CLK100MHZ --[sc_clkgen: MMCM]--> 20 MHz system clock
//   ck_rst button AND MMCM locked --[sc_rst_sync]--> rst_n
//   USB-UART (115200 8N1) --[sc_uart_axi_link, 2-byte word
//       addresses]--> AXI4-Lite --> sc_axi_multi_axis (the multi-axis map,
//       docs/regmap.md: group window 0, X in window 1, Y in window 2)
//   X: STEP/DIR/EN on Pmod JA1-3, encoder A/B/Z on JB1/JB2/JB9, limit -,
//      limit +, home on JB3/JB4/JB7
//   Y: STEP/DIR/EN on Pmod JC1-3, encoder A/B/Z on JD1/JD2/JD9, limit -,
//      limit +, home on JD3/JD4/JD7
//   the board's one probe on JB8, fanned out to both axes
//   BTN0 --[sc_sync]--> e-stop (both axes: abort, EN off, ERR.ESTOP latched)
//   LD4 heartbeat, LD5 busy (either axis), LD6 done (both), LD7 fault (either)
//   / e-stop; irq (either axis's IRQ_STATUS & IRQ_ENABLE) on Pmod JA4 and
//   the red of RGB LED LD0
// Every input pin is asynchronous and goes through a two-flop synchroniser;
// every output pin comes from a flop of the system clock domain.
module sc_board_xy_top #(
  parameter int ClksPerBit = sc_pkg::UartClksPerBit
) (
  input  logic       clk100_i,    // E3, 100 MHz oscillator
  input  logic       ck_rst_ni,   // C2, red RESET button (low = pressed)
  input  logic       estop_i,     // D9, BTN0 (high = pressed): e-stop
  input  logic       uart_rx_i,   // A9, uart_txd_in: data from the PC
  output logic       uart_tx_o,   // D10, uart_rxd_out: data to the PC
  output logic [1:0] step_o,      // X: G13 (JA1), Y: U12 (JC1)
  output logic [1:0] dir_o,       // X: B11 (JA2), Y: V12 (JC2)
  output logic [1:0] en_o,        // X: A11 (JA3), Y: V10 (JC3) (high = enabled)
  output logic       irq_o,       // D12, Pmod JA4 (high = interrupt pending)
  output logic       led_irq_o,   // G6, LD0 red: interrupt pending
  input  logic [1:0] enc_a_i,     // X: E15 (JB1), Y: D4 (JD1)
  input  logic [1:0] enc_b_i,     // X: E16 (JB2), Y: D3 (JD2)
  input  logic [1:0] enc_z_i,     // X: K15 (JB9), Y: H2 (JD9): index (0 when absent)
  input  logic [5:0] sw_i,        // X limit -, +, home: D15 C15 J17 (JB3 JB4 JB7);
                                  // Y limit -, +, home: F4 F3 E2 (JD3 JD4 JD7)
  input  logic       probe_i,     // J18, Pmod JB8: the probe, both axes
  output logic [3:0] led_o        // H5 J5 T9 T10 (LD4..LD7)
);

  localparam int Axes    = 2;
  localparam int AW      = sc_pkg::MultiRegAddrW;
  localparam int SwW     = sc_pkg::SwW;
  localparam int PosIntW = sc_pkg::PosIntW;
  localparam int EncCntW = sc_pkg::EncCntW;
  localparam int PhaseW  = sc_pkg::PhaseW;
  localparam int HeartW  = 24;    // 2^23 clocks = 0.42 s per LED toggle

  logic clk, locked, rst_n;

  sc_clkgen u_clkgen (
    .clk100_i,
    .clk_o    (clk),
    .locked_o (locked)
  );

  sc_rst_sync u_rst_sync (
    .clk_i   (clk),
    .arst_ni (ck_rst_ni && locked),
    .rst_no  (rst_n)
  );

  // ---- asynchronous inputs --------------------------------------------------
  logic estop_sync;

  sc_sync #(.Width(1), .ResetVal(1'b0)) u_sync_estop (
    .clk_i (clk), .rst_ni (rst_n), .d_i (estop_i), .q_o (estop_sync)
  );

  // ---- UART link: the PC's register reads and writes ----------------------------
  logic [AW-1:0] awaddr, araddr;
  logic          awvalid, awready, wvalid, wready, bvalid, bready;
  logic          arvalid, arready, rvalid, rready;
  logic [31:0]   wdata, rdata;
  logic [3:0]    wstrb;
  logic [1:0]    bresp, rresp;
  logic          unused_crc_err;

  sc_uart_axi_link #(
    .ClksPerBit (ClksPerBit),
    .AddrW      (AW)
  ) u_link (
    .clk_i           (clk),
    .rst_ni          (rst_n),
    .uart_rx_i,
    .uart_tx_o,
    .m_axi_awaddr_o  (awaddr),
    .m_axi_awvalid_o (awvalid),
    .m_axi_awready_i (awready),
    .m_axi_wdata_o   (wdata),
    .m_axi_wstrb_o   (wstrb),
    .m_axi_wvalid_o  (wvalid),
    .m_axi_wready_i  (wready),
    .m_axi_bresp_i   (bresp),
    .m_axi_bvalid_i  (bvalid),
    .m_axi_bready_o  (bready),
    .m_axi_araddr_o  (araddr),
    .m_axi_arvalid_o (arvalid),
    .m_axi_arready_i (arready),
    .m_axi_rdata_i   (rdata),
    .m_axi_rresp_i   (rresp),
    .m_axi_rvalid_i  (rvalid),
    .m_axi_rready_o  (rready),
    .crc_err_o       (unused_crc_err)
  );

  // ---- the two axes ----------------------------------------------------------------
  logic [Axes-1:0]         busy, done, fault;
  logic                    irq;
  logic [Axes*SwW-1:0]     axis_sw;
  logic [Axes*PhaseW-1:0]  unused_phase;
  logic [Axes*PosIntW-1:0] unused_pulse_count, unused_ref_pos;
  logic [Axes*EncCntW-1:0] unused_enc_pos;
  logic [Axes-1:0]         unused_in_pos, unused_fault_ferr;

  // per axis {probe, home, limit +, limit -} (sc_pkg::SwLimNeg .. SwProbe)
  assign axis_sw = {probe_i, sw_i[5:3], probe_i, sw_i[2:0]};

  // Without the soft-limit look-ahead: with it the two closed-loop axes
  // need about 102 % of the xc7a35t's LUTs by yosys' count (docs/limits.md);
  // SOFT_MIN / SOFT_MAX still act as limits on REF_POS.
  sc_axi_multi_axis #(.Axes(Axes), .Servo(1'b1), .Lookahead(1'b0)) u_axes (
    .clk_i           (clk),
    .rst_ni          (rst_n),
    .s_axi_awaddr_i  (awaddr),
    .s_axi_awvalid_i (awvalid),
    .s_axi_awready_o (awready),
    .s_axi_wdata_i   (wdata),
    .s_axi_wstrb_i   (wstrb),
    .s_axi_wvalid_i  (wvalid),
    .s_axi_wready_o  (wready),
    .s_axi_bresp_o   (bresp),
    .s_axi_bvalid_o  (bvalid),
    .s_axi_bready_i  (bready),
    .s_axi_araddr_i  (araddr),
    .s_axi_arvalid_i (arvalid),
    .s_axi_arready_o (arready),
    .s_axi_rdata_o   (rdata),
    .s_axi_rresp_o   (rresp),
    .s_axi_rvalid_o  (rvalid),
    .s_axi_rready_i  (rready),
    .estop_i         (estop_sync),
    .enc_a_i,
    .enc_b_i,
    .enc_z_i,
    .sw_i            (axis_sw),
    .step_o,
    .dir_o,
    .en_o,
    .busy_o          (busy),
    .done_o          (done),
    .fault_o         (fault),
    .phase_o         (unused_phase),
    .pulse_count_o   (unused_pulse_count),
    .ref_pos_o       (unused_ref_pos),
    .enc_pos_o       (unused_enc_pos),
    .in_pos_o        (unused_in_pos),
    .fault_ferr_o    (unused_fault_ferr),
    .irq_o           (irq)
  );

  // ---- LEDs ------------------------------------------------------------------------
  logic [HeartW-1:0] heart_q;
  logic [3:0]        led_q, led_d;
  logic              irq_q;  // the OR of two axes' flops, through a flop to the pins

  always_comb begin
    led_d    = '0;
    led_d[0] = heart_q[HeartW-1];
    led_d[1] = |busy;
    led_d[2] = &done;
    led_d[3] = (|fault) || estop_sync;
  end

  always_ff @(posedge clk) begin
    if (!rst_n) begin
      heart_q <= '0;
      led_q   <= '0;
      irq_q   <= 1'b0;
    end else begin
      heart_q <= heart_q + HeartW'(1);
      led_q   <= led_d;
      irq_q   <= irq;
    end
  end

  assign led_o     = led_q;
  assign irq_o     = irq_q;
  assign led_irq_o = irq_q;

endmodule
