#!/usr/bin/env python3
"""Layouts shared by RTL, model, host software and docs, from the tags of rtl/sc_pkg.sv.

Usage:
  gen_layout.py [--pkg rtl/sc_pkg.sv] --update       rewrite the generated section of
                                                    sc_pkg.sv and docs/regmap.md
  gen_layout.py [--pkg rtl/sc_pkg.sv] --check        exit 1 if either is stale
  gen_layout.py [--pkg rtl/sc_pkg.sv] --header OUT   C++ header (build/generated/sc_layout.h)

Source (the hand-written part of sc_pkg.sv, see scripts/gen_regmap.py):
  - the //@field tags carrying cfg=MEMBER [signed] [q=FRAC] [unit=UNIT] on
    the closed-loop settings registers (tagged `servo`): the controller
    configuration, in word order, then field order;
  - //@enum TYPE WIDTH "text" / //@value TYPE NAME [=N] "text": encodings.
Generated:
  - SV, in the generated section at the end of sc_pkg.sv: ClCfgWords, the
    configuration vector's width CtlCfgW and per field CtlCfg<Member>Lsb and
    CtlCfg<Member>W (the layout of a `struct packed` with the members in
    source order: first member at the MSB), the word masks ClCfgMask and
    reset values ClCfgReset, ctl_cfg_from_words() (register words ->
    vector) and the encodings as <Type><Name> localparams;
  - C++: the same constants, struct sc::CtlCfg (member defaults = the
    register reset values), ctl_cfg_from_words / ctl_cfg_to_words /
    ctl_cfg_masked / ctl_cfg_zero / ctl_cfg_pack (the RTL vector as 32-bit
    words, for Verilator ports) / ctl_cfg_visit, and the enums;
  - docs/regmap.md (scripts/gen_regmap.py) including the configuration and
    encoding tables.
The vector travels as `logic [sc_pkg::CtlCfgW-1:0]` rather than a packed
struct type: Icarus 11 asserts on a package-scoped type (sc_pkg::ctl_cfg_t)
and yosys 0.23 accepts no package import in a module header or in $unit,
so no struct-typed port works in all three tools.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_regmap  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN = ("  " + gen_regmap.GEN_BEGIN + " (scripts/gen_layout.py from the //@ tags above;\n"
         "  // do not edit: regenerate with scripts/gen_layout.py --update) ----\n")
END = "  " + gen_regmap.GEN_END + " ----\n"


def camel(member):
    return "".join(p[:1].upper() + p[1:] for p in member.split("_"))


def config(pkg):
    """Fields of the controller configuration, in order, and the word count."""
    params, words = gen_regmap.parse(pkg)
    first = params.get("RegClFirst")
    if first is None:
        sys.exit(f"{pkg}: RegClFirst missing")
    fields, cwords, seen = [], [], set()
    for w in words:
        cf = [f for f in w["fields"] if f.get("cfg")]
        if not cf:
            continue
        if not w["servo"] or w["access"] != "RW":
            sys.exit(f"{pkg}: {w['name']}: cfg= fields belong on RW servo registers")
        if len(cf) != len(w["fields"]):
            sys.exit(f"{pkg}: {w['name']}: every field of a settings word needs cfg=")
        idx = len(cwords)
        if w["addr"] != first + 4 * idx:
            sys.exit(f"{pkg}: {w['name']} at 0x{w['addr']:02X}: settings words must be contiguous "
                     f"from RegClFirst (expected 0x{first + 4 * idx:02X})")
        cwords.append(w)
        for f in sorted(cf, key=lambda f: f["lsb"]):
            if f["cfg"] in seen:
                sys.exit(f"{pkg}: member {f['cfg']} defined twice")
            seen.add(f["cfg"])
            if f["width"] > 32 or (f["signed"] and f["width"] < 2):
                sys.exit(f"{pkg}: {f['cfg']}: width {f['width']} not supported")
            fields.append(dict(f, word=idx, reg=w["name"]))
    if not fields:
        sys.exit(f"{pkg}: no cfg= fields")
    total = sum(f["width"] for f in fields)
    pos = total
    for f in fields:
        pos -= f["width"]
        f["vlsb"] = pos
    return params, cwords, fields, total


def ctype(f):
    if f["width"] == 1 and not f["signed"]:
        return "bool"
    if f["signed"]:
        return "int32_t"
    return "uint8_t" if f["width"] <= 8 else "uint16_t" if f["width"] <= 16 else "uint32_t"


def sv_section(pkg):
    params, cwords, fields, total = config(pkg)
    enums = gen_regmap.parse_enums(pkg, params)
    n = len(cwords)
    o = [BEGIN.rstrip("\n"),
         "  // Controller configuration: the fields of the settings words as one",
         "  // vector, first field at the MSB (the layout of a struct packed with",
         "  // these members in this order).",
         f"  localparam int ClCfgWords = {n};",
         f"  localparam int CtlCfgW    = {total};"]
    for f in fields:
        c = camel(f["cfg"])
        sg = "signed " if f["signed"] else ""
        o.append(f"  localparam int CtlCfg{c}Lsb = {f['vlsb']};  "
                 f"// {f['cfg']}: {sg}{f['width_param']}, {f['reg']}.{f['name']}")
        o.append(f"  localparam int CtlCfg{c}W = {f['width']};")
    masks = [w["mask"] for w in cwords]
    resets = [w["reset"] for w in cwords]
    o.append("  // implemented bits and reset value of each settings word (word 0 lowest)")
    o.append("  localparam logic [ClCfgWords*32-1:0] ClCfgMask = {")
    o += [f"      32'h{m:08X}{',' if i else ''}  // {cwords[i]['name']}" for i, m in reversed(list(enumerate(masks)))]
    o.append("  };")
    o.append("  localparam logic [ClCfgWords*32-1:0] ClCfgReset = {")
    o += [f"      32'h{r:08X}{',' if i else ''}  // {cwords[i]['name']}" for i, r in reversed(list(enumerate(resets)))]
    o.append("  };")
    o.append("  // settings words -> configuration vector")
    o.append("  function automatic logic [CtlCfgW-1:0] ctl_cfg_from_words(input logic [ClCfgWords*32-1:0] cl_words);")
    o.append("    ctl_cfg_from_words = {")
    for i, f in enumerate(fields):
        sep = "," if i < len(fields) - 1 else ""
        o.append(f"      cl_words[32*{f['word']} + {f['param']} +: {f['width_param']}]{sep}  // {f['cfg']}")
    o.append("    };")
    o.append("  endfunction")
    for e in enums:
        o.append(f"  // {e['name']}: {e['desc']}")
        for v in e["values"]:
            o.append(f"  localparam logic [{e['width_param']}-1:0] {e['name']}{v['name']} = "
                     f"{e['width']}'d{v['value']};")
    o.append(END.rstrip("\n"))
    return "\n".join(o) + "\n"


def split_pkg(text, pkg):
    """(before, generated section, after); the section sits before `endpackage`."""
    b = text.find(gen_regmap.GEN_BEGIN)
    if b < 0:
        k = text.rfind("endpackage")
        if k < 0:
            sys.exit(f"{pkg}: no endpackage")
        return text[:k], "", text[k:]
    b = text.rfind("\n", 0, b) + 1
    e = text.find(gen_regmap.GEN_END, b)
    if e < 0:
        sys.exit(f"{pkg}: generated section not closed")
    e = text.find("\n", e) + 1
    return text[:b], text[b:e], text[e:]


def header(pkg):
    params, cwords, fields, total = config(pkg)
    enums = gen_regmap.parse_enums(pkg, params)
    n = len(cwords)
    nw = (total + 31) // 32
    o = ["// Generated from rtl/sc_pkg.sv by scripts/gen_layout.py - do not edit.",
         "// The controller configuration (the settings words CL_CFG .. of sc_axi_servo,",
         "// the vector sc_axi_regs -> sc_servo_axis -> sc_neuron_pi carries) and the",
         "// encodings shared by the RTL and the model.",
         "#pragma once", "#include <array>", "#include <cstddef>", "#include <cstdint>", "", "#include \"sc_params.h\"", "",
         "namespace sc {", "",
         f"inline constexpr int ClCfgWords = {n};",
         f"inline constexpr int CtlCfgW = {total};",
         f"inline constexpr int CtlCfgWords32 = {nw};  // 32-bit words of the vector"]
    for f in fields:
        c = camel(f["cfg"])
        o.append(f"inline constexpr int CtlCfg{c}Lsb = {f['vlsb']};")
        o.append(f"inline constexpr int CtlCfg{c}W = {f['width']};")
    o.append("inline constexpr uint32_t kClCfgMask[ClCfgWords] = {")
    o += [f"    0x{w['mask']:08X}u,  // {w['name']}" for w in cwords]
    o.append("};")
    o.append("inline constexpr uint32_t kClCfgReset[ClCfgWords] = {")
    o += [f"    0x{w['reset']:08X}u,  // {w['name']}" for w in cwords]
    o.append("};")
    o += ["", "// Controller configuration; member defaults = the register reset values.",
          "struct CtlCfg {"]
    for f in fields:
        q = f", Q.{f['q']}" if f["q"] else ""
        unit = f" {f['unit']}" if f["unit"] and f["unit"] != "1" else ""
        rv = f["reset"]
        init = ("true" if rv else "false") if ctype(f) == "bool" else str(rv)
        o.append(f"  {ctype(f)} {f['cfg']} = {init};  // {f['reg']}.{f['name']}: "
                 f"{'signed' if f['signed'] else 'unsigned'} {f['width']} bits{q}{unit}; {f['desc']}")
    eq = " &&\n           ".join(f"{f['cfg']} == o.{f['cfg']}" for f in fields)
    o += ["  // (spelled out: the header is valid C++17 for the SystemC translation units)",
          "  constexpr bool operator==(const CtlCfg& o) const {", f"    return {eq};", "  }",
          "  constexpr bool operator!=(const CtlCfg& o) const { return !(*this == o); }", "};", ""]
    o += ["// Every field 0 (sc_servo_axis's registers after reset).",
          "constexpr CtlCfg ctl_cfg_zero() {", "  CtlCfg c;"]
    for f in fields:
        o.append(f"  c.{f['cfg']} = {'false' if ctype(f) == 'bool' else '0'};")
    o += ["  return c;", "}", ""]
    o += ["namespace layout_detail {",
          "constexpr uint32_t ufield(uint32_t w, int lsb, int width) {",
          "  return width >= 32 ? w >> lsb : (w >> lsb) & ((uint32_t(1) << width) - 1);",
          "}",
          "constexpr int32_t sfield(uint32_t w, int lsb, int width) {",
          "  const int64_t s = int64_t(1) << (width - 1);",
          "  return int32_t((int64_t(ufield(w, lsb, width)) ^ s) - s);",
          "}",
          "constexpr uint32_t place(uint32_t v, int lsb, int width) {",
          "  return uint32_t(((uint64_t(v) & ((uint64_t(1) << width) - 1))) << lsb);",
          "}",
          "}  // namespace layout_detail", "",
          "// Settings words -> configuration (unsigned fields zero-, signed ones sign-extended).",
          "constexpr CtlCfg ctl_cfg_from_words(const std::array<uint32_t, ClCfgWords>& w) {",
          "  using namespace layout_detail;", "  CtlCfg c;"]
    for f in fields:
        fn = "sfield" if f["signed"] else "ufield"
        expr = f"{fn}(w[{f['word']}], {f['lsb']}, {f['width']})"
        if ctype(f) == "bool":
            expr = f"{expr} != 0"
        elif ctype(f) not in ("int32_t", "uint32_t"):
            expr = f"{ctype(f)}({expr})"
        o.append(f"  c.{f['cfg']} = {expr};")
    o += ["  return c;", "}", "",
          "// Configuration -> settings words (each field cut to its width).",
          "constexpr std::array<uint32_t, ClCfgWords> ctl_cfg_to_words(const CtlCfg& c) {",
          "  using namespace layout_detail;", "  std::array<uint32_t, ClCfgWords> w{};"]
    for f in fields:
        o.append(f"  w[{f['word']}] |= place(uint32_t(c.{f['cfg']}), {f['lsb']}, {f['width']});")
    o += ["  return w;", "}", "",
          "// What the RTL's configuration registers hold for `c` (fields cut to width).",
          "constexpr CtlCfg ctl_cfg_masked(const CtlCfg& c) { return ctl_cfg_from_words(ctl_cfg_to_words(c)); }", "",
          "// The RTL vector (logic [CtlCfgW-1:0]) as 32-bit words, word 0 = bits 31:0.",
          "constexpr std::array<uint32_t, CtlCfgWords32> ctl_cfg_pack(const CtlCfg& c) {",
          "  std::array<uint32_t, CtlCfgWords32> v{};",
          "  auto put = [&v](int lsb, int width, uint32_t x) {",
          "    for (int b = 0; b < width; ++b) {",
          "      if ((x >> b) & 1u) v[std::size_t((lsb + b) / 32)] |= uint32_t(1) << ((lsb + b) % 32);",
          "    }",
          "  };"]
    for f in fields:
        o.append(f"  put(CtlCfg{camel(f['cfg'])}Lsb, {f['width']}, uint32_t(c.{f['cfg']}));")
    o += ["  return v;", "}", "",
          "// f(name, value) for every field, in layout order (printing, random configs).",
          "template <class F>",
          "constexpr void ctl_cfg_visit(const CtlCfg& c, F&& f) {"]
    for f in fields:
        o.append(f"  f(\"{f['cfg']}\", int64_t(c.{f['cfg']}));")
    o += ["}", ""]
    for e in enums:
        o.append(f"// {e['desc']}")
        o.append(f"enum {e['name']} : uint8_t {{")
        for v in e["values"]:
            o.append(f"  {e['name']}{v['name']} = {v['value']},  // {v['desc']}")
        o.append("};")
        o.append("")
    o += ["}  // namespace sc", ""]
    return "\n".join(o)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pkg", default=os.path.join(ROOT, "rtl", "sc_pkg.sv"))
    ap.add_argument("--doc", default=os.path.join(ROOT, "docs", "regmap.md"))
    ap.add_argument("--update", action="store_true")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--header")
    a = ap.parse_args()
    text = open(a.pkg, encoding="utf-8").read()
    before, have, after = split_pkg(text, a.pkg)
    want = sv_section(a.pkg)
    doc = gen_regmap.doc_for(a.pkg)
    if a.update:
        gen_regmap.write_if_changed(a.pkg, before + want + after)
        gen_regmap.write_if_changed(a.doc, doc)
    if a.check:
        stale = []
        if have != want:
            stale.append(f"{a.pkg} (generated section)")
        try:
            if open(a.doc, encoding="utf-8").read() != doc:
                stale.append(a.doc)
        except FileNotFoundError:
            stale.append(a.doc)
        if stale:
            sys.exit("stale generated layout: " + ", ".join(stale) +
                     "\nregenerate with: scripts/gen_layout.py --update  (then commit)")
    if a.header:
        gen_regmap.write_if_changed(a.header, header(a.pkg))


if __name__ == "__main__":
    main()
