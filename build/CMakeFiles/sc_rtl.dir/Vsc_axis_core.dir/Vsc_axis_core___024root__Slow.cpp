// Verilated -*- C++ -*-
// DESCRIPTION: Verilator output: Design implementation internals
// See Vsc_axis_core.h for the primary calling header

#include "verilated.h"

#include "Vsc_axis_core__Syms.h"
#include "Vsc_axis_core___024root.h"

void Vsc_axis_core___024root___ctor_var_reset(Vsc_axis_core___024root* vlSelf);

Vsc_axis_core___024root::Vsc_axis_core___024root(Vsc_axis_core__Syms* symsp, const char* v__name)
    : VerilatedModule{v__name}
    , vlSymsp{symsp}
 {
    // Reset structure values
    Vsc_axis_core___024root___ctor_var_reset(this);
}

void Vsc_axis_core___024root::__Vconfigure(bool first) {
    if (false && first) {}  // Prevent unused
}

Vsc_axis_core___024root::~Vsc_axis_core___024root() {
}
