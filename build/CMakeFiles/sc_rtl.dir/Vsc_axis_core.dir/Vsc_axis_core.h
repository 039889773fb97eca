// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Primary model header
//
// This header should be included by all source files instantiating the design.
// The class here is then constructed to instantiate the design.
// See the Verilator manual for examples.

#ifndef VERILATED_VSC_AXIS_CORE_H_
#define VERILATED_VSC_AXIS_CORE_H_  // guard

#include "verilated.h"

class Vsc_axis_core__Syms;
class Vsc_axis_core___024root;
class VerilatedFstC;

// This class is the main interface to the Verilated model
class Vsc_axis_core VL_NOT_FINAL : public VerilatedModel {
  private:
    // Symbol table holding complete model state (owned by this class)
    Vsc_axis_core__Syms* const vlSymsp;

  public:

    // PORTS
    // The application code writes and reads these signals to
    // propagate new values into/out from the Verilated model.
    VL_IN8(&clk_i,0,0);
    VL_IN8(&rst_ni,0,0);
    VL_IN8(&enable_i,0,0);
    VL_IN8(&seg_we_i,0,0);
    VL_IN8(&seg_waddr_i,3,0);
    VL_IN8(&seg_phase_i,3,0);
    VL_IN8(&seg_count_i,4,0);
    VL_IN8(&start_i,0,0);
    VL_IN8(&abort_i,0,0);
    VL_OUT8(&step_o,0,0);
    VL_OUT8(&dir_o,0,0);
    VL_OUT8(&en_o,0,0);
    VL_OUT8(&busy_o,0,0);
    VL_OUT8(&done_o,0,0);
    VL_OUT8(&phase_o,3,0);
    VL_OUT8(&fault_table_o,0,0);
    VL_OUT8(&fault_overrun_o,0,0);
    VL_OUT8(&seg_idx_o,3,0);
    VL_OUT8(&step_pending_o,3,0);
    VL_IN16(&cfg_high_i,15,0);
    VL_IN16(&cfg_low_i,15,0);
    VL_IN16(&cfg_setup_i,15,0);
    VL_IN16(&cfg_hold_i,15,0);
    VL_IN(&seg_clocks_i,31,0);
    VL_INW(&seg_vel0_i,80,0,3);
    VL_INW(&pos_frac0_i,79,0,3);
    VL_OUT(&pulse_count_o,31,0);
    VL_OUT(&ref_pos_int_o,31,0);
    VL_OUTW(&ref_pos_frac_o,79,0,3);
    VL_OUTW(&ref_vel_o,80,0,3);
    VL_IN64(&seg_jerk_i,47,0);
    VL_IN64(&seg_acc0_i,63,0);
    VL_OUT64(&ref_acc_o,63,0);
    VL_OUT64(&ref_jerk_o,47,0);

    // CELLS
    // Public to allow access to /* verilator public */ items.
    // Otherwise the application code can consider these internals.

    // Root instance pointer to allow access to model internals,
    // including inlined /* verilator public_flat_* */ items.
    Vsc_axis_core___024root* const rootp;

    // CONSTRUCTORS
    /// Construct the model; called by application code
    /// If contextp is null, then the model will use the default global context
    /// If name is "", then makes a wrapper with a
    /// single model invisible with respect to DPI scope names.
    explicit Vsc_axis_core(VerilatedContext* contextp, const char* name = "TOP");
    explicit Vsc_axis_core(const char* name = "TOP");
    /// Destroy the model; called (often implicitly) by application code
    virtual ~Vsc_axis_core();
  private:
    VL_UNCOPYABLE(Vsc_axis_core);  ///< Copying not allowed

  public:
    // API METHODS
    /// Evaluate the model.  Application must call when inputs change.
    void eval() { eval_step(); }
    /// Evaluate when calling multiple units/models per time step.
    void eval_step();
    /// Evaluate at end of a timestep for tracing, when using eval_step().
    /// Application must call after all eval() and before time changes.
    void eval_end_step() {}
    /// Simulation complete, run final blocks.  Application must call on completion.
    void final();
    /// Are there scheduled events to handle?
    bool eventsPending();
    /// Returns time at next time slot. Aborts if !eventsPending()
    uint64_t nextTimeSlot();
    /// Trace signals in the model; called by application code
    void trace(VerilatedFstC* tfp, int levels, int options = 0);
    /// Retrieve name of this model instance (as passed to constructor).
    const char* name() const;

    // Abstract methods from VerilatedModel
    const char* hierName() const override final;
    const char* modelName() const override final;
    unsigned threads() const override final;
    std::unique_ptr<VerilatedTraceConfig> traceConfig() const override final;
} VL_ATTR_ALIGNED(VL_CACHE_LINE_BYTES);

#endif  // guard
