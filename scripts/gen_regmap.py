#!/usr/bin/env python3
"""Register map: docs and C++ table from the one definition in rtl/sc_pkg.sv.

Usage:
  gen_regmap.py <sc_pkg.sv> --header <out.h>     C++ table (sc::regmap)
  gen_regmap.py <sc_pkg.sv> --doc <out.md>       Markdown (docs/regmap.md)
  gen_regmap.py <sc_pkg.sv> --check <regmap.md>  exit 1 if the file differs

The "host register map" section of sc_pkg.sv tags its localparams:
  localparam int RegX = 32'h0000_000C;  //@reg NAME ACCESS [wide=WidthParam] "text"
  localparam int XyzLsb = 4;            //@field REG NAME WIDTH [reset=N] "text"
ACCESS is RO, RW, WO or W1C; WIDTH is a number or a localparam name; a
field's LSB is its localparam's value. A wide register spans
ceil(width/32) words NAME_0, NAME_1, ... (low word first). The RTL uses the
same localparams for its decode, so address and bit positions cannot drift;
tests/test_board.cpp checks the implemented/reserved bits against this table.
Fails loudly on any tag it does not understand.
"""
import argparse
import re
import sys

LP = re.compile(r"localparam\s+int\s+(\w+)\s*=\s*([0-9_]+|[0-9]+'h[0-9a-fA-F_]+)\s*;\s*(//.*)?$")
REG = re.compile(r'//@reg\s+(\w+)\s+(RO|RW|WO|W1C)\s*(?:wide=(\w+))?\s*(?:reset=(\w+))?\s*(servo)?\s*"([^"]*)"\s*$')
# Constants wider than an int (reset values of wide registers).
WIDE_LP = re.compile(r"localparam\s+logic\s*\[(\d+):0\]\s*(\w+)\s*=\s*(\d+)'d([0-9_]+)\s*;")
FIELD = re.compile(r'//@field\s+(\w+)\s+(\w+)\s+(\w+)((?:\s+[\w=/]+)*)\s*"([^"]*)"\s*$')
FIELD_OPTS = re.compile(r"^(reset|cfg|q|unit)=([\w/]+)$|^(signed)$")
ENUM = re.compile(r'^\s*//@enum\s+(\w+)\s+(\w+)\s+"([^"]*)"\s*$')
VALUE = re.compile(r'^\s*//@value\s+(\w+)\s+(\w+)\s*(?:=(\d+))?\s+"([^"]*)"\s*$')
# The generated section of sc_pkg.sv (scripts/gen_layout.py) is output, not source.
GEN_BEGIN = "// ---- generated section"
GEN_END = "// ---- end of generated section"


def num(v):
    v = v.replace("_", "")
    if "'h" in v:
        return int(v.split("'h")[1], 16)
    return int(v)


def source_lines(path):
    """(lineno, line) of sc_pkg.sv outside the generated section."""
    out, skip = [], False
    for lineno, line in enumerate(open(path, encoding="utf-8"), 1):
        if GEN_BEGIN in line:
            skip = True
        if not skip:
            out.append((lineno, line))
        if GEN_END in line:
            skip = False
    return out


def parse_enums(path, params):
    """//@enum TYPE WIDTH "text" and //@value TYPE NAME [=N] "text" tags."""
    enums, by_name = [], {}
    for lineno, line in source_lines(path):
        if line.lstrip().startswith("//@enum"):
            m = ENUM.match(line)
            if not m:
                sys.exit(f"{path}:{lineno}: bad //@enum tag: {line.strip()}")
            width = params.get(m.group(2)) if not m.group(2).isdigit() else int(m.group(2))
            if width is None:
                sys.exit(f"{path}:{lineno}: unknown width {m.group(2)}")
            e = {"name": m.group(1), "width": width, "width_param": m.group(2), "desc": m.group(3),
                 "values": []}
            if e["name"] in by_name:
                sys.exit(f"{path}:{lineno}: enum {e['name']} defined twice")
            by_name[e["name"]] = e
            enums.append(e)
        elif line.lstrip().startswith("//@value"):
            m = VALUE.match(line)
            if not m:
                sys.exit(f"{path}:{lineno}: bad //@value tag: {line.strip()}")
            e = by_name.get(m.group(1))
            if e is None:
                sys.exit(f"{path}:{lineno}: value of unknown enum {m.group(1)}")
            if m.group(3) is not None:
                v = int(m.group(3))
            else:
                v = e["values"][-1]["value"] + 1 if e["values"] else 0
            for o in e["values"]:
                if o["name"] == m.group(2) or o["value"] == v:
                    sys.exit(f"{path}:{lineno}: {e['name']}{m.group(2)} = {v} repeats a name or value")
            if v >= (1 << e["width"]):
                sys.exit(f"{path}:{lineno}: {e['name']}{m.group(2)} = {v} does not fit {e['width']} bits")
            e["values"].append({"name": m.group(2), "value": v, "desc": m.group(4)})
    return enums


