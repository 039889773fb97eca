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
    tracep->declBit(c+237,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+238,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+239,"enable_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+240,"cfg_high_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+241,"cfg_low_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+242,"cfg_setup_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+243,"cfg_hold_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBit(c+244,"seg_we_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+245,"seg_waddr_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+246,"seg_phase_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+247,"seg_clocks_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declQuad(c+248,"seg_jerk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declQuad(c+250,"seg_acc0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declArray(c+252,"seg_vel0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declBus(c+255,"seg_count_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 4,0);
    tracep->declArray(c+256,"pos_frac0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declBit(c+259,"start_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+260,"abort_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+261,"step_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+262,"dir_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+263,"en_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+264,"busy_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+265,"done_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+266,"phase_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBit(c+267,"fault_table_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+268,"fault_overrun_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+269,"pulse_count_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declBus(c+270,"ref_pos_int_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declArray(c+271,"ref_pos_frac_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declArray(c+274,"ref_vel_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declQuad(c+277,"ref_acc_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declQuad(c+279,"ref_jerk_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declBus(c+281,"seg_idx_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+282,"step_pending_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->pushNamePrefix("sc_axis_core ");
    tracep->declBit(c+237,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+238,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+239,"enable_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+240,"cfg_high_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+241,"cfg_low_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+242,"cfg_setup_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+243,"cfg_hold_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBit(c+244,"seg_we_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+245,"seg_waddr_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+246,"seg_phase_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+247,"seg_clocks_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declQuad(c+248,"seg_jerk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declQuad(c+250,"seg_acc0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declArray(c+252,"seg_vel0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declBus(c+255,"seg_count_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 4,0);
    tracep->declArray(c+256,"pos_frac0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declBit(c+259,"start_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+260,"abort_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+261,"step_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+262,"dir_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+263,"en_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+264,"busy_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+265,"done_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+266,"phase_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBit(c+267,"fault_table_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+268,"fault_overrun_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+269,"pulse_count_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declBus(c+270,"ref_pos_int_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declArray(c+271,"ref_pos_frac_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declArray(c+274,"ref_vel_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declQuad(c+277,"ref_acc_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declQuad(c+279,"ref_jerk_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declBus(c+281,"seg_idx_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+282,"step_pending_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+283,"PulseTimeW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+284,"SegCntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+285,"FracBits",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+286,"PhaseW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBit(c+1,"exec_running",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+2,"exec_finished",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+267,"exec_fault",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
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
    tracep->declBit(c+237,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+238,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+244,"seg_we_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+245,"seg_waddr_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+246,"seg_phase_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+247,"seg_clocks_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declQuad(c+248,"seg_jerk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declQuad(c+250,"seg_acc0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declArray(c+252,"seg_vel0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declBus(c+15,"seg_count_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 4,0);
    tracep->declArray(c+16,"pos_frac0_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declBit(c+7,"start_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+10,"abort_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+1,"running_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+2,"finished_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+267,"fault_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+3,"step_req_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+4,"step_fwd_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+270,"pos_int_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declArray(c+271,"pos_frac_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 79,0);
    tracep->declArray(c+274,"vel_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 80,0);
    tracep->declQuad(c+277,"acc_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 63,0);
    tracep->declQuad(c+279,"jerk_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 47,0);
    tracep->declBus(c+5,"phase_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+281,"seg_idx_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+285,"FracBits",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+287,"PosIntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+288,"VelW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+289,"AccW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+290,"JerkW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+287,"SegClkW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+286,"SegIdxW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+284,"SegCntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+286,"PhaseW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+283,"MaxSegs",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    for (int i = 0; i < 16; ++i) {
        tracep->declBus(c+19+i*1,"mem_phase_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, true,(i+0), 3,0);
    }
    for (int i = 0; i < 16; ++i) {
        tracep->declBus(c+35+i*1,"mem_clocks_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, true,(i+0), 31,0);
    }
    for (int i = 0; i < 16; ++i) {
        tracep->declQuad(c+51+i*2,"mem_jerk_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, true,(i+0), 47,0);
    }
    for (int i = 0; i < 16; ++i) {
        tracep->declQuad(c+83+i*2,"mem_acc0_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, true,(i+0), 63,0);
    }
    for (int i = 0; i < 16; ++i) {
        tracep->declArray(c+115+i*3,"mem_vel0_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, true,(i+0), 80,0);
    }
    tracep->declBit(c+1,"run_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+163,"run_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+2,"finished_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+164,"finished_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+165,"fault_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+166,"fault_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+167,"idx_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+168,"idx_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+169,"count_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 4,0);
    tracep->declBus(c+170,"count_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 4,0);
    tracep->declBus(c+171,"left_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+172,"left_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declQuad(c+173,"jerk_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 47,0);
    tracep->declQuad(c+175,"jerk_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 47,0);
    tracep->declQuad(c+177,"acc_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 63,0);
    tracep->declQuad(c+179,"acc_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 63,0);
    tracep->declArray(c+181,"vel_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 80,0);
    tracep->declArray(c+184,"vel_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 80,0);
    tracep->declArray(c+187,"frac_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 79,0);
    tracep->declArray(c+190,"frac_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 79,0);
    tracep->declBus(c+193,"pint_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+194,"pint_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+5,"phase_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+195,"phase_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBit(c+3,"step_req_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+196,"step_req_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+4,"step_fwd_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+197,"step_fwd_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declArray(c+198,"pos_sum",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 81,0);
    tracep->declBit(c+201,"load",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+202,"load_idx",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+203,"ld_phase",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+204,"ld_clocks",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declQuad(c+205,"ld_jerk",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 47,0);
    tracep->declQuad(c+207,"ld_acc0",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 63,0);
    tracep->declArray(c+209,"ld_vel0",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 80,0);
    tracep->declBus(c+212,"next_idx_ext",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 4,0);
    tracep->popNamePrefix(1);
    tracep->pushNamePrefix("u_step_gen ");
    tracep->declBit(c+237,"clk_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+238,"rst_ni",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+11,"cfg_high_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+12,"cfg_low_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+13,"cfg_setup_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBus(c+14,"cfg_hold_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1, 15,0);
    tracep->declBit(c+7,"clear_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+3,"step_req_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+4,"step_fwd_i",-1,FST_VD_INPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+261,"step_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+262,"dir_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+6,"busy_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBit(c+268,"overrun_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1);
    tracep->declBus(c+282,"pending_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 3,0);
    tracep->declBus(c+269,"count_o",-1,FST_VD_OUTPUT,FST_VT_VCD_WIRE, false,-1, 31,0);
    tracep->declBus(c+283,"PulseTimeW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+286,"PendW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+287,"PosIntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+291,"CntMax",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 15,0);
    tracep->declBus(c+292,"PendMax",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+293,"PendMin",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBit(c+213,"step_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+214,"step_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+215,"dir_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+216,"dir_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+217,"high_left_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+218,"high_left_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+219,"low_cnt_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+220,"low_cnt_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+221,"since_rise_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+222,"since_rise_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+223,"since_dir_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+224,"since_dir_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 15,0);
    tracep->declBus(c+225,"pend_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBus(c+226,"pend_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 3,0);
    tracep->declBit(c+227,"overrun_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+228,"overrun_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBus(c+229,"count_q",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBus(c+230,"count_d",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1, 31,0);
    tracep->declBit(c+231,"want_fwd",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+232,"have_steps",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+233,"dir_ok",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+234,"rise",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+235,"flip_dir",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->declBit(c+236,"req_blocked",-1, FST_VD_IMPLICIT,FST_VT_SV_LOGIC, false,-1);
    tracep->popNamePrefix(2);
}

VL_ATTR_COLD void Vsc_axis_core___024root__trace_init_sub__TOP__sc_pkg__0(Vsc_axis_core___024root* vlSelf, VerilatedFst* tracep) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_init_sub__TOP__sc_pkg__0\n"); );
    // Init
    const int c = vlSymsp->__Vm_baseCode;
    // Body
    tracep->declBus(c+294,"ClkHz",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+285,"FracBits",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+287,"PosIntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+288,"VelW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+289,"AccW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+290,"JerkW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+287,"SegClkW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+283,"MaxSegs",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+286,"SegIdxW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+284,"SegCntW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+283,"PulseTimeW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+286,"PendW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+286,"PhaseW",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 31,0);
    tracep->declBus(c+295,"PhIdle",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+296,"PhAccJerkUp",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+297,"PhAccConst",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+298,"PhAccJerkDown",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+299,"PhCruise",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+300,"PhDecJerkUp",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+301,"PhDecConst",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+302,"PhDecJerkDown",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+303,"PhDone",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+304,"PhAbort",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
    tracep->declBus(c+305,"PhFault",-1, FST_VD_IMPLICIT,FST_VT_VCD_PARAMETER, false,-1, 3,0);
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
    VlWide<3>/*95:0*/ __Vtemp_h054c5458__0;
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
    bufp->fullCData(oldp+19,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[0]),4);
    bufp->fullCData(oldp+20,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[1]),4);
    bufp->fullCData(oldp+21,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[2]),4);
    bufp->fullCData(oldp+22,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[3]),4);
    bufp->fullCData(oldp+23,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[4]),4);
    bufp->fullCData(oldp+24,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[5]),4);
    bufp->fullCData(oldp+25,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[6]),4);
    bufp->fullCData(oldp+26,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[7]),4);
    bufp->fullCData(oldp+27,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[8]),4);
    bufp->fullCData(oldp+28,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[9]),4);
    bufp->fullCData(oldp+29,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[10]),4);
    bufp->fullCData(oldp+30,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[11]),4);
    bufp->fullCData(oldp+31,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[12]),4);
    bufp->fullCData(oldp+32,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[13]),4);
    bufp->fullCData(oldp+33,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[14]),4);
    bufp->fullCData(oldp+34,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[15]),4);
    bufp->fullIData(oldp+35,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[0]),32);
    bufp->fullIData(oldp+36,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[1]),32);
    bufp->fullIData(oldp+37,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[2]),32);
    bufp->fullIData(oldp+38,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[3]),32);
    bufp->fullIData(oldp+39,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[4]),32);
    bufp->fullIData(oldp+40,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[5]),32);
    bufp->fullIData(oldp+41,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[6]),32);
    bufp->fullIData(oldp+42,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[7]),32);
    bufp->fullIData(oldp+43,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[8]),32);
    bufp->fullIData(oldp+44,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[9]),32);
    bufp->fullIData(oldp+45,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[10]),32);
    bufp->fullIData(oldp+46,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[11]),32);
    bufp->fullIData(oldp+47,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[12]),32);
    bufp->fullIData(oldp+48,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[13]),32);
    bufp->fullIData(oldp+49,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[14]),32);
    bufp->fullIData(oldp+50,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[15]),32);
    bufp->fullQData(oldp+51,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[0]),48);
    bufp->fullQData(oldp+53,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[1]),48);
    bufp->fullQData(oldp+55,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[2]),48);
    bufp->fullQData(oldp+57,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[3]),48);
    bufp->fullQData(oldp+59,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[4]),48);
    bufp->fullQData(oldp+61,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[5]),48);
    bufp->fullQData(oldp+63,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[6]),48);
    bufp->fullQData(oldp+65,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[7]),48);
    bufp->fullQData(oldp+67,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[8]),48);
    bufp->fullQData(oldp+69,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[9]),48);
    bufp->fullQData(oldp+71,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[10]),48);
    bufp->fullQData(oldp+73,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[11]),48);
    bufp->fullQData(oldp+75,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[12]),48);
    bufp->fullQData(oldp+77,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[13]),48);
    bufp->fullQData(oldp+79,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[14]),48);
    bufp->fullQData(oldp+81,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[15]),48);
    bufp->fullQData(oldp+83,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[0]),64);
    bufp->fullQData(oldp+85,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[1]),64);
    bufp->fullQData(oldp+87,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[2]),64);
    bufp->fullQData(oldp+89,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[3]),64);
    bufp->fullQData(oldp+91,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[4]),64);
    bufp->fullQData(oldp+93,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[5]),64);
    bufp->fullQData(oldp+95,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[6]),64);
    bufp->fullQData(oldp+97,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[7]),64);
    bufp->fullQData(oldp+99,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[8]),64);
    bufp->fullQData(oldp+101,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[9]),64);
    bufp->fullQData(oldp+103,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[10]),64);
    bufp->fullQData(oldp+105,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[11]),64);
    bufp->fullQData(oldp+107,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[12]),64);
    bufp->fullQData(oldp+109,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[13]),64);
    bufp->fullQData(oldp+111,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[14]),64);
    bufp->fullQData(oldp+113,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[15]),64);
    bufp->fullWData(oldp+115,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[0]),81);
    bufp->fullWData(oldp+118,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[1]),81);
    bufp->fullWData(oldp+121,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[2]),81);
    bufp->fullWData(oldp+124,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[3]),81);
    bufp->fullWData(oldp+127,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[4]),81);
    bufp->fullWData(oldp+130,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[5]),81);
    bufp->fullWData(oldp+133,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[6]),81);
    bufp->fullWData(oldp+136,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[7]),81);
    bufp->fullWData(oldp+139,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[8]),81);
    bufp->fullWData(oldp+142,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[9]),81);
    bufp->fullWData(oldp+145,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[10]),81);
    bufp->fullWData(oldp+148,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[11]),81);
    bufp->fullWData(oldp+151,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[12]),81);
    bufp->fullWData(oldp+154,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[13]),81);
    bufp->fullWData(oldp+157,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[14]),81);
    bufp->fullWData(oldp+160,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[15]),81);
    bufp->fullBit(oldp+163,(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d));
    bufp->fullBit(oldp+164,(vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d));
    bufp->fullBit(oldp+165,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q));
    bufp->fullBit(oldp+166,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d));
    bufp->fullCData(oldp+167,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q),4);
    bufp->fullCData(oldp+168,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_d),4);
    bufp->fullCData(oldp+169,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q),5);
    bufp->fullCData(oldp+170,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_d),5);
    bufp->fullIData(oldp+171,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q),32);
    bufp->fullIData(oldp+172,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d),32);
    bufp->fullQData(oldp+173,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q),48);
    bufp->fullQData(oldp+175,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d),48);
    bufp->fullQData(oldp+177,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q),64);
    bufp->fullQData(oldp+179,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d),64);
    bufp->fullWData(oldp+181,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q),81);
    bufp->fullWData(oldp+184,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d),81);
    bufp->fullWData(oldp+187,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q),80);
    bufp->fullWData(oldp+190,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d),80);
    bufp->fullIData(oldp+193,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q),32);
    bufp->fullIData(oldp+194,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d),32);
    bufp->fullCData(oldp+195,(vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d),4);
    bufp->fullBit(oldp+196,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d));
    bufp->fullBit(oldp+197,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d));
    bufp->fullWData(oldp+198,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum),82);
    bufp->fullBit(oldp+201,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load));
    bufp->fullCData(oldp+202,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx),4);
    bufp->fullCData(oldp+203,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q
                              [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx]),4);
    bufp->fullIData(oldp+204,(vlSelf->sc_axis_core__DOT__u_exec__DOT__ld_clocks),32);
    bufp->fullQData(oldp+205,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q
                              [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx]),48);
    bufp->fullQData(oldp+207,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q
                              [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx]),64);
    __Vtemp_h054c5458__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
        [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][0U];
    __Vtemp_h054c5458__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
        [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][1U];
    __Vtemp_h054c5458__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
        [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][2U];
    bufp->fullWData(oldp+209,(__Vtemp_h054c5458__0),81);
    bufp->fullCData(oldp+212,((0x1fU & ((IData)(1U) 
                                        + (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q)))),5);
    bufp->fullBit(oldp+213,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q));
    bufp->fullBit(oldp+214,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d));
    bufp->fullBit(oldp+215,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q));
    bufp->fullBit(oldp+216,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_d));
    bufp->fullSData(oldp+217,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q),16);
    bufp->fullSData(oldp+218,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d),16);
    bufp->fullSData(oldp+219,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q),16);
    bufp->fullSData(oldp+220,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_d),16);
    bufp->fullSData(oldp+221,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q),16);
    bufp->fullSData(oldp+222,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_d),16);
    bufp->fullSData(oldp+223,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q),16);
    bufp->fullSData(oldp+224,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_d),16);
    bufp->fullCData(oldp+225,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q),4);
    bufp->fullCData(oldp+226,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d),4);
    bufp->fullBit(oldp+227,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q));
    bufp->fullBit(oldp+228,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d));
    bufp->fullIData(oldp+229,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q),32);
    bufp->fullIData(oldp+230,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d),32);
    bufp->fullBit(oldp+231,((1U & (~ ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q) 
                                      >> 3U)))));
    bufp->fullBit(oldp+232,((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q))));
    bufp->fullBit(oldp+233,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_ok));
    bufp->fullBit(oldp+234,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__rise));
    bufp->fullBit(oldp+235,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__flip_dir));
    bufp->fullBit(oldp+236,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked));
    bufp->fullBit(oldp+237,(vlSelf->clk_i));
    bufp->fullBit(oldp+238,(vlSelf->rst_ni));
    bufp->fullBit(oldp+239,(vlSelf->enable_i));
    bufp->fullSData(oldp+240,(vlSelf->cfg_high_i),16);
    bufp->fullSData(oldp+241,(vlSelf->cfg_low_i),16);
    bufp->fullSData(oldp+242,(vlSelf->cfg_setup_i),16);
    bufp->fullSData(oldp+243,(vlSelf->cfg_hold_i),16);
    bufp->fullBit(oldp+244,(vlSelf->seg_we_i));
    bufp->fullCData(oldp+245,(vlSelf->seg_waddr_i),4);
    bufp->fullCData(oldp+246,(vlSelf->seg_phase_i),4);
    bufp->fullIData(oldp+247,(vlSelf->seg_clocks_i),32);
    bufp->fullQData(oldp+248,(vlSelf->seg_jerk_i),48);
    bufp->fullQData(oldp+250,(vlSelf->seg_acc0_i),64);
    bufp->fullWData(oldp+252,(vlSelf->seg_vel0_i),81);
    bufp->fullCData(oldp+255,(vlSelf->seg_count_i),5);
    bufp->fullWData(oldp+256,(vlSelf->pos_frac0_i),80);
    bufp->fullBit(oldp+259,(vlSelf->start_i));
    bufp->fullBit(oldp+260,(vlSelf->abort_i));
    bufp->fullBit(oldp+261,(vlSelf->step_o));
    bufp->fullBit(oldp+262,(vlSelf->dir_o));
    bufp->fullBit(oldp+263,(vlSelf->en_o));
    bufp->fullBit(oldp+264,(vlSelf->busy_o));
    bufp->fullBit(oldp+265,(vlSelf->done_o));
    bufp->fullCData(oldp+266,(vlSelf->phase_o),4);
    bufp->fullBit(oldp+267,(vlSelf->fault_table_o));
    bufp->fullBit(oldp+268,(vlSelf->fault_overrun_o));
    bufp->fullIData(oldp+269,(vlSelf->pulse_count_o),32);
    bufp->fullIData(oldp+270,(vlSelf->ref_pos_int_o),32);
    bufp->fullWData(oldp+271,(vlSelf->ref_pos_frac_o),80);
    bufp->fullWData(oldp+274,(vlSelf->ref_vel_o),81);
    bufp->fullQData(oldp+277,(vlSelf->ref_acc_o),64);
    bufp->fullQData(oldp+279,(vlSelf->ref_jerk_o),48);
    bufp->fullCData(oldp+281,(vlSelf->seg_idx_o),4);
    bufp->fullCData(oldp+282,(vlSelf->step_pending_o),4);
    bufp->fullIData(oldp+283,(0x10U),32);
    bufp->fullIData(oldp+284,(5U),32);
    bufp->fullIData(oldp+285,(0x50U),32);
    bufp->fullIData(oldp+286,(4U),32);
    bufp->fullIData(oldp+287,(0x20U),32);
    bufp->fullIData(oldp+288,(0x51U),32);
    bufp->fullIData(oldp+289,(0x40U),32);
    bufp->fullIData(oldp+290,(0x30U),32);
    bufp->fullSData(oldp+291,(0xffffU),16);
    bufp->fullCData(oldp+292,(7U),4);
    bufp->fullCData(oldp+293,(8U),4);
    bufp->fullIData(oldp+294,(0x1312d00U),32);
    bufp->fullCData(oldp+295,(0U),4);
    bufp->fullCData(oldp+296,(1U),4);
    bufp->fullCData(oldp+297,(2U),4);
    bufp->fullCData(oldp+298,(3U),4);
    bufp->fullCData(oldp+299,(4U),4);
    bufp->fullCData(oldp+300,(5U),4);
    bufp->fullCData(oldp+301,(6U),4);
    bufp->fullCData(oldp+302,(7U),4);
    bufp->fullCData(oldp+303,(8U),4);
    bufp->fullCData(oldp+304,(9U),4);
    bufp->fullCData(oldp+305,(0xaU),4);
}
