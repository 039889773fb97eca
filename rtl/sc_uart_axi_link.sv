// sc_uart_axi_link: a board's UART pins to an AXI4-Lite master, so a PC
// drives the register map with no processor: the RX pin's two-flop
// synchroniser, sc_uart_rx / sc_uart_tx (8N1 at ClksPerBit clocks per bit)
// and sc_uart_bridge (frames to register reads and writes of an AddrW-bit
// map; protocol: docs/regmap.md). Both board tops use it.
module sc_uart_axi_link #(
  parameter int ClksPerBit = sc_pkg::UartClksPerBit,
  parameter int AddrW      = sc_pkg::RegAddrW
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              uart_rx_i,   // asynchronous: the PC's transmit line
  output logic              uart_tx_o,   // a flop of sc_uart_tx

  output logic [AddrW-1:0]  m_axi_awaddr_o,
  output logic              m_axi_awvalid_o,
  input  logic              m_axi_awready_i,
  output logic [31:0]       m_axi_wdata_o,
  output logic [3:0]        m_axi_wstrb_o,
  output logic              m_axi_wvalid_o,
  input  logic              m_axi_wready_i,
  input  logic [1:0]        m_axi_bresp_i,
  input  logic              m_axi_bvalid_i,
  output logic              m_axi_bready_o,
  output logic [AddrW-1:0]  m_axi_araddr_o,
  output logic              m_axi_arvalid_o,
  input  logic              m_axi_arready_i,
  input  logic [31:0]       m_axi_rdata_i,
  input  logic [1:0]        m_axi_rresp_i,
  input  logic              m_axi_rvalid_i,
  output logic              m_axi_rready_o,
  output logic              crc_err_o      // one clock per rejected frame
);

  logic       rx_sync, rx_valid, rx_ferr, tx_valid, tx_ready;
  logic [7:0] rx_data, tx_data;

  sc_sync #(.Width(1), .ResetVal(1'b1)) u_sync_rx (
    .clk_i, .rst_ni, .d_i (uart_rx_i), .q_o (rx_sync)
  );

  sc_uart_rx #(.ClksPerBit(ClksPerBit)) u_uart_rx (
    .clk_i,
    .rst_ni,
    .rx_i        (rx_sync),
    .valid_o     (rx_valid),
    .data_o      (rx_data),
    .frame_err_o (rx_ferr)
  );

  sc_uart_tx #(.ClksPerBit(ClksPerBit)) u_uart_tx (
    .clk_i,
    .rst_ni,
    .valid_i (tx_valid),
    .data_i  (tx_data),
    .ready_o (tx_ready),
    .tx_o    (uart_tx_o)
  );

  sc_uart_bridge #(
    .TimeoutClks (sc_pkg::UartTimeoutBits * ClksPerBit),
    .AddrW       (AddrW)
  ) u_bridge (
    .clk_i,
    .rst_ni,
    .rx_valid_i      (rx_valid),
    .rx_data_i       (rx_data),
    .rx_frame_err_i  (rx_ferr),
    .tx_valid_o      (tx_valid),
    .tx_data_o       (tx_data),
    .tx_ready_i      (tx_ready),
    .m_axi_awaddr_o,
    .m_axi_awvalid_o,
    .m_axi_awready_i,
    .m_axi_wdata_o,
    .m_axi_wstrb_o,
    .m_axi_wvalid_o,
    .m_axi_wready_i,
    .m_axi_bresp_i,
    .m_axi_bvalid_i,
    .m_axi_bready_o,
    .m_axi_araddr_o,
    .m_axi_arvalid_o,
    .m_axi_arready_i,
    .m_axi_rdata_i,
    .m_axi_rresp_i,
    .m_axi_rvalid_i,
    .m_axi_rready_o,
    .crc_err_o
  );

endmodule
