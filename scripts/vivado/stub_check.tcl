# Dry run of build.tcl and the XDC under plain tclsh with the Vivado
# commands stubbed (ctest vivado_flow_dry_run): catches Tcl errors and
# prints the RTL files the flow reads, which the test compares with
# scripts/rtl_deps.py so the Vivado file list cannot drift from the RTL.
#   tclsh scripts/vivado/stub_check.tcl <outdir> <top>
foreach cmd {set_part read_xdc synth_design write_checkpoint report_utilization
             report_timing_summary opt_design place_design phys_opt_design route_design
             report_clock_utilization report_drc report_methodology write_bitstream
             create_clock create_generated_clock set_false_path set_input_delay
             set_output_delay current_design set_property} {
  proc $cmd {args} {return {}}
}
proc read_verilog {args} { puts "RTL [lindex $args end]" }
proc get_ports {args} { return $args }
proc get_pins {args} { return $args }
proc get_clocks {args} { return $args }
proc get_cells {args} { return $args }
proc get_timing_paths {args} { return path }
proc get_property {p o} { return 0.0 }
set here [file dirname [file normalize [info script]]]
set argv [list [lindex $argv 0] [lindex $argv 1]]
source [file join $here build.tcl]
source [file join $here .. .. constraints $xdc_of($top)]
