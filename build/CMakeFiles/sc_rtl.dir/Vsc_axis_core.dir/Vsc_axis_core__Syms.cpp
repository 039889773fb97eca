// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Symbol table implementation internals

#include "Vsc_axis_core__Syms.h"
#include "Vsc_axis_core.h"
#include "Vsc_axis_core___024root.h"

// FUNCTIONS
Vsc_axis_core__Syms::~Vsc_axis_core__Syms()
{
}

Vsc_axis_core__Syms::Vsc_axis_core__Syms(VerilatedContext* contextp, const char* namep, Vsc_axis_core* modelp)
    : VerilatedSyms{contextp}
    // Setup internal state of the Syms class
    , __Vm_modelp{modelp}
    // Setup module instances
    , TOP{this, namep}
{
    // Configure time unit / time precision
    _vm_contextp__->timeunit(-12);
    _vm_contextp__->timeprecision(-12);
    // Setup each module's pointers to their submodules
    // Setup each module's pointer back to symbol table (for public functions)
    TOP.__Vconfigure(true);
}
