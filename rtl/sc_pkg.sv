// sc_pkg: the single definition of every width, Q format and code shared by
// the RTL and the C++ model. CMake parses this file (scripts/gen_params.py)
// into build/generated/sc_params.h, so the model cannot drift from the RTL.
//
// Fixed-point convention (all kinematic quantities in pulses, time in clocks):
//   position fraction  UQ0.FracBits        pulses
//   velocity           SQ1.FracBits (VelW) pulses / clock        (|v| < 1)
//   acceleration       SQ.FracBits  (AccW) pulses / clock^2      (integer LSBs)
//   jerk               SQ.FracBits  (JerkW) pulses / clock^3     (integer LSBs)
// i.e. one LSB of each is 2^-FracBits pulses per clock^k, so the executor's
// integrator chain is exact integer arithmetic and the host planner can
// predict the final position in closed form.
package sc_pkg;

  // ---- clock -------------------------------------------------------------
  localparam int ClkHz = 20000000;

  // ---- profile executor --------------------------------------------------
  localparam int FracBits = 80;
  localparam int PosIntW  = 32;  // signed integer position (pulses)
  localparam int VelW     = 81;  // signed, |v| < 1 pulse/clock
  localparam int AccW     = 64;  // signed
  localparam int JerkW    = 48;  // signed
  localparam int SegClkW  = 32;  // segment duration in clocks
  localparam int MaxSegs  = 16;  // segment table depth
  localparam int SegIdxW  = 4;   // $clog2(MaxSegs)
  localparam int SegCntW  = 5;   // 0..MaxSegs

  // ---- step pulse generator ----------------------------------------------
  localparam int PulseTimeW = 16;  // high/low/setup/hold in clocks
  localparam int PendW      = 4;   // signed queue of requested steps

  // ---- status ------------------------------------------------------------
  localparam int PhaseW = 4;

  // Phase codes reported on phase_o and carried by each segment.
  // "Dec" phases are the mirrors of the "Acc" ones (|a| rising, constant,
  // falling while slowing down).
  localparam logic [3:0] PhIdle        = 4'd0;
  localparam logic [3:0] PhAccJerkUp   = 4'd1;
  localparam logic [3:0] PhAccConst    = 4'd2;
  localparam logic [3:0] PhAccJerkDown = 4'd3;
  localparam logic [3:0] PhCruise      = 4'd4;
  localparam logic [3:0] PhDecJerkUp   = 4'd5;
  localparam logic [3:0] PhDecConst    = 4'd6;
  localparam logic [3:0] PhDecJerkDown = 4'd7;
  localparam logic [3:0] PhDone        = 4'd8;
  localparam logic [3:0] PhAbort       = 4'd9;
  localparam logic [3:0] PhFault       = 4'd10;

  // One row of the segment table (written field by field on the seg_*_i
  // ports): phase code, duration in clocks, jerk, and the exact starting
  // acceleration and velocity (reloaded at the segment start).
  // Tool note: the RTL uses only what Verilator, Icarus 11 and yosys 0.23
  // all accept: no package import, no structs or enums on ports; modules
  // refer to sc_pkg:: names explicitly.

endpackage
