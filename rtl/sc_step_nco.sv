// sc_step_nco: turns the closed loop's rate command u into one-clock step
// requests for sc_step_gen.
//
// u is in counts per control period, Q.CtlFrac. One pulse is 2^shift counts
// and a control period is cfg_div_i clocks, so a phase accumulator with
// modulus M = cfg_div_i << (CtlFrac + shift) that adds u every clock wraps
// (u / M) times per clock: exactly u counts per period, with no divider.
// A wrap up is a forward step, a wrap below zero a backward step. The
// accumulator starts at M/2 (half a step either way). |u| < M is required
// (the controller's output limit keeps it far below).
module sc_step_nco (
  input  logic                                clk_i,
  input  logic                                rst_ni,

  // cfg_div << cfg_shift (from sc_neuron_pi, which shifts it for V* too)
  input  logic [sc_pkg::CtlDivW+(1<<sc_pkg::EncShiftW)-2:0] div_sh_i,

  input  logic                                load_i,   // phase := M/2
  input  logic                                run_i,    // integrate u
  input  logic signed [sc_pkg::CtlW-1:0]      u_i,

  output logic                                step_req_o,
  output logic                                step_fwd_o,
  output logic signed [sc_pkg::NcoW-1:0]      phase_o
);

  localparam int NcoW    = sc_pkg::NcoW;
  localparam int CtlFrac = sc_pkg::CtlFrac;

  logic signed [NcoW-1:0] acc_q, acc_d;
  logic signed [NcoW-1:0] modulus, sum, sum_hi;
  logic                   req_q, req_d, fwd_q, fwd_d;

  assign modulus = NcoW'({div_sh_i, CtlFrac'(0)});
  assign sum     = acc_q + NcoW'(u_i);
  // sum >= M iff sum - M >= 0 (no overflow: |acc|, |u|, M < 2^(NcoW-2))
  assign sum_hi  = sum - modulus;

  always_comb begin
    acc_d = acc_q;
    req_d = 1'b0;
    fwd_d = fwd_q;
    if (load_i) begin
      acc_d = modulus >>> 1;
    end else if (run_i) begin
      if (!sum_hi[NcoW-1]) begin
        acc_d = sum_hi;
        req_d = 1'b1;
        fwd_d = 1'b1;
      end else if (sum[NcoW-1]) begin
        acc_d = sum + modulus;
        req_d = 1'b1;
        fwd_d = 1'b0;
      end else begin
        acc_d = sum;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      acc_q <= '0;
      req_q <= 1'b0;
      fwd_q <= 1'b1;
    end else begin
      acc_q <= acc_d;
      req_q <= req_d;
      fwd_q <= fwd_d;
    end
  end

  assign step_req_o = req_q;
  assign step_fwd_o = fwd_q;
  assign phase_o    = acc_q;

endmodule
