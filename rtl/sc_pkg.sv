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
  typedef enum logic [3:0] {  // [PhaseW-1:0]; Icarus 11 needs a literal width here
    PhIdle        = 4'd0,
    PhAccJerkUp   = 4'd1,
    PhAccConst    = 4'd2,
    PhAccJerkDown = 4'd3,
    PhCruise      = 4'd4,
    PhDecJerkUp   = 4'd5,
    PhDecConst    = 4'd6,
    PhDecJerkDown = 4'd7,
    PhDone        = 4'd8,
    PhAbort       = 4'd9,
    PhFault       = 4'd10
  } phase_e;

  // One row of the segment table: duration, jerk and the exact starting
  // acceleration and velocity (reloaded at the segment start).
  typedef struct packed {
    logic [PhaseW-1:0]          phase;
    logic [SegClkW-1:0]         clocks;
    logic signed [JerkW-1:0]    jerk;
    logic signed [AccW-1:0]     acc0;
    logic signed [VelW-1:0]     vel0;
  } seg_t;

endpackage
