## Digilent Arty A7-35T (xc7a35ticsg324-1L) constraints for sc_board_xy_top:
## two coordinated axes, X on Pmods JA (driver) and JB (encoder, switches),
## Y on Pmods JC (driver) and JD (encoder, switches).
## Pin locations from Digilent's Arty-A7-35-Master.xdc (Rev. D/E).
## Used by scripts/vivado/build.tcl (-tclargs <outdir> sc_board_xy_top).

## ---- clocks -----------------------------------------------------------------
## 100 MHz oscillator; the MMCM in sc_clkgen derives the 20 MHz system clock.
set_property -dict { PACKAGE_PIN E3  IOSTANDARD LVCMOS33 } [get_ports clk100_i]
create_clock -name clk100 -period 10.000 -waveform {0.000 5.000} [get_ports clk100_i]
create_generated_clock -name clk_sys [get_pins u_clkgen/u_mmcm/CLKOUT0]

## ---- reset, e-stop --------------------------------------------------------------
set_property -dict { PACKAGE_PIN C2  IOSTANDARD LVCMOS33 } [get_ports ck_rst_ni]
set_property -dict { PACKAGE_PIN D9  IOSTANDARD LVCMOS33 } [get_ports estop_i]

## ---- USB-UART (FTDI) ------------------------------------------------------------
set_property -dict { PACKAGE_PIN A9  IOSTANDARD LVCMOS33 } [get_ports uart_rx_i]
set_property -dict { PACKAGE_PIN D10 IOSTANDARD LVCMOS33 } [get_ports uart_tx_o]

## ---- X stepper driver on Pmod JA (JA1 STEP, JA2 DIR, JA3 EN; JA4 interrupt out) ---
set_property -dict { PACKAGE_PIN G13 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports {step_o[0]}]
set_property -dict { PACKAGE_PIN B11 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports {dir_o[0]}]
set_property -dict { PACKAGE_PIN A11 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports {en_o[0]}]
set_property -dict { PACKAGE_PIN D12 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports irq_o]

## ---- Y stepper driver on Pmod JC (JC1 STEP, JC2 DIR, JC3 EN) ---------------------
set_property -dict { PACKAGE_PIN U12 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports {step_o[1]}]
set_property -dict { PACKAGE_PIN V12 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports {dir_o[1]}]
set_property -dict { PACKAGE_PIN V10 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports {en_o[1]}]

## ---- encoders: X on Pmod JB (JB1 A, JB2 B, JB9 Z), Y on Pmod JD (JD1 A, JD2 B, JD9 Z)
## Z is pulled down: an encoder without an index never latches on it.
set_property -dict { PACKAGE_PIN E15 IOSTANDARD LVCMOS33 PULLUP TRUE } [get_ports {enc_a_i[0]}]
set_property -dict { PACKAGE_PIN E16 IOSTANDARD LVCMOS33 PULLUP TRUE } [get_ports {enc_b_i[0]}]
set_property -dict { PACKAGE_PIN K15 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {enc_z_i[0]}]
set_property -dict { PACKAGE_PIN D4  IOSTANDARD LVCMOS33 PULLUP TRUE } [get_ports {enc_a_i[1]}]
set_property -dict { PACKAGE_PIN D3  IOSTANDARD LVCMOS33 PULLUP TRUE } [get_ports {enc_b_i[1]}]
set_property -dict { PACKAGE_PIN H2  IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {enc_z_i[1]}]

## ---- switches: X on JB3/JB4/JB7, Y on JD3/JD4/JD7 (limit -, limit +, home);
## the probe on JB8 (both axes). Pulled down: unconnected reads inactive.
set_property -dict { PACKAGE_PIN D15 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[0]}]
set_property -dict { PACKAGE_PIN C15 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[1]}]
set_property -dict { PACKAGE_PIN J17 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[2]}]
set_property -dict { PACKAGE_PIN F4  IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[3]}]
set_property -dict { PACKAGE_PIN F3  IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[4]}]
set_property -dict { PACKAGE_PIN E2  IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[5]}]
set_property -dict { PACKAGE_PIN J18 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {probe_i}]

## ---- LEDs LD4..LD7 -------------------------------------------------------------------
set_property -dict { PACKAGE_PIN H5  IOSTANDARD LVCMOS33 } [get_ports {led_o[0]}]
set_property -dict { PACKAGE_PIN J5  IOSTANDARD LVCMOS33 } [get_ports {led_o[1]}]
set_property -dict { PACKAGE_PIN T9  IOSTANDARD LVCMOS33 } [get_ports {led_o[2]}]
set_property -dict { PACKAGE_PIN T10 IOSTANDARD LVCMOS33 } [get_ports {led_o[3]}]
## RGB LED LD0, red: interrupt pending
set_property -dict { PACKAGE_PIN G6  IOSTANDARD LVCMOS33 } [get_ports led_irq_o]

## ---- IO timing ---------------------------------------------------------------------
## Asynchronous inputs: each goes through a two-flop sc_sync (ASYNC_REG) or
## sc_rst_sync, as on the one-axis board (constraints/arty_a7_35t.xdc).
set_false_path -from [get_ports {enc_a_i[*] enc_b_i[*] enc_z_i[*] estop_i ck_rst_ni uart_rx_i sw_i[*] probe_i}]

## STEP/DIR/EN of both axes come straight from flops of clk_sys.
set_output_delay -clock [get_clocks clk_sys] -max 20.000 [get_ports {step_o[*] dir_o[*] en_o[*]}]
set_output_delay -clock [get_clocks clk_sys] -min 0.000  [get_ports {step_o[*] dir_o[*] en_o[*]}]

## UART TX, LEDs and the interrupt line: human / bit-time scale, not timed.
set_false_path -to [get_ports {uart_tx_o led_o[*] led_irq_o irq_o}]

## ---- configuration ---------------------------------------------------------------------
set_property CFGBVS VCCO [current_design]
set_property CONFIG_VOLTAGE 3.3 [current_design]
set_property BITSTREAM.GENERAL.COMPRESS TRUE [current_design]
set_property BITSTREAM.CONFIG.SPI_BUSWIDTH 4 [current_design]
