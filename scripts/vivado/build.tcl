# Vivado non-project batch flow for the Arty A7-35T board top (off-machine:
# Vivado is not installed on the CI machine; yosys checks synthesizability
# there, see scripts/synth_yosys.sh).
#
#   vivado -mode batch -source scripts/vivado/build.tcl [-tclargs <outdir> [<top>]]
#
# <top>: sc_board_top (one closed-loop axis, constraints/arty_a7_35t.xdc,
# the default) or sc_board_xy_top (two coordinated axes X and Y,
# constraints/arty_a7_35t_xy.xdc).
# Reads the RTL and constraints, synthesizes, optimizes, places, routes,
# writes utilization and timing reports and the bitstream to <outdir>
# (default build/vivado). Fails (non-zero exit) when timing is not met.

set script_dir [file dirname [file normalize [info script]]]
set root       [file normalize [file join $script_dir .. ..]]
set part       xc7a35ticsg324-1L
set top        sc_board_top
set out        [file join $root build vivado]
if {[llength $argv] > 0} { set out [file normalize [lindex $argv 0]] }
if {[llength $argv] > 1} { set top [lindex $argv 1] }
file mkdir $out

# The package first, then every module the top instantiates
# (scripts/rtl_deps.py rtl <top> prints the same list).
set rtl_files_of(sc_board_top) {
  sc_pkg.sv
  sc_stop_gen.sv
  sc_row_reach.sv
  sc_row_fifo.sv
  sc_step_gen.sv
  sc_profile_exec.sv
  sc_step_nco.sv
  sc_neuron_pi.sv
  sc_quad_decoder.sv
  sc_axis_core.sv
  sc_servo_axis.sv
  sc_switch_filter.sv
  sc_axi_regs.sv
  sc_cl_stat_pack.sv
  sc_uart_bridge.sv
  sc_uart_tx.sv
  sc_uart_rx.sv
  sc_axi_servo.sv
  sc_uart_axi_link.sv
  sc_sync.sv
  sc_rst_sync.sv
  sc_clkgen.sv
  sc_board_top.sv
}
set rtl_files_of(sc_board_xy_top) {
  sc_pkg.sv
  sc_stop_gen.sv
  sc_row_fifo.sv
  sc_step_gen.sv
  sc_profile_exec.sv
  sc_step_nco.sv
  sc_neuron_pi.sv
  sc_quad_decoder.sv
  sc_axis_core.sv
  sc_servo_axis.sv
  sc_row_reach.sv
  sc_multi_axis_core.sv
  sc_switch_filter.sv
  sc_axi_regs.sv
  sc_cl_stat_pack.sv
  sc_axi_window_demux.sv
  sc_uart_bridge.sv
  sc_uart_tx.sv
  sc_uart_rx.sv
  sc_axi_multi_axis.sv
  sc_uart_axi_link.sv
  sc_sync.sv
  sc_rst_sync.sv
  sc_clkgen.sv
  sc_board_xy_top.sv
}
set xdc_of(sc_board_top)    arty_a7_35t.xdc
set xdc_of(sc_board_xy_top) arty_a7_35t_xy.xdc
if {![info exists rtl_files_of($top)]} {
  error "top $top: not sc_board_top or sc_board_xy_top"
}
set rtl_files $rtl_files_of($top)
set_part $part
foreach f $rtl_files { read_verilog -sv [file join $root rtl $f] }
read_xdc [file join $root constraints $xdc_of($top)]

# ---- synthesis (SYNTHESIS selects the MMCM in sc_clkgen, not the sim stand-in)
synth_design -top $top -part $part -verilog_define SYNTHESIS -flatten_hierarchy rebuilt
write_checkpoint -force [file join $out post_synth.dcp]
report_utilization    -file [file join $out post_synth_utilization.rpt]
report_timing_summary -file [file join $out post_synth_timing_summary.rpt]

# ---- implementation
opt_design
place_design
phys_opt_design
route_design
write_checkpoint -force [file join $out post_route.dcp]

# ---- reports
report_utilization              -file [file join $out utilization.rpt]
report_utilization -hierarchical -file [file join $out utilization_hier.rpt]
report_timing_summary -max_paths 10 -report_unconstrained -file [file join $out timing_summary.rpt]
report_clock_utilization        -file [file join $out clock_utilization.rpt]
report_drc                      -file [file join $out drc.rpt]
report_methodology              -file [file join $out methodology.rpt]

set wns [get_property SLACK [get_timing_paths -delay_type max -max_paths 1]]
set whs [get_property SLACK [get_timing_paths -delay_type min -max_paths 1]]
puts "$top: WNS $wns ns, WHS $whs ns (reports in $out)"
if {$wns < 0 || $whs < 0} {
  error "timing not met: WNS $wns ns, WHS $whs ns (see $out/timing_summary.rpt)"
}

# ---- bitstream
write_bitstream -force [file join $out $top.bit]
puts "bitstream: [file join $out $top.bit]"
