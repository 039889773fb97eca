// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Tracing implementation internals
#include "verilated_fst_c.h"
#include "Vsc_axis_core__Syms.h"


VL_ATTR_COLD void Vsc_axis_core___024root__trace_init_sub__TOP__0(Vsc_axis_core___024root* vlSelf, VerilatedFst* tracep) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_init_sub__TOP__0\n"); );
    // Init
    const int c = vlSymsp->__Vm_baseCode;
    // Body
    tracep->declBit(c+220,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+221,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+222,"enable_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+223,"cfg_high_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+224,"cfg_low_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+225,"cfg_setup_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+226,"cfg_hold_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBit(c+227,"seg_we_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+228,"seg_waddr_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declArray(c+229,"seg_wdata_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 228,0);
    tracep->declBus(c+237,"seg_count_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 4,0);
    tracep->declArray(c+238,"pos_frac0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declBit(c+241,"start_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+242,"abort_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+243,"step_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+244,"dir_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+245,"en_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+246,"busy_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+247,"done_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+248,"phase_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBit(c+249,"fault_table_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+250,"fault_overrun_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+251,"pulse_count_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declBus(c+252,"ref_pos_int_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declArray(c+253,"ref_pos_frac_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declArray(c+256,"ref_vel_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declQuad(c+259,"ref_acc_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declQuad(c+261,"ref_jerk_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declBus(c+263,"seg_idx_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+264,"step_pending_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->pushNamePrefix("sc_axis_core ");
    tracep->declBit(c+220,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+221,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+222,"enable_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+223,"cfg_high_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+224,"cfg_low_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+225,"cfg_setup_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+226,"cfg_hold_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBit(c+227,"seg_we_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+228,"seg_waddr_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declArray(c+229,"seg_wdata_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 228,0);
    tracep->declBus(c+237,"seg_count_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 4,0);
    tracep->declArray(c+238,"pos_frac0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declBit(c+241,"start_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+242,"abort_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+243,"step_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+244,"dir_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+245,"en_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+246,"busy_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+247,"done_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+248,"phase_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBit(c+249,"fault_table_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+250,"fault_overrun_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+251,"pulse_count_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declBus(c+252,"ref_pos_int_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declArray(c+253,"ref_pos_frac_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declArray(c+256,"ref_vel_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declQuad(c+259,"ref_acc_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declQuad(c+261,"ref_jerk_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declBus(c+263,"seg_idx_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+264,"step_pending_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBit(c+1,"exec_running",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+2,"exec_finished",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+249,"exec_fault",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+3,"exec_step_req",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+4,"exec_step_fwd",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+5,"exec_phase",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBit(c+6,"sg_busy",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+7,"start_ok",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+8,"en_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+9,"start_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+10,"abort_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+11,"cfg_high_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+12,"cfg_low_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+13,"cfg_setup_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+14,"cfg_hold_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+15,"seg_count_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 4,0);
    tracep->declArray(c+16,"pos_frac0_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 79,0);
    tracep->pushNamePrefix("u_exec ");
    tracep->declBit(c+220,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+221,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+227,"seg_we_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+228,"seg_waddr_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declArray(c+229,"seg_wdata_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 228,0);
    tracep->declBus(c+15,"seg_count_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 4,0);
    tracep->declArray(c+16,"pos_frac0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declBit(c+7,"start_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+10,"abort_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+1,"running_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+2,"finished_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+249,"fault_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+3,"step_req_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+4,"step_fwd_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+252,"pos_int_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declArray(c+253,"pos_frac_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declArray(c+256,"vel_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declQuad(c+259,"acc_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declQuad(c+261,"jerk_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declBus(c+5,"phase_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+263,"seg_idx_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->pushNamePrefix("seg_mem_q");
    tracep->declArray(c+19,"[0]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+27,"[1]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+35,"[2]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+43,"[3]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+51,"[4]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+59,"[5]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+67,"[6]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+75,"[7]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+83,"[8]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+91,"[9]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+99,"[10]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+107,"[11]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+115,"[12]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+123,"[13]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+131,"[14]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declArray(c+139,"[15]",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->popNamePrefix(1);
    tracep->declBit(c+1,"run_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+147,"run_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+2,"finished_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+148,"finished_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+149,"fault_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+150,"fault_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+151,"idx_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+152,"idx_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+153,"count_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 4,0);
    tracep->declBus(c+154,"count_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 4,0);
    tracep->declBus(c+155,"left_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+156,"left_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declQuad(c+157,"jerk_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 47,0);
    tracep->declQuad(c+159,"jerk_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 47,0);
    tracep->declQuad(c+161,"acc_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 63,0);
    tracep->declQuad(c+163,"acc_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 63,0);
    tracep->declArray(c+165,"vel_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 80,0);
    tracep->declArray(c+168,"vel_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 80,0);
    tracep->declArray(c+171,"frac_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 79,0);
    tracep->declArray(c+174,"frac_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 79,0);
    tracep->declBus(c+177,"pint_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+178,"pint_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+5,"phase_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+179,"phase_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBit(c+3,"step_req_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+180,"step_req_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+4,"step_fwd_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+181,"step_fwd_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declArray(c+182,"pos_sum",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 81,0);
    tracep->declBit(c+185,"load",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+186,"load_idx",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declArray(c+187,"load_seg",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 228,0);
    tracep->declBus(c+195,"next_idx_ext",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 4,0);
    tracep->popNamePrefix(1);
    tracep->pushNamePrefix("u_step_gen ");
    tracep->declBit(c+220,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+221,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+11,"cfg_high_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+12,"cfg_low_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+13,"cfg_setup_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+14,"cfg_hold_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBit(c+7,"clear_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+3,"step_req_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+4,"step_fwd_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+243,"step_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+244,"dir_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+6,"busy_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+250,"overrun_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+264,"pending_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+251,"count_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declBus(c+265,"CntMax",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 15,0);
    tracep->declBus(c+266,"PendMax",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+267,"PendMin",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBit(c+196,"step_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+197,"step_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+198,"dir_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+199,"dir_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+200,"high_left_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+201,"high_left_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+202,"low_cnt_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+203,"low_cnt_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+204,"since_rise_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+205,"since_rise_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+206,"since_dir_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+207,"since_dir_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+208,"pend_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+209,"pend_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBit(c+210,"overrun_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+211,"overrun_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+212,"count_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+213,"count_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBit(c+214,"want_fwd",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+215,"have_steps",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+216,"dir_ok",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+217,"rise",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+218,"flip_dir",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+219,"req_blocked",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->popNamePrefix(2);
}

VL_ATTR_COLD void Vsc_axis_core___024root__trace_init_sub__TOP__sc_pkg__0(Vsc_axis_core___024root* vlSelf, VerilatedFst* tracep) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_init_sub__TOP__sc_pkg__0\n"); );
    // Init
    const int c = vlSymsp->__Vm_baseCode;
    // Body
    tracep->declBus(c+268,"ClkHz",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+269,"FracBits",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+270,"PosIntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+271,"VelW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+272,"AccW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+273,"JerkW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+270,"SegClkW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+274,"MaxSegs",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+275,"SegIdxW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+276,"SegCntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+274,"PulseTimeW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+275,"PendW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+275,"PhaseW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
}

VL_ATTR_COLD void Vsc_axis_core___024root__trace_init_top(Vsc_axis_core___024root* vlSelf, VerilatedFst* tracep) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_init_top\n"); );
    // Body
    Vsc_axis_core___024root__trace_init_sub__TOP__0(vlSelf, tracep);
    tracep->pushNamePrefix("sc_pkg ");
    Vsc_axis_core___024root__trace_init_sub__TOP__sc_pkg__0(vlSelf, tracep);
    tracep->popNamePrefix(1);
}

VL_ATTR_COLD void Vsc_axis_core___024root__trace_full_top_0(void* voidSelf, VerilatedFst::Buffer* bufp);
void Vsc_axis_core___024root__trace_chg_top_0(void* voidSelf, VerilatedFst::Buffer* bufp);
void Vsc_axis_core___024root__trace_cleanup(void* voidSelf, VerilatedFst* /*unused*/);

VL_ATTR_COLD void Vsc_axis_core___024root__trace_register(Vsc_axis_core___024root* vlSelf, VerilatedFst* tracep) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_register\n"); );
    // Body
    tracep->addFullCb(&Vsc_axis_core___024root__trace_full_top_0, vlSelf);
    tracep->addChgCb(&Vsc_axis_core___024root__trace_chg_top_0, vlSelf);
    tracep->addCleanupCb(&Vsc_axis_core___024root__trace_cleanup, vlSelf);
}

VL_ATTR_COLD void Vsc_axis_core___024root__trace_full_sub_0(Vsc_axis_core___024root* vlSelf, VerilatedFst::Buffer* bufp);

VL_ATTR_COLD void Vsc_axis_core___024root__trace_full_top_0(void* voidSelf, VerilatedFst::Buffer* bufp) {
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_full_top_0\n"); );
    // Init
    Vsc_axis_core___024root* const __restrict vlSelf VL_ATTR_UNUSED = static_cast<Vsc_axis_core___024root*>(voidSelf);
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    // Body
    Vsc_axis_core___024root__trace_full_sub_0((&vlSymsp->TOP), bufp);
}

VL_ATTR_COLD void Vsc_axis_core___024root__trace_full_sub_0(Vsc_axis_core___024root* vlSelf, VerilatedFst::Buffer* bufp) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_full_sub_0\n"); );
    // Init
    uint32_t* const oldp VL_ATTR_UNUSED = bufp->oldp(vlSymsp->__Vm_baseCode);
    VlWide<8>/*255:0*/ __Vtemp_hda6aaae8__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ad00c__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ad14b__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ace96__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6acfd5__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ad117__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ace58__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ad391__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ad0d2__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6aae12__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6aaf51__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6aac98__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6aadd7__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6aaf15__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6aac56__0;
    VlWide<8>/*255:0*/ __Vtemp_hda6ad18b__0;
    // Body
    bufp->fullBit(oldp+1,(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q));
    bufp->fullBit(oldp+2,(vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_q));
    bufp->fullBit(oldp+3,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_q));
    bufp->fullBit(oldp+4,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_q));
    bufp->fullCData(oldp+5,(vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_q),4);
    bufp->fullBit(oldp+6,(((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q)) 
                           | (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q))));
    bufp->fullBit(oldp+7,(vlSelf->sc_axis_core__DOT__start_ok));
    bufp->fullBit(oldp+8,(vlSelf->sc_axis_core__DOT__en_q));
    bufp->fullBit(oldp+9,(vlSelf->sc_axis_core__DOT__start_q));
    bufp->fullBit(oldp+10,(vlSelf->sc_axis_core__DOT__abort_q));
    bufp->fullSData(oldp+11,(vlSelf->sc_axis_core__DOT__cfg_high_q),16);
    bufp->fullSData(oldp+12,(vlSelf->sc_axis_core__DOT__cfg_low_q),16);
    bufp->fullSData(oldp+13,(vlSelf->sc_axis_core__DOT__cfg_setup_q),16);
    bufp->fullSData(oldp+14,(vlSelf->sc_axis_core__DOT__cfg_hold_q),16);
    bufp->fullCData(oldp+15,(vlSelf->sc_axis_core__DOT__seg_count_q),5);
    bufp->fullWData(oldp+16,(vlSelf->sc_axis_core__DOT__pos_frac0_q),80);
    __Vtemp_hda6aaae8__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][0U];
    __Vtemp_hda6aaae8__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][1U];
    __Vtemp_hda6aaae8__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][2U];
    __Vtemp_hda6aaae8__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][3U];
    __Vtemp_hda6aaae8__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][4U];
    __Vtemp_hda6aaae8__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][5U];
    __Vtemp_hda6aaae8__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][6U];
    __Vtemp_hda6aaae8__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0U][7U];
    bufp->fullWData(oldp+19,(__Vtemp_hda6aaae8__0),229);
    __Vtemp_hda6ad00c__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][0U];
    __Vtemp_hda6ad00c__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][1U];
    __Vtemp_hda6ad00c__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][2U];
    __Vtemp_hda6ad00c__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][3U];
    __Vtemp_hda6ad00c__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][4U];
    __Vtemp_hda6ad00c__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][5U];
    __Vtemp_hda6ad00c__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][6U];
    __Vtemp_hda6ad00c__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [1U][7U];
    bufp->fullWData(oldp+27,(__Vtemp_hda6ad00c__0),229);
    __Vtemp_hda6ad14b__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][0U];
    __Vtemp_hda6ad14b__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][1U];
    __Vtemp_hda6ad14b__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][2U];
    __Vtemp_hda6ad14b__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][3U];
    __Vtemp_hda6ad14b__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][4U];
    __Vtemp_hda6ad14b__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][5U];
    __Vtemp_hda6ad14b__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][6U];
    __Vtemp_hda6ad14b__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [2U][7U];
    bufp->fullWData(oldp+35,(__Vtemp_hda6ad14b__0),229);
    __Vtemp_hda6ace96__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][0U];
    __Vtemp_hda6ace96__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][1U];
    __Vtemp_hda6ace96__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][2U];
    __Vtemp_hda6ace96__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][3U];
    __Vtemp_hda6ace96__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][4U];
    __Vtemp_hda6ace96__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][5U];
    __Vtemp_hda6ace96__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][6U];
    __Vtemp_hda6ace96__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [3U][7U];
    bufp->fullWData(oldp+43,(__Vtemp_hda6ace96__0),229);
    __Vtemp_hda6acfd5__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][0U];
    __Vtemp_hda6acfd5__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][1U];
    __Vtemp_hda6acfd5__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][2U];
    __Vtemp_hda6acfd5__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][3U];
    __Vtemp_hda6acfd5__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][4U];
    __Vtemp_hda6acfd5__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][5U];
    __Vtemp_hda6acfd5__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][6U];
    __Vtemp_hda6acfd5__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [4U][7U];
    bufp->fullWData(oldp+51,(__Vtemp_hda6acfd5__0),229);
    __Vtemp_hda6ad117__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][0U];
    __Vtemp_hda6ad117__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][1U];
    __Vtemp_hda6ad117__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][2U];
    __Vtemp_hda6ad117__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][3U];
    __Vtemp_hda6ad117__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][4U];
    __Vtemp_hda6ad117__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][5U];
    __Vtemp_hda6ad117__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][6U];
    __Vtemp_hda6ad117__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [5U][7U];
    bufp->fullWData(oldp+59,(__Vtemp_hda6ad117__0),229);
    __Vtemp_hda6ace58__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][0U];
    __Vtemp_hda6ace58__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][1U];
    __Vtemp_hda6ace58__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][2U];
    __Vtemp_hda6ace58__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][3U];
    __Vtemp_hda6ace58__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][4U];
    __Vtemp_hda6ace58__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][5U];
    __Vtemp_hda6ace58__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][6U];
    __Vtemp_hda6ace58__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [6U][7U];
    bufp->fullWData(oldp+67,(__Vtemp_hda6ace58__0),229);
    __Vtemp_hda6ad391__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][0U];
    __Vtemp_hda6ad391__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][1U];
    __Vtemp_hda6ad391__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][2U];
    __Vtemp_hda6ad391__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][3U];
    __Vtemp_hda6ad391__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][4U];
    __Vtemp_hda6ad391__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][5U];
    __Vtemp_hda6ad391__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][6U];
    __Vtemp_hda6ad391__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [7U][7U];
    bufp->fullWData(oldp+75,(__Vtemp_hda6ad391__0),229);
    __Vtemp_hda6ad0d2__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][0U];
    __Vtemp_hda6ad0d2__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][1U];
    __Vtemp_hda6ad0d2__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][2U];
    __Vtemp_hda6ad0d2__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][3U];
    __Vtemp_hda6ad0d2__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][4U];
    __Vtemp_hda6ad0d2__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][5U];
    __Vtemp_hda6ad0d2__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][6U];
    __Vtemp_hda6ad0d2__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [8U][7U];
    bufp->fullWData(oldp+83,(__Vtemp_hda6ad0d2__0),229);
    __Vtemp_hda6aae12__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][0U];
    __Vtemp_hda6aae12__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][1U];
    __Vtemp_hda6aae12__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][2U];
    __Vtemp_hda6aae12__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][3U];
    __Vtemp_hda6aae12__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][4U];
    __Vtemp_hda6aae12__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][5U];
    __Vtemp_hda6aae12__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][6U];
    __Vtemp_hda6aae12__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [9U][7U];
    bufp->fullWData(oldp+91,(__Vtemp_hda6aae12__0),229);
    __Vtemp_hda6aaf51__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][0U];
    __Vtemp_hda6aaf51__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][1U];
    __Vtemp_hda6aaf51__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][2U];
    __Vtemp_hda6aaf51__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][3U];
    __Vtemp_hda6aaf51__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][4U];
    __Vtemp_hda6aaf51__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][5U];
    __Vtemp_hda6aaf51__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][6U];
    __Vtemp_hda6aaf51__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xaU][7U];
    bufp->fullWData(oldp+99,(__Vtemp_hda6aaf51__0),229);
    __Vtemp_hda6aac98__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][0U];
    __Vtemp_hda6aac98__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][1U];
    __Vtemp_hda6aac98__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][2U];
    __Vtemp_hda6aac98__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][3U];
    __Vtemp_hda6aac98__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][4U];
    __Vtemp_hda6aac98__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][5U];
    __Vtemp_hda6aac98__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][6U];
    __Vtemp_hda6aac98__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xbU][7U];
    bufp->fullWData(oldp+107,(__Vtemp_hda6aac98__0),229);
    __Vtemp_hda6aadd7__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][0U];
    __Vtemp_hda6aadd7__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][1U];
    __Vtemp_hda6aadd7__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][2U];
    __Vtemp_hda6aadd7__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][3U];
    __Vtemp_hda6aadd7__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][4U];
    __Vtemp_hda6aadd7__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][5U];
    __Vtemp_hda6aadd7__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][6U];
    __Vtemp_hda6aadd7__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xcU][7U];
    bufp->fullWData(oldp+115,(__Vtemp_hda6aadd7__0),229);
    __Vtemp_hda6aaf15__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][0U];
    __Vtemp_hda6aaf15__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][1U];
    __Vtemp_hda6aaf15__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][2U];
    __Vtemp_hda6aaf15__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][3U];
    __Vtemp_hda6aaf15__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][4U];
    __Vtemp_hda6aaf15__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][5U];
    __Vtemp_hda6aaf15__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][6U];
    __Vtemp_hda6aaf15__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xdU][7U];
    bufp->fullWData(oldp+123,(__Vtemp_hda6aaf15__0),229);
    __Vtemp_hda6aac56__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][0U];
    __Vtemp_hda6aac56__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][1U];
    __Vtemp_hda6aac56__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][2U];
    __Vtemp_hda6aac56__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][3U];
    __Vtemp_hda6aac56__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][4U];
    __Vtemp_hda6aac56__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][5U];
    __Vtemp_hda6aac56__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][6U];
    __Vtemp_hda6aac56__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xeU][7U];
    bufp->fullWData(oldp+131,(__Vtemp_hda6aac56__0),229);
    __Vtemp_hda6ad18b__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][0U];
    __Vtemp_hda6ad18b__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][1U];
    __Vtemp_hda6ad18b__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][2U];
    __Vtemp_hda6ad18b__0[3U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][3U];
    __Vtemp_hda6ad18b__0[4U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][4U];
    __Vtemp_hda6ad18b__0[5U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][5U];
    __Vtemp_hda6ad18b__0[6U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][6U];
    __Vtemp_hda6ad18b__0[7U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__seg_mem_q
        [0xfU][7U];
    bufp->fullWData(oldp+139,(__Vtemp_hda6ad18b__0),229);
    bufp->fullBit(oldp+147,(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d));
    bufp->fullBit(oldp+148,(vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d));
    bufp->fullBit(oldp+149,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q));
    bufp->fullBit(oldp+150,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d));
    bufp->fullCData(oldp+151,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q),4);
    bufp->fullCData(oldp+152,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_d),4);
    bufp->fullCData(oldp+153,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q),5);
    bufp->fullCData(oldp+154,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_d),5);
    bufp->fullIData(oldp+155,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q),32);
    bufp->fullIData(oldp+156,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d),32);
    bufp->fullQData(oldp+157,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q),48);
    bufp->fullQData(oldp+159,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d),48);
    bufp->fullQData(oldp+161,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q),64);
    bufp->fullQData(oldp+163,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d),64);
    bufp->fullWData(oldp+165,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q),81);
    bufp->fullWData(oldp+168,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d),81);
    bufp->fullWData(oldp+171,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q),80);
    bufp->fullWData(oldp+174,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d),80);
    bufp->fullIData(oldp+177,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q),32);
    bufp->fullIData(oldp+178,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d),32);
    bufp->fullCData(oldp+179,(vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d),4);
    bufp->fullBit(oldp+180,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d));
    bufp->fullBit(oldp+181,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d));
    bufp->fullWData(oldp+182,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum),82);
    bufp->fullBit(oldp+185,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load));
    bufp->fullCData(oldp+186,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx),4);
    bufp->fullWData(oldp+187,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load_seg),229);
    bufp->fullCData(oldp+195,((0x1fU & ((IData)(1U) 
                                        + (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q)))),5);
    bufp->fullBit(oldp+196,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q));
    bufp->fullBit(oldp+197,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d));
    bufp->fullBit(oldp+198,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q));
    bufp->fullBit(oldp+199,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_d));
    bufp->fullSData(oldp+200,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q),16);
    bufp->fullSData(oldp+201,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d),16);
    bufp->fullSData(oldp+202,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q),16);
    bufp->fullSData(oldp+203,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_d),16);
    bufp->fullSData(oldp+204,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q),16);
    bufp->fullSData(oldp+205,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_d),16);
    bufp->fullSData(oldp+206,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q),16);
    bufp->fullSData(oldp+207,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_d),16);
    bufp->fullCData(oldp+208,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q),4);
    bufp->fullCData(oldp+209,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d),4);
    bufp->fullBit(oldp+210,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q));
    bufp->fullBit(oldp+211,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d));
    bufp->fullIData(oldp+212,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q),32);
    bufp->fullIData(oldp+213,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d),32);
    bufp->fullBit(oldp+214,((1U & (~ ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q) 
                                      >> 3U)))));
    bufp->fullBit(oldp+215,((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q))));
    bufp->fullBit(oldp+216,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_ok));
    bufp->fullBit(oldp+217,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__rise));
    bufp->fullBit(oldp+218,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__flip_dir));
    bufp->fullBit(oldp+219,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked));
    bufp->fullBit(oldp+220,(vlSelf->clk_i));
    bufp->fullBit(oldp+221,(vlSelf->rst_ni));
    bufp->fullBit(oldp+222,(vlSelf->enable_i));
    bufp->fullSData(oldp+223,(vlSelf->cfg_high_i),16);
    bufp->fullSData(oldp+224,(vlSelf->cfg_low_i),16);
    bufp->fullSData(oldp+225,(vlSelf->cfg_setup_i),16);
    bufp->fullSData(oldp+226,(vlSelf->cfg_hold_i),16);
    bufp->fullBit(oldp+227,(vlSelf->seg_we_i));
    bufp->fullCData(oldp+228,(vlSelf->seg_waddr_i),4);
    bufp->fullWData(oldp+229,(vlSelf->seg_wdata_i),229);
    bufp->fullCData(oldp+237,(vlSelf->seg_count_i),5);
    bufp->fullWData(oldp+238,(vlSelf->pos_frac0_i),80);
    bufp->fullBit(oldp+241,(vlSelf->start_i));
    bufp->fullBit(oldp+242,(vlSelf->abort_i));
    bufp->fullBit(oldp+243,(vlSelf->step_o));
    bufp->fullBit(oldp+244,(vlSelf->dir_o));
    bufp->fullBit(oldp+245,(vlSelf->en_o));
    bufp->fullBit(oldp+246,(vlSelf->busy_o));
    bufp->fullBit(oldp+247,(vlSelf->done_o));
    bufp->fullCData(oldp+248,(vlSelf->phase_o),4);
    bufp->fullBit(oldp+249,(vlSelf->fault_table_o));
    bufp->fullBit(oldp+250,(vlSelf->fault_overrun_o));
    bufp->fullIData(oldp+251,(vlSelf->pulse_count_o),32);
    bufp->fullIData(oldp+252,(vlSelf->ref_pos_int_o),32);
    bufp->fullWData(oldp+253,(vlSelf->ref_pos_frac_o),80);
    bufp->fullWData(oldp+256,(vlSelf->ref_vel_o),81);
    bufp->fullQData(oldp+259,(vlSelf->ref_acc_o),64);
    bufp->fullQData(oldp+261,(vlSelf->ref_jerk_o),48);
    bufp->fullCData(oldp+263,(vlSelf->seg_idx_o),4);
    bufp->fullCData(oldp+264,(vlSelf->step_pending_o),4);
    bufp->fullSData(oldp+265,(0xffffU),16);
    bufp->fullCData(oldp+266,(7U),4);
    bufp->fullCData(oldp+267,(8U),4);
    bufp->fullIData(oldp+268,(0x1312d00U),32);
    bufp->fullIData(oldp+269,(0x50U),32);
    bufp->fullIData(oldp+270,(0x20U),32);
    bufp->fullIData(oldp+271,(0x51U),32);
    bufp->fullIData(oldp+272,(0x40U),32);
    bufp->fullIData(oldp+273,(0x30U),32);
    bufp->fullIData(oldp+274,(0x10U),32);
    bufp->fullIData(oldp+275,(4U),32);
    bufp->fullIData(oldp+276,(5U),32);
}
