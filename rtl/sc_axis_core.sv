// sc_axis_core: one open-loop axis = profile executor + step pulse generator.
//
// done_o rises once the executor has finished the stream AND the last
// requested step has left the STEP pin, so no pulse can follow done_o.
// phase_o reports the executor's segment phase, PhDone once done_o is set.
// Control and configuration inputs are registered here first (one clock of
// latency), so no logic inside depends combinationally on a top-level input:
// short input-to-flop paths on the FPGA, and Verilator evaluates the logic
// once per rising edge instead of on every input change.
//
// An accepted start first arms: DIR is turned to the move's direction (the
// sign of the head row of the row FIFO, taken when START is accepted) and
// held for the setup time, and only then does the executor start (exec_start_o pulses).
// Steps therefore never pile up in the step generator's queue behind a DIR
// change.
//
// stop_i asks for the controlled stop (sc_profile_exec: jerk-limited to
// rest with stop_jerk_i / stop_acc_i); during the arming it drops the start.
// abort_i is the immediate stop (e-stop). guard_*_i are the executor's
// row limits (sc_profile_exec; 0 = no limit).
//
// Step-rate guard: whatever rows arrive, the executor's steps never
// overflow the step generator's queue (no step is ever dropped). While the
// executor drives the steps and the queue is three short of full, the
// executor stops at once the next clock, as an abort (the trip is
// registered: a combinational path from the queue into the executor's
// abort cost about 1000 LUT): the two requests still in flight fit, the
// queue drains at the pulse timing, the pins end on the reference.
// fault_overrun_o reports it (until the next START), as it reports an
// overflow of the external source.
//
// Limits: lim_fwd_i / lim_rev_i say a limit switch is active on that side
// (filtered and enabled by the register top). Motion into an active limit
// stops it: the controlled stop, or with lim_hard_i the immediate stop; a
// START whose move heads into one is refused and an arming toward one is
// dropped. Motion away from it runs. lim_trip_fwd_o / lim_trip_rev_o are high
// while a limit acts (for the sticky flags). "Motion" is the reference's: the
// arming direction, else the sign of the executor's velocity.
//
// ExtStep = 1 adds an external step source (sc_servo_axis's closed-loop
// NCO): with ext_sel_i set it replaces the executor's carry at the step
// generator. DIR is pre-positioned (while no step is owed) by the arming,
// else by the reference velocity's sign while the executor moves, else by
// the external hint (the sign of the rate command while settling), so a
// small rate command of the wrong sign never turns DIR and costs the setup
// time; steps actually owed turn DIR in either case. ext_busy_i extends busy_o, ext_abort_i aborts the executor,
// ext_done_i replaces "executor finished" in done_o. The external source
// starts on exec_start_o, together with the reference. With ExtStep = 0 the
// ext_* inputs are ignored and add no logic.
//
// SyncStart = 1 makes the core one axis of sc_multi_axis_core, whose axes
// start their executors on one clock: a START is accepted only with
// sync_start_ok_i (every axis can take it: start_able_o of all), the
// executor starts once every axis has DIR set up (sync_go_i, the AND of
// arm_ready_o) and the arming is dropped when any axis drops its own
// (sync_drop_i, the OR of arm_drop_o). All three outputs are functions of
// registers, so the OR/AND across axes adds no loop. With SyncStart = 0 the
// sync_* inputs are ignored and add no logic.
module sc_axis_core #(
  parameter bit ExtStep   = 1'b0,
  parameter bit SyncStart = 1'b0,
  parameter bit OwnReach  = 1'b1,  // 0: the row reach evaluator is outside (rc_*), shared
  parameter bit Lookahead = 1'b1   // 0: no soft-limit look-ahead (sc_profile_exec)
) (
  input  logic                        clk_i,
  input  logic                        rst_ni,

  input  logic                        enable_i,     // drives the EN pin
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_high_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_low_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_setup_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_hold_i,

  input  logic                        row_push_i,   // append a row (ignored while fifo_full_o)
  input  logic                        row_replace_i,  // with row_push_i: replace from retarget_row_i on
  input  logic [sc_pkg::RowCountW-1:0]        retarget_row_i,
  input  logic [sc_pkg::RowFlagW-1:0]         row_flags_i,
  input  logic [sc_pkg::PhaseW-1:0]           row_phase_i,
  input  logic [sc_pkg::SegClkW-1:0]          row_clocks_i,
  input  logic signed [sc_pkg::JerkW-1:0]     row_jerk_i,
  input  logic signed [sc_pkg::AccW-1:0]      row_acc0_i,
  input  logic signed [sc_pkg::VelW-1:0]      row_vel0_i,
  input  logic                        fifo_flush_i,
  input  logic [sc_pkg::FracBits-1:0]         pos_frac0_i,
  input  logic                        start_i,      // ignored while busy_o or !enable_i (seen a clock later)
  input  logic                        abort_i,      // immediate stop (e-stop)
  input  logic                        stop_i,       // controlled stop; while arming, the start is dropped
  input  logic [sc_pkg::JerkW-1:0]            stop_jerk_i,  // controlled-stop limits
  input  logic [sc_pkg::AccW-1:0]             stop_acc_i,
  input  logic [sc_pkg::VelW-1:0]             guard_vel_i,  // row guard limits (0 = none)
  input  logic [sc_pkg::AccW-1:0]             guard_acc_i,
  input  logic [sc_pkg::JerkW-1:0]            guard_jerk_i,
  input  logic                        soft_en_i,    // soft-limit look-ahead on every row (sc_profile_exec)
  input  logic signed [sc_pkg::PosIntW-1:0]   soft_min_i,
  input  logic signed [sc_pkg::PosIntW-1:0]   soft_max_i,
  input  logic                        lim_fwd_i,    // a limit is active on the + side
  input  logic                        lim_rev_i,    // a limit is active on the - side
  input  logic                        lim_hard_i,   // 1: a limit stops at once, 0: controlled stop

  // external step source (ExtStep = 1 only)
  input  logic                        ext_sel_i,         // steps come from ext_req_i/ext_fwd_i
  input  logic                        ext_req_i,
  input  logic                        ext_fwd_i,
  input  logic                        ext_hint_valid_i,  // DIR pre-position while no step is owed
  input  logic                        ext_hint_i,
  input  logic                        ext_busy_i,
  input  logic                        ext_abort_i,       // aborts the executor (not the arming)
  input  logic                        ext_done_i,
  output logic                        exec_start_o,      // the executor starts this clock
  // start synchronisation across axes (SyncStart = 1 only)
  input  logic                        sync_start_ok_i,   // every axis can accept this START
  input  logic                        sync_go_i,         // every axis is armed and set up
  input  logic                        sync_drop_i,       // some axis drops its arming
  input  logic                        sync_reach_veto_i, // some axis refuses its head row (OR of reach_bad_o)
  output logic                        reach_bad_o,       // this axis's look-ahead refuses its head row now
  output logic                        start_able_o,      // this axis would accept the START it sees
  output logic                        arm_ready_o,       // armed, DIR set up: waits for sync_go_i
  output logic                        arm_drop_o,        // this axis drops its arming this clock
  output logic                        fault_abort_o,     // a hard limit, the rate guard or ext_abort_i: stop at once
  output logic                        arming_o,          // a START is arming (DIR to the move, its setup)
  output logic                        abort_o,           // abort_i as registered here, or a hard limit acting
  output logic                        ref_done_o,        // the executor has finished the stream
  output logic                        ref_running_o,     // the executor runs (a stream or its controlled stop)
  output logic                        step_busy_o,       // a step is owed or STEP is high
  output logic                        lim_trip_fwd_o,    // the + limit stops motion or refuses a start
  output logic                        lim_trip_rev_o,    // the - limit stops motion or refuses a start

  output logic                        step_o,
  output logic                        dir_o,
  output logic                        en_o,

  output logic                        busy_o,
  output logic                        done_o,
  output logic [sc_pkg::PhaseW-1:0]           phase_o,
  output logic                        fault_table_o,
  output logic                        fault_overrun_o,
  output logic                        underrun_o,
  output logic                        discont_o,
  output logic                        guard_o,      // a row broke a guard limit (until START)
  output logic                        reach_o,      // the soft-limit look-ahead refused a row (until START)
  output logic                        stopping_o,   // a controlled stop runs
  output logic                        overshoot_o,  // the last stop could not avoid a reversal
  output logic                        move_done_o,
  output logic [sc_pkg::MoveIdxW-1:0]         move_idx_o,
  output logic signed [sc_pkg::PosIntW-1:0]   boundary_pos_o,
  output logic [sc_pkg::RowLevelW-1:0]        fifo_level_o,
  output logic [sc_pkg::RowCountW-1:0]        row_count_o,         // rows loaded since START
  output logic                        retarget_refused_o,  // a replace was refused (one clock)
  output logic                        fifo_full_o,
  output logic signed [sc_pkg::PosIntW-1:0]   pulse_count_o,  // net steps since start

  // reference kinematics (P*, V*, A*, J*) for the closed loop and for checks
  output logic signed [sc_pkg::PosIntW-1:0]   ref_pos_int_o,
  output logic [sc_pkg::FracBits-1:0]         ref_pos_frac_o,
  output logic signed [sc_pkg::VelW-1:0]      ref_vel_o,
  output logic signed [sc_pkg::AccW-1:0]      ref_acc_o,
  output logic signed [sc_pkg::JerkW-1:0]     ref_jerk_o,
  output logic [sc_pkg::SegIdxW-1:0]          seg_idx_o,
  output logic signed [sc_pkg::PendW-1:0]     step_pending_o,

  // the row reach evaluator outside (OwnReach = 0; sc_profile_exec)
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

  localparam int PulseTimeW = sc_pkg::PulseTimeW;
  localparam int FracBits   = sc_pkg::FracBits;
  localparam int PhaseW     = sc_pkg::PhaseW;
  // |queued steps| at which the executor is stopped: three short of full
  localparam logic signed [sc_pkg::PendW-1:0] PendNearFull = sc_pkg::PendW'((1 << (sc_pkg::PendW - 1)) - 3);

  logic   exec_running, exec_finished, exec_fault;
  logic   exec_step_req, exec_step_fwd;
  logic [PhaseW-1:0] exec_phase;
  logic   sg_busy, sg_dir;
  logic   sg_req, sg_fwd, sg_hint_valid, sg_hint;
  logic   use_ext, exec_abort, finished, ref_moving;
  logic   start_ok, exec_start;
  logic   en_q, start_q, abort_q, stop_q;
  logic   lim_fwd_q, lim_rev_q, lim_hard_q;
  logic   start_req, start_into_lim, into_fwd, into_rev, lim_act, lim_stop, lim_abort;
  logic   rate_trip_q, rate_trip_d, rate_q, rate_d, sg_overrun;
  logic [sc_pkg::JerkW-1:0] stop_jerk_q;
  logic [sc_pkg::AccW-1:0]  stop_acc_q;
  logic [sc_pkg::VelW-1:0]  guard_vel_q;
  logic [sc_pkg::AccW-1:0]  guard_acc_q;
  logic [sc_pkg::JerkW-1:0] guard_jerk_q;
  logic   soft_en_q;
  logic signed [sc_pkg::PosIntW-1:0] soft_min_q, soft_max_q;
  logic   exec_ready;                    // the head row's reach is known (or not needed)
  logic   head_fwd;                      // direction of the FIFO's head row
  logic   arm_q, arm_d;                  // start accepted, waiting for DIR
  logic   arm_fwd_q, arm_fwd_d;
  logic [PulseTimeW-1:0] arm_cnt_q, arm_cnt_d;  // clocks DIR has pointed the right way
  logic [PulseTimeW-1:0] cfg_high_q, cfg_low_q, cfg_setup_q, cfg_hold_q;
  logic [FracBits-1:0]   pos_frac0_q;

  assign use_ext    = ExtStep && ext_sel_i;
  assign busy_o     = exec_running || exec_step_req || sg_busy || arm_q || (ExtStep && ext_busy_i);
  assign start_req  = start_q && !busy_o && en_q;
  // A move toward an active limit is refused (an empty FIFO is the table
  // fault, as without limits).
  assign start_into_lim = fifo_level_o != '0 && (head_fwd ? lim_fwd_q : lim_rev_q);
  assign start_able_o = start_req && !start_into_lim;
  assign start_ok   = start_able_o && (!SyncStart || sync_start_ok_i);
  // Motion into an active limit: the arming toward it, or the reference
  // moving toward it (at rest, or moving away, nothing happens).
  assign into_fwd   = lim_fwd_q && (arm_q ? arm_fwd_q : (ref_moving && !ref_vel_o[sc_pkg::VelW-1]));
  assign into_rev   = lim_rev_q && (arm_q ? !arm_fwd_q : (ref_moving && ref_vel_o[sc_pkg::VelW-1]));
  assign lim_act    = into_fwd || into_rev;
  assign lim_stop   = lim_act && !lim_hard_q;
  assign lim_abort  = lim_act && lim_hard_q;
  // A latched external fault must not block the arming of the next start:
  // the external source clears it when it starts with the executor.
  assign rate_trip_d = !use_ext && exec_running &&
                      (step_pending_o >= PendNearFull || step_pending_o <= -PendNearFull);
  assign rate_d     = start_ok ? 1'b0 : (rate_q || rate_trip_q);
  assign exec_abort = abort_q || lim_abort || rate_trip_q || (ExtStep && ext_abort_i);
  assign finished   = use_ext ? ext_done_i : exec_finished;

  // While arming, DIR is steered to the move's direction; otherwise, with no
  // step owed, it is pre-positioned to the commanded direction.
  assign ref_moving    = exec_running && ref_vel_o != '0;
  assign sg_req        = use_ext ? ext_req_i : exec_step_req;
  assign sg_fwd        = use_ext ? ext_fwd_i : exec_step_fwd;
  assign sg_hint_valid = arm_q || ref_moving || (use_ext && ext_hint_valid_i);
  // (!ExtStep: the plain core's hint needs no mux for the external one)
  assign sg_hint       = arm_q ? arm_fwd_q :
                         (!ExtStep || ref_moving) ? !ref_vel_o[sc_pkg::VelW-1] : ext_hint_i;

  assign arm_drop_o  = arm_q && (abort_q || stop_q || lim_act);
  assign arm_ready_o = arm_q && !arm_drop_o && sg_dir == arm_fwd_q && arm_cnt_q >= cfg_setup_q && exec_ready;
  // (an external fault aborts every axis of a multi-axis core while this
  // executor runs; latched, it must not hold the others' next start off)
  assign fault_abort_o = lim_abort || rate_trip_q || (ExtStep && ext_abort_i && exec_running);
  assign arming_o      = arm_q;

  always_comb begin
    arm_d      = arm_q;
    arm_fwd_d  = arm_fwd_q;
    arm_cnt_d  = arm_cnt_q;
    exec_start = 1'b0;
    if (start_ok) begin
      arm_d     = 1'b1;
      arm_fwd_d = head_fwd;
      arm_cnt_d = '0;
    end else if (arm_q) begin
      if (arm_drop_o || (SyncStart && sync_drop_i)) begin
        arm_d = 1'b0;
      end else if (sg_dir != arm_fwd_q) begin
        arm_cnt_d = '0;
      end else if (arm_cnt_q >= cfg_setup_q) begin
        // set up (and the head row's reach known): start now, or
        // (SyncStart) hold until every axis is
        if (exec_ready && (!SyncStart || sync_go_i)) begin
          arm_d      = 1'b0;
          exec_start = 1'b1;
        end
      end else begin
        arm_cnt_d = arm_cnt_q + PulseTimeW'(1);
      end
    end
  end

  sc_profile_exec #(
    .OwnReach  (OwnReach),
    .Lookahead (Lookahead)
  ) u_exec (
    .clk_i,
    .rst_ni,
    .row_push_i,
    .row_replace_i,
    .retarget_row_i,
    .row_flags_i,
    .row_phase_i,
    .row_clocks_i,
    .row_jerk_i,
    .row_acc0_i,
    .row_vel0_i,
    .fifo_flush_i,
    .pos_frac0_i (pos_frac0_q),
    .start_i     (exec_start),
    .abort_i     (exec_abort),
    .stop_i      (stop_q || lim_stop),
    .stop_jerk_i (stop_jerk_q),
    .stop_acc_i  (stop_acc_q),
    .guard_vel_i (guard_vel_q),
    .guard_acc_i (guard_acc_q),
    .guard_jerk_i (guard_jerk_q),
    .soft_en_i   (soft_en_q),
    .soft_min_i  (soft_min_q),
    .soft_max_i  (soft_max_q),
    .running_o   (exec_running),
    .finished_o  (exec_finished),
    .fault_o     (exec_fault),
    .underrun_o,
    .discont_o,
    .guard_o,
    .reach_o,
    .start_ready_o (exec_ready),
    .reach_veto_i  (SyncStart && sync_reach_veto_i),
    .reach_bad_o,
    .stopping_o,
    .overshoot_o,
    .move_done_o,
    .move_idx_o,
    .boundary_pos_o,
    .fifo_level_o,
    .row_count_o,
    .retarget_refused_o,
    .fifo_full_o,
    .head_fwd_o  (head_fwd),
    .step_req_o  (exec_step_req),
    .step_fwd_o  (exec_step_fwd),
    .pos_int_o   (ref_pos_int_o),
    .pos_frac_o  (ref_pos_frac_o),
    .vel_o       (ref_vel_o),
    .acc_o       (ref_acc_o),
    .jerk_o      (ref_jerk_o),
    .phase_o     (exec_phase),
    .seg_idx_o,
    .rc_start_o,
    .rc_abort_o,
    .rc_clocks_o,
    .rc_jerk_o,
    .rc_acc0_o,
    .rc_vel0_o,
    .rc_busy_i,
    .rc_done_i,
    .rc_fwd_i,
    .rc_rev_i
  );

  sc_step_gen u_step_gen (
    .clk_i,
    .rst_ni,
    .cfg_high_i  (cfg_high_q),
    .cfg_low_i   (cfg_low_q),
    .cfg_setup_i (cfg_setup_q),
    .cfg_hold_i  (cfg_hold_q),
    .clear_i     (start_ok),
    .step_req_i  (sg_req),
    .step_fwd_i  (sg_fwd),
    .dir_hint_valid_i (sg_hint_valid),
    .dir_hint_i  (sg_hint),
    .step_o,
    .dir_o       (sg_dir),
    .busy_o      (sg_busy),
    .overrun_o   (sg_overrun),
    .pending_o   (step_pending_o),
    .count_o     (pulse_count_o)
  );

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      en_q        <= 1'b0;
      arm_q       <= 1'b0;
      rate_q      <= 1'b0;
      rate_trip_q <= 1'b0;
      arm_fwd_q   <= 1'b1;
      arm_cnt_q   <= '0;
      start_q     <= 1'b0;
      abort_q     <= 1'b0;
      stop_q      <= 1'b0;
      lim_fwd_q   <= 1'b0;
      lim_rev_q   <= 1'b0;
      lim_hard_q  <= 1'b0;
      stop_jerk_q <= '0;
      stop_acc_q  <= '0;
      guard_vel_q <= '0;
      guard_acc_q <= '0;
      guard_jerk_q <= '0;
      soft_en_q   <= 1'b0;
      soft_min_q  <= '0;
      soft_max_q  <= '0;
      cfg_high_q  <= '0;
      cfg_low_q   <= '0;
      cfg_setup_q <= '0;
      cfg_hold_q  <= '0;
      pos_frac0_q <= '0;
    end else begin
      en_q        <= enable_i;
      arm_q       <= arm_d;
      rate_q      <= rate_d;
      rate_trip_q <= rate_trip_d;
      arm_fwd_q   <= arm_fwd_d;
      arm_cnt_q   <= arm_cnt_d;
      start_q     <= start_i;
      abort_q     <= abort_i;
      stop_q      <= stop_i;
      lim_fwd_q   <= lim_fwd_i;
      lim_rev_q   <= lim_rev_i;
      lim_hard_q  <= lim_hard_i;
      stop_jerk_q <= stop_jerk_i;
      stop_acc_q  <= stop_acc_i;
      guard_vel_q <= guard_vel_i;
      guard_acc_q <= guard_acc_i;
      guard_jerk_q <= guard_jerk_i;
      soft_en_q   <= soft_en_i;
      soft_min_q  <= soft_min_i;
      soft_max_q  <= soft_max_i;
      cfg_high_q  <= cfg_high_i;
      cfg_low_q   <= cfg_low_i;
      cfg_setup_q <= cfg_setup_i;
      cfg_hold_q  <= cfg_hold_i;
      pos_frac0_q <= pos_frac0_i;
    end
  end

  assign en_o          = en_q;
  assign dir_o         = sg_dir;
  assign done_o        = finished && !busy_o;
  assign phase_o       = done_o ? sc_pkg::PhDone : exec_phase;
  assign fault_table_o = exec_fault;
  assign fault_overrun_o = sg_overrun || rate_q;
  assign exec_start_o  = exec_start;
  assign abort_o       = abort_q || lim_abort;
  assign lim_trip_fwd_o = into_fwd || (start_req && start_into_lim && head_fwd);
  assign lim_trip_rev_o = into_rev || (start_req && start_into_lim && !head_fwd);
  assign ref_done_o    = exec_finished;
  assign ref_running_o = exec_running;
  assign step_busy_o   = sg_busy;

