// sc_board_top: Digilent Arty A7-35T (xc7a35ticsg324-1L) top level.
// Pins: constraints/arty_a7_35t.xdc.
//
//   CLK100MHZ --[sc_clkgen: MMCM]--> 20 MHz system clock
//   ck_rst button AND MMCM locked --[sc_rst_sync]--> rst_n
//   USB-UART (115200 8N1) --[sc_uart_axi_link: UART + sc_uart_bridge]--> AXI4-Lite
//       --> sc_axi_servo (sc_axi_regs + sc_servo_axis) --> STEP/DIR/EN on Pmod JA
//   encoder A/B/Z on Pmod JB --> sc_servo_axis's quadrature decoder (its own
//       two-flop synchronisers and glitch filter) --> closed loop, ENC_POS /
//       FOLLOW_ERR, position latch on the index; CTRL.CLOSED_LOOP = 0 runs
//       the move open loop
//   limit -, limit +, home switches on Pmod JB3, JB4, JB7 and the probe on
//       JB8 --> sc_axi_servo's switch filter (synchroniser, polarity,
//       debounce: SW_CFG) --> stop on limit, position latch on home or
//       probe, STATUS.SW_LEVEL, IRQ_STATUS.SWITCH
//   BTN0 --[sc_sync]--> e-stop (abort, EN off, ERR.ESTOP latched)
//   LD4 heartbeat, LD5 busy, LD6 done (closed loop: in position),
//   LD7 fault (table, overrun, following error) / e-stop
//   irq (IRQ_STATUS & IRQ_ENABLE) on Pmod JA4 and the red of RGB LED LD0
// Every input pin is asynchronous and goes through a two-flop synchroniser;
// every output pin comes from a flop of the system clock domain.
module sc_board_top #(
  parameter int ClksPerBit = sc_pkg::UartClksPerBit
) (
  input  logic       clk100_i,    // E3, 100 MHz oscillator
  input  logic       ck_rst_ni,   // C2, red RESET button (low = pressed)
  input  logic       estop_i,     // D9, BTN0 (high = pressed): e-stop
  input  logic       uart_rx_i,   // A9, uart_txd_in: data from the PC
  output logic       uart_tx_o,   // D10, uart_rxd_out: data to the PC
  output logic       step_o,      // G13, Pmod JA1
  output logic       dir_o,       // B11, Pmod JA2
  output logic       en_o,        // A11, Pmod JA3 (high = enabled)
  output logic       irq_o,       // D12, Pmod JA4 (high = interrupt pending)
  output logic       led_irq_o,   // G6, LD0 red: interrupt pending
  input  logic       enc_a_i,     // E15, Pmod JB1
  input  logic       enc_b_i,     // E16, Pmod JB2
  input  logic       enc_z_i,     // K15, Pmod JB9: encoder index (0 when absent)
  input  logic [2:0] sw_i,        // D15 C15 J17, Pmod JB3 JB4 JB7: limit -, limit +, home
  input  logic       probe_i,     // J18, Pmod JB8: the probe (touch-off, tool setter)
  output logic [3:0] led_o        // H5 J5 T9 T10 (LD4..LD7)
);

  localparam int AW      = sc_pkg::RegAddrW;
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

  // ---- the axis ------------------------------------------------------------------
  logic                      busy, done, fault, irq;
  logic [PhaseW-1:0]         unused_phase;
  logic signed [PosIntW-1:0] unused_pulse_count, unused_ref_pos;
  logic signed [EncCntW-1:0] unused_enc_pos;
  logic                      unused_in_pos, unused_fault_ferr;

  sc_axi_servo u_axis (
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
    .sw_i            ({probe_i, sw_i}),
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

  always_comb begin
    led_d    = '0;
    led_d[0] = heart_q[HeartW-1];
    led_d[1] = busy;
    led_d[2] = done;
    led_d[3] = fault || estop_sync;
  end

  always_ff @(posedge clk) begin
    if (!rst_n) begin
      heart_q <= '0;
      led_q   <= '0;
    end else begin
      heart_q <= heart_q + HeartW'(1);
      led_q   <= led_d;
    end
  end

  assign led_o     = led_q;
  // irq is a flop of sc_axi_regs: straight to the pins
  assign irq_o     = irq;
  assign led_irq_o = irq;

endmodule
