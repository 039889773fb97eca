// sc_axis_core: one open-loop axis = profile executor + step pulse generator.
//
// done_o rises once the executor has finished the table AND the last
// requested step has left the STEP pin, so no pulse can follow done_o.
// phase_o reports the executor's segment phase, PhDone once done_o is set.
// Control and configuration inputs are registered here first (one clock of
// latency), so no logic inside depends combinationally on a top-level input:
// short input-to-flop paths on the FPGA, and Verilator evaluates the logic
// once per rising edge instead of on every input change.
module sc_axis_core (
  input  logic                        clk_i,
  input  logic                        rst_ni,

  input  logic                        enable_i,     // drives the EN pin
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_high_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_low_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_setup_i,
  input  logic [sc_pkg::PulseTimeW-1:0]       cfg_hold_i,

  input  logic                        seg_we_i,
  input  logic [sc_pkg::SegIdxW-1:0]          seg_waddr_i,
  input  logic [sc_pkg::PhaseW-1:0]           seg_phase_i,
  input  logic [sc_pkg::SegClkW-1:0]          seg_clocks_i,
  input  logic signed [sc_pkg::JerkW-1:0]     seg_jerk_i,
  input  logic signed [sc_pkg::AccW-1:0]      seg_acc0_i,
  input  logic signed [sc_pkg::VelW-1:0]      seg_vel0_i,
  input  logic [sc_pkg::SegCntW-1:0]          seg_count_i,
  input  logic [sc_pkg::FracBits-1:0]         pos_frac0_i,
  input  logic                        start_i,      // ignored while busy_o or !enable_i (seen a clock later)
  input  logic                        abort_i,

  output logic                        step_o,
  output logic                        dir_o,
  output logic                        en_o,

  output logic                        busy_o,
  output logic                        done_o,
  output logic [sc_pkg::PhaseW-1:0]           phase_o,
  output logic                        fault_table_o,
  output logic                        fault_overrun_o,
  output logic signed [sc_pkg::PosIntW-1:0]   pulse_count_o,  // net steps since start

  // reference kinematics (P*, V*, A*, J*) for the closed loop and for checks
  output logic signed [sc_pkg::PosIntW-1:0]   ref_pos_int_o,
  output logic [sc_pkg::FracBits-1:0]         ref_pos_frac_o,
  output logic signed [sc_pkg::VelW-1:0]      ref_vel_o,
  output logic signed [sc_pkg::AccW-1:0]      ref_acc_o,
  output logic signed [sc_pkg::JerkW-1:0]     ref_jerk_o,
  output logic [sc_pkg::SegIdxW-1:0]          seg_idx_o,
  output logic signed [sc_pkg::PendW-1:0]     step_pending_o
);

  localparam int PulseTimeW = sc_pkg::PulseTimeW;
  localparam int SegCntW    = sc_pkg::SegCntW;
  localparam int FracBits   = sc_pkg::FracBits;
  localparam int PhaseW     = sc_pkg::PhaseW;

  logic   exec_running, exec_finished, exec_fault;
  logic   exec_step_req, exec_step_fwd;
  logic [PhaseW-1:0] exec_phase;
  logic   sg_busy;
  logic   start_ok;
  logic   en_q, start_q, abort_q;
  logic [PulseTimeW-1:0] cfg_high_q, cfg_low_q, cfg_setup_q, cfg_hold_q;
  logic [SegCntW-1:0]    seg_count_q;
  logic [FracBits-1:0]   pos_frac0_q;

  assign busy_o   = exec_running || exec_step_req || sg_busy;
  assign start_ok = start_q && !busy_o && en_q;

  sc_profile_exec u_exec (
    .clk_i,
    .rst_ni,
    .seg_we_i,
    .seg_waddr_i,
    .seg_phase_i,
    .seg_clocks_i,
    .seg_jerk_i,
    .seg_acc0_i,
    .seg_vel0_i,
    .seg_count_i (seg_count_q),
    .pos_frac0_i (pos_frac0_q),
    .start_i     (start_ok),
    .abort_i     (abort_q),
    .running_o   (exec_running),
    .finished_o  (exec_finished),
    .fault_o     (exec_fault),
    .step_req_o  (exec_step_req),
    .step_fwd_o  (exec_step_fwd),
    .pos_int_o   (ref_pos_int_o),
    .pos_frac_o  (ref_pos_frac_o),
    .vel_o       (ref_vel_o),
    .acc_o       (ref_acc_o),
    .jerk_o      (ref_jerk_o),
    .phase_o     (exec_phase),
    .seg_idx_o
  );

  sc_step_gen u_step_gen (
    .clk_i,
    .rst_ni,
    .cfg_high_i  (cfg_high_q),
    .cfg_low_i   (cfg_low_q),
    .cfg_setup_i (cfg_setup_q),
    .cfg_hold_i  (cfg_hold_q),
    .clear_i     (start_ok),
    .step_req_i  (exec_step_req),
    .step_fwd_i  (exec_step_fwd),
    .dir_hint_valid_i (exec_running && ref_vel_o != '0),
    .dir_hint_i  (!ref_vel_o[sc_pkg::VelW-1]),
    .step_o,
    .dir_o,
    .busy_o      (sg_busy),
    .overrun_o   (fault_overrun_o),
    .pending_o   (step_pending_o),
    .count_o     (pulse_count_o)
  );

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      en_q        <= 1'b0;
      start_q     <= 1'b0;
      abort_q     <= 1'b0;
      cfg_high_q  <= '0;
      cfg_low_q   <= '0;
      cfg_setup_q <= '0;
      cfg_hold_q  <= '0;
      seg_count_q <= '0;
      pos_frac0_q <= '0;
    end else begin
      en_q        <= enable_i;
      start_q     <= start_i;
      abort_q     <= abort_i;
      cfg_high_q  <= cfg_high_i;
      cfg_low_q   <= cfg_low_i;
      cfg_setup_q <= cfg_setup_i;
      cfg_hold_q  <= cfg_hold_i;
      seg_count_q <= seg_count_i;
      pos_frac0_q <= pos_frac0_i;
    end
  end

  assign en_o          = en_q;
  assign done_o        = exec_finished && !busy_o;
  assign phase_o       = done_o ? sc_pkg::PhDone : exec_phase;
  assign fault_table_o = exec_fault;

endmodule