`ifdef FORMAL
  // ---- formal properties (scripts/formal.py, docs/formal.md) ----------------
  // Proven on this module with ExtStep = 0 (the open-loop core of sc_axi_axis)
  // and its submodules read without FORMAL. Input contract: reset in the
  // first clock only; every other input is free in every clock (rows, START,
  // STOP, abort, limits, timing configuration). Shadows (f_*) hold pins of the
  // last clocks; f_*_p2 the value two clocks back.
  logic f_init_q = 1'b1;  // the first clock of every trace
  logic f_done_prev_q, f_start_ok_prev_q, f_step_prev_q;
  logic f_abort_p1_q, f_abort_p2_q;
  logic f_hard_fwd_p1_q, f_hard_fwd_p2_q, f_hard_rev_p1_q, f_hard_rev_p2_q;
  logic f_soft_fwd_p1_q, f_soft_fwd_p2_q, f_soft_rev_p1_q, f_soft_rev_p2_q;
  logic f_mv_fwd_prev_q, f_mv_rev_prev_q, f_stop_arm_prev_q;
  logic f_rise;
  localparam logic signed [sc_pkg::PendW-1:0] FPendMax = {1'b0, {(sc_pkg::PendW-1){1'b1}}};
  localparam logic signed [sc_pkg::PendW-1:0] FPendMin = {1'b1, {(sc_pkg::PendW-1){1'b0}}};

  assign f_rise = step_o && !f_step_prev_q;

  always_comb begin
    if (f_init_q) begin
      a_reset_first: assume (!rst_ni);
    end else begin
      a_no_reset: assume (rst_ni);
    end
    // core_abort only (formal.py drops it elsewhere): sc_axi_regs never
    // starts in the clock of an abort (CMD.ESTOP wins over START, the e-stop
    // input cancels it); the core alone would arm such a START
    a_abort_no_start: assume (!(abort_i && start_i));
  end

  always_ff @(posedge clk_i) begin
    f_init_q          <= 1'b0;
    f_done_prev_q     <= rst_ni && done_o;
    f_start_ok_prev_q <= rst_ni && start_ok;
    f_step_prev_q     <= rst_ni && step_o;
    f_abort_p1_q      <= rst_ni && abort_i;
    f_abort_p2_q      <= rst_ni && f_abort_p1_q;
    f_hard_fwd_p1_q   <= rst_ni && lim_fwd_i && lim_hard_i;
    f_hard_fwd_p2_q   <= rst_ni && f_hard_fwd_p1_q;
    f_hard_rev_p1_q   <= rst_ni && lim_rev_i && lim_hard_i;
    f_hard_rev_p2_q   <= rst_ni && f_hard_rev_p1_q;
    f_soft_fwd_p1_q   <= rst_ni && lim_fwd_i && !lim_hard_i;
    f_soft_fwd_p2_q   <= rst_ni && f_soft_fwd_p1_q;
    f_soft_rev_p1_q   <= rst_ni && lim_rev_i && !lim_hard_i;
    f_soft_rev_p2_q   <= rst_ni && f_soft_rev_p1_q;
    f_mv_fwd_prev_q   <= rst_ni && ref_running_o && ref_vel_o > 0;
    f_mv_rev_prev_q   <= rst_ni && ref_running_o && ref_vel_o < 0;
    f_stop_arm_prev_q <= rst_ni && stop_q && arm_q;
  end

  always_comb begin
    if (!f_init_q) begin
      // -- group core_done: once done_o is up, and until a START is accepted,
      // done_o stays, no step request reaches the step generator and STEP
      // has no rising edge
      p_done_quiet: assert (!(f_done_prev_q && !f_start_ok_prev_q) ||
                            (done_o && !sg_req && !f_rise));
      // -- group core_abort: abort_i (e-stop) two clocks back: the executor
      // does not run and no step request reaches the step generator (STEP
      // only completes steps already owed); the arming of a START is dropped
      p_abort_2: assert (!f_abort_p2_q || (!ref_running_o && !sg_req && !exec_start_o && !arm_q));
      // CMD.STOP (stop_i, registered) during the arming drops the START: the
      // next clock nothing arms, runs or requests a step
      p_stop_arm: assert (!f_stop_arm_prev_q || (!arm_q && !ref_running_o && !sg_req));
      // -- group core_limits: an active limit on a side with lim_hard_i two
      // clocks back: no step request toward that side; without lim_hard_i and
      // the reference moving toward it in the last clock: the controlled
      // stop runs (or the run has ended)
      p_lim_hard_fwd: assert (!f_hard_fwd_p2_q || !(sg_req && sg_fwd));
      p_lim_hard_rev: assert (!f_hard_rev_p2_q || !(sg_req && !sg_fwd));
      p_lim_stop_fwd: assert (!(f_soft_fwd_p2_q && f_mv_fwd_prev_q) || stopping_o || !ref_running_o);
      p_lim_stop_rev: assert (!(f_soft_rev_p2_q && f_mv_rev_prev_q) || stopping_o || !ref_running_o);
      // -- group core_rate: the executor's steps never overflow the step
      // generator's queue (no step dropped: the pins end on the reference)
      p_no_overrun: assert (!sg_overrun);
      // -- helper invariants: while arming the executor is idle and nothing
      // is owed; a queue one past the trip level with the executor still
      // active has the trip registered; a full queue has the executor stopped
      inv_arm_idle: assert (!arm_q || (!exec_running && !exec_step_req && step_pending_o == '0));
      inv_rate_near: assert (!((exec_running || exec_step_req) &&
                               (step_pending_o > PendNearFull || step_pending_o < -PendNearFull)) ||
                             rate_trip_q);
      inv_rate_full: assert (!(step_pending_o == FPendMax || step_pending_o == FPendMin) ||
                             (!exec_running && !exec_step_req));
    end
  end
`endif

endmodule
