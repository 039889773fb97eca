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
REG = re.compile(r'//@reg\s+(\w+)\s+(RO|RW|WO|W1C)\s*(?:wide=(\w+))?\s*(servo)?\s*"([^"]*)"\s*$')
FIELD = re.compile(r'//@field\s+(\w+)\s+(\w+)\s+(\w+)\s*(?:reset=(\w+))?\s*"([^"]*)"\s*$')


def num(v):
    v = v.replace("_", "")
    if "'h" in v:
        return int(v.split("'h")[1], 16)
    return int(v)


def parse(path):
    params, regs = {}, []
    by_name = {}
    for lineno, line in enumerate(open(path, encoding="utf-8"), 1):
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
            reg = {"name": r.group(1), "access": r.group(2), "wide": r.group(3),
                   "servo": bool(r.group(4)), "desc": r.group(5), "addr": value, "param": name, "fields": []}
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
            rv = f.group(4) or "0"
            reset = int(rv) if rv.isdigit() else params.get(rv)
            if reset is None:
                sys.exit(f"{path}:{lineno}: unknown reset value {rv}")
            reg["fields"].append({"name": f.group(2), "lsb": value, "width": width,
                                  "reset": reset, "desc": f.group(5),
                                  "param": name})
    if not regs:
        sys.exit(f"{path}: no //@reg tags found")
    # expand wide registers into words, check overlaps
    words, used = [], {}
    for reg in regs:
        if reg["wide"]:
            width = params.get(reg["wide"])
            if width is None:
                sys.exit(f"{path}: {reg['name']}: unknown width {reg['wide']}")
            n = (width + 31) // 32
            for i in range(n):
                bits = min(32, width - 32 * i)
                words.append({"name": f"{reg['name']}_{i}", "addr": reg["addr"] + 4 * i,
                              "access": reg["access"], "desc": f"{reg['desc']} (bits {32*i+bits-1}:{32*i})",
                              "mask": (1 << bits) - 1, "reset": 0, "fields": [], "group": reg["name"],
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
    for w in words:
        if w["addr"] % 4 or w["addr"] >= (1 << params["RegAddrW"]):
            sys.exit(f"{path}: {w['name']} address 0x{w['addr']:x} unaligned or outside the window")
        if w["addr"] in used:
            sys.exit(f"{path}: {w['name']} and {used[w['addr']]} share address 0x{w['addr']:02x}")
        used[w["addr"]] = w["name"]
    words.sort(key=lambda w: w["addr"])
    return params, words


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


def doc(params, words):
    p = params
    out = ["# Register map and UART protocol", "",
           "<!-- Generated from rtl/sc_pkg.sv by scripts/gen_regmap.py - do not edit;",
           "     ctest regmap_docs_in_sync fails when this file is stale. -->", "",
           f"AXI4-Lite slave `sc_axi_regs` (in `sc_axi_axis` and `sc_axi_servo`), {p['RegAddrW']}-bit byte addresses, "
           "32-bit registers. Any other address answers DECERR; a write to a read-only register "
           "answers SLVERR. Both set ERR.BAD_ACCESS and change nothing else. Reserved bits read 0 "
           "and ignore writes. WSTRB selects bytes (CMD, ERR and SEG_COMMIT act on byte 0).", "",
           "Writes to SEG_COUNT, PULSE_TIME, DIR_TIME, POS_FRAC0_*, SEG_* and CMD.START while "
           "STATUS.BUSY is set are refused: SLVERR, ERR.REJECT set, the running move is not touched. "
           "CMD.START is also refused while ERR.ESTOP is set or CTRL.ENABLE is 0.", "",
           "Registers marked (servo) exist in `sc_axi_servo` (closed-loop axis, the board top's) only; "
           "`sc_axi_axis` (open loop) answers DECERR there. The controller settings (CL_CFG .. "
           "SETTLE_RATE) are locked while STATUS.BUSY is set like the table, and so is CTRL.CLOSED_LOOP "
           "(a CTRL write changing it while busy is refused). Their units: docs/closed_loop.md; reset "
           "values = the closed-loop runner's defaults (`scurve sim --closed-loop`).", "",
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
    out += ["## Loading and running a move", "",
            "1. CTRL = 1 (enable); optionally PULSE_TIME / DIR_TIME.",
            "2. For each table row i: SEG_PHASE, SEG_CLOCKS, SEG_JERK_0/1, SEG_ACC0_0/1, "
            "SEG_VEL0_0/1/2 (two's complement, low word first), then SEG_COMMIT = i.",
            "3. SEG_COUNT = rows, POS_FRAC0_0/1/2 = the plan's initial fraction.",
            "4. CMD = START; poll STATUS until DONE (or read PULSE_COUNT).",
            "",
            "`scurve regs` prints this sequence for a planned move (`--uart` as frames).", "",
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
            "- data little-endian (d0 = bits 7:0); addr = byte address;",
            "- crc: CRC-8, polynomial 0x07, initial value 0x00, no reflection, no final XOR, over "
            "every byte after the sync byte;",
            "- status: the AXI response, 0 OKAY, 2 SLVERR, 3 DECERR;",
            "- a frame whose CRC is wrong is answered 0x80 and nothing is written or read;",
            f"- a UART framing error or a gap of more than {p['UartTimeoutBits']} bit times inside "
            "a frame drops the partial frame silently; bytes other than the sync byte between frames "
            "are skipped.", ""]
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pkg")
    ap.add_argument("--header")
    ap.add_argument("--doc")
    ap.add_argument("--check")
    a = ap.parse_args()
    params, words = parse(a.pkg)
    if a.header:
        text = header(params, words)
        try:
            if open(a.header, encoding="utf-8").read() == text:
                text = None
        except FileNotFoundError:
            pass
        if text is not None:
            open(a.header, "w", encoding="utf-8").write(text)
    if a.doc:
        open(a.doc, "w", encoding="utf-8").write(doc(params, words))
    if a.check:
        try:
            have = open(a.check, encoding="utf-8").read()
        except FileNotFoundError:
            have = ""
        if have != doc(params, words):
            sys.exit(f"{a.check} is stale: run scripts/gen_regmap.py rtl/sc_pkg.sv --doc {a.check}")


if __name__ == "__main__":
    main()
