## Digilent Arty A7-35T (xc7a35ticsg324-1L) constraints for sc_board_top.
## Pin locations from Digilent's Arty-A7-35-Master.xdc (Rev. D/E).
## Used by scripts/vivado/build.tcl (non-project batch flow).

## ---- clocks -----------------------------------------------------------------
## 100 MHz oscillator. The MMCM in sc_clkgen derives the 20 MHz system clock
## from it automatically (CLKOUT0 = 100 MHz * 10 / 50); the line after only
## gives that auto-derived clock a readable name.
set_property -dict { PACKAGE_PIN E3  IOSTANDARD LVCMOS33 } [get_ports clk100_i]
create_clock -name clk100 -period 10.000 -waveform {0.000 5.000} [get_ports clk100_i]
create_generated_clock -name clk_sys [get_pins u_clkgen/u_mmcm/CLKOUT0]

## ---- reset, e-stop --------------------------------------------------------------
## ck_rst (red RESET button, low when pressed) and BTN0 (e-stop, high when
## pressed): asynchronous, synchronised inside (sc_rst_sync, sc_sync).
set_property -dict { PACKAGE_PIN C2  IOSTANDARD LVCMOS33 } [get_ports ck_rst_ni]
set_property -dict { PACKAGE_PIN D9  IOSTANDARD LVCMOS33 } [get_ports estop_i]

## ---- USB-UART (FTDI) ------------------------------------------------------------
## uart_txd_in (A9) is the PC's transmit line = our receive input;
## uart_rxd_out (D10) is our transmit output.
set_property -dict { PACKAGE_PIN A9  IOSTANDARD LVCMOS33 } [get_ports uart_rx_i]
set_property -dict { PACKAGE_PIN D10 IOSTANDARD LVCMOS33 } [get_ports uart_tx_o]

## ---- stepper driver on Pmod JA (JA1 STEP, JA2 DIR, JA3 EN; JA4 interrupt out) -----
set_property -dict { PACKAGE_PIN G13 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports step_o]
set_property -dict { PACKAGE_PIN B11 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports dir_o]
set_property -dict { PACKAGE_PIN A11 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports en_o]
set_property -dict { PACKAGE_PIN D12 IOSTANDARD LVCMOS33 DRIVE 8 SLEW SLOW } [get_ports irq_o]

## ---- quadrature encoder on Pmod JB (JB1 A, JB2 B, JB9 index Z) -----------------------
## Z is pulled down: an encoder without an index never latches on it.
set_property -dict { PACKAGE_PIN E15 IOSTANDARD LVCMOS33 PULLUP TRUE } [get_ports enc_a_i]
set_property -dict { PACKAGE_PIN E16 IOSTANDARD LVCMOS33 PULLUP TRUE } [get_ports enc_b_i]
set_property -dict { PACKAGE_PIN K15 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports enc_z_i]

## ---- switches on Pmod JB (JB3 limit -, JB4 limit +, JB7 home, JB8 probe) ------------
## Pulled down: with nothing connected they read inactive (SW_CFG.INVERT = 0).
## A switch to 3.3 V closes active high; a normally-closed switch to GND with
## an external pull-up reads active when it opens (or its wire breaks).
set_property -dict { PACKAGE_PIN D15 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[0]}]
set_property -dict { PACKAGE_PIN C15 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[1]}]
set_property -dict { PACKAGE_PIN J17 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {sw_i[2]}]
set_property -dict { PACKAGE_PIN J18 IOSTANDARD LVCMOS33 PULLDOWN TRUE } [get_ports {probe_i}]

## ---- LEDs LD4..LD7 -------------------------------------------------------------------
set_property -dict { PACKAGE_PIN H5  IOSTANDARD LVCMOS33 } [get_ports {led_o[0]}]
set_property -dict { PACKAGE_PIN J5  IOSTANDARD LVCMOS33 } [get_ports {led_o[1]}]
set_property -dict { PACKAGE_PIN T9  IOSTANDARD LVCMOS33 } [get_ports {led_o[2]}]
set_property -dict { PACKAGE_PIN T10 IOSTANDARD LVCMOS33 } [get_ports {led_o[3]}]
## RGB LED LD0, red: interrupt pending
set_property -dict { PACKAGE_PIN G6  IOSTANDARD LVCMOS33 } [get_ports led_irq_o]

## ---- IO timing ---------------------------------------------------------------------
## Asynchronous inputs (encoder, buttons, UART RX): no phase relation to any
## FPGA clock, so no input delay applies. Each data input goes through an
## sc_sync (two flops meta_q -> sync_q, both ASYNC_REG): u_link/u_sync_rx,
## u_sync_estop, u_axis/u_servo/u_dec/u_sync_abz (encoder A/B/Z into the
## decoder), u_axis/u_sync_enc (encoder A/B for STATUS.ENC_AB) and
## u_axis/u_sw/u_sync (the limit and home switches); the reset
## button goes through sc_rst_sync (u_rst_sync/chain_q, ASYNC_REG).
## Encoder edges are >= 4 system clocks apart at the rated speed, the
## synchroniser adds 2 clocks of latency.
set_false_path -from [get_ports {enc_a_i enc_b_i enc_z_i estop_i ck_rst_ni uart_rx_i sw_i[*] probe_i}]

## STEP/DIR/EN come straight from flops of clk_sys. The driver needs microsecond
## pulse/setup/hold times (counted in clocks by sc_step_gen); the output delay
## below keeps clock-to-pin short and the three pins' skew within a few ns.
set_output_delay -clock [get_clocks clk_sys] -max 20.000 [get_ports {step_o dir_o en_o}]
set_output_delay -clock [get_clocks clk_sys] -min 0.000  [get_ports {step_o dir_o en_o}]

## UART TX (8.7 us bits), LEDs and the interrupt line (a level read by a host
## or a microcontroller): human / bit-time scale, not timed.
set_false_path -to [get_ports {uart_tx_o led_o[*] led_irq_o irq_o}]

## ---- configuration ---------------------------------------------------------------------
set_property CFGBVS VCCO [current_design]
set_property CONFIG_VOLTAGE 3.3 [current_design]
set_property BITSTREAM.GENERAL.COMPRESS TRUE [current_design]
set_property BITSTREAM.CONFIG.SPI_BUSWIDTH 4 [current_design]
