// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Tracing implementation internals
#include "verilated_fst_c.h"
#include "Vsc_axis_core__Syms.h"


void Vsc_axis_core___024root__trace_chg_sub_0(Vsc_axis_core___024root* vlSelf, VerilatedFst::Buffer* bufp);

void Vsc_axis_core___024root__trace_chg_top_0(void* voidSelf, VerilatedFst::Buffer* bufp) {
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_chg_top_0\n"); );
    // Init
    Vsc_axis_core___024root* const __restrict vlSelf VL_ATTR_UNUSED = static_cast<Vsc_axis_core___024root*>(voidSelf);
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    if (VL_UNLIKELY(!vlSymsp->__Vm_activity)) return;
    // Body
    Vsc_axis_core___024root__trace_chg_sub_0((&vlSymsp->TOP), bufp);
}

void Vsc_axis_core___024root__trace_chg_sub_0(Vsc_axis_core___024root* vlSelf, VerilatedFst::Buffer* bufp) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_chg_sub_0\n"); );
    // Init
    uint32_t* const oldp VL_ATTR_UNUSED = bufp->oldp(vlSymsp->__Vm_baseCode + 1);
    VlWide<3>/*95:0*/ __Vtemp_h054c5458__0;
    // Body
    if (VL_UNLIKELY(vlSelf->__Vm_traceActivity[1U])) {
        bufp->chgBit(oldp+0,(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q));
        bufp->chgBit(oldp+1,(vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_q));
        bufp->chgBit(oldp+2,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_q));
        bufp->chgBit(oldp+3,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_q));
        bufp->chgCData(oldp+4,(vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_q),4);
        bufp->chgBit(oldp+5,(((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q)) 
                              | (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q))));
        bufp->chgBit(oldp+6,(vlSelf->sc_axis_core__DOT__start_ok));
        bufp->chgBit(oldp+7,(vlSelf->sc_axis_core__DOT__en_q));
        bufp->chgBit(oldp+8,(vlSelf->sc_axis_core__DOT__start_q));
        bufp->chgBit(oldp+9,(vlSelf->sc_axis_core__DOT__abort_q));
        bufp->chgSData(oldp+10,(vlSelf->sc_axis_core__DOT__cfg_high_q),16);
        bufp->chgSData(oldp+11,(vlSelf->sc_axis_core__DOT__cfg_low_q),16);
        bufp->chgSData(oldp+12,(vlSelf->sc_axis_core__DOT__cfg_setup_q),16);
        bufp->chgSData(oldp+13,(vlSelf->sc_axis_core__DOT__cfg_hold_q),16);
        bufp->chgCData(oldp+14,(vlSelf->sc_axis_core__DOT__seg_count_q),5);
        bufp->chgWData(oldp+15,(vlSelf->sc_axis_core__DOT__pos_frac0_q),80);
        bufp->chgCData(oldp+18,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[0]),4);
        bufp->chgCData(oldp+19,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[1]),4);
        bufp->chgCData(oldp+20,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[2]),4);
        bufp->chgCData(oldp+21,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[3]),4);
        bufp->chgCData(oldp+22,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[4]),4);
        bufp->chgCData(oldp+23,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[5]),4);
        bufp->chgCData(oldp+24,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[6]),4);
        bufp->chgCData(oldp+25,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[7]),4);
        bufp->chgCData(oldp+26,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[8]),4);
        bufp->chgCData(oldp+27,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[9]),4);
        bufp->chgCData(oldp+28,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[10]),4);
        bufp->chgCData(oldp+29,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[11]),4);
        bufp->chgCData(oldp+30,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[12]),4);
        bufp->chgCData(oldp+31,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[13]),4);
        bufp->chgCData(oldp+32,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[14]),4);
        bufp->chgCData(oldp+33,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[15]),4);
        bufp->chgIData(oldp+34,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[0]),32);
        bufp->chgIData(oldp+35,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[1]),32);
        bufp->chgIData(oldp+36,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[2]),32);
        bufp->chgIData(oldp+37,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[3]),32);
        bufp->chgIData(oldp+38,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[4]),32);
        bufp->chgIData(oldp+39,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[5]),32);
        bufp->chgIData(oldp+40,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[6]),32);
        bufp->chgIData(oldp+41,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[7]),32);
        bufp->chgIData(oldp+42,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[8]),32);
        bufp->chgIData(oldp+43,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[9]),32);
        bufp->chgIData(oldp+44,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[10]),32);
        bufp->chgIData(oldp+45,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[11]),32);
        bufp->chgIData(oldp+46,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[12]),32);
        bufp->chgIData(oldp+47,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[13]),32);
        bufp->chgIData(oldp+48,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[14]),32);
        bufp->chgIData(oldp+49,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[15]),32);
        bufp->chgQData(oldp+50,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[0]),48);
        bufp->chgQData(oldp+52,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[1]),48);
        bufp->chgQData(oldp+54,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[2]),48);
        bufp->chgQData(oldp+56,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[3]),48);
        bufp->chgQData(oldp+58,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[4]),48);
        bufp->chgQData(oldp+60,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[5]),48);
        bufp->chgQData(oldp+62,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[6]),48);
        bufp->chgQData(oldp+64,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[7]),48);
        bufp->chgQData(oldp+66,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[8]),48);
        bufp->chgQData(oldp+68,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[9]),48);
        bufp->chgQData(oldp+70,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[10]),48);
        bufp->chgQData(oldp+72,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[11]),48);
        bufp->chgQData(oldp+74,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[12]),48);
        bufp->chgQData(oldp+76,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[13]),48);
        bufp->chgQData(oldp+78,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[14]),48);
        bufp->chgQData(oldp+80,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[15]),48);
        bufp->chgQData(oldp+82,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[0]),64);
        bufp->chgQData(oldp+84,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[1]),64);
        bufp->chgQData(oldp+86,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[2]),64);
        bufp->chgQData(oldp+88,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[3]),64);
        bufp->chgQData(oldp+90,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[4]),64);
        bufp->chgQData(oldp+92,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[5]),64);
        bufp->chgQData(oldp+94,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[6]),64);
        bufp->chgQData(oldp+96,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[7]),64);
        bufp->chgQData(oldp+98,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[8]),64);
        bufp->chgQData(oldp+100,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[9]),64);
        bufp->chgQData(oldp+102,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[10]),64);
        bufp->chgQData(oldp+104,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[11]),64);
        bufp->chgQData(oldp+106,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[12]),64);
        bufp->chgQData(oldp+108,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[13]),64);
        bufp->chgQData(oldp+110,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[14]),64);
        bufp->chgQData(oldp+112,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[15]),64);
        bufp->chgWData(oldp+114,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[0]),81);
        bufp->chgWData(oldp+117,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[1]),81);
        bufp->chgWData(oldp+120,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[2]),81);
        bufp->chgWData(oldp+123,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[3]),81);
        bufp->chgWData(oldp+126,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[4]),81);
        bufp->chgWData(oldp+129,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[5]),81);
        bufp->chgWData(oldp+132,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[6]),81);
        bufp->chgWData(oldp+135,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[7]),81);
        bufp->chgWData(oldp+138,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[8]),81);
        bufp->chgWData(oldp+141,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[9]),81);
        bufp->chgWData(oldp+144,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[10]),81);
        bufp->chgWData(oldp+147,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[11]),81);
        bufp->chgWData(oldp+150,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[12]),81);
        bufp->chgWData(oldp+153,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[13]),81);
        bufp->chgWData(oldp+156,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[14]),81);
        bufp->chgWData(oldp+159,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[15]),81);
        bufp->chgBit(oldp+162,(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d));
        bufp->chgBit(oldp+163,(vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d));
        bufp->chgBit(oldp+164,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q));
        bufp->chgBit(oldp+165,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d));
        bufp->chgCData(oldp+166,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q),4);
        bufp->chgCData(oldp+167,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_d),4);
        bufp->chgCData(oldp+168,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q),5);
        bufp->chgCData(oldp+169,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_d),5);
        bufp->chgIData(oldp+170,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q),32);
        bufp->chgIData(oldp+171,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d),32);
        bufp->chgQData(oldp+172,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q),48);
        bufp->chgQData(oldp+174,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d),48);
        bufp->chgQData(oldp+176,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q),64);
        bufp->chgQData(oldp+178,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d),64);
        bufp->chgWData(oldp+180,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q),81);
        bufp->chgWData(oldp+183,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d),81);
        bufp->chgWData(oldp+186,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q),80);
        bufp->chgWData(oldp+189,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d),80);
        bufp->chgIData(oldp+192,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q),32);
        bufp->chgIData(oldp+193,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d),32);
        bufp->chgCData(oldp+194,(vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d),4);
        bufp->chgBit(oldp+195,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d));
        bufp->chgBit(oldp+196,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d));
        bufp->chgWData(oldp+197,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum),82);
        bufp->chgBit(oldp+200,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load));
        bufp->chgCData(oldp+201,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx),4);
        bufp->chgCData(oldp+202,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q
                                 [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx]),4);
        bufp->chgIData(oldp+203,(vlSelf->sc_axis_core__DOT__u_exec__DOT__ld_clocks),32);
        bufp->chgQData(oldp+204,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q
                                 [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx]),48);
        bufp->chgQData(oldp+206,(vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q
                                 [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx]),64);
        __Vtemp_h054c5458__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
            [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][0U];
        __Vtemp_h054c5458__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
            [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][1U];
        __Vtemp_h054c5458__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
            [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][2U];
        bufp->chgWData(oldp+208,(__Vtemp_h054c5458__0),81);
        bufp->chgCData(oldp+211,((0x1fU & ((IData)(1U) 
                                           + (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q)))),5);
        bufp->chgBit(oldp+212,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q));
        bufp->chgBit(oldp+213,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d));
        bufp->chgBit(oldp+214,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q));
        bufp->chgBit(oldp+215,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_d));
        bufp->chgSData(oldp+216,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q),16);
        bufp->chgSData(oldp+217,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d),16);
        bufp->chgSData(oldp+218,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q),16);
        bufp->chgSData(oldp+219,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_d),16);
        bufp->chgSData(oldp+220,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q),16);
        bufp->chgSData(oldp+221,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_d),16);
        bufp->chgSData(oldp+222,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q),16);
        bufp->chgSData(oldp+223,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_d),16);
        bufp->chgCData(oldp+224,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q),4);
        bufp->chgCData(oldp+225,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d),4);
        bufp->chgBit(oldp+226,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q));
        bufp->chgBit(oldp+227,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d));
        bufp->chgIData(oldp+228,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q),32);
        bufp->chgIData(oldp+229,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d),32);
        bufp->chgBit(oldp+230,((1U & (~ ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q) 
                                         >> 3U)))));
        bufp->chgBit(oldp+231,((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q))));
        bufp->chgBit(oldp+232,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_ok));
        bufp->chgBit(oldp+233,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__rise));
        bufp->chgBit(oldp+234,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__flip_dir));
        bufp->chgBit(oldp+235,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked));
    }
    bufp->chgBit(oldp+236,(vlSelf->clk_i));
    bufp->chgBit(oldp+237,(vlSelf->rst_ni));
    bufp->chgBit(oldp+238,(vlSelf->enable_i));
    bufp->chgSData(oldp+239,(vlSelf->cfg_high_i),16);
    bufp->chgSData(oldp+240,(vlSelf->cfg_low_i),16);
    bufp->chgSData(oldp+241,(vlSelf->cfg_setup_i),16);
    bufp->chgSData(oldp+242,(vlSelf->cfg_hold_i),16);
    bufp->chgBit(oldp+243,(vlSelf->seg_we_i));
    bufp->chgCData(oldp+244,(vlSelf->seg_waddr_i),4);
    bufp->chgCData(oldp+245,(vlSelf->seg_phase_i),4);
    bufp->chgIData(oldp+246,(vlSelf->seg_clocks_i),32);
    bufp->chgQData(oldp+247,(vlSelf->seg_jerk_i),48);
    bufp->chgQData(oldp+249,(vlSelf->seg_acc0_i),64);
    bufp->chgWData(oldp+251,(vlSelf->seg_vel0_i),81);
    bufp->chgCData(oldp+254,(vlSelf->seg_count_i),5);
    bufp->chgWData(oldp+255,(vlSelf->pos_frac0_i),80);
    bufp->chgBit(oldp+258,(vlSelf->start_i));
    bufp->chgBit(oldp+259,(vlSelf->abort_i));
    bufp->chgBit(oldp+260,(vlSelf->step_o));
    bufp->chgBit(oldp+261,(vlSelf->dir_o));
    bufp->chgBit(oldp+262,(vlSelf->en_o));
    bufp->chgBit(oldp+263,(vlSelf->busy_o));
    bufp->chgBit(oldp+264,(vlSelf->done_o));
    bufp->chgCData(oldp+265,(vlSelf->phase_o),4);
    bufp->chgBit(oldp+266,(vlSelf->fault_table_o));
    bufp->chgBit(oldp+267,(vlSelf->fault_overrun_o));
    bufp->chgIData(oldp+268,(vlSelf->pulse_count_o),32);
    bufp->chgIData(oldp+269,(vlSelf->ref_pos_int_o),32);
    bufp->chgWData(oldp+270,(vlSelf->ref_pos_frac_o),80);
    bufp->chgWData(oldp+273,(vlSelf->ref_vel_o),81);
    bufp->chgQData(oldp+276,(vlSelf->ref_acc_o),64);
    bufp->chgQData(oldp+278,(vlSelf->ref_jerk_o),48);
    bufp->chgCData(oldp+280,(vlSelf->seg_idx_o),4);
    bufp->chgCData(oldp+281,(vlSelf->step_pending_o),4);
}

void Vsc_axis_core___024root__trace_cleanup(void* voidSelf, VerilatedFst* /*unused*/) {
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root__trace_cleanup\n"); );
    // Init
    Vsc_axis_core___024root* const __restrict vlSelf VL_ATTR_UNUSED = static_cast<Vsc_axis_core___024root*>(voidSelf);
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    // Body
    vlSymsp->__Vm_activity = false;
    vlSymsp->TOP.__Vm_traceActivity[0U] = 0U;
    vlSymsp->TOP.__Vm_traceActivity[1U] = 0U;
}
