// sc_switch_filter: switch inputs (limit, home, probe) through the common
// synchroniser, a polarity select and a debounce filter.
//
// Each bit is synchronised on its own (sc_sync), inverted where invert_i is
// set (active-low switches), and its filtered level takes a new value only
// after the synchronised input has held that value for debounce_i
// consecutive clocks after the first (debounce_i = 0: the clock after it
// arrives). A bounce shorter than that is ignored; a
// change is therefore seen debounce_i + 3 clocks after the pin (two of
// synchronisation, one of filtering). edge_o is high for the clock after
// level_o changed. Model: cmodel/switch_filter.h.
module sc_switch_filter #(
  parameter int Width = 3
) (
  input  logic                           clk_i,
  input  logic                           rst_ni,
  input  logic [Width-1:0]               sw_i,        // pins, asynchronous
  input  logic [Width-1:0]               invert_i,    // 1: the switch is active low
  input  logic [sc_pkg::DebounceW-1:0]   debounce_i,  // clocks a new level must hold
  output logic [Width-1:0]               level_o,     // filtered, 1 = active
  output logic [Width-1:0]               edge_o       // level_o changed a clock ago
);

  localparam int DebounceW = sc_pkg::DebounceW;

  logic [Width-1:0] sync_q;
  logic [Width-1:0] raw;

  // Switch inputs idle inactive (0 at the pin for an active-high switch).
  sc_sync #(.Width(Width), .ResetVal(1'b0)) u_sync (
    .clk_i,
    .rst_ni,
    .d_i (sw_i),
    .q_o (sync_q)
  );

  assign raw = sync_q ^ invert_i;

  for (genvar i = 0; i < Width; i++) begin : g_bit
    logic [DebounceW-1:0] cnt_q, cnt_d;
    logic                 level_q, level_d, edge_q;

    always_comb begin
      level_d = level_q;
      cnt_d   = '0;
      if (raw[i] != level_q) begin
        if (cnt_q >= debounce_i) begin
          level_d = raw[i];
        end else begin
          cnt_d = cnt_q + DebounceW'(1);
        end
      end
    end

    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        cnt_q   <= '0;
        level_q <= 1'b0;
        edge_q  <= 1'b0;
      end else begin
        cnt_q   <= cnt_d;
        level_q <= level_d;
        edge_q  <= level_d != level_q;
      end
    end

    assign level_o[i] = level_q;
    assign edge_o[i]  = edge_q;
  end

endmodule
