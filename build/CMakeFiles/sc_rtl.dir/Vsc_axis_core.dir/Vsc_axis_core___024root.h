// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Design internal header
// See Vsc_axis_core.h for the primary calling header

#ifndef VERILATED_VSC_AXIS_CORE___024ROOT_H_
#define VERILATED_VSC_AXIS_CORE___024ROOT_H_  // guard

#include "verilated.h"

class Vsc_axis_core__Syms;

class Vsc_axis_core___024root final : public VerilatedModule {
  public:

    // DESIGN SPECIFIC STATE
    // Anonymous structures to workaround compiler member-count bugs
    struct {
        VL_IN8(clk_i,0,0);
        VL_IN8(rst_ni,0,0);
        VL_IN8(enable_i,0,0);
        VL_IN8(seg_we_i,0,0);
        VL_IN8(seg_waddr_i,3,0);
        VL_IN8(seg_phase_i,3,0);
        VL_IN8(seg_count_i,4,0);
        VL_IN8(start_i,0,0);
        VL_IN8(abort_i,0,0);
        VL_OUT8(step_o,0,0);
        VL_OUT8(dir_o,0,0);
        VL_OUT8(en_o,0,0);
        VL_OUT8(busy_o,0,0);
        VL_OUT8(done_o,0,0);
        VL_OUT8(phase_o,3,0);
        VL_OUT8(fault_table_o,0,0);
        VL_OUT8(fault_overrun_o,0,0);
        VL_OUT8(seg_idx_o,3,0);
        VL_OUT8(step_pending_o,3,0);
        CData/*0:0*/ sc_axis_core__DOT__start_ok;
        CData/*0:0*/ sc_axis_core__DOT__en_q;
        CData/*0:0*/ sc_axis_core__DOT__start_q;
        CData/*0:0*/ sc_axis_core__DOT__abort_q;
        CData/*4:0*/ sc_axis_core__DOT__seg_count_q;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__run_q;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__run_d;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__finished_q;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__finished_d;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__fault_q;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__fault_d;
        CData/*3:0*/ sc_axis_core__DOT__u_exec__DOT__idx_q;
        CData/*3:0*/ sc_axis_core__DOT__u_exec__DOT__idx_d;
        CData/*4:0*/ sc_axis_core__DOT__u_exec__DOT__count_q;
        CData/*4:0*/ sc_axis_core__DOT__u_exec__DOT__count_d;
        CData/*3:0*/ sc_axis_core__DOT__u_exec__DOT__phase_q;
        CData/*3:0*/ sc_axis_core__DOT__u_exec__DOT__phase_d;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__step_req_q;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__step_req_d;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__step_fwd_q;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__step_fwd_d;
        CData/*0:0*/ sc_axis_core__DOT__u_exec__DOT__load;
        CData/*3:0*/ sc_axis_core__DOT__u_exec__DOT__load_idx;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__step_q;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__step_d;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__dir_q;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__dir_d;
        CData/*3:0*/ sc_axis_core__DOT__u_step_gen__DOT__pend_q;
        CData/*3:0*/ sc_axis_core__DOT__u_step_gen__DOT__pend_d;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__overrun_q;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__overrun_d;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__dir_ok;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__rise;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__flip_dir;
        CData/*0:0*/ sc_axis_core__DOT__u_step_gen__DOT__req_blocked;
        CData/*0:0*/ __Vtrigrprev__TOP__clk_i;
        CData/*0:0*/ __VactContinue;
        VL_IN16(cfg_high_i,15,0);
        VL_IN16(cfg_low_i,15,0);
        VL_IN16(cfg_setup_i,15,0);
        VL_IN16(cfg_hold_i,15,0);
        SData/*15:0*/ sc_axis_core__DOT__cfg_high_q;
        SData/*15:0*/ sc_axis_core__DOT__cfg_low_q;
        SData/*15:0*/ sc_axis_core__DOT__cfg_setup_q;
        SData/*15:0*/ sc_axis_core__DOT__cfg_hold_q;
    };
    struct {
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__high_left_q;
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__high_left_d;
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__low_cnt_q;
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__low_cnt_d;
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__since_rise_q;
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__since_rise_d;
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__since_dir_q;
        SData/*15:0*/ sc_axis_core__DOT__u_step_gen__DOT__since_dir_d;
        VL_IN(seg_clocks_i,31,0);
        VL_INW(seg_vel0_i,80,0,3);
        VL_INW(pos_frac0_i,79,0,3);
        VL_OUT(pulse_count_o,31,0);
        VL_OUT(ref_pos_int_o,31,0);
        VL_OUTW(ref_pos_frac_o,79,0,3);
        VL_OUTW(ref_vel_o,80,0,3);
        VlWide<3>/*79:0*/ sc_axis_core__DOT__pos_frac0_q;
        IData/*31:0*/ sc_axis_core__DOT__u_exec__DOT__left_q;
        IData/*31:0*/ sc_axis_core__DOT__u_exec__DOT__left_d;
        VlWide<3>/*80:0*/ sc_axis_core__DOT__u_exec__DOT__vel_q;
        VlWide<3>/*80:0*/ sc_axis_core__DOT__u_exec__DOT__vel_d;
        VlWide<3>/*79:0*/ sc_axis_core__DOT__u_exec__DOT__frac_q;
        VlWide<3>/*79:0*/ sc_axis_core__DOT__u_exec__DOT__frac_d;
        IData/*31:0*/ sc_axis_core__DOT__u_exec__DOT__pint_q;
        IData/*31:0*/ sc_axis_core__DOT__u_exec__DOT__pint_d;
        VlWide<3>/*81:0*/ sc_axis_core__DOT__u_exec__DOT__pos_sum;
        IData/*31:0*/ sc_axis_core__DOT__u_exec__DOT__ld_clocks;
        IData/*31:0*/ sc_axis_core__DOT__u_step_gen__DOT__count_q;
        IData/*31:0*/ sc_axis_core__DOT__u_step_gen__DOT__count_d;
        IData/*31:0*/ __VstlIterCount;
        IData/*31:0*/ __VactIterCount;
        VL_IN64(seg_jerk_i,47,0);
        VL_IN64(seg_acc0_i,63,0);
        VL_OUT64(ref_acc_o,63,0);
        VL_OUT64(ref_jerk_o,47,0);
        QData/*47:0*/ sc_axis_core__DOT__u_exec__DOT__jerk_q;
        QData/*47:0*/ sc_axis_core__DOT__u_exec__DOT__jerk_d;
        QData/*63:0*/ sc_axis_core__DOT__u_exec__DOT__acc_q;
        QData/*63:0*/ sc_axis_core__DOT__u_exec__DOT__acc_d;
        VlUnpacked<CData/*3:0*/, 16> sc_axis_core__DOT__u_exec__DOT__mem_phase_q;
        VlUnpacked<IData/*31:0*/, 16> sc_axis_core__DOT__u_exec__DOT__mem_clocks_q;
        VlUnpacked<QData/*47:0*/, 16> sc_axis_core__DOT__u_exec__DOT__mem_jerk_q;
        VlUnpacked<QData/*63:0*/, 16> sc_axis_core__DOT__u_exec__DOT__mem_acc0_q;
        VlUnpacked<VlWide<3>/*80:0*/, 16> sc_axis_core__DOT__u_exec__DOT__mem_vel0_q;
        VlUnpacked<CData/*0:0*/, 2> __Vm_traceActivity;
    };
    VlTriggerVec<1> __VstlTriggered;
    VlTriggerVec<1> __VactTriggered;
    VlTriggerVec<1> __VnbaTriggered;

    // INTERNAL VARIABLES
    Vsc_axis_core__Syms* const vlSymsp;

    // CONSTRUCTORS
    Vsc_axis_core___024root(Vsc_axis_core__Syms* symsp, const char* v__name);
    ~Vsc_axis_core___024root();
    VL_UNCOPYABLE(Vsc_axis_core___024root);

    // INTERNAL METHODS
    void __Vconfigure(bool first);
} VL_ATTR_ALIGNED(VL_CACHE_LINE_BYTES);


#endif  // guard
