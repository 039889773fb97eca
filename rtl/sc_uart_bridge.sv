// sc_uart_bridge: UART frames to AXI4-Lite register reads and writes, so a
// PC can drive the register file with no processor (protocol: docs/regmap.md).
//
//   host -> board  write: A5 01 addr d0 d1 d2 d3 crc     (data little-endian)
//                  read : A5 02 addr crc
//   addr: WORD address (bus byte address = addr * 4), so the one byte
//   reaches all 256 words of the 1 KiB window (register map 3.0 on). With
//   AddrW wider than 10 (the multi-axis map) it is AddrBytes bytes, low
//   byte first; a word address beyond the AddrW-bit map answers DECERR
//   without a bus access.
//   board -> host  write: 5A status crc
//                  read : 5A status d0 d1 d2 d3 crc
//                  error: 5A 80 crc (CRC wrong) | 5A 81 crc (unknown command)
//   crc: CRC-8, polynomial 0x07, initial 0x00, over every byte after the
//   sync byte. status: the AXI response (0 OKAY, 2 SLVERR, 3 DECERR).
// A frame with a wrong CRC, a UART framing error, or a gap longer than
// TimeoutClks inside it is dropped before anything reaches the bus (a CRC
// error is answered, the others are not). Bytes that arrive while a
// request is executed or answered are ignored; bytes other than A5 between
// frames are skipped, so the host can always resynchronise.
module sc_uart_bridge #(
  parameter int TimeoutClks = 6960,
  parameter int AddrW       = sc_pkg::RegAddrW  // bus byte address bits
) (
  input  logic                         clk_i,
  input  logic                         rst_ni,

  // from sc_uart_rx / to sc_uart_tx
  input  logic                         rx_valid_i,
  input  logic [7:0]                   rx_data_i,
  input  logic                         rx_frame_err_i,
  output logic                         tx_valid_o,
  output logic [7:0]                   tx_data_o,
  input  logic                         tx_ready_i,

  // AXI4-Lite master
  output logic [AddrW-1:0]             m_axi_awaddr_o,
  output logic                         m_axi_awvalid_o,
  input  logic                         m_axi_awready_i,
  output logic [31:0]                  m_axi_wdata_o,
  output logic [3:0]                   m_axi_wstrb_o,
  output logic                         m_axi_wvalid_o,
  input  logic                         m_axi_wready_i,
  input  logic [1:0]                   m_axi_bresp_i,
  input  logic                         m_axi_bvalid_i,
  output logic                         m_axi_bready_o,
  output logic [AddrW-1:0]             m_axi_araddr_o,
  output logic                         m_axi_arvalid_o,
  input  logic                         m_axi_arready_i,
  input  logic [31:0]                  m_axi_rdata_i,
  input  logic [1:0]                   m_axi_rresp_i,
  input  logic                         m_axi_rvalid_i,
  output logic                         m_axi_rready_o,

  output logic                         crc_err_o     // one clock per rejected frame
);

  localparam int AW = AddrW;
  // word-address bytes of a frame, and their bits
  localparam int AddrBytes = (AW - 2 + 7) / 8;
  localparam int WordW     = 8 * AddrBytes;
  localparam logic [7:0] ReqSync  = 8'(sc_pkg::UartReqSync);
  localparam logic [7:0] RspSync  = 8'(sc_pkg::UartRspSync);
  localparam logic [7:0] CmdWrite = 8'(sc_pkg::UartCmdWrite);
  localparam logic [7:0] CmdRead  = 8'(sc_pkg::UartCmdRead);
  localparam logic [7:0] StCrcErr = 8'(sc_pkg::UartStCrcErr);
  localparam logic [7:0] StBadCmd = 8'(sc_pkg::UartStBadCmd);
  localparam logic [1:0] RespDecErr = 2'b11;
  localparam int ToW = $clog2(TimeoutClks + 1);

  typedef enum logic [3:0] {
    SSync  = 4'd0,
    SCmd   = 4'd1,
    SAddr  = 4'd2,
    SData  = 4'd3,
    SCrc   = 4'd4,
    SWrite = 4'd5,
    SRead  = 4'd6,
    STx    = 4'd7
  } state_e;

  // CRC-8, polynomial x^8 + x^2 + x + 1 (0x07), MSB first
  function automatic logic [7:0] crc8(input logic [7:0] crc, input logic [7:0] d);
    logic [7:0] c;
    c = crc ^ d;
    for (int i = 0; i < 8; i++) begin
      c = c[7] ? ((c << 1) ^ 8'h07) : (c << 1);
    end
    crc8 = c;
  endfunction

  state_e          state_q, state_d;
  logic            is_write_q, is_write_d;
  logic [WordW-1:0] addr_q, addr_d;       // word address as received
  logic            addr_ok;               // inside the AW-bit map
  logic [31:0]     data_q, data_d;
  logic [1:0]      dcnt_q, dcnt_d;
  logic [7:0]      crc_q, crc_d;
  logic [ToW-1:0]  idle_q, idle_d;
  logic            aw_done_q, aw_done_d;
  logic            w_done_q, w_done_d;
  logic            a_pend_q, a_pend_d;    // request presented, response awaited
  logic [7:0]      status_q, status_d;
  logic            has_data_q, has_data_d;
  logic [2:0]      tx_idx_q, tx_idx_d;
  logic            crc_err_q, crc_err_d;

  logic [7:0]      tx_byte;
  logic            tx_last;

  always_comb begin
    if (tx_idx_q == 3'd0) begin
      tx_byte = RspSync;
    end else if (tx_idx_q == 3'd1) begin
      tx_byte = status_q;
    end else if (has_data_q && tx_idx_q <= 3'd5) begin
      tx_byte = data_q[8 * (tx_idx_q - 3'd2) +: 8];
    end else begin
      tx_byte = crc_q;
    end
    tx_last = tx_idx_q == (has_data_q ? 3'd6 : 3'd2);
  end

  always_comb begin
    state_d    = state_q;
    is_write_d = is_write_q;
    addr_d     = addr_q;
    data_d     = data_q;
    dcnt_d     = dcnt_q;
    crc_d      = crc_q;
    idle_d     = idle_q;
    aw_done_d  = aw_done_q;
    w_done_d   = w_done_q;
    a_pend_d   = a_pend_q;
    status_d   = status_q;
    has_data_d = has_data_q;
    tx_idx_d   = tx_idx_q;
    crc_err_d  = 1'b0;

    // inter-byte timeout inside a request frame
    if (state_q == SCmd || state_q == SAddr || state_q == SData || state_q == SCrc) begin
      if (rx_valid_i) begin
        idle_d = '0;
      end else if (idle_q == ToW'(TimeoutClks)) begin
        state_d = SSync;
      end else begin
        idle_d = idle_q + ToW'(1);
      end
      if (rx_frame_err_i) state_d = SSync;
    end

    unique case (state_q)
      SSync: begin
        if (rx_valid_i && rx_data_i == ReqSync) begin
          state_d = SCmd;
          crc_d   = 8'h00;
          idle_d  = '0;
        end
      end
      SCmd: begin
        if (rx_valid_i) begin
          crc_d = crc8(crc_q, rx_data_i);
          if (rx_data_i == CmdWrite || rx_data_i == CmdRead) begin
            is_write_d = rx_data_i == CmdWrite;
            dcnt_d     = 2'd0;
            state_d    = SAddr;
          end else begin
            // unknown command: answer, then hunt for the next sync
            status_d   = StBadCmd;
            has_data_d = 1'b0;
            crc_d      = 8'h00;
            tx_idx_d   = 3'd0;
            state_d    = STx;
          end
        end
      end
      SAddr: begin
        if (rx_valid_i) begin
          crc_d   = crc8(crc_q, rx_data_i);
          // low byte first: each byte enters at the top
          addr_d  = WordW'({rx_data_i, addr_q} >> 8);
          dcnt_d  = dcnt_q + 2'd1;
          data_d  = '0;
          if (dcnt_q == 2'(AddrBytes - 1)) begin
            dcnt_d = 2'd0;
            if (is_write_q) state_d = SData;
            else            state_d = SCrc;
          end
        end
      end
      SData: begin
        if (rx_valid_i) begin
          crc_d  = crc8(crc_q, rx_data_i);
          data_d = {rx_data_i, data_q[31:8]};
          dcnt_d = dcnt_q + 2'd1;
          if (dcnt_q == 2'd3) state_d = SCrc;
        end
      end
      SCrc: begin
        if (rx_valid_i) begin
          tx_idx_d = 3'd0;
          if (rx_data_i != crc_q) begin
            status_d   = StCrcErr;
            has_data_d = 1'b0;
            crc_err_d  = 1'b1;
            state_d    = STx;
          end else if (!addr_ok) begin
            status_d   = 8'(RespDecErr);  // no such word: nothing reaches the bus
            data_d     = '0;
            has_data_d = !is_write_q;
            state_d    = STx;
          end else begin
            aw_done_d = 1'b0;
            w_done_d  = 1'b0;
            a_pend_d  = 1'b1;
            if (is_write_q) state_d = SWrite;
            else            state_d = SRead;
          end
          crc_d = 8'h00;
        end
      end
      SWrite: begin
        if (m_axi_awvalid_o && m_axi_awready_i) aw_done_d = 1'b1;
        if (m_axi_wvalid_o && m_axi_wready_i)   w_done_d  = 1'b1;
        if (m_axi_bvalid_i) begin
          status_d   = 8'(m_axi_bresp_i);
          has_data_d = 1'b0;
          a_pend_d   = 1'b0;
          state_d    = STx;
        end
      end
      SRead: begin
        if (m_axi_arvalid_o && m_axi_arready_i) a_pend_d = 1'b0;
        if (m_axi_rvalid_i) begin
          status_d   = 8'(m_axi_rresp_i);
          data_d     = m_axi_rdata_i;
          has_data_d = 1'b1;
          state_d    = STx;
        end
      end
      STx: begin
        if (tx_ready_i) begin
          tx_idx_d = tx_idx_q + 3'd1;
          if (tx_idx_q != 3'd0 && !tx_last) crc_d = crc8(crc_q, tx_byte);
          if (tx_last) state_d = SSync;
        end
      end
      default: state_d = SSync;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q    <= SSync;
      is_write_q <= 1'b0;
      addr_q     <= '0;
      data_q     <= '0;
      dcnt_q     <= '0;
      crc_q      <= '0;
      idle_q     <= '0;
      aw_done_q  <= 1'b0;
      w_done_q   <= 1'b0;
      a_pend_q   <= 1'b0;
      status_q   <= '0;
      has_data_q <= 1'b0;
      tx_idx_q   <= '0;
      crc_err_q  <= 1'b0;
    end else begin
      state_q    <= state_d;
      is_write_q <= is_write_d;
      addr_q     <= addr_d;
      data_q     <= data_d;
      dcnt_q     <= dcnt_d;
      crc_q      <= crc_d;
      idle_q     <= idle_d;
      aw_done_q  <= aw_done_d;
      w_done_q   <= w_done_d;
      a_pend_q   <= a_pend_d;
      status_q   <= status_d;
      has_data_q <= has_data_d;
      tx_idx_q   <= tx_idx_d;
      crc_err_q  <= crc_err_d;
    end
  end

  // word address -> byte address: always aligned, no alias inside the window
  assign addr_ok        = (WordW'(addr_q) >> (AW - 2)) == '0;
  assign m_axi_awaddr_o  = AW'({addr_q, 2'b00});
  assign m_axi_awvalid_o = state_q == SWrite && !aw_done_q;
  assign m_axi_wdata_o   = data_q;
  assign m_axi_wstrb_o   = 4'hF;
  assign m_axi_wvalid_o  = state_q == SWrite && !w_done_q;
  assign m_axi_bready_o  = state_q == SWrite;
  assign m_axi_araddr_o  = AW'({addr_q, 2'b00});
  assign m_axi_arvalid_o = state_q == SRead && a_pend_q;
  assign m_axi_rready_o  = state_q == SRead;

  assign tx_valid_o = state_q == STx;
  assign tx_data_o  = tx_byte;
  assign crc_err_o  = crc_err_q;

`ifdef SC_COVER
  // Cover points (the coverage build, scripts/coverage.py): every transition
  // of the frame FSM and every answer status.
  logic cov_on, cov_in_frame;
  assign cov_on       = rst_ni;
  assign cov_in_frame = state_q == SCmd || state_q == SAddr || state_q == SData || state_q == SCrc;
  c_sync:        cover property (@(posedge clk_i) cov_on && state_q == SSync && state_d == SCmd);
  c_cmd_ok:      cover property (@(posedge clk_i) cov_on && state_q == SCmd && state_d == SAddr);
  c_cmd_bad:     cover property (@(posedge clk_i) cov_on && state_q == SCmd && state_d == STx);
  c_addr_write:  cover property (@(posedge clk_i) cov_on && state_q == SAddr && state_d == SData);
  c_addr_read:   cover property (@(posedge clk_i) cov_on && state_q == SAddr && state_d == SCrc);
  c_data_done:   cover property (@(posedge clk_i) cov_on && state_q == SData && state_d == SCrc);
  c_crc_bad:     cover property (@(posedge clk_i) cov_on && state_q == SCrc && state_d == STx);
  c_crc_write:   cover property (@(posedge clk_i) cov_on && state_q == SCrc && state_d == SWrite);
  c_crc_read:    cover property (@(posedge clk_i) cov_on && state_q == SCrc && state_d == SRead);
  c_write_done:  cover property (@(posedge clk_i) cov_on && state_q == SWrite && state_d == STx);
  c_read_done:   cover property (@(posedge clk_i) cov_on && state_q == SRead && state_d == STx);
  c_tx_done:     cover property (@(posedge clk_i) cov_on && state_q == STx && state_d == SSync);
  c_timeout:     cover property (@(posedge clk_i) cov_on && cov_in_frame && !rx_valid_i && !rx_frame_err_i &&
                                 idle_q == ToW'(TimeoutClks));
  c_frame_err:   cover property (@(posedge clk_i) cov_on && cov_in_frame && rx_frame_err_i);
  c_resp_slverr: cover property (@(posedge clk_i) cov_on && state_d == STx && state_q != STx && status_d == 8'd2);
  c_resp_decerr: cover property (@(posedge clk_i) cov_on && state_d == STx && state_q != STx && status_d == 8'd3);
`endif

`ifdef FORMAL
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // Input contract: reset in the first clock only; sc_uart_rx never raises
  // rx_valid_i and rx_frame_err_i in the same clock. The bytes, their timing
  // and the whole AXI slave side are free.
  // The shadow keeps the last 8 received bytes (newest in [7:0]) and how many
  // of them form one clean run: no framing error between them and no gap of
  // more than TimeoutClks + 1 clocks from one to the next.
  localparam int FGapW = ToW + 1;

  logic             f_init_q = 1'b1;  // the first clock of every trace
  logic [63:0]      f_bytes_q;
  logic [3:0]       f_run_q;          // clean bytes in a row (saturating at 8)
  logic             f_err_q;          // a framing error since the last byte
  logic [FGapW-1:0] f_gap_q;          // clocks since the last byte (saturating)
  logic             f_awvalid_prev_q, f_arvalid_prev_q;
  logic [7:0]       f_b [8];          // f_b[i]: the i-th newest byte
  // f_crc_win_q[j-1]: CRC-8 of the j newest bytes (j = 1..6), kept up to date
  // byte by byte: the CRC of a window is crc8 of the CRC of the window one byte
  // shorter and the new byte. f_crc6_q / f_crc2_q: the CRC of the 6 / 2 bytes
  // before the newest one (what a write / read frame's last byte must be).
  logic [6*8-1:0]   f_crc_win_q;
  logic [7:0]       f_crc6_q, f_crc2_q;

  // CRC-8 (0x07), the textbook bit-serial form (one message bit at a time into
  // the top), written apart from crc8 above
  function automatic logic [7:0] f_crc8(input logic [7:0] crc, input logic [7:0] d);
    logic [7:0] c;
    c = crc;
    for (int i = 7; i >= 0; i--) begin
      c = {c[6:0], 1'b0} ^ (8'h07 & {8{c[7] ^ d[i]}});
    end
    f_crc8 = c;
  endfunction

  (* anyseq *) logic [7:0] f_any_crc, f_any_byte;  // free values for p_crc8_ref

  always_comb begin
    for (int i = 0; i < 8; i++) f_b[i] = f_bytes_q[8*i +: 8];
  end

  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
    end
    a_rx_excl: assume (!(rx_valid_i && rx_frame_err_i));
  end

  always_ff @(posedge clk_i) begin
    f_init_q <= 1'b0;
    if (!rst_ni) begin
      f_bytes_q        <= '0;
      f_run_q          <= '0;
      f_err_q          <= 1'b0;
      f_gap_q          <= '1;
      f_awvalid_prev_q <= 1'b0;
      f_arvalid_prev_q <= 1'b0;
      f_crc_win_q      <= '0;
      f_crc6_q         <= '0;
      f_crc2_q         <= '0;
    end else begin
      f_awvalid_prev_q <= m_axi_awvalid_o;
      f_arvalid_prev_q <= m_axi_arvalid_o;
      if (rx_valid_i) begin
        f_bytes_q <= {f_bytes_q[55:0], rx_data_i};
        f_crc_win_q[7:0] <= crc8(8'h00, rx_data_i);
        for (int j = 1; j < 6; j++) begin
          f_crc_win_q[8*j +: 8] <= crc8(f_crc_win_q[8*(j-1) +: 8], rx_data_i);
        end
        f_crc6_q  <= f_crc_win_q[8*5 +: 8];
        f_crc2_q  <= f_crc_win_q[8*1 +: 8];
        f_run_q   <= (f_err_q || f_gap_q > FGapW'(TimeoutClks + 1)) ? 4'd1 :
                     (f_run_q == 4'd8 ? 4'd8 : f_run_q + 4'd1);
        f_err_q   <= 1'b0;
        f_gap_q   <= FGapW'(1);
      end else begin
        if (rx_frame_err_i) f_err_q <= 1'b1;
        if (f_gap_q != '1) f_gap_q <= f_gap_q + FGapW'(1);
      end
    end
  end

  logic f_in_frame;
  assign f_in_frame = state_q == SCmd || state_q == SAddr || state_q == SData || state_q == SCrc;

  always_comb begin
    if (!f_init_q) begin
      // -- group frames: a register write (AWVALID rising) only right after 8
      // clean bytes that are a write frame (A5 01 addr d0..d3 crc), with its
      // address and data; a read (ARVALID rising) after a read frame (A5 02 addr crc)
      p_write_frame: assert (!(m_axi_awvalid_o && !f_awvalid_prev_q) ||
                             (f_run_q == 4'd8 && f_b[7] == ReqSync && f_b[6] == CmdWrite &&
                              m_axi_awaddr_o == AW'({f_b[5], 2'b00}) &&
                              m_axi_wdata_o == {f_b[1], f_b[2], f_b[3], f_b[4]} &&
                              m_axi_wvalid_o && m_axi_wstrb_o == 4'hF));
      p_read_frame: assert (!(m_axi_arvalid_o && !f_arvalid_prev_q) ||
                            (f_run_q >= 4'd4 && f_b[3] == ReqSync && f_b[2] == CmdRead &&
                             m_axi_araddr_o == AW'({f_b[1], 2'b00})));
      p_axi_in_state: assert (!(m_axi_awvalid_o || m_axi_wvalid_o) || state_q == SWrite);
      // -- group crc: ... and only when its last byte is the CRC-8 of the bytes
      // after A5 (the running CRC of the parser tracks the shadow windows)
      p_write_crc: assert (!(m_axi_awvalid_o && !f_awvalid_prev_q) || f_b[0] == f_crc6_q);
      p_read_crc: assert (!(m_axi_arvalid_o && !f_arvalid_prev_q) || f_b[0] == f_crc2_q);
      inv_crc_cmd: assert (state_q != SCmd || crc_q == 8'h00);
      inv_crc_addr: assert (state_q != SAddr || crc_q == f_crc_win_q[7:0]);
      inv_crc_data: assert (state_q != SData || crc_q == f_crc_win_q[8*(3'd1 + 3'(dcnt_q)) +: 8]);
      inv_crc_end: assert (state_q != SCrc || crc_q == (is_write_q ? f_crc_win_q[8*5 +: 8]
                                                                   : f_crc_win_q[8*1 +: 8]));
      // -- helper invariants: the parser state against the shadow bytes
      inv_run: assert (f_run_q <= 4'd8);
      inv_frame_clean: assert (!f_in_frame || (!f_err_q && f_gap_q <= FGapW'(TimeoutClks + 1) &&
                                               idle_q <= ToW'(TimeoutClks) &&
                                               FGapW'(idle_q) + FGapW'(1) == f_gap_q));
      inv_state: assert (state_q <= STx && (state_q != SWrite || is_write_q) &&
                         (state_q != SRead || !is_write_q));
      inv_cmd: assert (state_q != SCmd || (f_run_q >= 4'd1 && f_b[0] == ReqSync));
      // (the properties describe the one-byte word address of the 1 KiB map)
      inv_addr_cnt: assert (state_q != SAddr || dcnt_q == 2'd0);
      inv_addr: assert (state_q != SAddr ||
                        (f_run_q >= 4'd2 && f_b[1] == ReqSync && is_write_q == (f_b[0] == CmdWrite) &&
                         (f_b[0] == CmdWrite || f_b[0] == CmdRead)));
      inv_data: assert (state_q != SData ||
                        (is_write_q && f_run_q >= 4'd3 + 4'(dcnt_q) &&
                         f_b[4'd2 + 4'(dcnt_q)] == ReqSync && f_b[4'd1 + 4'(dcnt_q)] == CmdWrite &&
                         addr_q == f_b[dcnt_q] &&
                         (dcnt_q != 2'd0 || data_q == '0) &&
                         (dcnt_q != 2'd1 || data_q == {f_b[0], 24'h0}) &&
                         (dcnt_q != 2'd2 || data_q == {f_b[0], f_b[1], 16'h0}) &&
                         (dcnt_q != 2'd3 || data_q == {f_b[0], f_b[1], f_b[2], 8'h0})));
      inv_at_crc: assert (state_q != SCrc ||
                          (is_write_q ? (f_run_q >= 4'd7 && f_b[6] == ReqSync && f_b[5] == CmdWrite &&
                                         addr_q == f_b[4] && data_q == {f_b[0], f_b[1], f_b[2], f_b[3]})
                                      : (f_run_q >= 4'd3 && f_b[2] == ReqSync && f_b[1] == CmdRead &&
                                         addr_q == f_b[0])));
      // -- group crc8: the CRC function the frame check uses is the protocol's
      // CRC-8 (polynomial 0x07, MSB first, see the header), for every input
      p_crc8_ref: assert (crc8(f_any_crc, f_any_byte) == f_crc8(f_any_crc, f_any_byte));
    end
  end
`endif

endmodule
