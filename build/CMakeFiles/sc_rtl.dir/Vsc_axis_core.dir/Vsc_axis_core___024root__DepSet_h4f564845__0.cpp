// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Design implementation internals
// See Vsc_axis_core.h for the primary calling header

#include "verilated.h"

#include "Vsc_axis_core___024root.h"

void Vsc_axis_core___024root___eval_act(Vsc_axis_core___024root* vlSelf) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root___eval_act\n"); );
}

VL_INLINE_OPT void Vsc_axis_core___024root___nba_sequent__TOP__0(Vsc_axis_core___024root* vlSelf) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root___nba_sequent__TOP__0\n"); );
    // Init
    SData/*15:0*/ __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__Vfuncout;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__Vfuncout = 0;
    SData/*15:0*/ __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__v;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__v = 0;
    SData/*15:0*/ __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__Vfuncout;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__Vfuncout = 0;
    SData/*15:0*/ __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__v;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__v = 0;
    SData/*15:0*/ __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__Vfuncout;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__Vfuncout = 0;
    SData/*15:0*/ __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__v;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__v = 0;
    CData/*3:0*/ __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0;
    __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0 = 0;
    CData/*3:0*/ __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0;
    __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0 = 0;
    CData/*0:0*/ __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0 = 0;
    CData/*3:0*/ __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0;
    __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0 = 0;
    QData/*63:0*/ __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0;
    __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0 = 0;
    CData/*0:0*/ __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0 = 0;
    CData/*3:0*/ __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0;
    __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0 = 0;
    IData/*31:0*/ __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0;
    __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0 = 0;
    CData/*0:0*/ __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0 = 0;
    CData/*3:0*/ __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0;
    __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0 = 0;
    QData/*47:0*/ __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0;
    __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0 = 0;
    CData/*0:0*/ __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0 = 0;
    CData/*3:0*/ __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0;
    __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0 = 0;
    VlWide<3>/*80:0*/ __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0;
    VL_ZERO_W(81, __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0);
    CData/*0:0*/ __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0 = 0;
    VlWide<3>/*95:0*/ __Vtemp_h68fa04a4__0;
    VlWide<3>/*95:0*/ __Vtemp_h250b1d4a__0;
    VlWide<3>/*95:0*/ __Vtemp_h54adfcc2__0;
    VlWide<3>/*95:0*/ __Vtemp_h97375c78__0;
    VlWide<3>/*95:0*/ __Vtemp_hc514e7b5__0;
    // Body
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0 = 0U;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0 = 0U;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0 = 0U;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0 = 0U;
    __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0 = 0U;
    if (((IData)(vlSelf->seg_we_i) & (~ (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q)))) {
        __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0 
            = vlSelf->seg_jerk_i;
        __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0 = 1U;
        __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0 
            = vlSelf->seg_waddr_i;
        __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0 
            = vlSelf->seg_phase_i;
        __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0 = 1U;
        __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0 
            = vlSelf->seg_waddr_i;
        __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0[0U] 
            = vlSelf->seg_vel0_i[0U];
        __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0[1U] 
            = vlSelf->seg_vel0_i[1U];
        __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0[2U] 
            = vlSelf->seg_vel0_i[2U];
        __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0 = 1U;
        __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0 
            = vlSelf->seg_waddr_i;
        __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0 
            = vlSelf->seg_acc0_i;
        __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0 = 1U;
        __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0 
            = vlSelf->seg_waddr_i;
        __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0 
            = vlSelf->seg_clocks_i;
        __Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0 = 1U;
        __Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0 
            = vlSelf->seg_waddr_i;
    }
    if (vlSelf->rst_ni) {
        vlSelf->sc_axis_core__DOT__cfg_high_q = vlSelf->cfg_high_i;
        vlSelf->sc_axis_core__DOT__pos_frac0_q[0U] 
            = vlSelf->pos_frac0_i[0U];
        vlSelf->sc_axis_core__DOT__pos_frac0_q[1U] 
            = vlSelf->pos_frac0_i[1U];
        vlSelf->sc_axis_core__DOT__pos_frac0_q[2U] 
            = vlSelf->pos_frac0_i[2U];
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d;
        vlSelf->sc_axis_core__DOT__cfg_hold_q = vlSelf->cfg_hold_i;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[0U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[0U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[1U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[1U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[2U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[2U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[0U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[1U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[2U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U];
        vlSelf->sc_axis_core__DOT__cfg_setup_q = vlSelf->cfg_setup_i;
        vlSelf->sc_axis_core__DOT__cfg_low_q = vlSelf->cfg_low_i;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_d;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_d;
        vlSelf->sc_axis_core__DOT__seg_count_q = vlSelf->seg_count_i;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__count_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_q 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d;
    } else {
        vlSelf->sc_axis_core__DOT__cfg_high_q = 0U;
        vlSelf->sc_axis_core__DOT__pos_frac0_q[0U] = 0U;
        vlSelf->sc_axis_core__DOT__pos_frac0_q[1U] = 0U;
        vlSelf->sc_axis_core__DOT__pos_frac0_q[2U] = 0U;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_q = 0U;
        vlSelf->sc_axis_core__DOT__cfg_hold_q = 0U;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q = 0ULL;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q = 0ULL;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q = 0xffffU;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[0U] = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[1U] = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[2U] = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[0U] = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[1U] = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[2U] = 0U;
        vlSelf->sc_axis_core__DOT__cfg_setup_q = 0U;
        vlSelf->sc_axis_core__DOT__cfg_low_q = 0U;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q = 0xffffU;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q = 0xffffU;
        vlSelf->sc_axis_core__DOT__seg_count_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q = 0U;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_q = 0U;
    }
    vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_q 
        = (1U & ((~ (IData)(vlSelf->rst_ni)) | (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d)));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q 
        = ((IData)(vlSelf->rst_ni) & (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q 
        = (1U & ((~ (IData)(vlSelf->rst_ni)) | (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_d)));
    vlSelf->sc_axis_core__DOT__start_q = ((IData)(vlSelf->rst_ni) 
                                          & (IData)(vlSelf->start_i));
    vlSelf->sc_axis_core__DOT__en_q = ((IData)(vlSelf->rst_ni) 
                                       & (IData)(vlSelf->enable_i));
    vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_q 
        = ((IData)(vlSelf->rst_ni) & (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q 
        = ((IData)(vlSelf->rst_ni) & (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d));
    vlSelf->sc_axis_core__DOT__abort_q = ((IData)(vlSelf->rst_ni) 
                                          & (IData)(vlSelf->abort_i));
    if (__Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0) {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q[__Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0] 
            = __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_jerk_q__v0;
    }
    if (__Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0) {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q[__Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0] 
            = __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_phase_q__v0;
    }
    if (__Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0) {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[__Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0][0U] 
            = __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0[0U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[__Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0][1U] 
            = __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0[1U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q[__Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0][2U] 
            = __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_vel0_q__v0[2U];
    }
    if (__Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0) {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q[__Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0] 
            = __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_acc0_q__v0;
    }
    if (__Vdlyvset__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0) {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q[__Vdlyvdim0__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0] 
            = __Vdlyvval__sc_axis_core__DOT__u_exec__DOT__mem_clocks_q__v0;
    }
    vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q = 
        ((IData)(vlSelf->rst_ni) & (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d));
    vlSelf->pulse_count_o = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q;
    vlSelf->ref_pos_int_o = vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q;
    vlSelf->fault_table_o = vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q;
    vlSelf->fault_overrun_o = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q;
    vlSelf->ref_jerk_o = vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q;
    vlSelf->ref_acc_o = vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q;
    vlSelf->ref_pos_frac_o[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[0U];
    vlSelf->ref_pos_frac_o[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[1U];
    vlSelf->ref_pos_frac_o[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[2U];
    vlSelf->ref_vel_o[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[0U];
    vlSelf->ref_vel_o[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[1U];
    vlSelf->ref_vel_o[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[2U];
    __Vtemp_h68fa04a4__0[0U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[0U];
    __Vtemp_h68fa04a4__0[1U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[1U];
    __Vtemp_h68fa04a4__0[2U] = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[2U];
    VL_EXTENDS_WW(82,81, __Vtemp_h250b1d4a__0, vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q);
    VL_ADD_W(3, __Vtemp_h54adfcc2__0, __Vtemp_h68fa04a4__0, __Vtemp_h250b1d4a__0);
    vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[0U] 
        = __Vtemp_h54adfcc2__0[0U];
    vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[1U] 
        = __Vtemp_h54adfcc2__0[1U];
    vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[2U] 
        = (0x3ffffU & __Vtemp_h54adfcc2__0[2U]);
    vlSelf->dir_o = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q;
    vlSelf->en_o = vlSelf->sc_axis_core__DOT__en_q;
    vlSelf->seg_idx_o = vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q;
    vlSelf->step_o = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q;
    vlSelf->step_pending_o = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q;
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_ok 
        = ((1U & (~ ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q) 
                     >> 3U))) == (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__flip_dir 
        = ((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q)) 
           & ((~ (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_ok)) 
              & ((~ (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q)) 
                 & ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q) 
                    >= (IData)(vlSelf->sc_axis_core__DOT__cfg_hold_q)))));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__rise 
        = ((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q)) 
           & ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_ok) 
              & ((~ (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q)) 
                 & (((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q) 
                     >= (IData)(vlSelf->sc_axis_core__DOT__cfg_low_q)) 
                    & ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q) 
                       >= (IData)(vlSelf->sc_axis_core__DOT__cfg_setup_q))))));
    vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d = 0U;
    vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d 
        = vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q;
    vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d 
        = vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_q;
    vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx = 0U;
    vlSelf->busy_o = ((IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q) 
                      | ((IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_q) 
                         | ((0U != (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q)) 
                            | (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q))));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_d 
        = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__v 
        = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_q;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__Vfuncout 
        = (0xffffU & ((0xffffU == (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__v))
                       ? (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__v)
                       : ((IData)(1U) + (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__v))));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_d 
        = __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__0__Vfuncout;
    if (vlSelf->sc_axis_core__DOT__u_step_gen__DOT__flip_dir) {
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_d 
            = (1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q)));
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_dir_d = 1U;
    }
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d 
        = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__v 
        = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_q;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__Vfuncout 
        = (0xffffU & ((0xffffU == (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__v))
                       ? (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__v)
                       : ((IData)(1U) + (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__v))));
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_d 
        = __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__1__Vfuncout;
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d 
        = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__v 
        = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q;
    __Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__Vfuncout 
        = (0xffffU & ((0xffffU == (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__v))
                       ? (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__v)
                       : ((IData)(1U) + (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__v))));
    if (vlSelf->sc_axis_core__DOT__u_step_gen__DOT__rise) {
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d 
            = vlSelf->sc_axis_core__DOT__cfg_high_q;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__since_rise_d = 1U;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d = 1U;
    } else if (vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_q) {
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_d 
            = (0xffffU & ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q) 
                          - (IData)(1U)));
        if ((1U >= (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__high_left_q))) {
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d = 0U;
        }
    }
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__low_cnt_d 
        = ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__step_d)
            ? 0U : (IData)(__Vfunc_sc_axis_core__DOT__u_step_gen__DOT__sat_inc__2__Vfuncout));
    if (vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q) {
        if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__abort_q)))) {
            if ((0x20000U & vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[2U])) {
                vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d = 1U;
                vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d 
                    = (vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q 
                       - (IData)(1U));
                vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d = 0U;
            } else if ((0x10000U & vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[2U])) {
                vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_d = 1U;
                vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_d 
                    = ((IData)(1U) + vlSelf->sc_axis_core__DOT__u_exec__DOT__pint_q);
                vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_d = 1U;
            }
        }
        if ((((~ (IData)(vlSelf->sc_axis_core__DOT__abort_q)) 
              & (1U == vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q)) 
             & ((0x1fU & ((IData)(1U) + (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q))) 
                < (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q)))) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx 
                = (0xfU & ((IData)(1U) + (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q)));
        }
    }
    vlSelf->sc_axis_core__DOT__u_exec__DOT__ld_clocks 
        = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_clocks_q
        [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx];
    vlSelf->done_o = ((~ (IData)(vlSelf->busy_o)) & (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_q));
    vlSelf->sc_axis_core__DOT__start_ok = ((IData)(vlSelf->sc_axis_core__DOT__start_q) 
                                           & ((~ (IData)(vlSelf->busy_o)) 
                                              & (IData)(vlSelf->sc_axis_core__DOT__en_q)));
    vlSelf->phase_o = ((IData)(vlSelf->done_o) ? 8U
                        : (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_q));
    vlSelf->sc_axis_core__DOT__u_exec__DOT__count_d 
        = vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q;
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d 
        = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q;
    if (vlSelf->sc_axis_core__DOT__u_step_gen__DOT__rise) {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[0U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[0U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[1U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[1U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[2U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[2U];
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q;
        if (vlSelf->sc_axis_core__DOT__u_step_gen__DOT__dir_q) {
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d 
                = ((IData)(1U) + vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q);
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d 
                = (0xfU & ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q) 
                           - (IData)(1U)));
        } else {
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d 
                = (vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_q 
                   - (IData)(1U));
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d 
                = (0xfU & ((IData)(1U) + (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q)));
        }
    } else {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[0U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[0U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[1U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[1U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[2U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_q[2U];
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_q;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d 
            = vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_q;
    }
    vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked = 0U;
    if (vlSelf->sc_axis_core__DOT__u_exec__DOT__step_req_q) {
        if (vlSelf->sc_axis_core__DOT__u_exec__DOT__step_fwd_q) {
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked 
                = (7U == (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d));
            if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked)))) {
                vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d 
                    = (0xfU & ((IData)(1U) + (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d)));
            }
        } else {
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked 
                = (8U == (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d));
            if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked)))) {
                vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d 
                    = (0xfU & ((IData)(vlSelf->sc_axis_core__DOT__u_step_gen__DOT__pend_d) 
                               - (IData)(1U)));
            }
        }
        if (vlSelf->sc_axis_core__DOT__u_step_gen__DOT__req_blocked) {
            vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d = 1U;
        }
    }
    if (vlSelf->sc_axis_core__DOT__start_ok) {
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__count_d = 0U;
        vlSelf->sc_axis_core__DOT__u_step_gen__DOT__overrun_d = 0U;
    }
    vlSelf->sc_axis_core__DOT__u_exec__DOT__load = 0U;
    vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_d = vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q;
    vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d 
        = vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q;
    vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d 
        = vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_q;
    if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q)))) {
        if (vlSelf->sc_axis_core__DOT__start_ok) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__count_d 
                = vlSelf->sc_axis_core__DOT__seg_count_q;
        }
    }
    if (vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q) {
        if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__abort_q)))) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[0U] 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[0U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[1U] 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[1U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[2U] 
                = (0xffffU & vlSelf->sc_axis_core__DOT__u_exec__DOT__pos_sum[2U]);
        }
        if ((((~ (IData)(vlSelf->sc_axis_core__DOT__abort_q)) 
              & (1U == vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q)) 
             & ((0x1fU & ((IData)(1U) + (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_q))) 
                < (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__count_q)))) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__load = 1U;
        }
    } else {
        if (vlSelf->sc_axis_core__DOT__start_ok) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[0U] 
                = vlSelf->sc_axis_core__DOT__pos_frac0_q[0U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[1U] 
                = vlSelf->sc_axis_core__DOT__pos_frac0_q[1U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__frac_d[2U] 
                = vlSelf->sc_axis_core__DOT__pos_frac0_q[2U];
        }
        if ((((IData)(vlSelf->sc_axis_core__DOT__start_ok) 
              & (0U != (IData)(vlSelf->sc_axis_core__DOT__seg_count_q))) 
             & (0x10U >= (IData)(vlSelf->sc_axis_core__DOT__seg_count_q)))) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__load = 1U;
        }
    }
    if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q)))) {
        if (vlSelf->sc_axis_core__DOT__start_ok) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d = 0U;
            if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__load)))) {
                vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d = 1U;
            }
        }
    }
    if (vlSelf->sc_axis_core__DOT__u_exec__DOT__run_q) {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d = 1U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_q;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_q;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[0U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[1U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[2U];
        if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__abort_q)))) {
            if ((1U != vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q)) {
                vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d 
                    = (vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q 
                       - (IData)(1U));
            }
            if ((1U == vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q)) {
                if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__load)))) {
                    vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d = 1U;
                }
            }
        }
        vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q;
        if (vlSelf->sc_axis_core__DOT__abort_q) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d = 0U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d = 9U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d = 0ULL;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U] = 0U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U] = 0U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U] = 0U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d = 0ULL;
        } else if ((1U == vlSelf->sc_axis_core__DOT__u_exec__DOT__left_q)) {
            if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__load)))) {
                vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d = 0U;
                vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d = 0ULL;
                vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U] = 0U;
                vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U] = 0U;
                vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U] = 0U;
                vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d = 0ULL;
            }
        } else {
            VL_EXTENDS_WQ(81,64, __Vtemp_h97375c78__0, vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q);
            VL_ADD_W(3, __Vtemp_hc514e7b5__0, vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q, __Vtemp_h97375c78__0);
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U] 
                = __Vtemp_hc514e7b5__0[0U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U] 
                = __Vtemp_hc514e7b5__0[1U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U] 
                = (0x1ffffU & __Vtemp_hc514e7b5__0[2U]);
            vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d 
                = (vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q 
                   + VL_EXTENDS_QQ(64,48, vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q));
        }
    } else {
        vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d = 0U;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_q;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_q;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_q;
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[0U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[1U];
        vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U] 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_q[2U];
        if (vlSelf->sc_axis_core__DOT__start_ok) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__finished_d = 0U;
            if ((1U & (~ (IData)(vlSelf->sc_axis_core__DOT__u_exec__DOT__load)))) {
                vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d = 0xaU;
            }
        }
        vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d 
            = vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_q;
    }
    if (vlSelf->sc_axis_core__DOT__u_exec__DOT__load) {
        if ((0U != vlSelf->sc_axis_core__DOT__u_exec__DOT__ld_clocks)) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__idx_d 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__left_d 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__ld_clocks;
        }
        if ((0U == vlSelf->sc_axis_core__DOT__u_exec__DOT__ld_clocks)) {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__fault_d = 1U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d = 0xaU;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d = 0ULL;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U] = 0U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U] = 0U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U] = 0U;
            vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d = 0ULL;
        } else {
            vlSelf->sc_axis_core__DOT__u_exec__DOT__phase_d 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_phase_q
                [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__jerk_d 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_jerk_q
                [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[0U] 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
                [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][0U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[1U] 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
                [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][1U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__vel_d[2U] 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_vel0_q
                [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx][2U];
            vlSelf->sc_axis_core__DOT__u_exec__DOT__acc_d 
                = vlSelf->sc_axis_core__DOT__u_exec__DOT__mem_acc0_q
                [vlSelf->sc_axis_core__DOT__u_exec__DOT__load_idx];
        }
        vlSelf->sc_axis_core__DOT__u_exec__DOT__run_d 
            = (0U != vlSelf->sc_axis_core__DOT__u_exec__DOT__ld_clocks);
    }
}

void Vsc_axis_core___024root___eval_nba(Vsc_axis_core___024root* vlSelf) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root___eval_nba\n"); );
    // Body
    if (vlSelf->__VnbaTriggered.at(0U)) {
        Vsc_axis_core___024root___nba_sequent__TOP__0(vlSelf);
        vlSelf->__Vm_traceActivity[1U] = 1U;
    }
}

void Vsc_axis_core___024root___eval_triggers__act(Vsc_axis_core___024root* vlSelf);
#ifdef VL_DEBUG
VL_ATTR_COLD void Vsc_axis_core___024root___dump_triggers__act(Vsc_axis_core___024root* vlSelf);
#endif  // VL_DEBUG
#ifdef VL_DEBUG
VL_ATTR_COLD void Vsc_axis_core___024root___dump_triggers__nba(Vsc_axis_core___024root* vlSelf);
#endif  // VL_DEBUG

void Vsc_axis_core___024root___eval(Vsc_axis_core___024root* vlSelf) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root___eval\n"); );
    // Init
    VlTriggerVec<1> __VpreTriggered;
    IData/*31:0*/ __VnbaIterCount;
    CData/*0:0*/ __VnbaContinue;
    // Body
    __VnbaIterCount = 0U;
    __VnbaContinue = 1U;
    while (__VnbaContinue) {
        __VnbaContinue = 0U;
        vlSelf->__VnbaTriggered.clear();
        vlSelf->__VactIterCount = 0U;
        vlSelf->__VactContinue = 1U;
        while (vlSelf->__VactContinue) {
            vlSelf->__VactContinue = 0U;
            Vsc_axis_core___024root___eval_triggers__act(vlSelf);
            if (vlSelf->__VactTriggered.any()) {
                vlSelf->__VactContinue = 1U;
                if (VL_UNLIKELY((0x64U < vlSelf->__VactIterCount))) {
#ifdef VL_DEBUG
                    Vsc_axis_core___024root___dump_triggers__act(vlSelf);
#endif
                    VL_FATAL_MT("/work/main/rtl/sc_axis_core.sv", 10, "", "Active region did not converge.");
                }
                vlSelf->__VactIterCount = ((IData)(1U) 
                                           + vlSelf->__VactIterCount);
                __VpreTriggered.andNot(vlSelf->__VactTriggered, vlSelf->__VnbaTriggered);
                vlSelf->__VnbaTriggered.set(vlSelf->__VactTriggered);
                Vsc_axis_core___024root___eval_act(vlSelf);
            }
        }
        if (vlSelf->__VnbaTriggered.any()) {
            __VnbaContinue = 1U;
            if (VL_UNLIKELY((0x64U < __VnbaIterCount))) {
#ifdef VL_DEBUG
                Vsc_axis_core___024root___dump_triggers__nba(vlSelf);
#endif
                VL_FATAL_MT("/work/main/rtl/sc_axis_core.sv", 10, "", "NBA region did not converge.");
            }
            __VnbaIterCount = ((IData)(1U) + __VnbaIterCount);
            Vsc_axis_core___024root___eval_nba(vlSelf);
        }
    }
}

