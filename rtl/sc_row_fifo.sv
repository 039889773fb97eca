// sc_row_fifo: first-in first-out queue in distributed (LUT) RAM with an
// asynchronous read of the head, for the executor's row stream.
//
// A push while full and a pop while empty are ignored (the caller reports
// them); push and pop in the same clock both act. flush_i empties the queue
// and wins over a push in the same clock. Depth is a power of two.
// replace_i (instead of push_i) keeps the first keep_i entries (counted from
// the head before this clock's pop), drops the rest and writes wdata_i
// behind them: the caller checks pop_i <= keep_i <= level and that the
// result fits. peek_o reads the high PeekW bits of the entry peek_i places
// behind the head (a second read port on those bits only: their own array).
// at_o reads the whole entry at_i places behind the head (a third read
// port, for a checker working through the queue). The side array holds
// SideW bits per entry that the checker writes later: side_we_i writes
// side_wdata_i to the entry side_off_i places behind the head (before this
// clock's pop); side_head_o reads the head's. Checker = 0 builds neither
// (at_o and side_head_o read 0).
module sc_row_fifo #(
  parameter int Width  = 8,
  parameter int Depth  = 32,
  parameter int LevelW = 6,  // $clog2(Depth + 1)
  parameter int PeekW  = 1,  // 1 .. Width - 1
  parameter int SideW  = 1,
  parameter bit Checker = 1'b1
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              flush_i,
  input  logic              push_i,
  input  logic [Width-1:0]  wdata_i,
  input  logic              pop_i,
  input  logic              replace_i,
  input  logic [LevelW-1:0] keep_i,
  input  logic [$clog2(Depth)-1:0] peek_i,
  output logic [Width-1:0]  head_o,   // valid while !empty_o
  output logic [PeekW-1:0]  peek_o,
  input  logic [$clog2(Depth)-1:0] at_i,
  output logic [Width-1:0]  at_o,
  input  logic              side_we_i,
  input  logic [$clog2(Depth)-1:0] side_off_i,
  input  logic [SideW-1:0]  side_wdata_i,
  output logic [SideW-1:0]  side_head_o,
  output logic              empty_o,
  output logic              full_o,
  output logic [LevelW-1:0] level_o
);

  localparam int PtrW = $clog2(Depth);

  logic [Width-PeekW-1:0] mem_q [Depth];
  logic [PeekW-1:0]  peek_mem_q [Depth];
  logic [PtrW-1:0]   wr_q, wr_d, rd_q, rd_d;
  logic [LevelW-1:0] level_q, level_d;
  logic              do_push, do_pop, do_replace;
  logic [PtrW-1:0]   waddr;

  assign empty_o = level_q == '0;
  assign full_o  = level_q == LevelW'(Depth);
  assign do_push = push_i && !replace_i && !full_o && !flush_i;
  assign do_replace = replace_i && !flush_i;
  assign do_pop  = pop_i && !empty_o && !flush_i;
  assign head_o  = {peek_mem_q[rd_q], mem_q[rd_q]};
  assign peek_o  = peek_mem_q[rd_q + peek_i];
  assign waddr   = do_replace ? rd_q + PtrW'(keep_i) : wr_q;

  always_comb begin
    wr_d    = wr_q;
    rd_d    = rd_q;
    level_d = level_q;
    if (flush_i) begin
      rd_d    = wr_q;
      level_d = '0;
    end else begin
      if (do_push) wr_d = wr_q + PtrW'(1);
      if (do_pop)  rd_d = rd_q + PtrW'(1);
      if (do_push && !do_pop) level_d = level_q + LevelW'(1);
      if (do_pop && !do_push) level_d = level_q - LevelW'(1);
      if (do_replace) begin
        wr_d    = rd_q + PtrW'(keep_i) + PtrW'(1);
        level_d = keep_i + LevelW'(1) - LevelW'(do_pop);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (do_push || do_replace) begin
      mem_q[waddr]      <= wdata_i[Width-PeekW-1:0];
      peek_mem_q[waddr] <= wdata_i[Width-1 -: PeekW];
    end
  end

  if (Checker) begin : g_checker
    logic [SideW-1:0] side_mem_q [Depth];
    assign at_o        = {peek_mem_q[rd_q + at_i], mem_q[rd_q + at_i]};
    assign side_head_o = side_mem_q[rd_q];
    always_ff @(posedge clk_i) begin
      if (side_we_i) side_mem_q[rd_q + side_off_i] <= side_wdata_i;
    end
  end else begin : g_no_checker
    assign at_o        = '0;
    assign side_head_o = '0;
    logic unused_checker;
    assign unused_checker = ^{at_i, side_we_i, side_off_i, side_wdata_i};
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_q    <= '0;
      rd_q    <= '0;
      level_q <= '0;
    end else begin
      wr_q    <= wr_d;
      rd_q    <= rd_d;
      level_q <= level_d;
    end
  end

  assign level_o = level_q;

endmodule
