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

  // ---- closed loop: encoder, neuron-PI cascade, step NCO (issue 3) -------
  // Controller word: Q(CtlW-CtlFrac).CtlFrac, in encoder counts (positions,
  // errors) or counts per control period (speeds, u). Weights Q.WgtFrac,
  // normalised weights Q1.NWgtFrac, coefficients (K, eta, Kb) unsigned
  // Q.CoefFrac. One multiplier MulAW x MulBW (signed). See docs/closed_loop.md.
  localparam int EncCntW   = 32;  // signed encoder position, counts
  localparam int EncFiltW  = 4;   // glitch filter length, clocks (0..15)
  localparam int EncIllW   = 16;  // illegal-transition counter (saturating)
  localparam int EncShiftW = 3;   // log2(encoder counts per pulse), 0..7
  localparam int CtlDivW   = 16;  // control period in clocks
  localparam int CtlW      = 32;
  localparam int CtlFrac   = 16;
  localparam int WgtW      = 24;
  localparam int WgtFrac   = 16;
  localparam int NWgtW     = 18;
  localparam int NWgtFrac  = 16;
  localparam int CoefW     = 24;
  localparam int CoefFrac  = 20;
  localparam int MulAW     = 32;
  localparam int MulBW     = 25;
  localparam int VffFrac   = 31;  // V* as Q.31 pulses/clock on the multiplier
  localparam int LearnShW  = 5;   // Hebb scale: dw = eta e x / 2^learn_shift
  localparam int HoldW     = 16;  // in-position hold, control periods
  localparam int NcoW      = 42;  // step NCO phase (signed, holds acc + u)
  localparam int CtlStW    = 4;   // controller FSM state code
  localparam int CorrW     = 16;  // settle-phase corrective steps (signed)

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

  // ---- host register map (AXI4-Lite slave, UART bridge) ------------------
  // The one definition of the register map: byte addresses of 32-bit
  // registers and their fields. Lines tagged //@reg and //@field are the
  // documentation source: scripts/gen_regmap.py turns this section into
  // docs/regmap.md and build/generated/sc_regmap.h (a ctest fails when the
  // committed docs differ). //@reg NAME ACCESS [wide=WidthParam] "text";
  // //@field REG NAME WIDTH [reset=N] "text" (LSB = the localparam's value).
  // Any address not listed answers DECERR.
  localparam int RegAddrW      = 8;       // byte address bits of the window
  localparam int RegMapVersion = 256;     // 0x0100 = 1.0
  localparam int RegIdMagic    = 21315;   // 0x5343, ASCII "SC"
  localparam int RstPulseHigh  = 50;      // reset values of the pulse timing
  localparam int RstPulseLow   = 50;
  localparam int RstDirSetup   = 100;
  localparam int RstDirHold    = 100;
  localparam int RegId         = 32'h0000_0000;  //@reg ID RO "identification"
  localparam int IdVersionLsb  = 0;      //@field ID VERSION 16 reset=256 "register map version, 0x0100 = 1.0"
  localparam int IdMagicLsb    = 16;     //@field ID MAGIC 16 reset=21315 "0x5343, ASCII 'SC'"
  localparam int RegCtrl       = 32'h0000_0004;  //@reg CTRL RW "control"
  localparam int CtrlEnableBit = 0;      //@field CTRL ENABLE 1 "drives the EN pin; START is refused while 0; ESTOP clears it"
  localparam int RegCmd        = 32'h0000_0008;  //@reg CMD WO "commands: write 1 to act; reads 0"
  localparam int CmdStartBit   = 0;      //@field CMD START 1 "start the loaded table (refused with SLVERR + ERR.REJECT while busy, e-stopped or disabled)"
  localparam int CmdStopBit    = 1;      //@field CMD STOP 1 "abort the move: the profile stops at once, a STEP pulse in flight completes"
  localparam int CmdEstopBit   = 2;      //@field CMD ESTOP 1 "STOP, clear CTRL.ENABLE and latch ERR.ESTOP"
  localparam int RegStatus     = 32'h0000_000C;  //@reg STATUS RO "axis status"
  localparam int StatusPhaseLsb        = 0;   //@field STATUS PHASE PhaseW "phase code (0 idle .. 8 done, 9 abort, 10 fault)"
  localparam int StatusBusyBit         = 4;   //@field STATUS BUSY 1 "a move is running or STEP pulses are owed (from the accepted START on)"
  localparam int StatusDoneBit         = 5;   //@field STATUS DONE 1 "the table has finished and the last pulse has left the pin"
  localparam int StatusEnBit           = 6;   //@field STATUS EN 1 "level of the EN pin"
  localparam int StatusFaultTableBit   = 7;   //@field STATUS FAULT_TABLE 1 "the last START met a malformed table (count 0 or > 16, a zero-length row)"
  localparam int StatusFaultOverrunBit = 8;   //@field STATUS FAULT_OVERRUN 1 "step requests overflowed the pulse queue"
  localparam int StatusEstopBit        = 9;   //@field STATUS ESTOP 1 "ERR.ESTOP is set (START refused)"
  localparam int StatusErrBit          = 10;  //@field STATUS ERR 1 "some ERR flag is set"
  localparam int StatusEncALsb         = 12;  //@field STATUS ENC_AB 2 "synchronised encoder inputs: bit 12 = A, bit 13 = B"
  localparam int StatusSegIdxLsb       = 16;  //@field STATUS SEG_IDX SegIdxW "table row being executed"
  localparam int RegErr        = 32'h0000_0010;  //@reg ERR W1C "sticky error flags: write 1 to clear"
  localparam int ErrRejectBit  = 0;      //@field ERR REJECT 1 "a table/config/START write was refused (busy, e-stopped or disabled): SLVERR, nothing changed"
  localparam int ErrBadAddrBit = 1;      //@field ERR BAD_ACCESS 1 "an access answered DECERR (no register) or SLVERR (write to a read-only register)"
  localparam int ErrEstopBit   = 2;      //@field ERR ESTOP 1 "e-stop latched (CMD.ESTOP or the e-stop input); blocks START until cleared"
  localparam int RegPulseCount = 32'h0000_0014;  //@reg PULSE_COUNT RO "net STEP pulses since the last START (signed)"
  localparam int RegRefPos     = 32'h0000_0018;  //@reg REF_POS RO "reference position P*, integer pulses (signed)"
  localparam int RegEncPos     = 32'h0000_001C;  //@reg ENC_POS RO "encoder position P, counts (signed)"
  localparam int RegFollowErr  = 32'h0000_0020;  //@reg FOLLOW_ERR RO "following error P* - P (signed, wraps)"
  localparam int RegSegCount   = 32'h0000_0024;  //@reg SEG_COUNT RW "rows of the table to run"
  localparam int SegCountLsb   = 0;      //@field SEG_COUNT COUNT SegCntW "1..16"
  localparam int RegPulseTime  = 32'h0000_0028;  //@reg PULSE_TIME RW "STEP pulse timing, clocks"
  localparam int PulseHighLsb  = 0;      //@field PULSE_TIME HIGH PulseTimeW reset=50 "STEP high time (>= 1)"
  localparam int PulseLowLsb   = 16;     //@field PULSE_TIME LOW PulseTimeW reset=50 "minimum STEP low time (>= 1)"
  localparam int RegDirTime    = 32'h0000_002C;  //@reg DIR_TIME RW "DIR timing, clocks"
  localparam int DirSetupLsb   = 0;      //@field DIR_TIME SETUP PulseTimeW reset=100 "DIR change to STEP rising edge"
  localparam int DirHoldLsb    = 16;     //@field DIR_TIME HOLD PulseTimeW reset=100 "STEP rising edge to DIR change"
  localparam int RegPosFrac0   = 32'h0000_0030;  //@reg POS_FRAC0 RW wide=FracBits "initial position fraction, UQ0.80, 3 words low first"
  localparam int RegSegPhase   = 32'h0000_0040;  //@reg SEG_PHASE RW "row staging: phase code"
  localparam int SegPhaseLsb   = 0;      //@field SEG_PHASE PHASE PhaseW "phase reported while the row runs"
  localparam int RegSegClocks  = 32'h0000_0044;  //@reg SEG_CLOCKS RW "row staging: duration in clocks (>= 1)"
  localparam int RegSegJerk    = 32'h0000_0048;  //@reg SEG_JERK RW wide=JerkW "row staging: jerk, signed, 2 words low first"
  localparam int RegSegAcc0    = 32'h0000_0050;  //@reg SEG_ACC0 RW wide=AccW "row staging: start acceleration, signed, 2 words"
  localparam int RegSegVel0    = 32'h0000_0058;  //@reg SEG_VEL0 RW wide=VelW "row staging: start velocity, signed SQ1.80, 3 words"
  localparam int RegSegCommit  = 32'h0000_0064;  //@reg SEG_COMMIT WO "write the staged row into the table; reads 0"
  localparam int SegCommitLsb  = 0;      //@field SEG_COMMIT ROW SegIdxW "table row (0..15) to write"
  // Writes to SEG_COUNT, PULSE_TIME, DIR_TIME, POS_FRAC0, SEG_* and
  // CMD.START while STATUS.BUSY is set are refused (SLVERR, ERR.REJECT).

  // ---- UART bridge (115200 8N1 at ClkHz; protocol in docs/regmap.md) -----
  localparam int UartClksPerBit = 174;    // 20 MHz / 115200 = 173.6 (0.2 % fast)
  localparam int UartTimeoutBits = 40;    // a frame gap this long drops a partial frame
  localparam int UartReqSync   = 165;     // 0xA5: host -> board frame start
  localparam int UartRspSync   = 90;      // 0x5A: board -> host frame start
  localparam int UartCmdWrite  = 1;
  localparam int UartCmdRead   = 2;
  localparam int UartStCrcErr  = 128;     // response status: frame CRC wrong, nothing done
  localparam int UartStBadCmd  = 129;     // response status: unknown command byte

endpackage
