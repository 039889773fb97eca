// sc_profile_exec: executes the planner's segment table.
//
// Every clock while running:   pos += vel;  vel += acc;  acc += jerk
// in exact integer arithmetic (LSB = 2^-FracBits pulses / clock^k, see sc_pkg).
// A segment runs for seg.clocks clocks; on its last clock the position is
// still advanced, but vel/acc/jerk are reloaded from the next row instead of
// integrated, so each segment starts from the exact values the planner chose
// and nothing accumulates across segments. A carry (borrow) out of the
// position fraction is one step forward (backward): step_req_o, one clock.
module sc_profile_exec (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  // segment table, writable while not running
  input  logic                                seg_we_i,
  input  logic [sc_pkg::SegIdxW-1:0]          seg_waddr_i,
  input  logic [sc_pkg::PhaseW-1:0]           seg_phase_i,
  input  logic [sc_pkg::SegClkW-1:0]          seg_clocks_i,
  input  logic signed [sc_pkg::JerkW-1:0]     seg_jerk_i,
  input  logic signed [sc_pkg::AccW-1:0]      seg_acc0_i,
  input  logic signed [sc_pkg::VelW-1:0]      seg_vel0_i,
  input  logic [sc_pkg::SegCntW-1:0]          seg_count_i,
  input  logic [sc_pkg::FracBits-1:0]         pos_frac0_i,

  input  logic                       start_i,
  input  logic                       abort_i,

  output logic                       running_o,
  output logic                       finished_o,
  output logic                       fault_o,
  output logic                       step_req_o,
  output logic                       step_fwd_o,

  output logic signed [sc_pkg::PosIntW-1:0]   pos_int_o,
  output logic [sc_pkg::FracBits-1:0]         pos_frac_o,
  output logic signed [sc_pkg::VelW-1:0]      vel_o,
  output logic signed [sc_pkg::AccW-1:0]      acc_o,
  output logic signed [sc_pkg::JerkW-1:0]     jerk_o,
  output logic [sc_pkg::PhaseW-1:0]           phase_o,
  output logic [sc_pkg::SegIdxW-1:0]          seg_idx_o
);

  localparam int FracBits = sc_pkg::FracBits;
  localparam int PosIntW  = sc_pkg::PosIntW;
  localparam int VelW     = sc_pkg::VelW;
  localparam int AccW     = sc_pkg::AccW;
  localparam int JerkW    = sc_pkg::JerkW;
  localparam int SegClkW  = sc_pkg::SegClkW;
  localparam int SegIdxW  = sc_pkg::SegIdxW;
  localparam int SegCntW  = sc_pkg::SegCntW;
  localparam int PhaseW   = sc_pkg::PhaseW;
  localparam int MaxSegs  = sc_pkg::MaxSegs;

  // The segment table: one small RAM per field (LUTRAM on 7-series).
  logic [PhaseW-1:0]        mem_phase_q  [MaxSegs];
  logic [SegClkW-1:0]       mem_clocks_q [MaxSegs];
  logic signed [JerkW-1:0]  mem_jerk_q   [MaxSegs];
  logic signed [AccW-1:0]   mem_acc0_q   [MaxSegs];
  logic signed [VelW-1:0]   mem_vel0_q   [MaxSegs];

  logic                      run_q, run_d;
  logic                      finished_q, finished_d;
  logic                      fault_q, fault_d;
  logic [SegIdxW-1:0]        idx_q, idx_d;
  logic [SegCntW-1:0]        count_q, count_d;
  logic [SegClkW-1:0]        left_q, left_d;
  logic signed [JerkW-1:0]   jerk_q, jerk_d;
  logic signed [AccW-1:0]    acc_q, acc_d;
  logic signed [VelW-1:0]    vel_q, vel_d;
  logic [FracBits-1:0]       frac_q, frac_d;
  logic signed [PosIntW-1:0] pint_q, pint_d;
  logic [PhaseW-1:0]         phase_q, phase_d;
  logic                      step_req_q, step_req_d;
  logic                      step_fwd_q, step_fwd_d;

  // frac (unsigned) + vel (signed, |vel| < 1.0) needs two bits above the
  // fraction: bit FracBits+1 = result negative (borrow), bit FracBits = carry.
  logic signed [FracBits+1:0] pos_sum;
  logic                       load;
  logic [SegIdxW-1:0]         load_idx;
  logic [PhaseW-1:0]          ld_phase;
  logic [SegClkW-1:0]         ld_clocks;
  logic signed [JerkW-1:0]    ld_jerk;
  logic signed [AccW-1:0]     ld_acc0;
  logic signed [VelW-1:0]     ld_vel0;
  logic [SegCntW-1:0]         next_idx_ext;

  assign pos_sum      = $signed({2'b00, frac_q}) + (FracBits+2)'(vel_q);
  assign next_idx_ext = SegCntW'(idx_q) + SegCntW'(1);
  assign ld_phase     = mem_phase_q[load_idx];
  assign ld_clocks    = mem_clocks_q[load_idx];
  assign ld_jerk      = mem_jerk_q[load_idx];
  assign ld_acc0      = mem_acc0_q[load_idx];
  assign ld_vel0      = mem_vel0_q[load_idx];

  // Which table row (if any) is loaded this clock: the next row on the last
  // clock of a segment, row 0 on an accepted start.
  always_comb begin
    load     = 1'b0;
    load_idx = '0;
    if (run_q) begin
      if (!abort_i && left_q == SegClkW'(1) && next_idx_ext < count_q) begin
        load     = 1'b1;
        load_idx = idx_q + SegIdxW'(1);
      end
    end else if (start_i && seg_count_i != '0 && seg_count_i <= SegCntW'(MaxSegs)) begin
      load = 1'b1;
    end
  end

  always_comb begin
    run_d      = run_q;
    finished_d = finished_q;
    fault_d    = fault_q;
    idx_d      = idx_q;
    count_d    = count_q;
    left_d     = left_q;
    jerk_d     = jerk_q;
    acc_d      = acc_q;
    vel_d      = vel_q;
    frac_d     = frac_q;
    pint_d     = pint_q;
    phase_d    = phase_q;
    step_req_d = 1'b0;
    step_fwd_d = step_fwd_q;

    if (run_q) begin
      if (abort_i) begin
        run_d   = 1'b0;
        vel_d   = '0;
        acc_d   = '0;
        jerk_d  = '0;
        phase_d = sc_pkg::PhAbort;
      end else begin
        frac_d = pos_sum[FracBits-1:0];
        if (pos_sum[FracBits+1]) begin
          step_req_d = 1'b1;
          step_fwd_d = 1'b0;
          pint_d     = pint_q - PosIntW'(1);
        end else if (pos_sum[FracBits]) begin
          step_req_d = 1'b1;
          step_fwd_d = 1'b1;
          pint_d     = pint_q + PosIntW'(1);
        end
        if (left_q == SegClkW'(1)) begin
          if (!load) begin
            run_d      = 1'b0;
            finished_d = 1'b1;
            vel_d      = '0;
            acc_d      = '0;
            jerk_d     = '0;
          end
        end else begin
          left_d = left_q - SegClkW'(1);
          vel_d  = vel_q + VelW'(acc_q);
          acc_d  = acc_q + AccW'(jerk_q);
        end
      end
    end else if (start_i) begin
      finished_d = 1'b0;
      fault_d    = 1'b0;
      count_d    = seg_count_i;
      frac_d     = pos_frac0_i;
      if (!load) begin
        fault_d = 1'b1;
        phase_d = sc_pkg::PhFault;
      end
    end

    if (load) begin
      if (ld_clocks == '0) begin
        // A zero-length row is a malformed table: stop rather than guess.
        run_d   = 1'b0;
        fault_d = 1'b1;
        phase_d = sc_pkg::PhFault;
        vel_d   = '0;
        acc_d   = '0;
        jerk_d  = '0;
      end else begin
        run_d   = 1'b1;
        idx_d   = load_idx;
        left_d  = ld_clocks;
        jerk_d  = ld_jerk;
        acc_d   = ld_acc0;
        vel_d   = ld_vel0;
        phase_d = ld_phase;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (seg_we_i && !run_q) begin
      mem_phase_q[seg_waddr_i]  <= seg_phase_i;
      mem_clocks_q[seg_waddr_i] <= seg_clocks_i;
      mem_jerk_q[seg_waddr_i]   <= seg_jerk_i;
      mem_acc0_q[seg_waddr_i]   <= seg_acc0_i;
      mem_vel0_q[seg_waddr_i]   <= seg_vel0_i;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      run_q      <= 1'b0;
      finished_q <= 1'b0;
      fault_q    <= 1'b0;
      idx_q      <= '0;
      count_q    <= '0;
      left_q     <= '0;
      jerk_q     <= '0;
      acc_q      <= '0;
      vel_q      <= '0;
      frac_q     <= '0;
      pint_q     <= '0;
      phase_q    <= sc_pkg::PhIdle;
      step_req_q <= 1'b0;
      step_fwd_q <= 1'b1;
    end else begin
      run_q      <= run_d;
      finished_q <= finished_d;
      fault_q    <= fault_d;
      idx_q      <= idx_d;
      count_q    <= count_d;
      left_q     <= left_d;
      jerk_q     <= jerk_d;
      acc_q      <= acc_d;
      vel_q      <= vel_d;
      frac_q     <= frac_d;
      pint_q     <= pint_d;
      phase_q    <= phase_d;
      step_req_q <= step_req_d;
      step_fwd_q <= step_fwd_d;
    end
  end

  assign running_o  = run_q;
  assign finished_o = finished_q;
  assign fault_o    = fault_q;
  assign step_req_o = step_req_q;
  assign step_fwd_o = step_fwd_q;
  assign pos_int_o  = pint_q;
  assign pos_frac_o = frac_q;
  assign vel_o      = vel_q;
  assign acc_o      = acc_q;
  assign jerk_o     = jerk_q;
  assign phase_o    = phase_q;
  assign seg_idx_o  = idx_q;

endmodule