def parse(path):
    params, regs = {}, []
    by_name = {}
    for _, line in source_lines(path):
        w = WIDE_LP.search(line)
        if w:
            params[w.group(2)] = int(w.group(4).replace("_", ""))
    for lineno, line in source_lines(path):
        m = LP.search(line)
        if not m:
            if "//@" in line and not line.lstrip().startswith("//"):
                sys.exit(f"{path}:{lineno}: //@ tag on a line that is not 'localparam int'")
            continue
        name, value, comment = m.group(1), num(m.group(2)), m.group(3) or ""
        params[name] = value
        if "//@reg" in comment:
            r = REG.search(comment)
            if not r:
                sys.exit(f"{path}:{lineno}: bad //@reg tag: {comment}")
            reg = {"name": r.group(1), "access": r.group(2), "wide": r.group(3), "reset": r.group(4),
                   "servo": bool(r.group(5)), "desc": r.group(6), "addr": value, "param": name, "fields": []}
            if reg["reset"] and not reg["wide"]:
                sys.exit(f"{path}:{lineno}: reset= on //@reg is for wide registers (fields carry their own)")
            if reg["name"] in by_name:
                sys.exit(f"{path}:{lineno}: register {reg['name']} defined twice")
            by_name[reg["name"]] = reg
            regs.append(reg)
        elif "//@field" in comment:
            f = FIELD.search(comment)
            if not f:
                sys.exit(f"{path}:{lineno}: bad //@field tag: {comment}")
            reg = by_name.get(f.group(1))
            if reg is None:
                sys.exit(f"{path}:{lineno}: field of unknown register {f.group(1)}")
            w = f.group(3)
            width = int(w) if w.isdigit() else params.get(w)
            if width is None:
                sys.exit(f"{path}:{lineno}: unknown width {w}")
            opts = {}
            for tok in f.group(4).split():
                o = FIELD_OPTS.match(tok)
                if not o:
                    sys.exit(f"{path}:{lineno}: unknown //@field option {tok}")
                opts[o.group(1) or "signed"] = o.group(2) or True
            rv = opts.get("reset", "0")
            reset = int(rv) if rv.isdigit() else params.get(rv)
            if reset is None:
                sys.exit(f"{path}:{lineno}: unknown reset value {rv}")
            qv = opts.get("q", "0")
            q = int(qv) if qv.isdigit() else params.get(qv)
            if q is None:
                sys.exit(f"{path}:{lineno}: unknown Q format {qv}")
            signed = bool(opts.get("signed"))
            if signed and reset >= (1 << (width - 1)):
                sys.exit(f"{path}:{lineno}: signed reset value {reset} out of range")
            reg["fields"].append({"name": f.group(2), "lsb": value, "width": width,
                                  "reset": reset, "desc": f.group(5),
                                  "param": name, "width_param": w, "cfg": opts.get("cfg"),
                                  "signed": signed, "q": q, "q_param": qv, "unit": opts.get("unit", "")})
    if not regs:
        sys.exit(f"{path}: no //@reg tags found")
    # expand wide registers into words, check overlaps
    words = []
    for reg in regs:
        if reg["wide"]:
            width = params.get(reg["wide"])
            if width is None:
                sys.exit(f"{path}: {reg['name']}: unknown width {reg['wide']}")
            n = (width + 31) // 32
            reset = 0
            if reg["reset"]:
                reset = params.get(reg["reset"])
                if reset is None or reset >= (1 << width):
                    sys.exit(f"{path}: {reg['name']}: reset value {reg['reset']} unknown or wider than {width} bits")
            for i in range(n):
                bits = min(32, width - 32 * i)
                words.append({"name": f"{reg['name']}_{i}", "addr": reg["addr"] + 4 * i,
                              "access": reg["access"], "desc": f"{reg['desc']} (bits {32*i+bits-1}:{32*i})",
                              "mask": (1 << bits) - 1, "reset": (reset >> (32 * i)) & ((1 << bits) - 1),
                              "fields": [], "group": reg["name"],
                              "servo": reg["servo"]})
        else:
            mask, reset = 0, 0
            for f in reg["fields"]:
                fm = ((1 << f["width"]) - 1) << f["lsb"]
                if f["lsb"] + f["width"] > 32 or mask & fm:
                    sys.exit(f"{path}: {reg['name']}.{f['name']} overlaps or exceeds 32 bits")
                mask |= fm
                reset |= f["reset"] << f["lsb"]
            if not reg["fields"]:
                mask = 0xFFFFFFFF
            words.append({"name": reg["name"], "addr": reg["addr"], "access": reg["access"],
                          "desc": reg["desc"], "mask": mask, "reset": reset,
                          "fields": reg["fields"], "group": reg["name"], "servo": reg["servo"]})
    check_addresses(path, params, words)
    words.sort(key=lambda w: w["addr"])
    return params, words


