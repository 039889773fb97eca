// sc_pkg: the single definition of every width, Q format, code and layout
// shared by the RTL, the C++ model, the host software and the docs. CMake
// parses this file (scripts/gen_params.py) into build/generated/sc_params.h,
// so the model cannot drift from the RTL. The //@ tags are the source of the
// register map, the controller configuration and the encodings:
// scripts/gen_layout.py writes the generated section at the end of this
// package, build/generated/sc_layout.h and docs/regmap.md ("Register and
// layout source" there).
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
  localparam int MaxSegs  = 16;  // rows of one planned move (the planner's budget)
  localparam int SegIdxW  = 4;   // $clog2(MaxSegs)
  localparam int SegCntW  = 5;   // 0..MaxSegs
  // Row FIFO: the executor runs a stream of rows that the host appends to
  // while the axis moves (distributed RAM; the depth is a power of two).
  localparam int RowFifoDepth = 32;
  localparam int RowLevelW    = 6;   // 0..RowFifoDepth
  localparam int MoveIdxW     = 32;  // moves completed since START (wraps)
  localparam int RowCountW    = 32;  // rows loaded since START (wraps): ROW_COUNT, RETARGET_ROW
  // Row flags, pushed with each row.
  localparam int RowFlagW         = 4;
  localparam int RowFlagMoveEnd   = 0;  // last row of a move: a move boundary follows
  localparam int RowFlagStreamEnd = 1;  // last row of the stream: the plan ends here, at rest
                                        // or at its end speed (a stepper's stop speed)
  localparam int RowFlagAccStep   = 2;  // the row starts with a planned acceleration step
                                        // (trapezoid profiles): only its velocity must continue
  localparam int RowFlagHold      = 3;  // velocity mode: at its end the row holds its constant
                                        // velocity until a whole move (a MOVE_END row) is queued

  // Row reach (sc_row_reach): the furthest positions a row reaches relative
  // to its start, with ReachFrac fraction bits (rounded outward), for the
  // soft-limit look-ahead; ReachAccW is the evaluator's datapath width.
  localparam int ReachFrac = 16;
  localparam int ReachW    = 50;  // signed, PosIntW + 2 + ReachFrac: |reach| < 2^(PosIntW+ReachFrac)
  localparam int ReachAccW = 116;  // |6 S| < 2^115 for every row inside the velocity range

  // ---- coordinated axes ----------------------------------------------------
  localparam int MaxAxes = 4;  // axes of sc_multi_axis_core (its Axes: 1 .. MaxAxes)

  // ---- step pulse generator ----------------------------------------------
  localparam int PulseTimeW = 16;  // high/low/setup/hold in clocks
  localparam int PendW      = 4;   // signed queue of requested steps

  // ---- switch inputs (limits, home, probe) ---------------------------------
  localparam int DebounceW = 16;  // debounce filter length, clocks
  localparam int SwW       = 4;   // switch inputs per axis
  localparam int SwLimNeg  = 0;   // bit of each switch in sw_i, SW_CFG.INVERT, STATUS.SW_LEVEL
  localparam int SwLimPos  = 1;
  localparam int SwHome    = 2;
  localparam int SwProbe   = 3;   // the board's one probe input, fanned out to every axis

  // ---- closed loop: encoder, neuron-PI cascade, step NCO ----------------
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
  localparam int UpcW      = 6;   // micro-program step of sc_neuron_pi

  // Encodings of sc_neuron_pi, used by the RTL and cmodel/neuron_pi.* under
  // the generated names CtlSt<Name> / Upc<Name> (values count up from the
  // previous one unless given). //@enum TYPE WIDTH "text";
  // //@value TYPE NAME [=N] "text".
  //@enum CtlSt CtlStW "phase of the control period: sc_neuron_pi state_o, CL_STATUS.CTL_STATE"
  //@value CtlSt Idle =0 "stopped, or waiting for the next period strobe"
  //@value CtlSt Vff "feed-forward product V* x div << shift"
  //@value CtlSt Div "weight normalisation wn_i = w_i / (|w_1| + |w_2|) (divider)"
  //@value CtlSt Err "errors e, x2 = e - e_prev, learning/fault/in-position flags"
  //@value CtlSt T1 "t1 = wn_1 x1"
  //@value CtlSt T2 "t2 = wn_2 x2, sum = sat(t1 + t2)"
  //@value CtlSt Du "du = K sum"
  //@value CtlSt Bc "back-calculation, accumulator, output limit"
  //@value CtlSt H1 "Hebb product e x1"
  //@value CtlSt Dw1 "w_1 update and clamp"
  //@value CtlSt H2 "Hebb product e x2"
  //@value CtlSt Dw2 "w_2 update and clamp"
  //@value CtlSt Init "after start: loop registers cleared, weights loaded"
  //@enum Upc UpcW "micro-program step of sc_neuron_pi (one operation per clock)"
  //@value Upc Idle =0 "no operation; the period counter runs"
  //@value Upc Init =1 "1..12: clear/load the loop registers after start"
  //@value Upc Vff =13 "vff = V* x (div << shift)"
  //@value Upc Set1 "|w1| -> drem, T"
  //@value Upc Set2 "T + |w2| -> dsum"
  //@value Upc Div1 "w1 / dsum, NWgtFrac+1 clocks"
  //@value Upc Set3 "|w2| -> drem"
  //@value Upc Div2 "w2 / dsum"
  //@value Upc Ref "T = r"
  //@value Upc Err "eraw = T - y"
  //@value Upc Abs "T = |eraw|"
  //@value Upc Eq "eraw == e_prev ?"
  //@value Upc X2 "x2 = e - e_prev"
  //@value Upc E "e"
  //@value Upc Ep "e_prev = eraw"
  //@value Upc Learn "|e| > dead zone ?"
  //@value Upc Ferr "|e_p| > ferr_lim ? (position loop)"
  //@value Upc Win "in position ? (position loop)"
  //@value Upc T1 "t1 = wn1 e"
  //@value Upc T2 "t2 = wn2 x2"
  //@value Upc Sum "sum = sat(t1 + t2)"
  //@value Upc Du "du = K sum"
  //@value Upc Bc "bc = Kb es"
  //@value Upc Acc1 "T = acc + du"
  //@value Upc Acc2 "acc = sat(T - bc)"
  //@value Upc Tot "tot = sat(acc + b)"
  //@value Upc Hi "es = tot - lim if > 0"
  //@value Upc Lo "es = tot + lim if < 0"
  //@value Upc Out "out = tot - es"
  //@value Upc H1 "h = e e_b (w1)"
  //@value Upc Dw1 "dw = eta1 h / 2^ls"
  //@value Upc W1 "T = w1 + dw"
  //@value Upc W2 "T > w1_max ?"
  //@value Upc W3 "T < w_min ?"
  //@value Upc W4 "w1 = clamp"
  //@value Upc H2 "h = e e_b (w2)"
  //@value Upc Dw2 "dw = eta2 h / 2^ls"
  //@value Upc W5 "T = w2 + dw"
  //@value Upc W6 "T > w2_max ?"
  //@value Upc W7 "T < w_min ?"
  //@value Upc W8 "w2 = clamp; next loop or idle"

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
  localparam logic [3:0] PhStop        = 4'd11;  // controlled stop (sc_stop_gen)

  // Controlled-stop limits at reset, in executor LSBs at 20 MHz: jerk
  // 2e7 pulses/s^3 (2e7 * 2^80 / (2e7)^3), deceleration 2e5 pulses/s^2
  // (2e5 * 2^80 / (2e7)^2).
  localparam logic [47:0] StopJerkReset = 48'd3022314549;
  localparam logic [63:0] StopAccReset  = 64'd604462909807314;

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
  // Any address not listed answers DECERR. The window is 1 KiB (256 words;
  // the UART bridge's address byte is a word address so it reaches them all);
  // 0x000 .. 0x0FC hold the 2.x map unchanged, the rest is free.
  localparam int RegAddrW      = 10;      // byte address bits of the window
  // sc_axi_multi_axis: window w answers at byte addresses w << RegAddrW. Window 0
  // writes every axis in one bus write (reads answer axis 0's registers);
  // window 1 + a is axis a alone. Windows above the axes answer DECERR.
  localparam int RegWinW       = 3;       // window-number bits: the group window and MaxAxes axes
  localparam int MultiRegAddrW = 13;      // RegAddrW + RegWinW: byte address bits of the multi-axis map
  // 0x0306 = 3.6: 1 KiB window, UART word address; switch inputs, guards,
  // probe, soft limits, index latch; ROW_PUSH.HOLD (velocity mode), ROW_PUSH.REPLACE,
  // ROW_COUNT and RETARGET_ROW (retarget); 0x0307 = 3.7: STATUS.REACH (the
  // soft-limit look-ahead)
  localparam int RegMapVersion = 775;
  localparam int RegIdMagic    = 21315;   // 0x5343, ASCII "SC"
  localparam int RstPulseHigh  = 50;      // reset values of the pulse timing
  localparam int RstPulseLow   = 50;
  localparam int RstDirSetup   = 100;
  localparam int RstDirHold    = 100;
  localparam int RegId         = 32'h0000_0000;  //@reg ID RO "identification"
  localparam int IdVersionLsb  = 0;      //@field ID VERSION 16 reset=RegMapVersion "register map version, 0x0307 = 3.7"
  localparam int IdMagicLsb    = 16;     //@field ID MAGIC 16 reset=21315 "0x5343, ASCII 'SC'"
  localparam int RegCtrl       = 32'h0000_0004;  //@reg CTRL RW "control"
  localparam int CtrlEnableBit = 0;      //@field CTRL ENABLE 1 "drives the EN pin; START is refused while 0; ESTOP clears it"
  localparam int CtrlClosedBit = 1;      //@field CTRL CLOSED_LOOP 1 "sc_axi_servo: 1 = closed loop (encoder feedback), 0 = open loop; a write changing it while busy is refused (ignored by sc_axi_axis)"
  localparam int RegCmd        = 32'h0000_0008;  //@reg CMD WO "commands: write 1 to act; reads 0"
  localparam int CmdStartBit   = 0;      //@field CMD START 1 "start the rows in the FIFO (refused with SLVERR + ERR.REJECT while busy, e-stopped or disabled)"
  localparam int CmdStopBit    = 1;      //@field CMD STOP 1 "controlled stop: jerk-limited to rest with STOP_JERK / STOP_ACC, the FIFO is emptied (ignored while idle)"
  localparam int CmdEstopBit   = 2;      //@field CMD ESTOP 1 "immediate stop: the profile stops at once (a STEP pulse in flight completes), CTRL.ENABLE cleared, ERR.ESTOP latched"
  localparam int CmdFlushBit   = 3;      //@field CMD FLUSH 1 "empty the row FIFO (refused with SLVERR + ERR.REJECT while busy)"
  localparam int RegStatus     = 32'h0000_000C;  //@reg STATUS RO "axis status"
  localparam int StatusPhaseLsb        = 0;   //@field STATUS PHASE PhaseW "phase code (0 idle .. 8 done, 9 abort, 10 fault, 11 controlled stop)"
  localparam int StatusBusyBit         = 4;   //@field STATUS BUSY 1 "a move is running or STEP pulses are owed (from the accepted START on)"
  localparam int StatusDoneBit         = 5;   //@field STATUS DONE 1 "the stream has ended and the last pulse has left the pin"
  localparam int StatusEnBit           = 6;   //@field STATUS EN 1 "level of the EN pin"
  localparam int StatusFaultTableBit   = 7;   //@field STATUS FAULT_TABLE 1 "the last START met an empty FIFO, or a zero-length row was loaded"
  localparam int StatusFaultOverrunBit = 8;   //@field STATUS FAULT_OVERRUN 1 "the steps outran the pulse timing (until the next START): the profile stopped at once before the pulse queue could overflow, no step lost (open loop); the queue overflowed (closed loop)"
  localparam int StatusEstopBit        = 9;   //@field STATUS ESTOP 1 "ERR.ESTOP is set (START refused)"
  localparam int StatusErrBit          = 10;  //@field STATUS ERR 1 "some ERR flag is set"
  localparam int StatusFaultFerrBit    = 11;  //@field STATUS FAULT_FERR 1 "closed loop: following-error fault latched (|P* - P| > FERR_LIM); 0 in sc_axi_axis"
  localparam int StatusEncALsb         = 12;  //@field STATUS ENC_AB 2 "synchronised encoder inputs: bit 12 = A, bit 13 = B"
  localparam int StatusInPosBit        = 14;  //@field STATUS IN_POS 1 "closed loop: in position (|P - L| <= INPOS_WIN for INPOS_HOLD periods); 0 in sc_axi_axis"
  localparam int StatusUnderrunBit     = 15;  //@field STATUS UNDERRUN 1 "the FIFO ran dry while moving: the axis stopped (until the next START)"
  localparam int StatusSegIdxLsb       = 16;  //@field STATUS SEG_IDX SegIdxW "row of the current move being executed (modulo 16)"
  localparam int StatusDiscontBit      = 20;  //@field STATUS DISCONTINUITY 1 "a row did not continue the motion exactly: the axis stopped (until the next START)"
  localparam int StatusStoppingBit     = 21;  //@field STATUS STOPPING 1 "a controlled stop runs (CMD.STOP, underrun, discontinuity)"
  localparam int StatusLatchedBit      = 26;  //@field STATUS LATCHED 1 "LATCH_PULSE / LATCH_ENC hold a capture (a LATCH_CFG write re-arms)"
  localparam int StatusGuardBit        = 27;  //@field STATUS GUARD 1 "a row broke a GUARD_VEL / GUARD_ACC / GUARD_JERK limit and was refused: the axis stopped (until the next START)"
  localparam int StatusSwLevelLsb      = 28;  //@field STATUS SW_LEVEL SwW "filtered switch levels, 1 = active: bit 28 LIM_NEG, 29 LIM_POS, 30 HOME, 31 PROBE"
  localparam int StatusReachBit        = 23;  //@field STATUS REACH 1 "the soft-limit look-ahead refused a row (its reach left SOFT_MIN .. SOFT_MAX, or it was not checked by its boundary): the axis stopped or the START was refused (until the next START)"
  localparam int StatusOvershootBit    = 22;  //@field STATUS OVERSHOOT 1 "the last controlled stop could not avoid a velocity reversal within STOP_JERK (limits below the plan's)"
  localparam int RegErr        = 32'h0000_0010;  //@reg ERR W1C "sticky error flags: write 1 to clear"
  localparam int ErrRejectBit  = 0;      //@field ERR REJECT 1 "a table/config/START write was refused (busy, e-stopped or disabled): SLVERR, nothing changed"
  localparam int ErrBadAddrBit = 1;      //@field ERR BAD_ACCESS 1 "an access answered DECERR (no register) or SLVERR (write to a read-only register)"
  localparam int ErrEstopBit   = 2;      //@field ERR ESTOP 1 "e-stop latched (CMD.ESTOP or the e-stop input); blocks START until cleared"
  localparam int ErrFifoFullBit = 3;     //@field ERR FIFO_FULL 1 "a ROW_PUSH met a full FIFO: SLVERR, the row was not appended (the staged row is kept)"
  localparam int ErrDiscontBit = 4;      //@field ERR DISCONTINUITY 1 "a row did not continue the previous row's end state exactly: not executed, the axis stopped"
  localparam int ErrLimNegBit  = 6;      //@field ERR LIMIT_NEG 1 "the - limit (switch or SOFT_MIN) stopped motion into it or refused a START toward it"
  localparam int ErrLimPosBit  = 7;      //@field ERR LIMIT_POS 1 "the + limit (switch or SOFT_MAX) stopped motion into it or refused a START toward it"
  localparam int ErrGuardBit   = 8;      //@field ERR GUARD 1 "a row broke a guard limit: not executed, the axis stopped (or the START was refused)"
  localparam int ErrSoftLimBit = 9;      //@field ERR SOFT_LIMIT 1 "the soft-limit window stopped motion out of it or refused a START out of it (with LIMIT_NEG / LIMIT_POS for the side), or its look-ahead refused a row (STATUS.REACH)"
  localparam int ErrRetargetBit = 10;    //@field ERR RETARGET 1 "a ROW_PUSH.REPLACE was refused: row RETARGET_ROW was already loaded, lies beyond the queued rows, or no stream runs on (idle, stopping, STREAM_END row): nothing changed"
  localparam int ErrUnderrunBit = 5;     //@field ERR UNDERRUN 1 "the FIFO ran dry while the axis was moving: the axis stopped"
  localparam int RegPulseCount = 32'h0000_0014;  //@reg PULSE_COUNT RO "net STEP pulses since the last START (signed)"
  localparam int RegRefPos     = 32'h0000_0018;  //@reg REF_POS RO "reference position P*, integer pulses (signed)"
  localparam int RegEncPos     = 32'h0000_001C;  //@reg ENC_POS RO "encoder position P, counts (signed)"
  localparam int RegFollowErr  = 32'h0000_0020;  //@reg FOLLOW_ERR RO "following error P* - P (signed, wraps)"
  localparam int RegFifoStatus = 32'h0000_0024;  //@reg FIFO_STATUS RO "row FIFO"
  localparam int FifoLevelLsb  = 0;      //@field FIFO_STATUS LEVEL RowLevelW "rows queued (0..32)"
  localparam int FifoFullBit   = 8;      //@field FIFO_STATUS FULL 1 "no room: ROW_PUSH is refused"
  localparam int FifoLowBit    = 9;      //@field FIFO_STATUS LOW 1 "LEVEL is below FIFO_LOW_WATER"
  localparam int RegPulseTime  = 32'h0000_0028;  //@reg PULSE_TIME RW "STEP pulse timing, clocks"
  localparam int PulseHighLsb  = 0;      //@field PULSE_TIME HIGH PulseTimeW reset=50 "STEP high time (>= 1: a write leaving 0 is refused)"
  localparam int PulseLowLsb   = 16;     //@field PULSE_TIME LOW PulseTimeW reset=50 "minimum STEP low time (>= 1: a write leaving 0 is refused)"
  localparam int RegDirTime    = 32'h0000_002C;  //@reg DIR_TIME RW "DIR timing, clocks"
  localparam int DirSetupLsb   = 0;      //@field DIR_TIME SETUP PulseTimeW reset=100 "DIR change to STEP rising edge"
  localparam int DirHoldLsb    = 16;     //@field DIR_TIME HOLD PulseTimeW reset=100 "STEP rising edge to DIR change"
  localparam int RegFifoLow    = 32'h0000_003C;  //@reg FIFO_LOW_WATER RW "low-water mark of the row FIFO"
  localparam int FifoLowLsb    = 0;      //@field FIFO_LOW_WATER LEVEL RowLevelW reset=8 "IRQ_STATUS.LOW_WATER when LEVEL falls below this"
  localparam int RstFifoLow    = 8;
  localparam int RegPosFrac0   = 32'h0000_0030;  //@reg POS_FRAC0 RW wide=FracBits "initial position fraction, UQ0.80, 3 words low first"
  localparam int RegSegPhase   = 32'h0000_0040;  //@reg SEG_PHASE RW "row staging (writable while busy): phase code"
  localparam int SegPhaseLsb   = 0;      //@field SEG_PHASE PHASE PhaseW "phase reported while the row runs"
  localparam int RegSegClocks  = 32'h0000_0044;  //@reg SEG_CLOCKS RW "row staging: duration in clocks (>= 1)"
  localparam int RegSegJerk    = 32'h0000_0048;  //@reg SEG_JERK RW wide=JerkW "row staging: jerk, signed, 2 words low first"
  localparam int RegSegAcc0    = 32'h0000_0050;  //@reg SEG_ACC0 RW wide=AccW "row staging: start acceleration, signed, 2 words"
  localparam int RegSegVel0    = 32'h0000_0058;  //@reg SEG_VEL0 RW wide=VelW "row staging: start velocity, signed SQ1.80, 3 words"
  localparam int RegRowPush    = 32'h0000_0064;  //@reg ROW_PUSH WO "append the staged row to the FIFO with these flags (refused with SLVERR + ERR.FIFO_FULL when full); reads 0"
  localparam int RowPushMoveEndBit   = 0;  //@field ROW_PUSH MOVE_END 1 "last row of a move: MOVE_INDEX and BOUNDARY_POS update when it ends"
  localparam int RowPushStreamEndBit = 1;  //@field ROW_PUSH STREAM_END 1 "last row of the stream: the plan ends here (at rest or at its stop speed)"
  localparam int RowPushAccStepBit   = 2;  //@field ROW_PUSH ACC_STEP 1 "the row starts with a planned acceleration step (trapezoid): the continuity guard checks its velocity only"
  localparam int RowPushReplaceBit   = 4;  //@field ROW_PUSH REPLACE 1 "retarget: the staged row becomes row RETARGET_ROW, the queued rows from there on are dropped; refused (ERR.RETARGET, nothing changes) once that row is loaded (ERR.RETARGET within 4 clocks of the write's response)"
  localparam int RowPushHoldBit      = 3;  //@field ROW_PUSH HOLD 1 "velocity mode: a row ending at constant velocity (a = j = 0) keeps that velocity until a whole move (up to a MOVE_END row) is queued or the FIFO is full"
  // Closed-loop controller settings (sc_axi_servo only; DECERR in
  // sc_axi_axis): words RegClFirst .. RegClFirst + 4 * (ClCfgWords - 1), the
  // registers tagged `servo` whose fields carry cfg=MEMBER. Those fields are
  // the closed-loop configuration: scripts/gen_layout.py generates from
  // them ClCfgWords, the CtlCfg* layout of the configuration vector that
  // travels sc_axi_regs -> sc_servo_axis -> sc_neuron_pi, the word masks,
  // reset values and decode (generated section at the end of this package)
  // and the C++ struct sc::CtlCfg (build/generated/sc_layout.h). Field tag
  // extras: cfg=MEMBER, signed, q=FRAC_BITS, unit=UNIT. Reset
  // values = the closed-loop runner's defaults (tb/closed_loop_run.h,
  // 1 encoder count per pulse, 10 kHz control rate, 50/50-clock STEP).
  // Units: docs/closed_loop.md (Q.CtlFrac counts or counts per control
  // period, coefficients Q.CoefFrac, weights signed Q.WgtFrac).
  localparam int ClStatWords   = 9;
  localparam int RstEncFilt    = 3;
  localparam int RstFfEn       = 1;
  localparam int RstLearnShift = 10;
  localparam int RstCtlDiv     = 2000;
  localparam int RstInposHold  = 50;
  localparam int RstLearnDzP   = 49152;
  localparam int RstLearnDzV   = 98304;
  localparam int RstKp         = 4194;
  localparam int RstKv         = 20972;
  localparam int RstKb         = 1048576;
  localparam int RstEtaP1      = 209715;
  localparam int RstEtaP2      = 209715;
  localparam int RstEtaV1      = 157286;
  localparam int RstEtaV2      = 104858;
  localparam int RstWp1        = 0;
  localparam int RstWp2        = 4194304;
  localparam int RstWv1        = 4194304;
  localparam int RstWv2        = 1048576;
  localparam int RstWmin       = 0;
  localparam int RstWp1Max     = 32768;
  localparam int RstWp2Max     = 8323072;
  localparam int RstWv1Max     = 8323072;
  localparam int RstWv2Max     = 2097152;
  localparam int RstVLim       = 32768;
  localparam int RstULim       = 1179648;
  localparam int RstFerrLim    = 32768000;
  localparam int RstInposWin   = 0;
  localparam int RstSettleRate = 3277;
  localparam int RegClFirst    = 32'h0000_0068;
  localparam int RegClCfg      = 32'h0000_0068;  //@reg CL_CFG RW servo "closed loop: encoder and learning options"
  localparam int ClEncFiltLsb  = 0;      //@field CL_CFG ENC_FILT EncFiltW reset=RstEncFilt cfg=enc_filt unit=clocks "encoder glitch filter, clocks (0..15)"
  localparam int ClEncShiftLsb = 4;      //@field CL_CFG ENC_SHIFT EncShiftW reset=0 cfg=shift unit=log2 "log2(encoder counts per STEP pulse)"
  localparam int ClFfEnBit     = 8;      //@field CL_CFG FF_EN 1 reset=RstFfEn cfg=ff_en unit=flag "velocity feed-forward from V*"
  localparam int ClFerrStopBit = 9;      //@field CL_CFG FERR_STOP 1 reset=0 cfg=ferr_stop unit=flag "following-error fault: 1 = controlled stop (STOP_JERK / STOP_ACC), the controller keeps tracking; 0 = immediate (u = 0, executor aborted)"
  localparam int ClPidBit      = 10;     //@field CL_CFG PID 1 reset=0 cfg=pid unit=flag "controller: 0 = neuron-PI cascade; 1 = fixed-gain PID with back-calculation anti-windup (paper 003): the position loop alone drives u, learning off, its P and I gains K_P times the normalised weights W_P2 / W_P1, K_V its D gain, U_LIM its output limit"
  localparam int ClLearnShLsb  = 12;     //@field CL_CFG LEARN_SHIFT LearnShW reset=RstLearnShift cfg=learn_shift unit=log2 "Hebb scale: dw = eta e x / 2^LEARN_SHIFT"
  localparam int RegClPeriod   = 32'h0000_006C;  //@reg CL_PERIOD RW servo "closed loop: control period and in-position hold"
  localparam int ClDivLsb      = 0;      //@field CL_PERIOD DIV CtlDivW reset=RstCtlDiv cfg=div unit=clocks "control period, clocks (2000 = 10 kHz; at least 256)"
  localparam int ClInposHoldLsb = 16;    //@field CL_PERIOD INPOS_HOLD HoldW reset=RstInposHold cfg=inpos_hold unit=periods "in-position hold, control periods"
  localparam int RegClLearnDzP = 32'h0000_0070;  //@reg LEARN_DZ_P RW servo "no position-loop learning while |e_p| <= this, counts Q.16"
  localparam int ClLearnDzPLsb = 0;      //@field LEARN_DZ_P VALUE CtlW reset=RstLearnDzP cfg=learn_dz_p q=CtlFrac unit=counts "counts, Q.CtlFrac"
  localparam int RegClLearnDzV = 32'h0000_0074;  //@reg LEARN_DZ_V RW servo "no speed-loop learning while |e_v| <= this, counts/period Q.16"
  localparam int ClLearnDzVLsb = 0;      //@field LEARN_DZ_V VALUE CtlW reset=RstLearnDzV cfg=learn_dz_v q=CtlFrac unit=counts/period "counts per control period, Q.CtlFrac"
  localparam int RegClKp       = 32'h0000_0078;  //@reg K_P RW servo "position neuron gain K_p, unsigned Q.20"
  localparam int ClKpLsb       = 0;      //@field K_P VALUE CoefW reset=RstKp cfg=k_p q=CoefFrac unit=1 "Q.CoefFrac"
  localparam int RegClKv       = 32'h0000_007C;  //@reg K_V RW servo "speed neuron gain K_v, unsigned Q.20"
  localparam int ClKvLsb       = 0;      //@field K_V VALUE CoefW reset=RstKv cfg=k_v q=CoefFrac unit=1 "Q.CoefFrac"
  localparam int RegClKb       = 32'h0000_0080;  //@reg KB RW servo "back-calculation (anti-windup) gain, unsigned Q.20"
  localparam int ClKbLsb       = 0;      //@field KB VALUE CoefW reset=RstKb cfg=kb q=CoefFrac unit=1 "Q.CoefFrac"
  localparam int RegClEtaP1    = 32'h0000_0084;  //@reg ETA_P1 RW servo "learning rate, position loop, integral weight, Q.20"
  localparam int ClEtaP1Lsb    = 0;      //@field ETA_P1 VALUE CoefW reset=RstEtaP1 cfg=eta_p1 q=CoefFrac unit=1 "Q.CoefFrac (0: fixed gain)"
  localparam int RegClEtaP2    = 32'h0000_0088;  //@reg ETA_P2 RW servo "learning rate, position loop, proportional weight, Q.20"
  localparam int ClEtaP2Lsb    = 0;      //@field ETA_P2 VALUE CoefW reset=RstEtaP2 cfg=eta_p2 q=CoefFrac unit=1 "Q.CoefFrac"
  localparam int RegClEtaV1    = 32'h0000_008C;  //@reg ETA_V1 RW servo "learning rate, speed loop, integral weight, Q.20"
  localparam int ClEtaV1Lsb    = 0;      //@field ETA_V1 VALUE CoefW reset=RstEtaV1 cfg=eta_v1 q=CoefFrac unit=1 "Q.CoefFrac"
  localparam int RegClEtaV2    = 32'h0000_0090;  //@reg ETA_V2 RW servo "learning rate, speed loop, proportional weight, Q.20"
  localparam int ClEtaV2Lsb    = 0;      //@field ETA_V2 VALUE CoefW reset=RstEtaV2 cfg=eta_v2 q=CoefFrac unit=1 "Q.CoefFrac"
  localparam int RegClWp1      = 32'h0000_0094;  //@reg W_P1 RW servo "initial weight, position loop, integral (signed Q.16)"
  localparam int ClWp1Lsb      = 0;      //@field W_P1 VALUE WgtW reset=RstWp1 cfg=w_p1 signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWp2      = 32'h0000_0098;  //@reg W_P2 RW servo "initial weight, position loop, proportional (signed Q.16)"
  localparam int ClWp2Lsb      = 0;      //@field W_P2 VALUE WgtW reset=RstWp2 cfg=w_p2 signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv1      = 32'h0000_009C;  //@reg W_V1 RW servo "initial weight, speed loop, integral (signed Q.16)"
  localparam int ClWv1Lsb      = 0;      //@field W_V1 VALUE WgtW reset=RstWv1 cfg=w_v1 signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv2      = 32'h0000_00A0;  //@reg W_V2 RW servo "initial weight, speed loop, proportional (signed Q.16)"
  localparam int ClWv2Lsb      = 0;      //@field W_V2 VALUE WgtW reset=RstWv2 cfg=w_v2 signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWmin     = 32'h0000_00A4;  //@reg W_MIN RW servo "lower bound of every weight (signed Q.16)"
  localparam int ClWminLsb     = 0;      //@field W_MIN VALUE WgtW reset=RstWmin cfg=w_min signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWp1Max   = 32'h0000_00A8;  //@reg W_P1_MAX RW servo "upper bound of W_P1 (signed Q.16)"
  localparam int ClWp1MaxLsb   = 0;      //@field W_P1_MAX VALUE WgtW reset=RstWp1Max cfg=w_p1_max signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWp2Max   = 32'h0000_00AC;  //@reg W_P2_MAX RW servo "upper bound of W_P2 (signed Q.16)"
  localparam int ClWp2MaxLsb   = 0;      //@field W_P2_MAX VALUE WgtW reset=RstWp2Max cfg=w_p2_max signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv1Max   = 32'h0000_00B0;  //@reg W_V1_MAX RW servo "upper bound of W_V1 (signed Q.16)"
  localparam int ClWv1MaxLsb   = 0;      //@field W_V1_MAX VALUE WgtW reset=RstWv1Max cfg=w_v1_max signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv2Max   = 32'h0000_00B4;  //@reg W_V2_MAX RW servo "upper bound of W_V2 (signed Q.16)"
  localparam int ClWv2MaxLsb   = 0;      //@field W_V2_MAX VALUE WgtW reset=RstWv2Max cfg=w_v2_max signed q=WgtFrac unit=1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClVLim     = 32'h0000_00B8;  //@reg V_LIM RW servo "|position-loop output| limit, counts/period Q.16"
  localparam int ClVLimLsb     = 0;      //@field V_LIM VALUE CtlW reset=RstVLim cfg=v_lim q=CtlFrac unit=counts/period "Q.CtlFrac (32768 = 5000 pulses/s at 10 kHz)"
  localparam int RegClULim     = 32'h0000_00BC;  //@reg U_LIM RW servo "|u| limit (commanded step rate), counts/period Q.16"
  localparam int ClULimLsb     = 0;      //@field U_LIM VALUE CtlW reset=RstULim cfg=u_lim q=CtlFrac unit=counts/period "Q.CtlFrac (1179648 = 180,000 pulses/s at 10 kHz)"
  localparam int RegClFerrLim  = 32'h0000_00C0;  //@reg FERR_LIM RW servo "following-error fault limit, counts Q.16"
  localparam int ClFerrLimLsb  = 0;      //@field FERR_LIM VALUE CtlW reset=RstFerrLim cfg=ferr_lim q=CtlFrac unit=counts "Q.CtlFrac (500 counts)"
  localparam int RegClInposWin = 32'h0000_00C4;  //@reg INPOS_WIN RW servo "in-position window |P - L|, counts Q.16"
  localparam int ClInposWinLsb = 0;      //@field INPOS_WIN VALUE CtlW reset=RstInposWin cfg=inpos_win q=CtlFrac unit=counts "Q.CtlFrac"
  localparam int RegClSettle   = 32'h0000_00C8;  //@reg SETTLE_RATE RW servo "corrective step rate after the reference is done, counts/period Q.16"
  localparam int ClSettleLsb   = 0;      //@field SETTLE_RATE VALUE CtlW reset=RstSettleRate cfg=settle_rate q=CtlFrac unit=counts/period "Q.CtlFrac (3277 = 500 pulses/s at 10 kHz)"
  // Closed-loop status (sc_axi_servo only), words RegClStat .. + 4 * (ClStatWords - 1).
  localparam int RegClStat     = 32'h0000_00D0;  //@reg CL_STATUS RO servo "closed-loop status"
  localparam int ClStInPosBit  = 0;      //@field CL_STATUS IN_POS 1 "in position"
  localparam int ClStFerrBit   = 1;      //@field CL_STATUS FAULT_FERR 1 "following-error fault latched (cleared by the next START)"
  localparam int ClStActiveBit = 2;      //@field CL_STATUS CTL_ACTIVE 1 "controller running"
  localparam int ClStStateLsb  = 4;      //@field CL_STATUS CTL_STATE CtlStW "controller phase of the control period (CtlSt, see Encodings)"
  localparam int ClStIllLsb    = 16;     //@field CL_STATUS ENC_ILLEGAL EncIllW "illegal encoder transitions (saturating)"
  localparam int RegClU        = 32'h0000_00D4;  //@reg CTL_U RO servo "controller output u, signed counts/period Q.16"
  localparam int RegClVCmd     = 32'h0000_00D8;  //@reg CTL_V_CMD RO servo "position-loop output v_cmd, signed counts/period Q.16"
  localparam int RegClEp       = 32'h0000_00DC;  //@reg CTL_E_P RO servo "position error e_p, signed counts Q.16"
  localparam int RegClEv       = 32'h0000_00E0;  //@reg CTL_E_V RO servo "speed error e_v, signed counts/period Q.16"
  localparam int RegClWp1Now   = 32'h0000_00E4;  //@reg CTL_W_P1 RO servo "learned weight w_p1, signed Q.16 (sign-extended)"
  localparam int RegClWp2Now   = 32'h0000_00E8;  //@reg CTL_W_P2 RO servo "learned weight w_p2, signed Q.16 (sign-extended)"
  localparam int RegClWv1Now   = 32'h0000_00EC;  //@reg CTL_W_V1 RO servo "learned weight w_v1, signed Q.16 (sign-extended)"
  localparam int RegClWv2Now   = 32'h0000_00F0;  //@reg CTL_W_V2 RO servo "learned weight w_v2, signed Q.16 (sign-extended)"
  // Stream status and interrupts (the free words of the map).
  localparam int RegMoveIndex  = 32'h0000_00CC;  //@reg MOVE_INDEX RO "moves completed since START (MOVE_END rows ended, wraps)"
  localparam int RegBoundaryPos = 32'h0000_00F4;  //@reg BOUNDARY_POS RO "reference position at the last move boundary, integer pulses (signed; the start position until one ends)"
  localparam int RegIrqStatus  = 32'h0000_00F8;  //@reg IRQ_STATUS W1C "interrupt causes, sticky: write 1 to clear; irq_o = |(IRQ_STATUS & IRQ_ENABLE)"
  localparam int IrqLowWaterBit = 0;     //@field IRQ_STATUS LOW_WATER 1 "the FIFO level fell below FIFO_LOW_WATER"
  localparam int IrqMoveDoneBit = 1;     //@field IRQ_STATUS MOVE_DONE 1 "a move ended (MOVE_INDEX advanced)"
  localparam int IrqIdleBit     = 2;     //@field IRQ_STATUS IDLE 1 "the axis became idle (BUSY fell)"
  localparam int IrqUnderrunBit = 3;     //@field IRQ_STATUS UNDERRUN 1 "the FIFO ran dry while moving"
  localparam int IrqFaultBit    = 4;     //@field IRQ_STATUS FAULT 1 "a fault: FAULT_TABLE, FAULT_OVERRUN, DISCONTINUITY, GUARD, REACH, FAULT_FERR, e-stop or a limit acting"
  localparam int IrqSwitchBit   = 5;     //@field IRQ_STATUS SWITCH 1 "a filtered switch level (STATUS.SW_LEVEL) changed"
  localparam int IrqLatchBit    = 6;     //@field IRQ_STATUS LATCH 1 "the position latch captured (STATUS.LATCHED rose)"
  localparam int IrqW           = 7;
  localparam int RegIrqEnable  = 32'h0000_00FC;  //@reg IRQ_ENABLE RW "interrupt enables, one per IRQ_STATUS bit"
  localparam int IrqEnableLsb  = 0;      //@field IRQ_ENABLE MASK IrqW "bit i enables IRQ_STATUS bit i"
  // Controlled-stop limits (motion control, from 0x100 on).
  localparam int RegStopJerk   = 32'h0000_0100;  //@reg STOP_JERK RW wide=JerkW reset=StopJerkReset "controlled-stop jerk limit J, executor LSB (2^-80 pulse/clock^3, > 0), 2 words low first"
  localparam int RegStopAcc    = 32'h0000_0108;  //@reg STOP_ACC RW wide=AccW reset=StopAccReset "controlled-stop deceleration limit D, executor LSB (2^-80 pulse/clock^2, > 0), 2 words low first"
  // Switch inputs (limit -, limit +, home): polarity, debounce, limit action.
  localparam int RstDebounce   = 20000;   // 1 ms at 20 MHz
  localparam int RegSwCfg      = 32'h0000_0110;  //@reg SW_CFG RW "switch inputs: polarity, debounce and what a limit does"
  localparam int SwInvertLsb   = 0;      //@field SW_CFG INVERT SwW reset=0 "1 = active low: bit 0 LIM_NEG, 1 LIM_POS, 2 HOME, 3 PROBE"
  localparam int SwLimEnBit    = 4;      //@field SW_CFG LIM_EN 1 reset=1 "1: motion into an active limit stops, a START toward it is refused"
  localparam int SwLimHardBit  = 5;      //@field SW_CFG LIM_HARD 1 reset=0 "1: a limit stops at once (hard limit), 0: controlled stop with STOP_JERK / STOP_ACC"
  localparam int SwSoftEnBit   = 6;      //@field SW_CFG SOFT_EN 1 reset=0 "1: REF_POS beyond SOFT_MIN / SOFT_MAX acts as an active limit switch on that side"
  localparam int SwDebounceLsb = 16;     //@field SW_CFG DEBOUNCE DebounceW reset=RstDebounce "clocks a new switch level must hold before it is taken"
  // Position latch on the home switch, the probe or the encoder index: the
  // counts of the clock its filtered level changes (for a switch the first
  // clock STATUS.SW_LEVEL shows the new level; for the index the clock the
  // decoder's count shows the quadrature state Z came with).
  localparam int RegLatchCfg   = 32'h0000_0114;  //@reg LATCH_CFG RW "position latch: which input (home, probe or encoder index) and which of its filtered edges captures; a write re-arms"
  localparam int LatchRiseBit  = 0;      //@field LATCH_CFG RISE 1 reset=0 "capture when the input becomes active (Z: goes high)"
  localparam int LatchFallBit  = 1;      //@field LATCH_CFG FALL 1 reset=0 "capture when the input becomes inactive (released; Z: goes low)"
  localparam int LatchSrcW     = 2;
  localparam int LatchSrcLsb   = 2;      //@field LATCH_CFG SRC LatchSrcW reset=0 "the input: 0 = the axis's home switch, 1 = the board's probe, 2 = the encoder index (Z); 3 is refused (SLVERR, ERR.REJECT)"
  localparam int LatchSrcHome  = 0;
  localparam int LatchSrcProbe = 1;
  localparam int LatchSrcIndex = 2;
  localparam int RegLatchPulse = 32'h0000_0118;  //@reg LATCH_PULSE RO "PULSE_COUNT at the capture (signed)"
  localparam int RegLatchEnc   = 32'h0000_011C;  //@reg LATCH_ENC RO "ENC_POS at the capture (signed)"
  // Guards against the host: the largest |vel0|, |acc0| and |jerk| a row
  // may carry (executor LSBs, unsigned; 0 = no limit). The executor checks
  // the head row when it would load it (at START and at every row
  // boundary): a row over a limit is not executed. At START the start is
  // refused (no motion); at a boundary the axis stops under control from
  // the running row's end state (STOP_JERK / STOP_ACC). Either way the FIFO
  // is emptied and STATUS.GUARD / ERR.GUARD are set.
  localparam int RegGuardVel   = 32'h0000_0120;  //@reg GUARD_VEL RW wide=VelW "guard: largest |vel0| of a row, unsigned SQ1.80 magnitude (0 = no limit), 3 words low first"
  localparam int RegGuardAcc   = 32'h0000_0130;  //@reg GUARD_ACC RW wide=AccW "guard: largest |acc0| of a row, unsigned, executor LSB (0 = no limit), 2 words low first"
  localparam int RegGuardJerk  = 32'h0000_0138;  //@reg GUARD_JERK RW wide=JerkW "guard: largest |jerk| of a row, unsigned, executor LSB (0 = no limit), 2 words low first"
  // Soft limits: with SW_CFG.SOFT_EN, REF_POS < SOFT_MIN is an active -
  // limit and REF_POS > SOFT_MAX an active + limit (the window's last
  // positions are inside it), with everything a limit
  // switch does (motion into it stops, controlled or with SW_CFG.LIM_HARD at
  // once; a START toward it is refused; motion away runs).
  localparam int RegSoftMin    = 32'h0000_0140;  //@reg SOFT_MIN RW "soft limit -: the lowest REF_POS inside the window, pulses (signed); SW_CFG.SOFT_EN"
  localparam int RegRowCount   = 32'h0000_0148;  //@reg ROW_COUNT RO "rows loaded since START: the number of the next row to run (wraps)"
  localparam int RegRetargetRow = 32'h0000_014C;  //@reg RETARGET_ROW RW "row number a ROW_PUSH.REPLACE replaces from (counted as ROW_COUNT)"
  localparam int RegSoftMax    = 32'h0000_0144;  //@reg SOFT_MAX RW "soft limit +: the highest REF_POS inside the window, pulses (signed); SW_CFG.SOFT_EN"
  // Writes to PULSE_TIME, DIR_TIME, POS_FRAC0, STOP_JERK, STOP_ACC, SW_CFG, GUARD_*, SOFT_MIN, SOFT_MAX, CMD.START and CMD.FLUSH
  // while STATUS.BUSY is set are refused (SLVERR, ERR.REJECT); so are writes
  // to the controller settings (CL_CFG .. SETTLE_RATE). The row staging
  // registers and ROW_PUSH stay open: the host streams while the axis runs.

  // ---- UART bridge (115200 8N1 at ClkHz; protocol in docs/regmap.md) -----
  localparam int UartClksPerBit = 174;    // 20 MHz / 115200 = 173.6 (0.2 % fast)
  localparam int UartTimeoutBits = 40;    // a frame gap this long drops a partial frame
  localparam int UartReqSync   = 165;     // 0xA5: host -> board frame start
  localparam int UartRspSync   = 90;      // 0x5A: board -> host frame start
  localparam int UartCmdWrite  = 1;
  localparam int UartCmdRead   = 2;
  localparam int UartStCrcErr  = 128;     // response status: frame CRC wrong, nothing done
  localparam int UartStBadCmd  = 129;     // response status: unknown command byte

  // ---- generated section (scripts/gen_layout.py from the //@ tags above;
  // do not edit: regenerate with scripts/gen_layout.py --update) ----
  // Controller configuration: the fields of the settings words as one
  // vector, first field at the MSB (the layout of a struct packed with
  // these members in this order).
  localparam int ClCfgWords = 25;
  localparam int CtlCfgW    = 655;
  localparam int CtlCfgEncFiltLsb = 651;  // enc_filt: EncFiltW, CL_CFG.ENC_FILT
  localparam int CtlCfgEncFiltW = 4;
  localparam int CtlCfgShiftLsb = 648;  // shift: EncShiftW, CL_CFG.ENC_SHIFT
  localparam int CtlCfgShiftW = 3;
  localparam int CtlCfgFfEnLsb = 647;  // ff_en: 1, CL_CFG.FF_EN
  localparam int CtlCfgFfEnW = 1;
  localparam int CtlCfgFerrStopLsb = 646;  // ferr_stop: 1, CL_CFG.FERR_STOP
  localparam int CtlCfgFerrStopW = 1;
  localparam int CtlCfgPidLsb = 645;  // pid: 1, CL_CFG.PID
  localparam int CtlCfgPidW = 1;
  localparam int CtlCfgLearnShiftLsb = 640;  // learn_shift: LearnShW, CL_CFG.LEARN_SHIFT
  localparam int CtlCfgLearnShiftW = 5;
  localparam int CtlCfgDivLsb = 624;  // div: CtlDivW, CL_PERIOD.DIV
  localparam int CtlCfgDivW = 16;
  localparam int CtlCfgInposHoldLsb = 608;  // inpos_hold: HoldW, CL_PERIOD.INPOS_HOLD
  localparam int CtlCfgInposHoldW = 16;
  localparam int CtlCfgLearnDzPLsb = 576;  // learn_dz_p: CtlW, LEARN_DZ_P.VALUE
  localparam int CtlCfgLearnDzPW = 32;
  localparam int CtlCfgLearnDzVLsb = 544;  // learn_dz_v: CtlW, LEARN_DZ_V.VALUE
  localparam int CtlCfgLearnDzVW = 32;
  localparam int CtlCfgKPLsb = 520;  // k_p: CoefW, K_P.VALUE
  localparam int CtlCfgKPW = 24;
  localparam int CtlCfgKVLsb = 496;  // k_v: CoefW, K_V.VALUE
  localparam int CtlCfgKVW = 24;
  localparam int CtlCfgKbLsb = 472;  // kb: CoefW, KB.VALUE
  localparam int CtlCfgKbW = 24;
  localparam int CtlCfgEtaP1Lsb = 448;  // eta_p1: CoefW, ETA_P1.VALUE
  localparam int CtlCfgEtaP1W = 24;
  localparam int CtlCfgEtaP2Lsb = 424;  // eta_p2: CoefW, ETA_P2.VALUE
  localparam int CtlCfgEtaP2W = 24;
  localparam int CtlCfgEtaV1Lsb = 400;  // eta_v1: CoefW, ETA_V1.VALUE
  localparam int CtlCfgEtaV1W = 24;
  localparam int CtlCfgEtaV2Lsb = 376;  // eta_v2: CoefW, ETA_V2.VALUE
  localparam int CtlCfgEtaV2W = 24;
  localparam int CtlCfgWP1Lsb = 352;  // w_p1: signed WgtW, W_P1.VALUE
  localparam int CtlCfgWP1W = 24;
  localparam int CtlCfgWP2Lsb = 328;  // w_p2: signed WgtW, W_P2.VALUE
  localparam int CtlCfgWP2W = 24;
  localparam int CtlCfgWV1Lsb = 304;  // w_v1: signed WgtW, W_V1.VALUE
  localparam int CtlCfgWV1W = 24;
  localparam int CtlCfgWV2Lsb = 280;  // w_v2: signed WgtW, W_V2.VALUE
  localparam int CtlCfgWV2W = 24;
  localparam int CtlCfgWMinLsb = 256;  // w_min: signed WgtW, W_MIN.VALUE
  localparam int CtlCfgWMinW = 24;
  localparam int CtlCfgWP1MaxLsb = 232;  // w_p1_max: signed WgtW, W_P1_MAX.VALUE
  localparam int CtlCfgWP1MaxW = 24;
  localparam int CtlCfgWP2MaxLsb = 208;  // w_p2_max: signed WgtW, W_P2_MAX.VALUE
  localparam int CtlCfgWP2MaxW = 24;
  localparam int CtlCfgWV1MaxLsb = 184;  // w_v1_max: signed WgtW, W_V1_MAX.VALUE
  localparam int CtlCfgWV1MaxW = 24;
  localparam int CtlCfgWV2MaxLsb = 160;  // w_v2_max: signed WgtW, W_V2_MAX.VALUE
  localparam int CtlCfgWV2MaxW = 24;
  localparam int CtlCfgVLimLsb = 128;  // v_lim: CtlW, V_LIM.VALUE
  localparam int CtlCfgVLimW = 32;
  localparam int CtlCfgULimLsb = 96;  // u_lim: CtlW, U_LIM.VALUE
  localparam int CtlCfgULimW = 32;
  localparam int CtlCfgFerrLimLsb = 64;  // ferr_lim: CtlW, FERR_LIM.VALUE
  localparam int CtlCfgFerrLimW = 32;
  localparam int CtlCfgInposWinLsb = 32;  // inpos_win: CtlW, INPOS_WIN.VALUE
  localparam int CtlCfgInposWinW = 32;
  localparam int CtlCfgSettleRateLsb = 0;  // settle_rate: CtlW, SETTLE_RATE.VALUE
  localparam int CtlCfgSettleRateW = 32;
  // implemented bits and reset value of each settings word (word 0 lowest)
  localparam logic [ClCfgWords*32-1:0] ClCfgMask = {
      32'hFFFFFFFF,  // SETTLE_RATE
      32'hFFFFFFFF,  // INPOS_WIN
      32'hFFFFFFFF,  // FERR_LIM
      32'hFFFFFFFF,  // U_LIM
      32'hFFFFFFFF,  // V_LIM
      32'h00FFFFFF,  // W_V2_MAX
      32'h00FFFFFF,  // W_V1_MAX
      32'h00FFFFFF,  // W_P2_MAX
      32'h00FFFFFF,  // W_P1_MAX
      32'h00FFFFFF,  // W_MIN
      32'h00FFFFFF,  // W_V2
      32'h00FFFFFF,  // W_V1
      32'h00FFFFFF,  // W_P2
      32'h00FFFFFF,  // W_P1
      32'h00FFFFFF,  // ETA_V2
      32'h00FFFFFF,  // ETA_V1
      32'h00FFFFFF,  // ETA_P2
      32'h00FFFFFF,  // ETA_P1
      32'h00FFFFFF,  // KB
      32'h00FFFFFF,  // K_V
      32'h00FFFFFF,  // K_P
      32'hFFFFFFFF,  // LEARN_DZ_V
      32'hFFFFFFFF,  // LEARN_DZ_P
      32'hFFFFFFFF,  // CL_PERIOD
      32'h0001F77F  // CL_CFG
  };
  localparam logic [ClCfgWords*32-1:0] ClCfgReset = {
      32'h00000CCD,  // SETTLE_RATE
      32'h00000000,  // INPOS_WIN
      32'h01F40000,  // FERR_LIM
      32'h00120000,  // U_LIM
      32'h00008000,  // V_LIM
      32'h00200000,  // W_V2_MAX
      32'h007F0000,  // W_V1_MAX
      32'h007F0000,  // W_P2_MAX
      32'h00008000,  // W_P1_MAX
      32'h00000000,  // W_MIN
      32'h00100000,  // W_V2
      32'h00400000,  // W_V1
      32'h00400000,  // W_P2
      32'h00000000,  // W_P1
      32'h0001999A,  // ETA_V2
      32'h00026666,  // ETA_V1
      32'h00033333,  // ETA_P2
      32'h00033333,  // ETA_P1
      32'h00100000,  // KB
      32'h000051EC,  // K_V
      32'h00001062,  // K_P
      32'h00018000,  // LEARN_DZ_V
      32'h0000C000,  // LEARN_DZ_P
      32'h003207D0,  // CL_PERIOD
      32'h0000A103  // CL_CFG
  };
  // settings words -> configuration vector
  function automatic logic [CtlCfgW-1:0] ctl_cfg_from_words(input logic [ClCfgWords*32-1:0] cl_words);
    ctl_cfg_from_words = {
      cl_words[32*0 + ClEncFiltLsb +: EncFiltW],  // enc_filt
      cl_words[32*0 + ClEncShiftLsb +: EncShiftW],  // shift
      cl_words[32*0 + ClFfEnBit +: 1],  // ff_en
      cl_words[32*0 + ClFerrStopBit +: 1],  // ferr_stop
      cl_words[32*0 + ClPidBit +: 1],  // pid
      cl_words[32*0 + ClLearnShLsb +: LearnShW],  // learn_shift
      cl_words[32*1 + ClDivLsb +: CtlDivW],  // div
      cl_words[32*1 + ClInposHoldLsb +: HoldW],  // inpos_hold
      cl_words[32*2 + ClLearnDzPLsb +: CtlW],  // learn_dz_p
      cl_words[32*3 + ClLearnDzVLsb +: CtlW],  // learn_dz_v
      cl_words[32*4 + ClKpLsb +: CoefW],  // k_p
      cl_words[32*5 + ClKvLsb +: CoefW],  // k_v
      cl_words[32*6 + ClKbLsb +: CoefW],  // kb
      cl_words[32*7 + ClEtaP1Lsb +: CoefW],  // eta_p1
      cl_words[32*8 + ClEtaP2Lsb +: CoefW],  // eta_p2
      cl_words[32*9 + ClEtaV1Lsb +: CoefW],  // eta_v1
      cl_words[32*10 + ClEtaV2Lsb +: CoefW],  // eta_v2
      cl_words[32*11 + ClWp1Lsb +: WgtW],  // w_p1
      cl_words[32*12 + ClWp2Lsb +: WgtW],  // w_p2
      cl_words[32*13 + ClWv1Lsb +: WgtW],  // w_v1
      cl_words[32*14 + ClWv2Lsb +: WgtW],  // w_v2
      cl_words[32*15 + ClWminLsb +: WgtW],  // w_min
      cl_words[32*16 + ClWp1MaxLsb +: WgtW],  // w_p1_max
      cl_words[32*17 + ClWp2MaxLsb +: WgtW],  // w_p2_max
      cl_words[32*18 + ClWv1MaxLsb +: WgtW],  // w_v1_max
      cl_words[32*19 + ClWv2MaxLsb +: WgtW],  // w_v2_max
      cl_words[32*20 + ClVLimLsb +: CtlW],  // v_lim
      cl_words[32*21 + ClULimLsb +: CtlW],  // u_lim
      cl_words[32*22 + ClFerrLimLsb +: CtlW],  // ferr_lim
      cl_words[32*23 + ClInposWinLsb +: CtlW],  // inpos_win
      cl_words[32*24 + ClSettleLsb +: CtlW]  // settle_rate
    };
  endfunction
  // CtlSt: phase of the control period: sc_neuron_pi state_o, CL_STATUS.CTL_STATE
  localparam logic [CtlStW-1:0] CtlStIdle = 4'd0;
  localparam logic [CtlStW-1:0] CtlStVff = 4'd1;
  localparam logic [CtlStW-1:0] CtlStDiv = 4'd2;
  localparam logic [CtlStW-1:0] CtlStErr = 4'd3;
  localparam logic [CtlStW-1:0] CtlStT1 = 4'd4;
  localparam logic [CtlStW-1:0] CtlStT2 = 4'd5;
  localparam logic [CtlStW-1:0] CtlStDu = 4'd6;
  localparam logic [CtlStW-1:0] CtlStBc = 4'd7;
  localparam logic [CtlStW-1:0] CtlStH1 = 4'd8;
  localparam logic [CtlStW-1:0] CtlStDw1 = 4'd9;
  localparam logic [CtlStW-1:0] CtlStH2 = 4'd10;
  localparam logic [CtlStW-1:0] CtlStDw2 = 4'd11;
  localparam logic [CtlStW-1:0] CtlStInit = 4'd12;
  // Upc: micro-program step of sc_neuron_pi (one operation per clock)
  localparam logic [UpcW-1:0] UpcIdle = 6'd0;
  localparam logic [UpcW-1:0] UpcInit = 6'd1;
  localparam logic [UpcW-1:0] UpcVff = 6'd13;
  localparam logic [UpcW-1:0] UpcSet1 = 6'd14;
  localparam logic [UpcW-1:0] UpcSet2 = 6'd15;
  localparam logic [UpcW-1:0] UpcDiv1 = 6'd16;
  localparam logic [UpcW-1:0] UpcSet3 = 6'd17;
  localparam logic [UpcW-1:0] UpcDiv2 = 6'd18;
  localparam logic [UpcW-1:0] UpcRef = 6'd19;
  localparam logic [UpcW-1:0] UpcErr = 6'd20;
  localparam logic [UpcW-1:0] UpcAbs = 6'd21;
  localparam logic [UpcW-1:0] UpcEq = 6'd22;
  localparam logic [UpcW-1:0] UpcX2 = 6'd23;
  localparam logic [UpcW-1:0] UpcE = 6'd24;
  localparam logic [UpcW-1:0] UpcEp = 6'd25;
  localparam logic [UpcW-1:0] UpcLearn = 6'd26;
  localparam logic [UpcW-1:0] UpcFerr = 6'd27;
  localparam logic [UpcW-1:0] UpcWin = 6'd28;
  localparam logic [UpcW-1:0] UpcT1 = 6'd29;
  localparam logic [UpcW-1:0] UpcT2 = 6'd30;
  localparam logic [UpcW-1:0] UpcSum = 6'd31;
  localparam logic [UpcW-1:0] UpcDu = 6'd32;
  localparam logic [UpcW-1:0] UpcBc = 6'd33;
  localparam logic [UpcW-1:0] UpcAcc1 = 6'd34;
  localparam logic [UpcW-1:0] UpcAcc2 = 6'd35;
  localparam logic [UpcW-1:0] UpcTot = 6'd36;
  localparam logic [UpcW-1:0] UpcHi = 6'd37;
  localparam logic [UpcW-1:0] UpcLo = 6'd38;
  localparam logic [UpcW-1:0] UpcOut = 6'd39;
  localparam logic [UpcW-1:0] UpcH1 = 6'd40;
  localparam logic [UpcW-1:0] UpcDw1 = 6'd41;
  localparam logic [UpcW-1:0] UpcW1 = 6'd42;
  localparam logic [UpcW-1:0] UpcW2 = 6'd43;
  localparam logic [UpcW-1:0] UpcW3 = 6'd44;
  localparam logic [UpcW-1:0] UpcW4 = 6'd45;
  localparam logic [UpcW-1:0] UpcH2 = 6'd46;
  localparam logic [UpcW-1:0] UpcDw2 = 6'd47;
  localparam logic [UpcW-1:0] UpcW5 = 6'd48;
  localparam logic [UpcW-1:0] UpcW6 = 6'd49;
  localparam logic [UpcW-1:0] UpcW7 = 6'd50;
  localparam logic [UpcW-1:0] UpcW8 = 6'd51;
  // ---- end of generated section ----
endpackage
