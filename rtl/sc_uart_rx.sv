// sc_uart_rx: 8N1 UART receiver. rx_i must already be synchronised
// (sc_sync, idle high). A falling edge starts a byte; the start bit is
// checked at its middle (a glitch shorter than half a bit is ignored), then
// each data bit (LSB first) and the stop bit are sampled at their middles.
// valid_o pulses one clock with data_o after a good stop bit; a low stop
// bit pulses frame_err_o instead (the byte is dropped).
module sc_uart_rx #(
  parameter int ClksPerBit = 174
) (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic       rx_i,
  output logic       valid_o,
  output logic [7:0] data_o,
  output logic       frame_err_o
);

  localparam int CntW = $clog2(ClksPerBit + 1);
  localparam logic [CntW-1:0] FullBit = CntW'(ClksPerBit - 1);
  localparam logic [CntW-1:0] HalfBit = CntW'((ClksPerBit - 1) / 2);

  typedef enum logic [1:0] {
    StIdle  = 2'd0,
    StStart = 2'd1,
    StData  = 2'd2,
    StStop  = 2'd3
  } state_e;

  state_e          state_q, state_d;
  logic [CntW-1:0] cnt_q, cnt_d;
  logic [2:0]      bit_q, bit_d;
  logic [7:0]      shift_q, shift_d;
  logic            valid_q, valid_d;
  logic            ferr_q, ferr_d;

  always_comb begin
    state_d = state_q;
    cnt_d   = cnt_q;
    bit_d   = bit_q;
    shift_d = shift_q;
    valid_d = 1'b0;
    ferr_d  = 1'b0;
    unique case (state_q)
      StIdle: begin
        if (!rx_i) begin
          state_d = StStart;
          cnt_d   = HalfBit;
        end
      end
      StStart: begin
        if (cnt_q != '0) begin
          cnt_d = cnt_q - CntW'(1);
        end else if (rx_i) begin
          state_d = StIdle;             // glitch, not a start bit
        end else begin
          state_d = StData;
          cnt_d   = FullBit;
          bit_d   = 3'd0;
        end
      end
      StData: begin
        if (cnt_q != '0) begin
          cnt_d = cnt_q - CntW'(1);
        end else begin
          shift_d = {rx_i, shift_q[7:1]};
          cnt_d   = FullBit;
          bit_d   = bit_q + 3'd1;
          if (bit_q == 3'd7) state_d = StStop;
        end
      end
      StStop: begin
        if (cnt_q != '0) begin
          cnt_d = cnt_q - CntW'(1);
        end else begin
          state_d = StIdle;
          valid_d = rx_i;
          ferr_d  = !rx_i;
        end
      end
      default: state_d = StIdle;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      cnt_q   <= '0;
      bit_q   <= '0;
      shift_q <= '0;
      valid_q <= 1'b0;
      ferr_q  <= 1'b0;
    end else begin
      state_q <= state_d;
      cnt_q   <= cnt_d;
      bit_q   <= bit_d;
      shift_q <= shift_d;
      valid_q <= valid_d;
      ferr_q  <= ferr_d;
    end
  end

  assign valid_o     = valid_q;
  assign data_o      = shift_q;
  assign frame_err_o = ferr_q;

`ifdef SC_COVER
  // Cover points (the coverage build, scripts/coverage.py): every transition.
  logic cov_on;
  assign cov_on = rst_ni;
  c_start_bit:  cover property (@(posedge clk_i) cov_on && state_q == StIdle && state_d == StStart);
  c_glitch:     cover property (@(posedge clk_i) cov_on && state_q == StStart && state_d == StIdle);
  c_data:       cover property (@(posedge clk_i) cov_on && state_q == StStart && state_d == StData);
  c_stop_bit:   cover property (@(posedge clk_i) cov_on && state_q == StData && state_d == StStop);
  c_byte:       cover property (@(posedge clk_i) cov_on && state_q == StStop && state_d == StIdle && valid_d);
  c_frame_err:  cover property (@(posedge clk_i) cov_on && state_q == StStop && state_d == StIdle && ferr_d);
`endif

endmodule
