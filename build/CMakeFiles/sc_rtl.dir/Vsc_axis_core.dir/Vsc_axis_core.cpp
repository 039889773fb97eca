// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Model implementation (design independent parts)

#include "Vsc_axis_core.h"
#include "Vsc_axis_core__Syms.h"
#include "verilated_fst_c.h"

//============================================================
// Constructors

Vsc_axis_core::Vsc_axis_core(VerilatedContext* _vcontextp__, const char* _vcname__)
    : VerilatedModel{*_vcontextp__}
    , vlSymsp{new Vsc_axis_core__Syms(contextp(), _vcname__, this)}
    , clk_i{vlSymsp->TOP.clk_i}
    , rst_ni{vlSymsp->TOP.rst_ni}
    , enable_i{vlSymsp->TOP.enable_i}
    , seg_we_i{vlSymsp->TOP.seg_we_i}
    , seg_waddr_i{vlSymsp->TOP.seg_waddr_i}
    , seg_phase_i{vlSymsp->TOP.seg_phase_i}
    , seg_count_i{vlSymsp->TOP.seg_count_i}
    , start_i{vlSymsp->TOP.start_i}
    , abort_i{vlSymsp->TOP.abort_i}
    , step_o{vlSymsp->TOP.step_o}
    , dir_o{vlSymsp->TOP.dir_o}
    , en_o{vlSymsp->TOP.en_o}
    , busy_o{vlSymsp->TOP.busy_o}
    , done_o{vlSymsp->TOP.done_o}
    , phase_o{vlSymsp->TOP.phase_o}
    , fault_table_o{vlSymsp->TOP.fault_table_o}
    , fault_overrun_o{vlSymsp->TOP.fault_overrun_o}
    , seg_idx_o{vlSymsp->TOP.seg_idx_o}
    , step_pending_o{vlSymsp->TOP.step_pending_o}
    , cfg_high_i{vlSymsp->TOP.cfg_high_i}
    , cfg_low_i{vlSymsp->TOP.cfg_low_i}
    , cfg_setup_i{vlSymsp->TOP.cfg_setup_i}
    , cfg_hold_i{vlSymsp->TOP.cfg_hold_i}
    , seg_clocks_i{vlSymsp->TOP.seg_clocks_i}
    , seg_vel0_i{vlSymsp->TOP.seg_vel0_i}
    , pos_frac0_i{vlSymsp->TOP.pos_frac0_i}
    , pulse_count_o{vlSymsp->TOP.pulse_count_o}
    , ref_pos_int_o{vlSymsp->TOP.ref_pos_int_o}
    , ref_pos_frac_o{vlSymsp->TOP.ref_pos_frac_o}
    , ref_vel_o{vlSymsp->TOP.ref_vel_o}
    , seg_jerk_i{vlSymsp->TOP.seg_jerk_i}
    , seg_acc0_i{vlSymsp->TOP.seg_acc0_i}
    , ref_acc_o{vlSymsp->TOP.ref_acc_o}
    , ref_jerk_o{vlSymsp->TOP.ref_jerk_o}
    , rootp{&(vlSymsp->TOP)}
{
    // Register model with the context
    contextp()->addModel(this);
}

Vsc_axis_core::Vsc_axis_core(const char* _vcname__)
    : Vsc_axis_core(Verilated::threadContextp(), _vcname__)
{
}

//============================================================
// Destructor

Vsc_axis_core::~Vsc_axis_core() {
    delete vlSymsp;
}

//============================================================
// Evaluation function

#ifdef VL_DEBUG
void Vsc_axis_core___024root___eval_debug_assertions(Vsc_axis_core___024root* vlSelf);
#endif  // VL_DEBUG
void Vsc_axis_core___024root___eval_static(Vsc_axis_core___024root* vlSelf);
void Vsc_axis_core___024root___eval_initial(Vsc_axis_core___024root* vlSelf);
void Vsc_axis_core___024root___eval_settle(Vsc_axis_core___024root* vlSelf);
void Vsc_axis_core___024root___eval(Vsc_axis_core___024root* vlSelf);

