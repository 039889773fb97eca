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
        bufp->chgWData(oldp+18,(__Vtemp_hda6aaae8__0),229);
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
        bufp->chgWData(oldp+26,(__Vtemp_hda6ad00c__0),229);
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
        bufp->chgWData(oldp+34,(__Vtemp_hda6ad14b__0),229);
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
        bufp->chgWData(oldp+42,(__Vtemp_hda6ace96__0),229);
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
        bufp->chgWData(oldp+50,(__Vtemp_hda6acfd5__0),229);
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
        bufp->chgWData(oldp+58,(__Vtemp_hda6ad117__0),229);
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
        bufp->chgWData(oldp+66,(__Vtemp_hda6ace58__0),229);
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
        bufp->chgWData(oldp+74,(__Vtemp_hda6ad391__0),229);
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
        bufp->chgWData(oldp+82,(__Vtemp_hda6ad0d2__0),229);
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
        bufp->chgWData(oldp+90,(__Vtemp_hda6aae12__0),229);
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
        bufp->chgWData(oldp+98,(__Vtemp_hda6aaf51__0),229);
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
        bufp->chgWData(oldp+106,(__Vtemp_hda6aac98__0),229);
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
        bufp->chgWData(oldp+114,(__Vtemp_hda6aadd7__0),229);
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
        bufp->chgWData(oldp+122,(__Vtemp_hda6aaf15__0),229);
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
        bufp->chgWData(oldp+130,(__Vtemp_hda6aac56__0),229);
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
        bufp->chgWData(oldp+138,(__Vtemp_hda6ad18b__0),229);
        bufp->chgBit(oldp+146,(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d));
        bufp->chgBit(oldp+147,(vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d));
        bufp->chgBit(oldp+148,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q));
        bufp->chgBit(oldp+149,(vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d));
        bufp->chgCData(oldp+150,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q),4);
        bufp->chgCData(oldp+151,(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_d),4);
        bufp->chgCData(oldp+152,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q),5);
        bufp->chgCData(oldp+153,(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_d),5);
        bufp->chgIData(oldp+154,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q),32);
        bufp->chgIData(oldp+155,(vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d),32);
        bufp->chgQData(oldp+156,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q),48);
        bufp->chgQData(oldp+158,(vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d),48);
        bufp->chgQData(oldp+160,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q),64);
        bufp->chgQData(oldp+162,(vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d),64);
        bufp->chgWData(oldp+164,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q),81);
        bufp->chgWData(oldp+167,(vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d),81);
        bufp->chgWData(oldp+170,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q),80);
        bufp->chgWData(oldp+173,(vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d),80);
        bufp->chgIData(oldp+176,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q),32);
        bufp->chgIData(oldp+177,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d),32);
        bufp->chgCData(oldp+178,(vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d),4);
        bufp->chgBit(oldp+179,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d));
        bufp->chgBit(oldp+180,(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d));
        bufp->chgWData(oldp+181,(vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum),82);
        bufp->chgBit(oldp+184,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load));
        bufp->chgCData(oldp+185,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx),4);
        bufp->chgWData(oldp+186,(vlSelf->sc_axis_core__DOT__u_exec__DOT__load_seg),229);
        bufp->chgCData(oldp+194,((0x1fU & ((IData)(1U) 
                                           + (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q)))),5);
        bufp->chgBit(oldp+195,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q));
        bufp->chgBit(oldp+196,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d));
        bufp->chgBit(oldp+197,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q));
        bufp->chgBit(oldp+198,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_d));
        bufp->chgSData(oldp+199,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q),16);
        bufp->chgSData(oldp+200,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d),16);
        bufp->chgSData(oldp+201,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q),16);
        bufp->chgSData(oldp+202,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_d),16);
        bufp->chgSData(oldp+203,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q),16);
        bufp->chgSData(oldp+204,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_d),16);
        bufp->chgSData(oldp+205,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q),16);
        bufp->chgSData(oldp+206,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_d),16);
        bufp->chgCData(oldp+207,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q),4);
        bufp->chgCData(oldp+208,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d),4);
        bufp->chgBit(oldp+209,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q));
        bufp->chgBit(oldp+210,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d));
        bufp->chgIData(oldp+211,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q),32);
        bufp->chgIData(oldp+212,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d),32);
        bufp->chgBit(oldp+213,((1U & (~ ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q) 
                                         >> 3U)))));
        bufp->chgBit(oldp+214,((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q))));
        bufp->chgBit(oldp+215,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_ok));
        bufp->chgBit(oldp+216,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__rise));
        bufp->chgBit(oldp+217,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__flip_dir));
        bufp->chgBit(oldp+218,(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked));
    }
    bufp->chgBit(oldp+219,(vlSelf->clk_i));
    bufp->chgBit(oldp+220,(vlSelf->rst_ni));
    bufp->chgBit(oldp+221,(vlSelf->enable_i));
    bufp->chgSData(oldp+222,(vlSelf->cfg_high_i),16);
    bufp->chgSData(oldp+223,(vlSelf->cfg_low_i),16);
    bufp->chgSData(oldp+224,(vlSelf->cfg_setup_i),16);
    bufp->chgSData(oldp+225,(vlSelf->cfg_hold_i),16);
    bufp->chgBit(oldp+226,(vlSelf->seg_we_i));
    bufp->chgCData(oldp+227,(vlSelf->seg_waddr_i),4);
    bufp->chgWData(oldp+228,(vlSelf->seg_wdata_i),229);
    bufp->chgCData(oldp+236,(vlSelf->seg_count_i),5);
    bufp->chgWData(oldp+237,(vlSelf->pos_frac0_i),80);
    bufp->chgBit(oldp+240,(vlSelf->start_i));
    bufp->chgBit(oldp+241,(vlSelf->abort_i));
    bufp->chgBit(oldp+242,(vlSelf->step_o));
    bufp->chgBit(oldp+243,(vlSelf->dir_o));
    bufp->chgBit(oldp+244,(vlSelf->en_o));
    bufp->chgBit(oldp+245,(vlSelf->busy_o));
    bufp->chgBit(oldp+246,(vlSelf->done_o));
    bufp->chgCData(oldp+247,(vlSelf->phase_o),4);
    bufp->chgBit(oldp+248,(vlSelf->fault_table_o));
    bufp->chgBit(oldp+249,(vlSelf->fault_overrun_o));
    bufp->chgIData(oldp+250,(vlSelf->pulse_count_o),32);
    bufp->chgIData(oldp+251,(vlSelf->ref_pos_int_o),32);
    bufp->chgWData(oldp+252,(vlSelf->ref_pos_frac_o),80);
    bufp->chgWData(oldp+255,(vlSelf->ref_vel_o),81);
    bufp->chgQData(oldp+258,(vlSelf->ref_acc_o),64);
    bufp->chgQData(oldp+260,(vlSelf->ref_jerk_o),48);
    bufp->chgCData(oldp+262,(vlSelf->seg_idx_o),4);
    bufp->chgCData(oldp+263,(vlSelf->step_pending_o),4);
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
