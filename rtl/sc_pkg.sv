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
  localparam int CtrlClosedBit = 1;      //@field CTRL CLOSED_LOOP 1 "sc_axi_servo: 1 = closed loop (encoder feedback), 0 = open loop; a write changing it while busy is refused (ignored by sc_axi_axis)"
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
  localparam int StatusFaultFerrBit    = 11;  //@field STATUS FAULT_FERR 1 "closed loop: following-error fault latched (|P* - P| > FERR_LIM); 0 in sc_axi_axis"
  localparam int StatusEncALsb         = 12;  //@field STATUS ENC_AB 2 "synchronised encoder inputs: bit 12 = A, bit 13 = B"
  localparam int StatusInPosBit        = 14;  //@field STATUS IN_POS 1 "closed loop: in position (|P - L| <= INPOS_WIN for INPOS_HOLD periods); 0 in sc_axi_axis"
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
  // Closed-loop controller settings (sc_axi_servo only; DECERR in
  // sc_axi_axis): one 32-bit word per cfg_* input of sc_servo_axis, words
  // RegClFirst .. RegClFirst + 4 * (ClCfgWords - 1) in this order. Reset
  // values = the closed-loop runner's defaults (tb/closed_loop_run.h,
  // 1 encoder count per pulse, 10 kHz control rate, 50/50-clock STEP).
  // Units: docs/closed_loop.md (Q.CtlFrac counts or counts per control
  // period, coefficients Q.CoefFrac, weights signed Q.WgtFrac).
  localparam int ClCfgWords    = 25;
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
  localparam int ClEncFiltLsb  = 0;      //@field CL_CFG ENC_FILT EncFiltW reset=RstEncFilt "encoder glitch filter, clocks (0..15)"
  localparam int ClEncShiftLsb = 4;      //@field CL_CFG ENC_SHIFT EncShiftW reset=0 "log2(encoder counts per STEP pulse)"
  localparam int ClFfEnBit     = 8;      //@field CL_CFG FF_EN 1 reset=RstFfEn "velocity feed-forward from V*"
  localparam int ClLearnShLsb  = 12;     //@field CL_CFG LEARN_SHIFT LearnShW reset=RstLearnShift "Hebb scale: dw = eta e x / 2^LEARN_SHIFT"
  localparam int RegClPeriod   = 32'h0000_006C;  //@reg CL_PERIOD RW servo "closed loop: control period and in-position hold"
  localparam int ClDivLsb      = 0;      //@field CL_PERIOD DIV CtlDivW reset=RstCtlDiv "control period, clocks (2000 = 10 kHz; at least 256)"
  localparam int ClInposHoldLsb = 16;    //@field CL_PERIOD INPOS_HOLD HoldW reset=RstInposHold "in-position hold, control periods"
  localparam int RegClLearnDzP = 32'h0000_0070;  //@reg LEARN_DZ_P RW servo "no position-loop learning while |e_p| <= this, counts Q.16"
  localparam int ClLearnDzPLsb = 0;      //@field LEARN_DZ_P VALUE CtlW reset=RstLearnDzP "counts, Q.CtlFrac"
  localparam int RegClLearnDzV = 32'h0000_0074;  //@reg LEARN_DZ_V RW servo "no speed-loop learning while |e_v| <= this, counts/period Q.16"
  localparam int ClLearnDzVLsb = 0;      //@field LEARN_DZ_V VALUE CtlW reset=RstLearnDzV "counts per control period, Q.CtlFrac"
  localparam int RegClKp       = 32'h0000_0078;  //@reg K_P RW servo "position neuron gain K_p, unsigned Q.20"
  localparam int ClKpLsb       = 0;      //@field K_P VALUE CoefW reset=RstKp "Q.CoefFrac"
  localparam int RegClKv       = 32'h0000_007C;  //@reg K_V RW servo "speed neuron gain K_v, unsigned Q.20"
  localparam int ClKvLsb       = 0;      //@field K_V VALUE CoefW reset=RstKv "Q.CoefFrac"
  localparam int RegClKb       = 32'h0000_0080;  //@reg KB RW servo "back-calculation (anti-windup) gain, unsigned Q.20"
  localparam int ClKbLsb       = 0;      //@field KB VALUE CoefW reset=RstKb "Q.CoefFrac"
  localparam int RegClEtaP1    = 32'h0000_0084;  //@reg ETA_P1 RW servo "learning rate, position loop, integral weight, Q.20"
  localparam int ClEtaP1Lsb    = 0;      //@field ETA_P1 VALUE CoefW reset=RstEtaP1 "Q.CoefFrac (0: fixed gain)"
  localparam int RegClEtaP2    = 32'h0000_0088;  //@reg ETA_P2 RW servo "learning rate, position loop, proportional weight, Q.20"
  localparam int ClEtaP2Lsb    = 0;      //@field ETA_P2 VALUE CoefW reset=RstEtaP2 "Q.CoefFrac"
  localparam int RegClEtaV1    = 32'h0000_008C;  //@reg ETA_V1 RW servo "learning rate, speed loop, integral weight, Q.20"
  localparam int ClEtaV1Lsb    = 0;      //@field ETA_V1 VALUE CoefW reset=RstEtaV1 "Q.CoefFrac"
  localparam int RegClEtaV2    = 32'h0000_0090;  //@reg ETA_V2 RW servo "learning rate, speed loop, proportional weight, Q.20"
  localparam int ClEtaV2Lsb    = 0;      //@field ETA_V2 VALUE CoefW reset=RstEtaV2 "Q.CoefFrac"
  localparam int RegClWp1      = 32'h0000_0094;  //@reg W_P1 RW servo "initial weight, position loop, integral (signed Q.16)"
  localparam int ClWp1Lsb      = 0;      //@field W_P1 VALUE WgtW reset=RstWp1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWp2      = 32'h0000_0098;  //@reg W_P2 RW servo "initial weight, position loop, proportional (signed Q.16)"
  localparam int ClWp2Lsb      = 0;      //@field W_P2 VALUE WgtW reset=RstWp2 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv1      = 32'h0000_009C;  //@reg W_V1 RW servo "initial weight, speed loop, integral (signed Q.16)"
  localparam int ClWv1Lsb      = 0;      //@field W_V1 VALUE WgtW reset=RstWv1 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv2      = 32'h0000_00A0;  //@reg W_V2 RW servo "initial weight, speed loop, proportional (signed Q.16)"
  localparam int ClWv2Lsb      = 0;      //@field W_V2 VALUE WgtW reset=RstWv2 "signed Q.WgtFrac, 24 bits"
  localparam int RegClWmin     = 32'h0000_00A4;  //@reg W_MIN RW servo "lower bound of every weight (signed Q.16)"
  localparam int ClWminLsb     = 0;      //@field W_MIN VALUE WgtW reset=RstWmin "signed Q.WgtFrac, 24 bits"
  localparam int RegClWp1Max   = 32'h0000_00A8;  //@reg W_P1_MAX RW servo "upper bound of W_P1 (signed Q.16)"
  localparam int ClWp1MaxLsb   = 0;      //@field W_P1_MAX VALUE WgtW reset=RstWp1Max "signed Q.WgtFrac, 24 bits"
  localparam int RegClWp2Max   = 32'h0000_00AC;  //@reg W_P2_MAX RW servo "upper bound of W_P2 (signed Q.16)"
  localparam int ClWp2MaxLsb   = 0;      //@field W_P2_MAX VALUE WgtW reset=RstWp2Max "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv1Max   = 32'h0000_00B0;  //@reg W_V1_MAX RW servo "upper bound of W_V1 (signed Q.16)"
  localparam int ClWv1MaxLsb   = 0;      //@field W_V1_MAX VALUE WgtW reset=RstWv1Max "signed Q.WgtFrac, 24 bits"
  localparam int RegClWv2Max   = 32'h0000_00B4;  //@reg W_V2_MAX RW servo "upper bound of W_V2 (signed Q.16)"
  localparam int ClWv2MaxLsb   = 0;      //@field W_V2_MAX VALUE WgtW reset=RstWv2Max "signed Q.WgtFrac, 24 bits"
  localparam int RegClVLim     = 32'h0000_00B8;  //@reg V_LIM RW servo "|position-loop output| limit, counts/period Q.16"
  localparam int ClVLimLsb     = 0;      //@field V_LIM VALUE CtlW reset=RstVLim "Q.CtlFrac (32768 = 5000 pulses/s at 10 kHz)"
  localparam int RegClULim     = 32'h0000_00BC;  //@reg U_LIM RW servo "|u| limit (commanded step rate), counts/period Q.16"
  localparam int ClULimLsb     = 0;      //@field U_LIM VALUE CtlW reset=RstULim "Q.CtlFrac (1179648 = 180,000 pulses/s at 10 kHz)"
  localparam int RegClFerrLim  = 32'h0000_00C0;  //@reg FERR_LIM RW servo "following-error fault limit, counts Q.16"
  localparam int ClFerrLimLsb  = 0;      //@field FERR_LIM VALUE CtlW reset=RstFerrLim "Q.CtlFrac (500 counts)"
  localparam int RegClInposWin = 32'h0000_00C4;  //@reg INPOS_WIN RW servo "in-position window |P - L|, counts Q.16"
  localparam int ClInposWinLsb = 0;      //@field INPOS_WIN VALUE CtlW reset=RstInposWin "Q.CtlFrac"
  localparam int RegClSettle   = 32'h0000_00C8;  //@reg SETTLE_RATE RW servo "corrective step rate after the reference is done, counts/period Q.16"
  localparam int ClSettleLsb   = 0;      //@field SETTLE_RATE VALUE CtlW reset=RstSettleRate "Q.CtlFrac (3277 = 500 pulses/s at 10 kHz)"
  // Closed-loop status (sc_axi_servo only), words RegClStat .. + 4 * (ClStatWords - 1).
  localparam int RegClStat     = 32'h0000_00D0;  //@reg CL_STATUS RO servo "closed-loop status"
  localparam int ClStInPosBit  = 0;      //@field CL_STATUS IN_POS 1 "in position"
  localparam int ClStFerrBit   = 1;      //@field CL_STATUS FAULT_FERR 1 "following-error fault latched (cleared by the next START)"
  localparam int ClStActiveBit = 2;      //@field CL_STATUS CTL_ACTIVE 1 "controller running"
  localparam int ClStStateLsb  = 4;      //@field CL_STATUS CTL_STATE CtlStW "controller FSM state"
  localparam int ClStIllLsb    = 16;     //@field CL_STATUS ENC_ILLEGAL EncIllW "illegal encoder transitions (saturating)"
  localparam int RegClU        = 32'h0000_00D4;  //@reg CTL_U RO servo "controller output u, signed counts/period Q.16"
  localparam int RegClVCmd     = 32'h0000_00D8;  //@reg CTL_V_CMD RO servo "position-loop output v_cmd, signed counts/period Q.16"
  localparam int RegClEp       = 32'h0000_00DC;  //@reg CTL_E_P RO servo "position error e_p, signed counts Q.16"
  localparam int RegClEv       = 32'h0000_00E0;  //@reg CTL_E_V RO servo "speed error e_v, signed counts/period Q.16"
  localparam int RegClWp1Now   = 32'h0000_00E4;  //@reg CTL_W_P1 RO servo "learned weight w_p1, signed Q.16 (sign-extended)"
  localparam int RegClWp2Now   = 32'h0000_00E8;  //@reg CTL_W_P2 RO servo "learned weight w_p2, signed Q.16 (sign-extended)"
  localparam int RegClWv1Now   = 32'h0000_00EC;  //@reg CTL_W_V1 RO servo "learned weight w_v1, signed Q.16 (sign-extended)"
  localparam int RegClWv2Now   = 32'h0000_00F0;  //@reg CTL_W_V2 RO servo "learned weight w_v2, signed Q.16 (sign-extended)"
  // Writes to SEG_COUNT, PULSE_TIME, DIR_TIME, POS_FRAC0, SEG_* and
  // CMD.START while STATUS.BUSY is set are refused (SLVERR, ERR.REJECT);
  // so are writes to the controller settings (CL_CFG .. SETTLE_RATE).

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
