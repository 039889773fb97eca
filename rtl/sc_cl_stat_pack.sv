// sc_cl_stat_pack: the closed-loop status words CL_STATUS .. CTL_W_V2 of
// one axis (word i at bits 32i+31:32i), as sc_axi_regs reads them on
// cl_stat_i. Pure wiring; the register tops of one and of several axes
// share it.
module sc_cl_stat_pack (
  input  logic                                  in_pos_i,
  input  logic                                  fault_ferr_i,
  input  logic                                  ctl_active_i,
  input  logic [sc_pkg::CtlStW-1:0]             ctl_state_i,
  input  logic [sc_pkg::EncIllW-1:0]            enc_illegal_i,
  input  logic signed [sc_pkg::CtlW-1:0]        u_i,
  input  logic signed [sc_pkg::CtlW-1:0]        v_cmd_i,
  input  logic signed [sc_pkg::CtlW-1:0]        e_p_i,
  input  logic signed [sc_pkg::CtlW-1:0]        e_v_i,
  input  logic signed [sc_pkg::WgtW-1:0]        w_p1_i,
  input  logic signed [sc_pkg::WgtW-1:0]        w_p2_i,
  input  logic signed [sc_pkg::WgtW-1:0]        w_v1_i,
  input  logic signed [sc_pkg::WgtW-1:0]        w_v2_i,
  output logic [sc_pkg::ClStatWords*32-1:0]     cl_stat_o
);

  always_comb begin
    cl_stat_o = '0;
    cl_stat_o[sc_pkg::ClStInPosBit]                   = in_pos_i;
    cl_stat_o[sc_pkg::ClStFerrBit]                    = fault_ferr_i;
    cl_stat_o[sc_pkg::ClStActiveBit]                  = ctl_active_i;
    cl_stat_o[sc_pkg::ClStStateLsb +: sc_pkg::CtlStW] = ctl_state_i;
    cl_stat_o[sc_pkg::ClStIllLsb +: sc_pkg::EncIllW]  = enc_illegal_i;
    cl_stat_o[32*1 +: 32] = 32'(u_i);
    cl_stat_o[32*2 +: 32] = 32'(v_cmd_i);
    cl_stat_o[32*3 +: 32] = 32'(e_p_i);
    cl_stat_o[32*4 +: 32] = 32'(e_v_i);
    cl_stat_o[32*5 +: 32] = 32'(w_p1_i);
    cl_stat_o[32*6 +: 32] = 32'(w_p2_i);
    cl_stat_o[32*7 +: 32] = 32'(w_v1_i);
    cl_stat_o[32*8 +: 32] = 32'(w_v2_i);
  end

endmodule
