// sc_uart_tx: 8N1 UART transmitter. A byte is taken when valid_i && ready_o
// and sent LSB first between a start and a stop bit, ClksPerBit clocks each.
module sc_uart_tx #(
  parameter int ClksPerBit = 174
) (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic       valid_i,
  input  logic [7:0] data_i,
  output logic       ready_o,
  output logic       tx_o
);

  localparam int CntW = $clog2(ClksPerBit + 1);
  localparam logic [CntW-1:0] FullBit = CntW'(ClksPerBit - 1);

  logic            busy_q, busy_d;
  logic [CntW-1:0] cnt_q, cnt_d;
  logic [3:0]      bits_q, bits_d;      // bits still to send after this one
  logic [8:0]      shift_q, shift_d;    // {data, start}; bit 0 is on the line
  logic            tx_q, tx_d;

  always_comb begin
    busy_d  = busy_q;
    cnt_d   = cnt_q;
    bits_d  = bits_q;
    shift_d = shift_q;
    tx_d    = tx_q;
    if (!busy_q) begin
      tx_d = 1'b1;
      if (valid_i) begin
        busy_d  = 1'b1;
        shift_d = {data_i, 1'b0};
        tx_d    = 1'b0;
        cnt_d   = FullBit;
        bits_d  = 4'd9;
      end
    end else if (cnt_q != '0) begin
      cnt_d = cnt_q - CntW'(1);
    end else if (bits_q == 4'd0) begin
      busy_d = 1'b0;                     // stop bit done
      tx_d   = 1'b1;
    end else begin
      shift_d = {1'b1, shift_q[8:1]};    // next data bit, then the stop bit
      tx_d    = shift_q[1];
      cnt_d   = FullBit;
      bits_d  = bits_q - 4'd1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q  <= 1'b0;
      cnt_q   <= '0;
      bits_q  <= '0;
      shift_q <= '1;
      tx_q    <= 1'b1;
    end else begin
      busy_q  <= busy_d;
      cnt_q   <= cnt_d;
      bits_q  <= bits_d;
      shift_q <= shift_d;
      tx_q    <= tx_d;
    end
  end

  assign ready_o = !busy_q;
  assign tx_o    = tx_q;

endmodule