def check_addresses(path, params, words):
    """Every register word inside the RegAddrW-bit window, word-aligned and
    alone at its address; the window no larger than the UART bridge's
    address byte reaches (256 words: the frame carries the word address)."""
    aw = params.get("RegAddrW")
    if aw is None:
        sys.exit(f"{path}: RegAddrW (byte address bits of the register window) missing")
    if not 2 < aw <= 10:
        sys.exit(f"{path}: RegAddrW = {aw}: the window must hold 2..256 words (3 <= RegAddrW <= 10; "
                 "the UART frame's address byte is a word address)")
    top = (1 << aw) - 4
    used = {}
    for w in words:
        where = f"{path}: register {w['name']} at 0x{w['addr']:03X}"
        if w["addr"] % 4:
            sys.exit(f"{where}: not word-aligned (byte addresses must be multiples of 4)")
        if not 0 <= w["addr"] <= top:
            sys.exit(f"{where}: outside the register window 0x000..0x{top:03X} (RegAddrW = {aw})")
        if w["addr"] in used:
            sys.exit(f"{where}: address already used by {used[w['addr']]}")
        used[w["addr"]] = w["name"]


def cstr(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def header(params, words):
    out = ["// Generated from rtl/sc_pkg.sv by scripts/gen_regmap.py - do not edit.",
           "#pragma once", "#include <cstdint>", "", "namespace sc::regmap {", "",
           "enum class Access : uint8_t { RO, RW, WO, W1C };", "",
           "struct Field {", "  const char* name;", "  int lsb;", "  int width;",
           "  uint32_t reset;", "  const char* desc;", "};", "",
           "struct Reg {", "  const char* name;", "  uint32_t addr;", "  Access access;",
           "  uint32_t mask;   // implemented bits (the rest read 0)",
           "  uint32_t reset;", "  const char* desc;", "  const Field* fields;", "  int nfields;",
           "  bool servo;      // closed-loop register: sc_axi_servo only (DECERR in sc_axi_axis)",
           "};", ""]
    for w in words:
        if w["fields"]:
            out.append(f"inline constexpr Field k{w['name'].title().replace('_', '')}Fields[] = {{")
            for f in w["fields"]:
                out.append(f"    {{{cstr(f['name'])}, {f['lsb']}, {f['width']}, {f['reset']}u, {cstr(f['desc'])}}},")
            out.append("};")
    out.append("")
    out.append("inline constexpr Reg kRegs[] = {")
    for w in words:
        fl = f"k{w['name'].title().replace('_', '')}Fields" if w["fields"] else "nullptr"
        out.append(f"    {{{cstr(w['name'])}, 0x{w['addr']:02X}u, Access::{w['access']}, 0x{w['mask']:08X}u, "
                   f"0x{w['reset']:08X}u, {cstr(w['desc'])}, {fl}, {len(w['fields'])}, {'true' if w['servo'] else 'false'}}},")
    out.append("};")
    out.append(f"inline constexpr int kNumRegs = {len(words)};")
    out += ["", "}  // namespace sc::regmap", ""]
    return "\n".join(out)


SOURCE_DOC = """## Register and layout source

Every layout that the RTL, the model, the host software and these docs share has one
source: the tagged SV package `rtl/sc_pkg.sv`. The register map (`//@reg`, `//@field`),
the controller configuration (the `cfg=` fields of the settings words, with width,
signedness, Q format, unit and reset value), the encodings visible outside a module
(`//@enum` / `//@value`: the controller phase `CtlSt`, which CL_STATUS.CTL_STATE shows,
and the micro-program steps `Upc` of `sc_neuron_pi`), the phase codes, fault bits and
UART frame constants are written there once. Generated from it:

| output | by | committed | drift check |
|---|---|---|---|
| generated section at the end of `rtl/sc_pkg.sv`: `ClCfgWords`, `CtlCfgW`, `CtlCfg<M>Lsb/W`, `ClCfgMask`, `ClCfgReset`, `ctl_cfg_from_words()`, `CtlSt*`, `Upc*` | `scripts/gen_layout.py --update` | yes | ctest `layout_in_sync` |
| this file | `scripts/gen_layout.py --update` (or `gen_regmap.py --doc`) | yes | ctest `layout_in_sync`, `regmap_docs_in_sync` |
| `build/generated/sc_params.h` (widths, codes, addresses, bits) | `scripts/gen_params.py` (CMake) | no | - |
| `build/generated/sc_regmap.h` (register table) | `scripts/gen_regmap.py --header` (CMake) | no | - |
| `build/generated/sc_layout.h` (`sc::CtlCfg`, word masks/resets, `ctl_cfg_from_words` / `ctl_cfg_to_words` / `ctl_cfg_pack` / `ctl_cfg_visit`, `CtlSt*`, `Upc*`) | `scripts/gen_layout.py --header` (CMake) | no | - |

A stale committed output fails its ctest with the command that regenerates it
(`scripts/gen_layout.py --update`).

Why the tagged package and not SystemRDL/PeakRDL: the package already was the source of
the register map and of every width the model uses, and the RTL reads the same
localparams, so extending its tags adds no tool to the Verilator / Icarus / yosys /
Vivado flows. SystemRDL describes registers, not the controller's micro-program and
phase encodings or the Q formats the bit-exact model shares, so a second source would
remain; PeakRDL's main product, a generated register block, is what we do not want
(`sc_axi_regs` stays hand-written for area), and its C headers would not replace the
model's typed configuration struct.

The configuration travels sc_axi_regs -> sc_axi_servo -> sc_servo_axis -> sc_neuron_pi
as one vector `logic [sc_pkg::CtlCfgW-1:0]` with generated field positions, the layout a
`struct packed` with the same members would have. It is not a struct type because no
struct-typed port works in all three tools here: Icarus 11 asserts on a package-scoped
type (`sc_pkg::ctl_cfg_t`) and only accepts it through `import`, which yosys 0.23 does
not accept in a module header or in `$unit`.

### Adding a controller parameter

1. `rtl/sc_pkg.sv`: a `//@reg NAME RW servo` register at the next free settings address
   (the settings words are contiguous from `RegClFirst`; the generator checks it) with a
   `//@field ... cfg=member [signed] [q=..] unit=.. reset=..` field; run
   `scripts/gen_layout.py --update` (rewrites the generated section and this file).
2. `rtl/sc_neuron_pi.sv`: read it as `ctl_cfg_i[sc_pkg::CtlCfg<Member>Lsb +: sc_pkg::CtlCfg<Member>W]`
   and use it in the datapath.
3. `cmodel/neuron_pi.cpp`: use `cfg.member` in the same arithmetic.
4. One test that exercises it (for example `tests/test_neuron_pi_rtl.cpp`'s random configurations).

The register file (masks, reset values, decode), `sc_axi_servo`, `sc_servo_axis`, the
model's register file, `sc::CtlCfg`, the host encoding (`encode_servo_config`), the
Verilator adapters and this document follow from the generated files. Measured on a
scratch branch: a dummy parameter LEARN_EN (a new settings word at 0xCC, 1 bit,
reset 1, gating the Hebb update in both the RTL and the model, randomised by the
neuron-level lockstep test) carried end to end touched 5 files, 4 edited by hand
(`rtl/sc_pkg.sv` tags, `rtl/sc_neuron_pi.sv`, `cmodel/neuron_pi.cpp`,
`tests/test_neuron_pi_rtl.cpp`) and 1 regenerated (`docs/regmap.md`; the package's
generated section is in the source file), with the closed-loop, neuron-level and
register-file lockstep tests green. Before this layout source the same change
touched 17 files.

""".splitlines()


def config_doc(params, words, enums):
    """The controller configuration and the encodings (scripts/gen_layout.py)."""
    cfg = [(w, f) for w in words for f in sorted(w["fields"], key=lambda f: f["lsb"]) if f.get("cfg")]
    out = []
    if cfg:
        out += ["## Controller configuration", "",
                "The fields of the settings words form the controller configuration: one vector "
                "`logic [sc_pkg::CtlCfgW-1:0]` in the RTL (sc_axi_regs -> sc_servo_axis -> sc_neuron_pi; "
                "field `m` at `sc_pkg::CtlCfg<M>Lsb`, first member at the MSB) and `struct sc::CtlCfg` in C++ "
                "(`build/generated/sc_layout.h`, member defaults = the reset values). Q = fraction bits.", "",
                "| word | register.field | bits | member | type | Q | unit | reset |",
                "|---|---|---|---|---|---|---|---|"]
        first = min(w["addr"] for w, _ in cfg)
        for w, f in cfg:
            hi = f["lsb"] + f["width"] - 1
            bits = f"{hi}:{f['lsb']}" if f["width"] > 1 else f"{f['lsb']}"
            typ = f"{'s' if f['signed'] else 'u'}{f['width']}"
            out.append(f"| {(w['addr'] - first) // 4} | {w['name']}.{f['name']} | {bits} | `{f['cfg']}` | {typ} | "
                       f"{f['q'] or '-'} | {f['unit'] or '-'} | {f['reset']} |")
        out.append("")
    if enums:
        out += ["## Encodings", "",
                "Generated as `sc_pkg::<Type><Name>` (SV) and `sc::<Type><Name>` (C++).", ""]
        for e in enums:
            out += [f"### {e['name']} ({e['width']} bits)", "", e["desc"] + ".", "",
                    "| value | name | meaning |", "|---|---|---|"]
            for v in e["values"]:
                out.append(f"| {v['value']} | {e['name']}{v['name']} | {v['desc']} |")
            out.append("")
    return out


def doc_for(pkg):
    params, words = parse(pkg)
    return doc(params, words, parse_enums(pkg, params))


def doc(params, words, enums=None):
    p = params
    out = ["# Register map and UART protocol", "",
           "<!-- Generated from rtl/sc_pkg.sv by scripts/gen_regmap.py - do not edit;",
           "     ctest regmap_docs_in_sync fails when this file is stale. -->", "",
           f"AXI4-Lite slave `sc_axi_regs` (in `sc_axi_axis` and `sc_axi_servo`), {p['RegAddrW']}-bit byte addresses "
           f"(a {1 << p['RegAddrW']}-byte window of {1 << (p['RegAddrW'] - 2)} words; register map "
           f"{p['RegMapVersion'] >> 8}.{p['RegMapVersion'] & 0xFF}, ID.VERSION = 0x{p['RegMapVersion']:04X}), "
           "32-bit registers. Any other address answers DECERR (addresses do not wrap: 0x100 is not 0x000); "
           "a write to a read-only register "
           "answers SLVERR. Both set ERR.BAD_ACCESS and change nothing else. Reserved bits read 0 "
           "and ignore writes. WSTRB selects bytes (CMD, ERR, IRQ_STATUS and ROW_PUSH act on byte 0).", "",
           "Writes to PULSE_TIME, DIR_TIME, POS_FRAC0_*, STOP_JERK_*, STOP_ACC_*, SW_CFG, GUARD_*, CMD.START and "
           "CMD.FLUSH while "
           "STATUS.BUSY is set are refused: SLVERR, ERR.REJECT set, the running move is not touched. "
           "So is a PULSE_TIME write that would leave HIGH or LOW at 0 (the register keeps its value). "
           "CMD.START is also refused while ERR.ESTOP is set or CTRL.ENABLE is 0. The row staging "
           "registers (SEG_*) and ROW_PUSH stay open while busy: the host appends rows to the "
           f"{p['RowFifoDepth']}-row FIFO while the axis runs; a ROW_PUSH to a full FIFO answers "
           "SLVERR, sets ERR.FIFO_FULL and keeps the staged row for a retry.", "",
           "Registers marked (servo) exist in `sc_axi_servo` (closed-loop axis, the board top's) only; "
           "`sc_axi_axis` (open loop) answers DECERR there. The controller settings (CL_CFG .. "
           "SETTLE_RATE) are locked while STATUS.BUSY is set like the pulse timing, and so is CTRL.CLOSED_LOOP "
           "(a CTRL write changing it while busy is refused). Their units: docs/closed_loop.md; reset "
           "values = the closed-loop runner's defaults (`scurve sim --closed-loop`).", "",
           "Switch inputs (limit -, limit +, home, probe; `sw_i` of both tops; on the board Pmod JB3/JB4/JB7 and "
           "the board's one probe on JB8, `probe_i`, fanned out to every axis): each goes "
           "through the common two-flop synchroniser, SW_CFG.INVERT and a debounce filter of SW_CFG.DEBOUNCE "
           "clocks; STATUS.SW_LEVEL shows the filtered levels and every change raises IRQ_STATUS.SWITCH. With "
           "SW_CFG.LIM_EN, motion into an active limit stops (SW_CFG.LIM_HARD = 0: the controlled stop with "
           "STOP_JERK / STOP_ACC; 1: at once), and a START whose move heads into one is taken by the register "
           "file but refused by the core (nothing moves). Either sets ERR.LIMIT_NEG / LIMIT_POS and "
           "IRQ_STATUS.FAULT. Motion away from an active limit runs. Counts stay exact: PULSE_COUNT, REF_POS "
           "and the pins agree after any limit stop (docs/limits.md). The probe stops nothing; with home and "
           "the encoder index it is a source of the position latch (LATCH_CFG.SRC).", "",
           "Encoder index (Z; `enc_z_i` of sc_axi_servo, on the board Pmod JB9, pulled down): through the "
           "decoder's synchroniser and glitch filter with A and B, so its filtered level changes in the clock "
           "ENC_POS shows the quadrature state it came with; LATCH_CFG.SRC = 2 latches on its edges "
           "(sc_axi_axis takes the filtered level as `enc_index_i`, in step with `enc_pos_i`).", "",
           "Guards against the host: GUARD_VEL, GUARD_ACC and GUARD_JERK (0 = no limit, the reset value) are "
           "the largest |vel0|, |acc0| and |jerk| a row may start with. The executor checks the head row when "
           "it would load it: a START whose first row is over a guard is refused (nothing moves); a later row "
           "over one is not executed and the axis stops under control from the running row's end state (STOP_JERK "
           "/ STOP_ACC). Either way the FIFO is emptied, STATUS.GUARD is set until the next START and "
           "ERR.GUARD and IRQ_STATUS.FAULT are raised; counts stay exact. Recovery: clear ERR, load rows within "
           "the guards, START (docs/limits.md).", ""]
    out += SOURCE_DOC
    out += ["## Registers", "",
           "| offset | name | access | reset | implemented bits | description |",
           "|---|---|---|---|---|---|"]
    for w in words:
        out.append(f"| 0x{w['addr']:02X} | {w['name']}{' (servo)' if w['servo'] else ''} | {w['access']} | "
                   f"0x{w['reset']:08X} | 0x{w['mask']:08X} | {w['desc']} |")
    out += ["", "## Fields", ""]
    for w in words:
        if not w["fields"]:
            continue
        out += [f"### {w['name']} (0x{w['addr']:02X}, {w['access']})", "",
                "| bits | field | reset | description |", "|---|---|---|---|"]
        for f in sorted(w["fields"], key=lambda f: -f["lsb"]):
            hi = f["lsb"] + f["width"] - 1
            bits = f"{hi}:{f['lsb']}" if f["width"] > 1 else f"{f['lsb']}"
            out.append(f"| {bits} | {f['name']} | {f['reset']} | {f['desc']} |")
        out.append("")
    out += config_doc(params, words, enums or [])
    out += ["## Loading and running a move", "",
            "1. CTRL = 1 (enable); optionally PULSE_TIME / DIR_TIME.",
            "2. For each row of the move: SEG_PHASE, SEG_CLOCKS, SEG_JERK_0/1, SEG_ACC0_0/1, "
            "SEG_VEL0_0/1/2 (two's complement, low word first), then ROW_PUSH (0 for every row "
            "but the last; MOVE_END | STREAM_END = 3 for the last).",
            "3. POS_FRAC0_0/1/2 = the plan's initial fraction.",
            "4. CMD = START; poll STATUS until DONE (or read PULSE_COUNT), or enable IRQ_STATUS.IDLE.",
            "",
            "`scurve regs` prints this sequence for a planned move (`--uart` as frames).", "",
            "## Streaming moves", "",
            "START runs the FIFO's rows; the host keeps appending while the axis runs (FIFO_STATUS."
            "LEVEL, IRQ_STATUS.LOW_WATER). Each row after the first must start from the exact state "
            "the previous row ends in (SEG_VEL0 = v + a and SEG_ACC0 = a + j of its last clock; "
            "`scurve::StreamPlanner` emits such rows), else the axis stops and sets "
            "ERR.DISCONTINUITY. Mark the last row of each move MOVE_END (MOVE_INDEX and "
            "BOUNDARY_POS follow the moves) and the last row of the stream STREAM_END. A stream "
            "that ends at rest without STREAM_END simply ends; a FIFO that runs dry while the axis "
            "moves stops it and sets ERR.UNDERRUN. A stop empties the FIFO.", "",
            "## Multi-axis map", "",
            f"`sc_axi_multi_axis` (1 to {p['MaxAxes']} coordinated axes, `sc_multi_axis_core`, closed-loop "
            f"capable with Servo = 1) has one AXI4-Lite slave with {p['MultiRegAddrW']}-bit byte addresses: "
            f"{1 << p['RegWinW']} windows of {1 << p['RegAddrW']} bytes, window w at byte address "
            f"w * 0x{1 << p['RegAddrW']:X}. Window 1 + a is axis a's register file, the map above "
            "(its own staging row, pulse timing, stop and guard limits, switches, soft limits, "
            "closed-loop settings, status). Window 0 is the group window: a write there reaches every "
            "axis's register file in the same clock and answers with the worst of their responses; a "
            "read answers axis 0's register. Windows above the axes answer DECERR.", "",
            "What belongs to all axes is written through the group window only: SEG_CLOCKS (every axis's "
            "row lasts the same clocks), ROW_PUSH (appends one multi-axis row: every axis's staged row, "
            "with the write's flags), RETARGET_ROW and CMD.START / CMD.FLUSH. In an axis's window they "
            "answer SLVERR and set that axis's ERR.REJECT. A START is taken by every axis or by none: "
            "refused (SLVERR, ERR.REJECT on every axis) unless every axis is enabled, idle and not "
            "e-stopped. CMD.STOP or CMD.ESTOP in any window stops every axis (controlled, along the "
            "path, or at once); the core is enabled while CTRL.ENABLE is set on every axis. STATUS.BUSY "
            "rises on the same clock on every axis and falls on each when its last pulse has left. "
            "The interrupt output is the OR of the axes'. A group write that some axes refuse (a register "
            "locked while busy, written while one axis still sends its last pulses) answers SLVERR: the axes "
            "that took it changed, the others set ERR.REJECT; wait until no axis is busy, or write per axis.",
            "",
            "Loading a line: POS_FRAC0 per axis in its window; per row the staging registers "
            "(SEG_PHASE, SEG_JERK, SEG_ACC0, SEG_VEL0) per axis, then SEG_CLOCKS and ROW_PUSH in the "
            "group window (`scurve::encode_multi_row`); CMD = START in the group window.", "",
            "## UART bridge protocol", "",
            f"115200 baud 8N1 at 20 MHz ({p['UartClksPerBit']} clocks per bit), on the board's "
            "USB-UART. One request at a time; the board answers every complete frame.", "",
            "| frame | bytes |", "|---|---|",
            f"| write request | 0x{p['UartReqSync']:02X}, 0x{p['UartCmdWrite']:02X}, addr, d0, d1, d2, d3, crc |",
            f"| read request | 0x{p['UartReqSync']:02X}, 0x{p['UartCmdRead']:02X}, addr, crc |",
            f"| write response | 0x{p['UartRspSync']:02X}, status, crc |",
            f"| read response | 0x{p['UartRspSync']:02X}, status, d0, d1, d2, d3, crc |",
            f"| error response | 0x{p['UartRspSync']:02X}, 0x{p['UartStCrcErr']:02X} (CRC wrong) "
            f"or 0x{p['UartStBadCmd']:02X} (unknown command), crc |", "",
            f"- addr = WORD address: the bus byte address is addr * 4, so the one byte reaches all "
            f"{1 << (p['RegAddrW'] - 2)} words of the window (register byte address 0x{(1 << p['RegAddrW']) - 4:03X} "
            "is addr 0xFF) and an unaligned access cannot be sent. Register map 2.x (8-bit window) "
            "sent the byte address here: a 2.x host talking to a 3.0 board reaches the wrong "
            "registers, so check ID.VERSION first (it is at 0 in both);",
            f"- the multi-axis map (`sc_board_xy_top`, {p['MultiRegAddrW']}-bit byte addresses) sends the "
            "word address in 2 bytes, low byte first (a write request is 9 bytes, a read request 5); "
            "a word address past the map is answered DECERR by the bridge, nothing reaches the bus;",
            "- data little-endian (d0 = bits 7:0);",
            "- crc: CRC-8, polynomial 0x07, initial value 0x00, no reflection, no final XOR, over "
            "every byte after the sync byte;",
            "- status: the AXI response, 0 OKAY, 2 SLVERR, 3 DECERR;",
            "- a frame whose CRC is wrong is answered 0x80 and nothing is written or read;",
            f"- a UART framing error or a gap of more than {p['UartTimeoutBits']} bit times inside "
            "a frame drops the partial frame silently; bytes other than the sync byte between frames "
            "are skipped.", ""]
    return "\n".join(out)


def write_if_changed(path, text):
    """Write text to path unless it already holds it (keeps the timestamp, so
    nothing that depends on the file rebuilds)."""
    try:
        if open(path, encoding="utf-8").read() == text:
            return
    except FileNotFoundError:
        pass
    open(path, "w", encoding="utf-8").write(text)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pkg")
    ap.add_argument("--header")
    ap.add_argument("--doc")
    ap.add_argument("--check")
    a = ap.parse_args()
    params, words = parse(a.pkg)
    if a.header:
        write_if_changed(a.header, header(params, words))
    if a.doc:
        open(a.doc, "w", encoding="utf-8").write(doc_for(a.pkg))
    if a.check:
        try:
            have = open(a.check, encoding="utf-8").read()
        except FileNotFoundError:
            have = ""
        if have != doc_for(a.pkg):
            sys.exit(f"{a.check} is stale: run scripts/gen_layout.py --update (or scripts/gen_regmap.py "
                     f"rtl/sc_pkg.sv --doc {a.check}) and commit it")


if __name__ == "__main__":
    main()