void Vsc_axis_core::eval_step() {
    VL_DEBUG_IF(VL_DBG_MSGF("+++++TOP Evaluate Vsc_axis_core::eval_step\n"); );
#ifdef VL_DEBUG
    // Debug assertions
    Vsc_axis_core___024root___eval_debug_assertions(&(vlSymsp->TOP));
#endif  // VL_DEBUG
    vlSymsp->__Vm_activity = true;
    if (VL_UNLIKELY(!vlSymsp->__Vm_didInit)) {
        vlSymsp->__Vm_didInit = true;
        VL_DEBUG_IF(VL_DBG_MSGF("+ Initial\n"););
        Vsc_axis_core___024root___eval_static(&(vlSymsp->TOP));
        Vsc_axis_core___024root___eval_initial(&(vlSymsp->TOP));
        Vsc_axis_core___024root___eval_settle(&(vlSymsp->TOP));
    }
    // MTask 0 start
    VL_DEBUG_IF(VL_DBG_MSGF("MTask0 starting\n"););
    Verilated::mtaskId(0);
    VL_DEBUG_IF(VL_DBG_MSGF("+ Eval\n"););
    Vsc_axis_core___024root___eval(&(vlSymsp->TOP));
    // Evaluate cleanup
    Verilated::endOfThreadMTask(vlSymsp->__Vm_evalMsgQp);
    Verilated::endOfEval(vlSymsp->__Vm_evalMsgQp);
}

//============================================================
// Events and timing
bool Vsc_axis_core::eventsPending() { return false; }

uint64_t Vsc_axis_core::nextTimeSlot() {
    VL_FATAL_MT(__FILE__, __LINE__, "", "%Error: No delays in the design");
    return 0;
}

//============================================================
// Utilities

const char* Vsc_axis_core::name() const {
    return vlSymsp->name();
}

//============================================================
// Invoke final blocks

void Vsc_axis_core___024root___eval_final(Vsc_axis_core___024root* vlSelf);

VL_ATTR_COLD void Vsc_axis_core::final() {
    Vsc_axis_core___024root___eval_final(&(vlSymsp->TOP));
}

//============================================================
// Implementations of abstract methods from VerilatedModel

const char* Vsc_axis_core::hierName() const { return vlSymsp->name(); }
const char* Vsc_axis_core::modelName() const { return "Vsc_axis_core"; }
unsigned Vsc_axis_core::threads() const { return 1; }
std::unique_ptr<VerilatedTraceConfig> Vsc_axis_core::traceConfig() const {
    return std::unique_ptr<VerilatedTraceConfig>{new VerilatedTraceConfig{false, false, false}};
};

//============================================================
// Trace configuration

void Vsc_axis_core___024root__trace_init_top(Vsc_axis_core___024root* vlSelf, VerilatedFst* tracep);

VL_ATTR_COLD static void trace_init(void* voidSelf, VerilatedFst* tracep, uint32_t code) {
    // Callback from tracep->open()
    Vsc_axis_core___024root* const __restrict vlSelf VL_ATTR_UNUSED = static_cast<Vsc_axis_core___024root*>(voidSelf);
    Vsc_axis_core__Syms* const __restrict vlSymsp VL_ATTR_UNUSED = vlSelf->vlSymsp;
    if (!vlSymsp->_vm_contextp__->calcUnusedSigs()) {
        VL_FATAL_MT(__FILE__, __LINE__, __FILE__,
            "Turning on wave traces requires Verilated::traceEverOn(true) call before time 0.");
    }
    vlSymsp->__Vm_baseCode = code;
    tracep->scopeEscape(' ');
    tracep->pushNamePrefix(std::string{vlSymsp->name()} + ' ');
    Vsc_axis_core___024root__trace_init_top(vlSelf, tracep);
    tracep->popNamePrefix();
    tracep->scopeEscape('.');
}

VL_ATTR_COLD void Vsc_axis_core___024root__trace_register(Vsc_axis_core___024root* vlSelf, VerilatedFst* tracep);

VL_ATTR_COLD void Vsc_axis_core::trace(VerilatedFstC* tfp, int levels, int options) {
    if (tfp->isOpen()) {
        vl_fatal(__FILE__, __LINE__, __FILE__,"'Vsc_axis_core::trace()' shall not be called after 'VerilatedFstC::open()'.");
    }
    if (false && levels && options) {}  // Prevent unused
    tfp->spTrace()->addModel(this);
    tfp->spTrace()->addInitCb(&trace_init, &(vlSymsp->TOP));
    Vsc_axis_core___024root__trace_register(&(vlSymsp->TOP), tfp->spTrace());
}
