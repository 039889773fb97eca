// sc_profile_exec: executes the planner's rows from a row stream.
//
// Every clock while running:   pos += vel;  vel += acc;  acc += jerk
// in exact integer arithmetic (LSB = 2^-FracBits pulses / clock^k, see sc_pkg).
// A row runs for row.clocks clocks; on its last clock the position is
// still advanced, but vel/acc/jerk are reloaded from the next row instead of
// integrated. A carry (borrow) out of the position fraction is one step
// forward (backward): step_req_o, one clock.
//
// Rows come from a FIFO (sc_row_fifo, RowFifoDepth deep) that the host
// appends to while the axis runs. START loads the head row as it is (a move
// may start at a stepper's start speed); every later row must continue the
// running row's end state exactly (vel0 = v + a and acc0 = a + j of the
// last clock, i.e. the state one more integration would give; a row flagged
// ACC_STEP, a trapezoid's planned acceleration step, only in velocity),
// else it is not executed: the continuity guard stops the axis and flags it. At the end
// of a row:
//   * row flagged STREAM_END: the stream ends (v, a, j to 0: the plan's end);
//   * else the head row is loaded if it continues exactly and is within
//     the guard limits;
//   * else, with the FIFO empty and the end state at rest (v = a = 0), the
//     stream ends;
//   * else (the FIFO ran dry while moving: underrun; the head row does not
//     continue: discontinuity; it is over a guard limit; or it has no
//     clocks): a controlled stop.
// Guards (guard_vel_i, guard_acc_i, guard_jerk_i; 0 = no limit): a head
// row whose |vel0|, |acc0| or |jerk| is over its limit is not loaded. At
// START nothing moves (the start is refused); at a boundary the axis stops
// under control as for a discontinuity. Either way guard_o is set (until
// START) and the FIFO is emptied: what the host queued behind a refused
// row is not run.
// Soft-limit look-ahead (soft_en_i): every queued row's reach (sc_row_reach:
// the furthest positions it moves to, forward and backward, exact to
// 2^-ReachFrac pulse and rounded outward) is evaluated in the background
// while the window is on, one row after the other from the head, and kept
// beside the row (by this executor's own evaluator, or with OwnReach = 0 by
// one outside that it shares with other executors through rc_*). A head
// row is loaded only when its reach is known and, from the position it
// starts at, stays inside [soft_min_i, soft_max_i] (or, beyond an edge, goes
// no further out than that position): otherwise the axis stops under
// control at that boundary and reach_o is set (until START), a START is
// refused (start_ready_o holds the core's arming until the head's reach
// is known).
// A row flagged MOVE_END closes a move: move_idx_o counts the moves done
// since START and boundary_pos_o holds the integer position at that
// boundary (after the step of its last clock).
// Velocity mode: a row flagged HOLD that ends at constant velocity
// (a = j = 0) does not end while no whole move is queued: its last clock
// repeats (pos += v) until a MOVE_END row is in the FIFO, or the FIFO is
// full, and then ends as any row. The host queues the next velocity change
// (ramp rows ending in a HOLD row, the last one MOVE_END) at any time, and
// it starts from the one state the hold has: v, a = 0. Waiting for the whole
// move means a slow host (the UART) cannot run the FIFO dry mid-ramp.
// Retarget: row_count_o counts the rows loaded since START (the index of
// the next row). A push with row_replace_i makes the pushed row number
// retarget_row_i: the queued rows from that number on are dropped and the
// row takes their place, in one clock. It is refused (retarget_refused_o,
// one clock; nothing changes) unless a stream runs on (no stop, not a
// STREAM_END row), that row is not loaded yet, also not in this clock, and
// it is at most one place behind the queued rows.
//
// Controlled stop (stop_i, underrun, discontinuity, malformed row): the
// clock that triggers it still integrates the running row (v + a, a + j),
// then sc_stop_gen chooses the jerk every clock (pos += v; v += a;
// a += jerk) until v = a = 0 with the stop limits stop_jerk_i and
// stop_acc_i: no velocity or acceleration step, position counts exact. A
// stop_i in the clock a stream ends as planned changes nothing. abort_i is
// the immediate stop (e-stop): v, a and j go to 0 at once. Every stop
// flushes the FIFO: rows planned from a state the axis never reached must
// not run after it.
module sc_profile_exec #(
  // 1: the executor has its own row reach evaluator; 0: it uses one outside
  // through rc_* (sc_multi_axis_core shares one among its axes)
  parameter bit OwnReach  = 1'b1,
  // 0: no soft-limit look-ahead (an area option: the window is then only
  // the register top's reactive limit; no reach is evaluated or stored)
  parameter bit Lookahead = 1'b1
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  // row stream (a push while the FIFO is full is ignored)
  input  logic                                row_push_i,
  input  logic                                row_replace_i,  // with row_push_i: replace from retarget_row_i on
  input  logic [sc_pkg::RowCountW-1:0]        retarget_row_i,
  input  logic [sc_pkg::RowFlagW-1:0]         row_flags_i,
  input  logic [sc_pkg::PhaseW-1:0]           row_phase_i,
  input  logic [sc_pkg::SegClkW-1:0]          row_clocks_i,
  input  logic signed [sc_pkg::JerkW-1:0]     row_jerk_i,
  input  logic signed [sc_pkg::AccW-1:0]      row_acc0_i,
  input  logic signed [sc_pkg::VelW-1:0]      row_vel0_i,
  input  logic                                fifo_flush_i,
  input  logic [sc_pkg::FracBits-1:0]         pos_frac0_i,

  input  logic                       start_i,
  input  logic                       abort_i,
  input  logic                       stop_i,        // controlled stop (ignored while idle)
  input  logic [sc_pkg::JerkW-1:0]            stop_jerk_i,   // stop limits (sc_stop_gen)
  input  logic [sc_pkg::AccW-1:0]             stop_acc_i,

  input  logic [sc_pkg::VelW-1:0]             guard_vel_i,   // row limits, magnitudes (0 = none)
  input  logic [sc_pkg::AccW-1:0]             guard_acc_i,
  input  logic [sc_pkg::JerkW-1:0]            guard_jerk_i,
  input  logic                                soft_en_i,     // soft-limit look-ahead
  input  logic signed [sc_pkg::PosIntW-1:0]   soft_min_i,    // lowest position inside
  input  logic signed [sc_pkg::PosIntW-1:0]   soft_max_i,    // highest position inside
  output logic                       running_o,
  output logic                       finished_o,
  output logic                       fault_o,       // START met an empty FIFO, or a zero-length row
  output logic                       underrun_o,    // the FIFO ran dry while moving (until START)
  output logic                       discont_o,     // a row did not continue the motion (until START)
  output logic                       guard_o,       // a row broke a guard limit (until START)
  output logic                       reach_o,       // the look-ahead refused a row (until START)
  output logic                       start_ready_o, // a START may load the head now (its reach is known)
  input  logic                       reach_veto_i,  // another executor refuses its head row: none loads it
  output logic                       reach_bad_o,   // the look-ahead refuses the head row this clock
  output logic                       stopping_o,    // a controlled stop runs
  output logic                       overshoot_o,   // the last stop could not avoid a reversal (until its next start)
  output logic                       move_done_o,   // a MOVE_END row ended (one clock, with its move_idx_o)
  output logic [sc_pkg::MoveIdxW-1:0]         move_idx_o,
  output logic signed [sc_pkg::PosIntW-1:0]   boundary_pos_o,
  output logic [sc_pkg::RowLevelW-1:0]        fifo_level_o,
  output logic [sc_pkg::RowCountW-1:0]        row_count_o,   // rows loaded since START
  output logic                       retarget_refused_o,  // a replace was refused (one clock)
  output logic                       fifo_full_o,   // no row is taken: full, or a controlled stop runs
  output logic                       head_fwd_o,    // direction of the head row
  output logic                       step_req_o,
  output logic                       step_fwd_o,

  output logic signed [sc_pkg::PosIntW-1:0]   pos_int_o,
  output logic [sc_pkg::FracBits-1:0]         pos_frac_o,
  output logic signed [sc_pkg::VelW-1:0]      vel_o,
  output logic signed [sc_pkg::AccW-1:0]      acc_o,
  output logic signed [sc_pkg::JerkW-1:0]     jerk_o,
  output logic [sc_pkg::PhaseW-1:0]           phase_o,
  output logic [sc_pkg::SegIdxW-1:0]          seg_idx_o,     // row of the current move (wraps)

  // the row reach evaluator outside (OwnReach = 0): this executor's request
  // (the row at rc_*: start when idle, abort its evaluation) and the
  // evaluator's state (busy with any executor's row, done with this one's)
  output logic                                rc_start_o,
  output logic                                rc_abort_o,
  output logic [sc_pkg::SegClkW-1:0]          rc_clocks_o,
  output logic signed [sc_pkg::JerkW-1:0]     rc_jerk_o,
  output logic signed [sc_pkg::AccW-1:0]      rc_acc0_o,
  output logic signed [sc_pkg::VelW-1:0]      rc_vel0_o,
  input  logic                                rc_busy_i,
  input  logic                                rc_done_i,
  input  logic signed [sc_pkg::ReachW-1:0]    rc_fwd_i,
  input  logic signed [sc_pkg::ReachW-1:0]    rc_rev_i
);

  localparam int FracBits  = sc_pkg::FracBits;
  localparam int PosIntW   = sc_pkg::PosIntW;
  localparam int VelW      = sc_pkg::VelW;
  localparam int AccW      = sc_pkg::AccW;
  localparam int JerkW     = sc_pkg::JerkW;
  localparam int SegClkW   = sc_pkg::SegClkW;
  localparam int SegIdxW   = sc_pkg::SegIdxW;
  localparam int PhaseW    = sc_pkg::PhaseW;
  localparam int RowFlagW  = sc_pkg::RowFlagW;
  localparam int RowLevelW = sc_pkg::RowLevelW;
  localparam int MoveIdxW  = sc_pkg::MoveIdxW;
  localparam int RowCountW = sc_pkg::RowCountW;
  // one FIFO word: {MOVE_END rows pushed up to this one, flags, phase, clocks, jerk, acc0, vel0}
  localparam int RowW      = RowLevelW + RowFlagW + PhaseW + SegClkW + JerkW + AccW + VelW;

  logic                      run_q, run_d;
  logic                      finished_q, finished_d;
  logic                      fault_q, fault_d;
  logic                      underrun_q, underrun_d;
  logic                      discont_q, discont_d;
  logic                      guard_q, guard_d;
  logic                      reach_q, reach_d;
  logic                      stop_q, stop_d;        // controlled stop running
  logic [SegIdxW-1:0]        idx_q, idx_d;
  logic [RowFlagW-1:0]       flags_q, flags_d;
  logic [SegClkW-1:0]        left_q, left_d;
  logic signed [JerkW-1:0]   jerk_q, jerk_d;
  logic signed [AccW-1:0]    acc_q, acc_d;
  logic signed [VelW-1:0]    vel_q, vel_d;
  logic [FracBits-1:0]       frac_q, frac_d;
  logic signed [PosIntW-1:0] pint_q, pint_d;
  logic [PhaseW-1:0]         phase_q, phase_d;
  logic                      step_req_q, step_req_d;
  logic                      step_fwd_q, step_fwd_d;
  logic [MoveIdxW-1:0]       move_idx_q, move_idx_d;
  logic signed [PosIntW-1:0] bpos_q, bpos_d;
  logic                      move_done, move_done_q;
  // MOVE_END rows pushed and popped since the last flush (mod 2^RowLevelW;
  // each FIFO word carries the pushed count up to itself, so a replace
  // knows the count of the rows it keeps): their difference is the number
  // of MOVE_END rows queued.
  logic [RowLevelW-1:0]      ends_in_q, ends_in_d, ends_out_q, ends_out_d;
  logic [RowLevelW-1:0]      moves_queued, hd_ends, pk_ends, w_ends, keep;
  logic                      hold;                  // a HOLD row waits for a whole move
  logic                      push_ok;
  logic [RowCountW-1:0]      rows_q, rows_d, rt_off;
  logic                      replace_req, replace_ok, refused_q;
  logic [$clog2(sc_pkg::RowFifoDepth)-1:0] peek_at;  // the last kept row

  // frac (unsigned) + vel (signed, |vel| < 1.0) needs two bits above the
  // fraction: bit FracBits+1 = result negative (borrow), bit FracBits = carry.
  logic signed [FracBits+1:0] pos_sum;
  logic                       boundary, load, pop, flush;
  logic                       row_bad, ends, stop_start;
  logic                       sg_active, sg_overshoot, unused_sg_done;
  logic signed [JerkW-1:0]    sg_jerk;
  logic signed [VelW-1:0]     vel_end;
  logic signed [AccW-1:0]     acc_end;
  logic                       continues, at_rest, over_guard;
  // soft-limit look-ahead
  localparam int ReachW = sc_pkg::ReachW;
  localparam int PtrW   = $clog2(sc_pkg::RowFifoDepth);
  logic [RowLevelW-1:0]       chk_q, chk_d, chk_inc, chk_keep;  // rows at the head with a known reach
  logic [RowW-1:0]            at_row;
  logic [RowLevelW-1:0]       unused_at_ends;
  logic [RowFlagW-1:0]        unused_at_flags;
  logic [PhaseW-1:0]          unused_at_phase;
  logic [SegClkW-1:0]         at_clocks;
  logic signed [JerkW-1:0]    at_jerk;
  logic signed [AccW-1:0]     at_acc0;
  logic signed [VelW-1:0]     at_vel0;
  logic                       rc_start, rc_abort, rc_busy, rc_done, rc_write;
  logic signed [ReachW-1:0]   rc_fwd, rc_rev, hd_fwd, hd_rev;
  logic                       hd_known, reach_bad, out_fwd, out_rev;
  logic signed [PosIntW-1:0]  p0_int, pint_next;
  logic [15:0]                p0_frac;
  localparam int SumW = ReachW + 1;                 // start (PosIntW.16) + reach
  localparam int IntW = SumW - sc_pkg::ReachFrac;   // its integer part
  logic signed [SumW-1:0]     fwd_sum, rev_sum;
  logic signed [IntW-1:0]     fwd_int, rev_int;
  logic [2*sc_pkg::ReachFrac-1:0] unused_sum_frac;
  logic [VelW-1:0]            hd_vel_x;
  logic [AccW-1:0]            hd_acc_x;
  logic [JerkW-1:0]           hd_jerk_x;
  logic                       over_vel, over_acc, over_jerk;

  logic [RowW-1:0]            head;
  logic [RowW-1:0]            wdata;
  logic                       fifo_empty, fifo_full;
  logic [RowFlagW-1:0]        hd_flags;
  logic [PhaseW-1:0]          hd_phase;
  logic [SegClkW-1:0]         hd_clocks;
  logic signed [JerkW-1:0]    hd_jerk;
  logic signed [AccW-1:0]     hd_acc0;
  logic signed [VelW-1:0]     hd_vel0;

  sc_row_fifo #(
    .Width  (RowW),
    .Depth  (sc_pkg::RowFifoDepth),
    .LevelW (RowLevelW),
    .PeekW  (RowLevelW),
    .SideW  (2 * ReachW),
    .Checker (Lookahead)
  ) u_fifo (
    .clk_i,
    .rst_ni,
    .flush_i   (flush),
    .push_i    (row_push_i && !row_replace_i),
    .wdata_i   (wdata),
    .pop_i     (pop),
    .replace_i (replace_ok),
    .keep_i    (keep),
    .peek_i    (peek_at),
    .head_o    (head),
    .peek_o    (pk_ends),
    .at_i      (chk_q[PtrW-1:0]),
    .at_o      (at_row),
    .side_we_i (rc_write),
    .side_off_i (chk_q[PtrW-1:0]),
    .side_wdata_i ({rc_fwd, rc_rev}),
    .side_head_o ({hd_fwd, hd_rev}),
    .empty_o   (fifo_empty),
    .full_o    (fifo_full),
    .level_o   (fifo_level_o)
  );

  assign {hd_ends, hd_flags, hd_phase, hd_clocks, hd_jerk, hd_acc0, hd_vel0} = head;
  assign {unused_at_ends, unused_at_flags, unused_at_phase, at_clocks, at_jerk, at_acc0, at_vel0} = at_row;
  assign wdata = {w_ends, row_flags_i, row_phase_i, row_clocks_i, row_jerk_i, row_acc0_i, row_vel0_i};

  assign pos_sum  = $signed({2'b00, frac_q}) + (FracBits+2)'(vel_q);
  // The state one more integration would give: where the next row must start.
  assign vel_end  = vel_q + VelW'(acc_q);
  assign acc_end  = acc_q + AccW'(jerk_q);
  assign continues = hd_vel0 == vel_end && (hd_acc0 == acc_end || hd_flags[sc_pkg::RowFlagAccStep]);
  assign at_rest   = vel_end == '0 && acc_end == '0;
  // |x| > L without a negation: for x < 0, |x| = ~x + 1, so |x| > L is
  // ~x >= L; x ^ {sign} is x or ~x (a comparator, no adder).
  assign hd_vel_x  = hd_vel0 ^ {VelW{hd_vel0[VelW-1]}};
  assign hd_acc_x  = hd_acc0 ^ {AccW{hd_acc0[AccW-1]}};
  assign hd_jerk_x = hd_jerk ^ {JerkW{hd_jerk[JerkW-1]}};
  assign over_vel  = hd_vel_x > guard_vel_i || (hd_vel0[VelW-1] && hd_vel_x == guard_vel_i);
  assign over_acc  = hd_acc_x > guard_acc_i || (hd_acc0[AccW-1] && hd_acc_x == guard_acc_i);
  assign over_jerk = hd_jerk_x > guard_jerk_i || (hd_jerk[JerkW-1] && hd_jerk_x == guard_jerk_i);
  assign over_guard = (guard_vel_i != '0 && over_vel) || (guard_acc_i != '0 && over_acc) ||
                      (guard_jerk_i != '0 && over_jerk);
  assign hold      = run_q && !stop_q && !abort_i && left_q == SegClkW'(1) &&
                     flags_q[sc_pkg::RowFlagHold] && acc_q == '0 && jerk_q == '0 &&
                     moves_queued == '0 && !fifo_full;
  assign boundary  = run_q && !stop_q && !abort_i && left_q == SegClkW'(1) && !hold;
  assign move_done = boundary && flags_q[sc_pkg::RowFlagMoveEnd];
  // The stream ends as planned at this boundary (no row follows).
  assign ends      = flags_q[sc_pkg::RowFlagStreamEnd] || (fifo_empty && at_rest);
  assign row_bad   = load && hd_clocks == '0;
  assign stop_start = run_q && !stop_q && !abort_i &&
                      ((stop_i && !(boundary && !load && ends)) ||
                       (boundary && ((!load && !ends) || row_bad)));

  // The head row is loaded at the end of a row that does not end the
  // stream, when it continues exactly, and on an accepted START; never
  // over a guard limit.
  always_comb begin
    load = 1'b0;
    if (boundary) begin
      load = !flags_q[sc_pkg::RowFlagStreamEnd] && !fifo_empty && continues && !over_guard && !reach_bad &&
             !reach_veto_i;
    end else if (!run_q) begin
      load = start_i && !fifo_empty && !over_guard && !reach_bad && !reach_veto_i;
    end
  end
  assign pop = load;

  always_comb begin
    run_d      = run_q;
    finished_d = finished_q;
    fault_d    = fault_q;
    underrun_d = underrun_q;
    discont_d  = discont_q;
    guard_d    = guard_q;
    reach_d    = reach_q;
    stop_d     = stop_q;
    idx_d      = idx_q;
    flags_d    = flags_q;
    left_d     = left_q;
    jerk_d     = jerk_q;
    acc_d      = acc_q;
    vel_d      = vel_q;
    frac_d     = frac_q;
    pint_d     = pint_q;
    phase_d    = phase_q;
    step_req_d = 1'b0;
    step_fwd_d = step_fwd_q;
    move_idx_d = move_idx_q;
    bpos_d     = bpos_q;
    flush      = 1'b0;

    if (run_q) begin
      if (abort_i) begin
        run_d   = 1'b0;
        stop_d  = 1'b0;
        vel_d   = '0;
        acc_d   = '0;
        jerk_d  = '0;
        phase_d = sc_pkg::PhAbort;
        flush   = 1'b1;
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
        if (stop_q) begin
          if (sg_active) begin
            vel_d = vel_end;
            acc_d = acc_q + AccW'(sg_jerk);
          end else begin
            // v = a = 0: the stop is over
            run_d  = 1'b0;
            stop_d = 1'b0;
          end
        end else if (hold) begin
          // v constant, a = j = 0: the row's last clock repeats
          left_d = left_q;
          vel_d  = vel_end;
          acc_d  = acc_end;
        end else if (left_q == SegClkW'(1)) begin
          if (move_done) begin
            move_idx_d = move_idx_q + MoveIdxW'(1);
            bpos_d     = pint_d;
          end
          if (!load && ends) begin
            run_d      = 1'b0;
            vel_d      = '0;
            acc_d      = '0;
            jerk_d     = '0;
            finished_d = 1'b1;
          end else if (!load) begin
            // No row, one that does not continue the motion, one over a
            // guard limit or one out of the soft limits: the rest of the
            // stream is not run.
            underrun_d = fifo_empty;
            discont_d  = !fifo_empty && !continues;
            guard_d    = !fifo_empty && continues && over_guard;
            reach_d    = !fifo_empty && continues && !over_guard && reach_bad;
          end
        end else begin
          left_d = left_q - SegClkW'(1);
          vel_d  = vel_end;  // the same adders feed the continuity guard
          acc_d  = acc_end;
        end
      end
    end else if (start_i) begin
      finished_d = 1'b0;
      fault_d    = 1'b0;
      underrun_d = 1'b0;
      discont_d  = 1'b0;
      guard_d    = 1'b0;
      reach_d    = 1'b0;
      frac_d     = pos_frac0_i;
      move_idx_d = '0;
      bpos_d     = pint_q;
      if (!load) begin
        // an empty FIFO is the table fault; a head row over a guard limit
        // or out of the soft limits is refused with everything queued
        // behind it
        fault_d = fifo_empty;
        guard_d = !fifo_empty && over_guard;
        reach_d = !fifo_empty && !over_guard && reach_bad;
        phase_d = sc_pkg::PhFault;
        flush   = !fifo_empty;
      end
    end

    if (stop_start) begin
      // The running row's integration, then the stop's jerk.
      stop_d  = 1'b1;
      vel_d   = vel_end;
      acc_d   = acc_end;
      jerk_d  = '0;
      phase_d = sc_pkg::PhStop;
      flush   = 1'b1;
      if (row_bad) fault_d = 1'b1;
    end else if (load) begin
      if (hd_clocks == '0) begin
        // A zero-length row is malformed: stop rather than guess.
        run_d   = 1'b0;
        fault_d = 1'b1;
        phase_d = sc_pkg::PhFault;
        vel_d   = '0;
        acc_d   = '0;
        jerk_d  = '0;
        flush   = 1'b1;
      end else begin
        run_d   = 1'b1;
        idx_d   = (!run_q || flags_q[sc_pkg::RowFlagMoveEnd]) ? '0 : idx_q + SegIdxW'(1);
        flags_d = hd_flags;
        left_d  = hd_clocks;
        jerk_d  = hd_jerk;
        acc_d   = hd_acc0;
        vel_d   = hd_vel0;
        phase_d = hd_phase;
      end
    end

    // Rows pushed while stopping were planned for motion that is not run.
    if (fifo_flush_i || stop_q) flush = 1'b1;
  end

  // Retarget: the offset of row retarget_row_i behind the head. Row k is
  // not loaded (k >= rows loaded, +1 when one loads now) and at most one
  // place behind the queued rows; the kept rows and it fit.
  assign rt_off      = retarget_row_i - rows_q;
  assign replace_req = row_push_i && row_replace_i;
  assign replace_ok  = replace_req && run_q && !stop_q && !abort_i && !flush &&
                       !flags_q[sc_pkg::RowFlagStreamEnd] &&
                       rt_off >= RowCountW'(pop) && rt_off <= RowCountW'(fifo_level_o) &&
                       rt_off - RowCountW'(pop) < RowCountW'(sc_pkg::RowFifoDepth);
  assign keep        = rt_off[RowLevelW-1:0];
  assign peek_at     = $bits(peek_at)'(keep - RowLevelW'(1));
  assign push_ok     = row_push_i && !row_replace_i && !fifo_full && !flush;
  // MOVE_END rows up to the written one: behind the kept rows for a replace.
  assign w_ends = (replace_req ? (keep == '0 ? ends_out_q : pk_ends) : ends_in_q) +
                  RowLevelW'(row_flags_i[sc_pkg::RowFlagMoveEnd]);
  assign moves_queued = ends_in_q - ends_out_q;
  always_comb begin
    ends_in_d  = ends_in_q;
    ends_out_d = ends_out_q;
    if (flush) begin
      ends_in_d  = '0;
      ends_out_d = '0;
    end else begin
      if (push_ok || replace_ok) ends_in_d = w_ends;
      if (pop)                   ends_out_d = hd_ends;
    end
  end

  always_comb begin
    rows_d = rows_q;
    if (!run_q && start_i) begin
      rows_d = RowCountW'(load);
    end else if (load) begin
      rows_d = rows_q + RowCountW'(1);
    end
  end

  // ---- soft-limit look-ahead ----------------------------------------------
  // The checker works on the first row without a known reach (chk_q rows
  // from the head have one). It drops a row that leaves the queue before
  // its result: popped, replaced, or flushed.
  assign chk_inc  = chk_q + RowLevelW'(rc_write);
  assign chk_keep = (replace_ok && keep < chk_inc) ? keep : chk_inc;
  assign rc_abort = flush || (pop && chk_q == '0) || (replace_ok && keep <= chk_q);
  // (only with the window on: without it nothing reads a reach)
  assign rc_start = Lookahead && soft_en_i && !rc_busy && chk_q < fifo_level_o && !rc_abort;
  assign rc_write = rc_done && !rc_abort;
  always_comb begin
    chk_d = chk_keep;
    if (flush)                          chk_d = '0;
    else if (pop && chk_keep != '0)     chk_d = chk_keep - RowLevelW'(1);
  end

  assign rc_start_o  = rc_start;
  assign rc_abort_o  = rc_abort;
  assign rc_clocks_o = at_clocks;
  assign rc_jerk_o   = at_jerk;
  assign rc_acc0_o   = at_acc0;
  assign rc_vel0_o   = at_vel0;

  if (OwnReach && Lookahead) begin : g_reach
    sc_row_reach u_reach (
      .clk_i,
      .rst_ni,
      .start_i     (rc_start),
      .abort_i     (rc_abort),
      .clocks_i    (at_clocks),
      .jerk_i      (at_jerk),
      .acc0_i      (at_acc0),
      .vel0_i      (at_vel0),
      .busy_o      (rc_busy),
      .done_o      (rc_done),
      .reach_fwd_o (rc_fwd),
      .reach_rev_o (rc_rev)
    );
    logic unused_rc;
    assign unused_rc = ^{rc_busy_i, rc_done_i, rc_fwd_i, rc_rev_i};
  end else begin : g_no_reach
    assign rc_busy = rc_busy_i;
    assign rc_done = rc_done_i;
    assign rc_fwd  = rc_fwd_i;
    assign rc_rev  = rc_rev_i;
  end

  // Where the head row would start: the position after this clock's
  // integration at a boundary, REF_POS with POS_FRAC0 at a START. The
  // window compare needs only the top ReachFrac fraction bits (the reach
  // is a multiple of 2^-ReachFrac, so the lower bits never carry into it).
  assign pint_next = pos_sum[FracBits+1] ? pint_q - PosIntW'(1) :
                     pos_sum[FracBits]   ? pint_q + PosIntW'(1) : pint_q;
  assign p0_int  = run_q ? pint_next : pint_q;
  assign p0_frac = run_q ? pos_sum[FracBits-1 -: 16] : pos_frac0_i[FracBits-1 -: 16];
  assign fwd_sum = SumW'($signed({p0_int, p0_frac})) + SumW'(hd_fwd);
  assign rev_sum = SumW'($signed({p0_int, p0_frac})) + SumW'(hd_rev);
  assign fwd_int = fwd_sum[SumW-1:sc_pkg::ReachFrac];
  assign rev_int = rev_sum[SumW-1:sc_pkg::ReachFrac];
  assign unused_sum_frac = {fwd_sum[sc_pkg::ReachFrac-1:0], rev_sum[sc_pkg::ReachFrac-1:0]};
  // Out: further than the edge and further out than the start (a row that
  // starts beyond an edge may move back in, or stay).
  assign out_fwd   = fwd_int > IntW'(soft_max_i) && fwd_int > IntW'(p0_int);
  assign out_rev   = rev_int < IntW'(soft_min_i) && rev_int < IntW'(p0_int);
  assign hd_known  = chk_q != '0;
  assign reach_bad = Lookahead && soft_en_i && (!hd_known || out_fwd || out_rev);
  assign start_ready_o = !Lookahead || !soft_en_i || fifo_empty || hd_known;
  assign reach_bad_o   = reach_bad;

  sc_stop_gen u_stop (
    .clk_i,
    .rst_ni,
    .start_i     (stop_start),
    .vel_i       (vel_end),
    .acc_i       (acc_end),
    .stop_jerk_i,
    .stop_acc_i,
    .active_o    (sg_active),
    .done_o      (unused_sg_done),
    .overshoot_o (sg_overshoot),
    .jerk_o      (sg_jerk)
  );

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      run_q      <= 1'b0;
      finished_q <= 1'b0;
      fault_q    <= 1'b0;
      underrun_q <= 1'b0;
      discont_q  <= 1'b0;
      guard_q    <= 1'b0;
      reach_q    <= 1'b0;
      chk_q      <= '0;
      stop_q     <= 1'b0;
      idx_q      <= '0;
      flags_q    <= '0;
      left_q     <= '0;
      jerk_q     <= '0;
      acc_q      <= '0;
      vel_q      <= '0;
      frac_q     <= '0;
      pint_q     <= '0;
      phase_q    <= sc_pkg::PhIdle;
      step_req_q <= 1'b0;
      step_fwd_q <= 1'b1;
      move_idx_q <= '0;
      bpos_q     <= '0;
      move_done_q <= 1'b0;
      ends_in_q  <= '0;
      ends_out_q <= '0;
      rows_q     <= '0;
      refused_q  <= 1'b0;
    end else begin
      run_q      <= run_d;
      finished_q <= finished_d;
      fault_q    <= fault_d;
      underrun_q <= underrun_d;
      discont_q  <= discont_d;
      guard_q    <= guard_d;
      reach_q    <= reach_d;
      chk_q      <= chk_d;
      stop_q     <= stop_d;
      idx_q      <= idx_d;
      flags_q    <= flags_d;
      left_q     <= left_d;
      jerk_q     <= jerk_d;
      acc_q      <= acc_d;
      vel_q      <= vel_d;
      frac_q     <= frac_d;
      pint_q     <= pint_d;
      phase_q    <= phase_d;
      step_req_q <= step_req_d;
      step_fwd_q <= step_fwd_d;
      move_idx_q <= move_idx_d;
      bpos_q     <= bpos_d;
      move_done_q <= move_done;
      ends_in_q  <= ends_in_d;
      ends_out_q <= ends_out_d;
      rows_q     <= rows_d;
      refused_q  <= replace_req && !replace_ok;
    end
  end

  // Direction of the head row: its velocity's sign, else its acceleration's,
  // else its jerk's (a move from rest starts with v = a = 0).
  assign head_fwd_o = (hd_vel0 != '0) ? !hd_vel0[VelW-1] :
                      (hd_acc0 != '0) ? !hd_acc0[AccW-1] : !hd_jerk[JerkW-1];

  assign running_o      = run_q;
  assign finished_o     = finished_q;
  assign fault_o        = fault_q;
  assign underrun_o     = underrun_q;
  assign discont_o      = discont_q;
  assign guard_o        = guard_q;
  assign reach_o        = reach_q;
  assign stopping_o     = stop_q;
  assign overshoot_o    = sg_overshoot;
  assign fifo_full_o    = fifo_full || stop_q;
  assign move_done_o    = move_done_q;
  assign move_idx_o     = move_idx_q;
  assign boundary_pos_o = bpos_q;
  assign row_count_o    = rows_q;
  assign retarget_refused_o = refused_q;
  assign step_req_o     = step_req_q;
  assign step_fwd_o     = step_fwd_q;
  assign pos_int_o      = pint_q;
  assign pos_frac_o     = frac_q;
  assign vel_o          = vel_q;
  assign acc_o          = acc_q;
  assign jerk_o         = stop_q ? sg_jerk : jerk_q;  // the jerk applied this clock
  assign phase_o        = phase_q;
  assign seg_idx_o      = idx_q;

`ifdef SC_COVER
  // Cover points (the coverage build, scripts/coverage.py): every phase code,
  // every way a row starts and a run ends, both step directions.
  for (genvar p = 0; p <= int'(sc_pkg::PhStop); p++) begin : g_cov_phase
    c_phase: cover property (@(posedge clk_i) rst_ni && phase_q == PhaseW'(p));
  end
  c_start:          cover property (@(posedge clk_i) rst_ni && !run_q && load);
  c_start_empty:    cover property (@(posedge clk_i) rst_ni && !run_q && start_i && fifo_empty);
  c_row_chained:    cover property (@(posedge clk_i) rst_ni && boundary && load);
  c_move_end:       cover property (@(posedge clk_i) rst_ni && move_done);
  c_hold:           cover property (@(posedge clk_i) rst_ni && hold && vel_q != '0);
  c_replace:        cover property (@(posedge clk_i) rst_ni && replace_ok && keep != '0);
  c_replace_head:   cover property (@(posedge clk_i) rst_ni && replace_ok && keep == '0);
  c_replace_late:   cover property (@(posedge clk_i) rst_ni && replace_req && run_q && !replace_ok);
  c_hold_left:      cover property (@(posedge clk_i) rst_ni && boundary && load &&
                                    flags_q[sc_pkg::RowFlagHold]);
  c_stream_end:     cover property (@(posedge clk_i) rst_ni && boundary && !load && ends);
  c_stop_command:   cover property (@(posedge clk_i) rst_ni && stop_start && stop_i);
  c_underrun:       cover property (@(posedge clk_i) rst_ni && underrun_d && !underrun_q);
  c_discontinuity:  cover property (@(posedge clk_i) rst_ni && discont_d && !discont_q);
  c_guard:          cover property (@(posedge clk_i) rst_ni && guard_d && !guard_q);
  c_fault:          cover property (@(posedge clk_i) rst_ni && fault_d && !fault_q);
  c_abort:          cover property (@(posedge clk_i) rst_ni && run_q && abort_i);
  c_step_fwd:       cover property (@(posedge clk_i) rst_ni && step_req_q && step_fwd_q);
  c_step_rev:       cover property (@(posedge clk_i) rst_ni && step_req_q && !step_fwd_q);
`endif

`ifdef FORMAL
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // Proven on this module with its sc_row_fifo and sc_stop_gen (read without
  // FORMAL). Input contract: reset in the first clock only; every other input
  // (rows, START, STOP, abort, limits, guards) is free in every clock. The
  // properties need no reasoning about the wide arithmetic beyond the adders
  // themselves, so they are proven on the full widths. Shadows (f_*) hold the
  // outputs of the last clock.
  logic                      f_init_q = 1'b1;  // the first clock of every trace
  logic                      f_run_prev_q, f_fin_prev_q, f_start_prev_q, f_abort_run_q;
  logic                      f_load_prev_q, f_disc_prev_q, f_under_prev_q;
  logic signed [PosIntW-1:0] f_pint_prev_q;
  logic signed [VelW-1:0]    f_vel_prev_q, f_vel_end_q;
  logic signed [AccW-1:0]    f_acc_prev_q, f_acc_end_q;
  logic signed [JerkW-1:0]   f_jerk_prev_q;
  logic                      f_head_cont, f_disc, f_under;

  // The head row continues the motion: the spec of the continuity guard,
  // written from the pins (v + a, a + j of this clock; ACC_STEP: velocity only).
  assign f_head_cont = hd_vel0 == vel_o + VelW'(acc_o) &&
                       (hd_acc0 == acc_o + AccW'(jerk_o) || hd_flags[sc_pkg::RowFlagAccStep]);
  // A row ends (running, no stop, no abort, its last clock), the stream does
  // not end there as planned, a row is queued and it does not continue.
  // A HOLD row waiting for a whole move (velocity mode) has not ended.
  assign f_disc = running_o && !stopping_o && !abort_i && left_q == SegClkW'(1) && !hold &&
                  !flags_q[sc_pkg::RowFlagStreamEnd] && !fifo_empty && !f_head_cont;

  // ... or no row is queued and the motion is not at rest (FIFO underrun).
  assign f_under = running_o && !stopping_o && !abort_i && left_q == SegClkW'(1) && !hold &&
                   !flags_q[sc_pkg::RowFlagStreamEnd] && fifo_empty &&
                   !(vel_o + VelW'(acc_o) == '0 && acc_o + AccW'(jerk_o) == '0);

  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
    end
  end

  always_ff @(posedge clk_i) begin
    f_init_q       <= 1'b0;
    f_run_prev_q   <= rst_ni && running_o;
    f_fin_prev_q   <= rst_ni && finished_o;
    f_start_prev_q <= start_i;
    f_abort_run_q  <= rst_ni && running_o && abort_i;
    f_load_prev_q  <= rst_ni && load;
    f_disc_prev_q  <= rst_ni && f_disc;
    f_under_prev_q <= rst_ni && f_under;
    f_pint_prev_q  <= rst_ni ? pos_int_o : '0;
    f_vel_prev_q   <= vel_o;
    f_acc_prev_q   <= acc_o;
    f_jerk_prev_q  <= jerk_o;
    f_vel_end_q    <= vel_o + VelW'(acc_o);
    f_acc_end_q    <= acc_o + AccW'(jerk_o);
  end

  always_comb begin
    if (!f_init_q) begin
      // -- group exec_steps: a step request only in the clock after a running
      // clock; the position moves by exactly the request (at most one pulse per
      // clock); once finished, nothing runs or steps until a START
      p_step_after_run: assert (!step_req_o || f_run_prev_q);
      p_pos_one: assert (pos_int_o == f_pint_prev_q +
                         (step_req_o ? (step_fwd_o ? PosIntW'(1) : {PosIntW{1'b1}}) : PosIntW'(0)));
      p_finished_idle: assert (!finished_o || !running_o);
      p_done_quiet: assert (!(f_fin_prev_q && !f_start_prev_q) ||
                            (finished_o && !running_o && !step_req_o));
      // -- group exec_abort: abort_i while running stops everything the next
      // clock: not running, no stop, no step request, v = a = j = 0, FIFO empty
      p_abort_now: assert (!f_abort_run_q || (!running_o && !stopping_o && !step_req_o &&
                                              vel_o == '0 && acc_o == '0 && jerk_o == '0 &&
                                              fifo_level_o == '0));
      // -- group exec_continuity: while running, v is always the integral of a
      // (no velocity step at a row boundary, at a stop or anywhere), a the
      // integral of the applied jerk except where a row flagged ACC_STEP was
      // just loaded; a row that does not continue is not run: the controlled
      // stop and discont_o follow at once, from the integrated state, the FIFO
      // emptied; likewise the stop and underrun_o when the FIFO ran dry while
      // moving; during a stop no row is queued
      p_vel_cont: assert (!(f_run_prev_q && running_o) || vel_o == f_vel_end_q);
      p_acc_cont: assert (!(f_run_prev_q && running_o) || acc_o == f_acc_end_q ||
                          (f_load_prev_q && flags_q[sc_pkg::RowFlagAccStep]));
      p_disc_stop: assert (!f_disc_prev_q || (running_o && stopping_o && discont_o &&
                                              vel_o == f_vel_end_q && acc_o == f_acc_end_q &&
                                              fifo_level_o == '0));
      p_under_stop: assert (!f_under_prev_q || (running_o && stopping_o && underrun_o &&
                                                vel_o == f_vel_end_q && acc_o == f_acc_end_q));
      p_stop_empty: assert (!stopping_o || fifo_level_o == '0);
    end
  end

  // -- group exec_soft (OwnReach = 0: the reach results are free inputs, any
  // answer an evaluator could give): with the look-ahead on, a row loads only
  // when, from the exact position it starts at, its forward reach stays at or
  // below the window's upper edge or its start, and its backward reach at or
  // above the lower edge or its start. Written on the whole position (the
  // start after this clock's integration at a boundary, whose adders
  // exec_steps covers, or REF_POS with POS_FRAC0 at a START), not on the 16
  // fraction bits the gate adds: it also proves that the bits the gate
  // drops never carry into the integer part it compares.
  localparam int FPosW  = PosIntW + FracBits;
  localparam int FW     = FPosW + 3;  // a position plus any reach (ReachW bits)
  localparam int FShift = FracBits - sc_pkg::ReachFrac;
  localparam int FIntW  = FW - FracBits;
  logic [FPosW-1:0]        f_p0_raw;
  logic signed [FW-1:0]    f_p0, f_fwd_end, f_rev_end;
  logic signed [FIntW-1:0] f_p0_floor, f_fwd_floor, f_rev_floor;
  logic                    f_fwd_ok, f_rev_ok;

  assign f_p0_raw    = run_q ? {pint_next, pos_sum[FracBits-1:0]} : {pint_q, pos_frac0_i};
  assign f_p0        = {{(FW-FPosW){f_p0_raw[FPosW-1]}}, f_p0_raw};
  assign f_fwd_end   = f_p0 + {{(FW-ReachW-FShift){hd_fwd[ReachW-1]}}, hd_fwd, {FShift{1'b0}}};
  assign f_rev_end   = f_p0 + {{(FW-ReachW-FShift){hd_rev[ReachW-1]}}, hd_rev, {FShift{1'b0}}};
  // the integer part of a position: floor, also below 0
  assign f_p0_floor  = f_p0[FW-1:FracBits];
  assign f_fwd_floor = f_fwd_end[FW-1:FracBits];
  assign f_rev_floor = f_rev_end[FW-1:FracBits];
  assign f_fwd_ok    = f_fwd_floor <= FIntW'(soft_max_i) || f_fwd_floor <= f_p0_floor;
  assign f_rev_ok    = f_rev_floor >= FIntW'(soft_min_i) || f_rev_floor >= f_p0_floor;

  always_comb begin
    if (!f_init_q) begin
      p_soft_gate: assert (!(Lookahead && soft_en_i && load) || (f_fwd_ok && f_rev_ok));
    end
  end
`endif

endmodule
