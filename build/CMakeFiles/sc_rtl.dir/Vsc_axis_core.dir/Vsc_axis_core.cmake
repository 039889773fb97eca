# Verilated -*- CMake -*-
# DESCRIPTION: Verilator output: CMake include script with class lists
#
# This CMake script lists generated Verilated files, for including in higher level CMake scripts.
# This file is meant to be consumed by the verilate() function,
# which becomes available after executing `find_package(verilator).

### Constants...
set(PERL "perl" CACHE FILEPATH "Perl executable (from $PERL)")
set(VERILATOR_ROOT "/usr/share/verilator" CACHE PATH "Path to Verilator kit (from $VERILATOR_ROOT)")

### Compiler flags...
# User CFLAGS (from -CFLAGS on Verilator command line)
set(Vsc_axis_core_USER_CFLAGS )
# User LDLIBS (from -LDFLAGS on Verilator command line)
set(Vsc_axis_core_USER_LDLIBS "-lz")

### Switches...
# SystemC output mode?  0/1 (from --sc)
set(Vsc_axis_core_SC 0)
# Coverage output mode?  0/1 (from --coverage)
set(Vsc_axis_core_COVERAGE 0)
# Timing mode?  0/1
set(Vsc_axis_core_TIMING 0)
# Threaded output mode?  1/N threads (from --threads)
set(Vsc_axis_core_THREADS 1)
# VCD Tracing output mode?  0/1 (from --trace)
set(Vsc_axis_core_TRACE_VCD 0)
# FST Tracing output mode? 0/1 (from --trace-fst)
set(Vsc_axis_core_TRACE_FST 1)

### Sources...
# Global classes, need linked once per executable
set(Vsc_axis_core_GLOBAL "${VERILATOR_ROOT}/include/verilated.cpp" "${VERILATOR_ROOT}/include/verilated_fst_c.cpp" "${VERILATOR_ROOT}/include/verilated_threads.cpp")
# Generated module classes, non-fast-path, compile with low/medium optimization
set(Vsc_axis_core_CLASSES_SLOW "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core___024root__Slow.cpp" "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core___024root__DepSet_h83fe1d52__0__Slow.cpp" "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core___024root__DepSet_h4f564845__0__Slow.cpp")
# Generated module classes, fast-path, compile with highest optimization
set(Vsc_axis_core_CLASSES_FAST "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core.cpp" "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core___024root__DepSet_h83fe1d52__0.cpp" "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core___024root__DepSet_h4f564845__0.cpp")
# Generated support classes, non-fast-path, compile with low/medium optimization
set(Vsc_axis_core_SUPPORT_SLOW "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core__Syms.cpp" "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core__Trace__0__Slow.cpp")
# Generated support classes, fast-path, compile with highest optimization
set(Vsc_axis_core_SUPPORT_FAST "/work/main/build/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir/Vsc_axis_core__Trace__0.cpp")
# All dependencies
set(Vsc_axis_core_DEPS "/usr/bin/verilator_bin" "/work/main/rtl/lint/verilator_waiver.vlt" "/work/main/rtl/sc_axis_core.sv" "/work/main/rtl/sc_pkg.sv" "/work/main/rtl/sc_profile_exec.sv" "/work/main/rtl/sc_step_gen.sv")
# User .cpp files (from .cpp's on Verilator command line)
set(Vsc_axis_core_USER_CLASSES )