#ifdef VL_DEBUG
void Vsc_axis_core___024root___eval_debug_assertions(Vsc_axis_core___024root* vlSelf) {
    if (false && vlSelf) {}  // Prevent unused
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    VL_DEBUG_IF(VL_DBG_MSGF("+    Vsc_axis_core___024root___eval_debug_assertions\n"); );
    // Body
    if (VL_UNLIKELY((vlSelf->clk_i & 0xfeU))) {
        Verilated::overWidthError("clk_i");}
    if (VL_UNLIKELY((vlSelf->rst_ni & 0xfeU))) {
        Verilated::overWidthError("rst_ni");}
    if (VL_UNLIKELY((vlSelf->enable_i & 0xfeU))) {
        Verilated::overWidthError("enable_i");}
    if (VL_UNLIKELY((vlSelf->seg_we_i & 0xfeU))) {
        Verilated::overWidthError("seg_we_i");}
    if (VL_UNLIKELY((vlSelf->seg_waddr_i & 0xf0U))) {
        Verilated::overWidthError("seg_waddr_i");}
    if (VL_UNLIKELY((vlSelf->seg_phase_i & 0xf0U))) {
        Verilated::overWidthError("seg_phase_i");}
    if (VL_UNLIKELY((vlSelf->seg_jerk_i & 0ULL))) {
        Verilated::overWidthError("seg_jerk_i");}
    if (VL_UNLIKELY((vlSelf->seg_vel0_i[2U] & 0xfffe0000U))) {
        Verilated::overWidthError("seg_vel0_i");}
    if (VL_UNLIKELY((vlSelf->seg_count_i & 0xe0U))) {
        Verilated::overWidthError("seg_count_i");}
    if (VL_UNLIKELY((vlSelf->pos_frac0_i[2U] & 0xffff0000U))) {
        Verilated::overWidthError("pos_frac0_i");}
    if (VL_UNLIKELY((vlSelf->start_i & 0xfeU))) {
        Verilated::overWidthError("start_i");}
    if (VL_UNLIKELY((vlSelf->abort_i & 0xfeU))) {
        Verilated::overWidthError("abort_i");}
}
#endif  // VL_DEBUG
